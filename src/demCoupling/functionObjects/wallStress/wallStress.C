/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "wallStress.H"
#include "inputChecks.H"
#include "demLibraryCall.H"
#include "demCloud.H"
#include "wallEnclosure.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(wallStress, 0);
    addToRunTimeSelectionTable(functionObject, wallStress, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::wallStress::writeFileHeader
(
    Ostream& os,
    const wordList& walls
)
{
    writeHeader(os, "Wall stresses (doc/CASE-FORMAT.md, function objects)");
    writeCommented(os, "time");
    for (const word& wall : walls)
    {
        for (const char* column : {"_position", "_force", "_stress"})
        {
            writeTabbed(os, wall + column);
        }
    }
    os << endl;
    headerWritten_ = true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::wallStress::wallStress
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    headerWritten_(false)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::wallStress::read(const dictionary& dict)
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


bool Foam::functionObjects::wallStress::execute()
{
    return true;
}


bool Foam::functionObjects::wallStress::write()
{
    // Reads of the DEM library: whatever it throws ends as a FatalError
    return demLibraryCall
    (
        "function object " + name(),
        [&]
        {
            const demCloud& cloud = mesh_.lookupObject<demCloud>("demCloud");
            const wallEnclosure box(cloud.system(), cloud.grid().grid());
            const label nWalls = box.walls().size();

            Ostream& os = file();
            if (!headerWritten_)
            {
                writeFileHeader(os, cloud.walls().names());
            }
            writeCurrentTime(os);
            for (label w = 0; w < nWalls; ++w)
            {
                const dem::WallData& wall = box.walls()[w];
                os  << tab << wall.position << tab << wall.grainForce
                    << tab << wall.grainForce/box.area(w);
            }
            os << endl;
            return true;
        }
    );
}


// ************************************************************************* //
