/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "packingStatistics.H"
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
    defineTypeNameAndDebug(packingStatistics, 0);
    addToRunTimeSelectionTable(functionObject, packingStatistics, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::packingStatistics::writeFileHeader(Ostream& os)
{
    writeHeader(os, "Packing statistics (doc/CASE-FORMAT.md, function objects)");
    writeCommented(os, "time");
    for
    (
        const char* column :
        {
            "density", "solidFraction", "coordinationNumber", "bondsIntact",
            "bondsFormed", "bondsBroken", "bondsApart", "meanPatchRadius",
            "lidPosition", "lidVelocity", "strainRate", "bulkViscosity"
        }
    )
    {
        writeTabbed(os, column);
    }
    os << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::packingStatistics::packingStatistics
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, "packing", dict)
{
    read(dict);
    writeFileHeader(file());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::packingStatistics::read(const dictionary& dict)
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


bool Foam::functionObjects::packingStatistics::execute()
{
    return true;
}


bool Foam::functionObjects::packingStatistics::write()
{
    // Reads of the DEM library: whatever it throws ends as a FatalError
    return demLibraryCall
    (
        "function object " + name(),
        [&]
        {
            const demCloud& cloud = mesh_.lookupObject<demCloud>("demCloud");
            const dem::System& dem = cloud.system();
            const wallEnclosure box(dem, cloud.grid().grid());
            const dem::GrainData g = dem.grains();
            const dem::BondCounts bonds = dem.bondCounts();

            scalar mass = 0, volume = 0;
            for (size_t i = 0; i < g.mass.size(); ++i)
            {
                mass += g.mass[i];
                volume += g.volume[i];
            }
            const label n = g.mass.size();
            const scalar coordination =
                n ? 2.0*(dem.contactCount() + bonds.apart)/n : 0;

            scalar lid = 0, lidVelocity = 0, strainRate = 0, viscosity = 0;
            if (box.lid() >= 0)
            {
                const dem::WallData& wall = box.walls()[box.lid()];
                lid = wall.position;
                lidVelocity = wall.velocity;
                strainRate = -lidVelocity/(lid - box.lower(2));
                const scalar stress = wall.grainForce/box.area(box.lid());
                viscosity = strainRate != 0 ? stress/strainRate : 0;
            }

            Ostream& os = file();
            writeCurrentTime(os);
            os  << tab << mass/box.volume() << tab << volume/box.volume()
                << tab << coordination
                << tab << label(bonds.intact) << tab << label(bonds.formed)
                << tab << label(bonds.broken) << tab << label(bonds.apart)
                << tab << bonds.meanPatchRadius
                << tab << lid << tab << lidVelocity << tab << strainRate
                << tab << viscosity << endl;
            return true;
        }
    );
}


// ************************************************************************* //
