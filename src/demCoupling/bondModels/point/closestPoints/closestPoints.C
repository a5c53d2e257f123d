/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "closestPoints.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bondPointModels
{
    defineTypeNameAndDebug(closestPoints, 0);
    addToRunTimeSelectionTable(bondPointModel, closestPoints, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bondPointModels::closestPoints::closestPoints(const dictionary& dict)
:
    bondPointModel(dict, wordList())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bondPointModels::closestPoints::set(dem::BondParameters& bonds) const
{
    bonds.point = dem::BondPoint::closestPoints;
}


// ************************************************************************* //
