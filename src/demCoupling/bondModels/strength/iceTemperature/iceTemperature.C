/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "iceTemperature.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bondStrengthModels
{
    defineTypeNameAndDebug(iceTemperature, 0);
    addToRunTimeSelectionTable(bondStrengthModel, iceTemperature, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bondStrengthModels::iceTemperature::iceTemperature(const dictionary& dict)
:
    bondStrengthModel(dict, fracture::withEntryNames({"scale"})),
    scale_(inputChecks::getPositiveOrDefault(dict, "scale", 1)),
    fracture_(dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bondStrengthModels::iceTemperature::set(dem::BondParameters& bonds) const
{
    bonds.strength = dem::BondStrength::iceTemperature;
    bonds.strengthScale = scale_;
    fracture_.set(bonds);
}


// ************************************************************************* //
