/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "constantStrength.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bondStrengthModels
{
    defineTypeNameAndDebug(constantStrength, 0);
    addToRunTimeSelectionTable(bondStrengthModel, constantStrength, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bondStrengthModels::constantStrength::constantStrength(const dictionary& dict)
:
    tensileStrength_(inputChecks::getPositive(dict, "tensileStrength")),
    shearStrength_(inputChecks::getPositive(dict, "shearStrength")),
    fracture_(dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bondStrengthModels::constantStrength::set(dem::BondParameters& bonds) const
{
    bonds.strength = dem::BondStrength::constant;
    bonds.tensileStrength = tensileStrength_;
    bonds.shearStrength = shearStrength_;
    fracture_.set(bonds);
}


// ************************************************************************* //
