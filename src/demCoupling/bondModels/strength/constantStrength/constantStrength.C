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


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- A required strength >= 0 (0: that mode never fails)
Foam::scalar nonNegative(const Foam::dictionary& dict, const Foam::word& key)
{
    if (!dict.found(key))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' not found in " << dict.name()
            << "; expected '" << key << " <value [Pa], >= 0>;'" << Foam::nl
            << Foam::exit(Foam::FatalIOError);
    }
    return Foam::inputChecks::getInRange(dict, key, 0, 0);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bondStrengthModels::constantStrength::constantStrength(const dictionary& dict)
:
    bondStrengthModel
    (
        dict,
        fracture::withEntryNames({"tensileStrength", "shearStrength"})
    ),
    tensileStrength_(nonNegative(dict, "tensileStrength")),
    shearStrength_(nonNegative(dict, "shearStrength")),
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
