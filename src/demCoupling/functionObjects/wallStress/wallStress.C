/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "wallStress.H"
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


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::wordList Foam::functionObjects::wallStress::columns
(
    const demCloud& cloud
) const
{
    // The walls are known once the grains are (demCloud's demWalls)
    wordList names;
    for (const word& wall : cloud.walls().names())
    {
        for (const char* column : {"_position", "_force", "_stress"})
        {
            names.append(word(wall + column));
        }
    }
    return names;
}


void Foam::functionObjects::wallStress::writeRow
(
    Ostream& os,
    const demCloud& cloud
)
{
    const wallEnclosure box(cloud.system(), cloud.grid().grid());
    const label nWalls = box.walls().size();
    for (label w = 0; w < nWalls; ++w)
    {
        const dem::WallData& wall = box.walls()[w];
        os  << tab << wall.position << tab << wall.grainForce
            << tab << wall.grainForce/box.area(w);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::wallStress::wallStress
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
        typeName,
        "Wall stresses (doc/CASE-FORMAT.md, function objects)"
    )
{}


// ************************************************************************* //
