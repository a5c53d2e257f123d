/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "powerLaw.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bondCompressiveCreepModels
{
    defineTypeNameAndDebug(powerLaw, 0);
    addToRunTimeSelectionTable(bondCompressiveCreepModel, powerLaw, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bondCompressiveCreepModels::powerLaw::powerLaw(const dictionary& dict)
:
    bondCompressiveCreepModel(dict, {"prefactor", "activationEnergy", "exponent"}),
    prefactor_
    (
        inputChecks::getPositiveOrDefault
        (
            dict, "prefactor", dem::BondParameters().creepPrefactor
        )
    ),
    activationEnergy_
    (
        inputChecks::getInRange
        (
            dict,
            "activationEnergy",
            dem::BondParameters().creepActivationEnergy,
            0
        )
    ),
    exponent_
    (
        inputChecks::getInInterval
        (
            dict, "exponent", dem::BondParameters().creepExponent, 1, 10, true, false
        )
    )
{
    // The default A0 is in s^-1 Pa^-3: with another exponent its units would not match
    if (exponent_ != dem::BondParameters().creepExponent && !dict.found("prefactor"))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'exponent' in " << dict.name() << " is "
            << inputChecks::shortForm(exponent_).c_str() << ", but 'prefactor' is not"
            << " given: its default, 0.00554458 s^-1 Pa^-3, holds for exponent"
            << " 3 only. Give prefactor in s^-1 Pa^-n for n = "
            << inputChecks::shortForm(exponent_).c_str() << ", or leave exponent out."
            << nl << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bondCompressiveCreepModels::powerLaw::set(dem::BondParameters& bonds) const
{
    bonds.compressiveCreep = dem::BondCompressiveCreep::powerLaw;
    bonds.creepPrefactor = prefactor_;
    bonds.creepActivationEnergy = activationEnergy_;
    bonds.creepExponent = exponent_;
}


// ************************************************************************* //
