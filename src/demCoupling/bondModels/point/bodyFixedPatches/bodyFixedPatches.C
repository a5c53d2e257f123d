/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "bodyFixedPatches.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bondPointModels
{
    defineTypeNameAndDebug(bodyFixedPatches, 0);
    addToRunTimeSelectionTable(bondPointModel, bodyFixedPatches, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bondPointModels::bodyFixedPatches::bodyFixedPatches(const dictionary& dict)
:
    bondPointModel(dict, wordList())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bondPointModels::bodyFixedPatches::set(dem::BondParameters& bonds) const
{
    bonds.point = dem::BondPoint::bodyFixedPatches;
}


// ************************************************************************* //
