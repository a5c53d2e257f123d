/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "latestCompleteTime.H"
#include "demStateFile.H"
#include "IFstream.H"
#include "dictionary.H"
#include "OSspecific.H"
#include "TimePaths.H"
#include "SubList.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::latestCompleteTime::hasGrains(const fileName& casePath)
{
    if (!isFile(casePath/"constant"/"demProperties"))
    {
        return false;
    }
    const fileName darcy(casePath/"constant"/"darcyProperties");
    if (!isFile(darcy))
    {
        return true; // demFoam
    }
    IFstream is(darcy);
    const dictionary dict(is);
    const dictionary* solid = dict.findDict("solidPhase");
    return solid && solid->getOrDefault<word>("type", word::null) == "demGrains";
}


bool Foam::latestCompleteTime::startsFromLatestTime(const fileName& casePath)
{
    IFstream is(casePath/"system"/"controlDict");
    if (!is.good())
    {
        return false; // Time will say what is missing
    }
    const dictionary dict(is);
    return dict.getOrDefault<word>("startFrom", word::null) == "latestTime";
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::latestCompleteTime::setAside(const argList& args)
{
    const fileName casePath(args.path());
    if
    (
        args.found("time")
     || !startsFromLatestTime(casePath)
     || !hasGrains(casePath)
    )
    {
        return 0;
    }

    // Time directories in order (findTimes lists 'constant' too)
    instantList times(TimePaths::findTimes(casePath));
    if (times.size() && times.first().name() == "constant")
    {
        times = instantList(SubList<instant>(times, times.size() - 1, 1));
    }
    label moved = 0;
    for (label i = times.size() - 1; i > 0; --i)
    {
        const fileName dir(casePath/times[i].name());
        if (demStateFile(dir/"demState").complete())
        {
            break;
        }
        if (!mvBak(dir, "incomplete"))
        {
            FatalErrorInFunction
                << "Cannot rename the incomplete time directory " << dir
                << nl << exit(FatalError);
        }
        ++moved;
        Warning
            << "Time " << times[i].name() << " is incomplete (no whole "
            << "demState: the run writing it was stopped mid-write); moved"
            << " to " << dir << ".incomplete and not used for the restart"
            << endl;
    }
    if (moved)
    {
        Info<< "startFrom latestTime: restarting from the latest complete"
            << " time " << times[times.size() - 1 - moved].name() << nl
            << endl;
    }
    return moved;
}


// ************************************************************************* //
