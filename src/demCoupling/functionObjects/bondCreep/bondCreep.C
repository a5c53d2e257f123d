/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "bondCreep.H"
#include "inputChecks.H"
#include "demLibraryCall.H"
#include "demCloud.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(bondCreep, 0);
    addToRunTimeSelectionTable(functionObject, bondCreep, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::bondCreep::writeFileHeader(Ostream& os)
{
    writeHeader
    (
        os,
        "Bond creep per mechanism (doc/CASE-FORMAT.md, function objects): "
        "sums over every bond since the start [m, m, rad, rad], "
        "then means over the intact bonds"
    );
    writeCommented(os, "time");
    for
    (
        const char* column :
        {
            "bondsIntact", "normal", "shear", "twist", "bend",
            "meanNormal", "meanShear", "meanTwist", "meanBend"
        }
    )
    {
        writeTabbed(os, column);
    }
    os << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::bondCreep::bondCreep
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, "creep", dict)
{
    read(dict);
    writeFileHeader(file());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::bondCreep::read(const dictionary& dict)
{
    // No entries of its own
    inputChecks::checkKnownEntries
    (
        dict,
        inputChecks::functionObjectEntryNames()
    );
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    return true;
}


bool Foam::functionObjects::bondCreep::execute()
{
    return true;
}


bool Foam::functionObjects::bondCreep::write()
{
    // Reads of the DEM library: whatever it throws ends as a FatalError
    return demLibraryCall
    (
        "function object " + name(),
        [&]
        {
            const demCloud& cloud = mesh_.lookupObject<demCloud>("demCloud");
            const dem::BondCounts bonds = cloud.system().bondCounts();
            const scalar intact = bonds.intact;

            Ostream& os = file();
            writeCurrentTime(os);
            os  << tab << label(bonds.intact);
            for (int m = 0; m < 4; ++m)
            {
                os  << tab << bonds.intactCreep[m] + bonds.brokenCreep[m];
            }
            for (int m = 0; m < 4; ++m)
            {
                os  << tab << (intact > 0 ? bonds.intactCreep[m]/intact : 0);
            }
            os  << endl;
            return true;
        }
    );
}


// ************************************************************************* //
