/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "latestCompleteTime.H"
#include "stepTimers.H"
#include "demStateFile.H"
#include "IFstream.H"
#include "OFstream.H"
#include "dictionary.H"
#include "OSspecific.H"
#include "TimePaths.H"
#include "SubList.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

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


bool Foam::latestCompleteTime::incomplete(const fileName& dir)
{
    return
        isFile(dir/markName)
     && !demStateFile(dir/"demState").complete();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const char* const Foam::latestCompleteTime::markName = ".writeInProgress";


void Foam::latestCompleteTime::beginWrite(const Time& runTime)
{
    if (!runTime.writeTime())
    {
        return;
    }
    const fileName dir(runTime.timePath());
    mkDir(dir);
    OFstream mark(dir/markName);
    mark.flush();
    if (!mark.good())
    {
        FatalErrorInFunction
            << "Cannot create " << dir/markName << nl << exit(FatalError);
    }
}


void Foam::latestCompleteTime::endWrite(const Time& runTime)
{
    if (runTime.writeTime())
    {
        rm(runTime.timePath()/markName);
    }
}


Foam::label Foam::latestCompleteTime::setAside(const argList& args)
{
    // Decomposed: controlDict in the case directory, the times in each
    // processor directory
    const fileName caseDir(args.rootPath()/args.globalCaseName());
    const fileName casePath(args.path());
    if (args.found("time") || !startsFromLatestTime(caseDir))
    {
        return 0;
    }

    // Time directories in order (findTimes lists 'constant' too)
    const auto timesOf = [](const fileName& dir)
    {
        instantList times(TimePaths::findTimes(dir));
        if (times.size() && times.first().name() == "constant")
        {
            times = instantList(SubList<instant>(times, times.size() - 1, 1));
        }
        return times;
    };
    const auto moveAside = [](const fileName& dir)
    {
        if (!mvBak(dir, "incomplete"))
        {
            FatalErrorInFunction
                << "Cannot rename the incomplete time directory " << dir
                << nl << exit(FatalError);
        }
    };

    const instantList times(timesOf(casePath));
    label moved = 0;
    for (label i = times.size() - 1; i >= 0; --i)
    {
        const fileName dir(casePath/times[i].name());
        if (!incomplete(dir))
        {
            // Killed after its last file, before the mark was removed
            rm(dir/markName);
            break;
        }
        moveAside(dir);
        ++moved;
        Warning
            << "Time " << times[i].name() << " is incomplete (the run"
            << " writing it was stopped mid-write: " << markName << " is"
            << " still there and no whole demState); moved"
            << " to " << dir << ".incomplete and not used for the restart"
            << endl;
    }

    // Decomposed: the latest time complete on every rank; later times
    // (complete on some ranks only) are set aside everywhere, with the
    // grains the master wrote into the case directory for them. A directory
    // without any time (decomposePar of a case without fields: demFoam's
    // grains are in the case directory's start time) sets no bound.
    scalar latest = times.empty() ? GREAT
      : moved < times.size() ? times[times.size() - 1 - moved].value()
      : -GREAT;
    if (Pstream::parRun())
    {
        latest = returnReduce(latest, minOp<scalar>());
        for (label i = times.size() - 1 - moved; i >= 0; --i)
        {
            if (times[i].value() <= latest)
            {
                break;
            }
            moveAside(casePath/times[i].name());
            ++moved;
        }
        if (Pstream::master())
        {
            for (const instant& t : timesOf(caseDir))
            {
                if (t.value() > latest && isDir(caseDir/t.name()))
                {
                    moveAside(caseDir/t.name());
                }
            }
        }
        reduce(moved, sumOp<label>());
    }

    if (latest == -GREAT)
    {
        FatalErrorInFunction
            << "Every time directory of " << casePath << " is incomplete"
            << " (set aside as <time>.incomplete): nothing to restart from"
            << nl << exit(FatalError);
    }
    if (moved)
    {
        Info<< "startFrom latestTime: restarting from the latest complete"
            << " time " << latest;
        if (Pstream::parRun())
        {
            Info<< " (complete on every rank; " << moved << " processor"
                << " time directories set aside)";
        }
        Info<< nl << endl;
    }
    return moved;
}


void Foam::latestCompleteTime::write
(
    Time& runTime,
    const std::function<void()>& last
)
{
    stepTimers& timers = stepTimers::New(runTime);
    {
        stepTimers::scope timed(timers, stepTimers::write);
        beginWrite(runTime);
        runTime.write();
        if (last)
        {
            last();
        }
        endWrite(runTime);
    }
    if (runTime.writeTime())
    {
        timers.printInterval(Info);
    }
}


// ************************************************************************* //
