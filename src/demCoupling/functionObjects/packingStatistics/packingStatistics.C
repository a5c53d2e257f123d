/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "packingStatistics.H"
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


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::wordList Foam::functionObjects::packingStatistics::columns
(
    const demCloud&
) const
{
    return
    {
        "density", "solidFraction", "coordinationNumber", "bondsIntact",
        "bondsFormed", "bondsBroken", "bondsApart", "meanPatchRadius",
        "lidPosition", "lidVelocity", "strainRate", "bulkViscosity"
    };
}


void Foam::functionObjects::packingStatistics::writeRow
(
    Ostream& os,
    const demCloud& cloud
)
{
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
    // Decomposed: each rank's own grains, summed over the ranks
    reduce(mass, sumOp<scalar>());
    reduce(volume, sumOp<scalar>());
    const label n = returnReduce(label(g.mass.size()), sumOp<label>());
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

    os  << tab << mass/box.volume() << tab << volume/box.volume()
        << tab << coordination
        << tab << label(bonds.intact) << tab << label(bonds.formed)
        << tab << label(bonds.broken) << tab << label(bonds.apart)
        << tab << bonds.meanPatchRadius
        << tab << lid << tab << lidVelocity << tab << strainRate
        << tab << viscosity;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::packingStatistics::packingStatistics
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    demTable
    (
        name,
        runTime,
        dict,
        "packing",
        "Packing statistics (doc/CASE-FORMAT.md, function objects)"
    )
{}


// ************************************************************************* //
