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
    bondCompressiveCreepModel(dict, {"prefactor", "activationEnergy"}),
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
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bondCompressiveCreepModels::powerLaw::set(dem::BondParameters& bonds) const
{
    bonds.compressiveCreep = dem::BondCompressiveCreep::powerLaw;
    bonds.creepPrefactor = prefactor_;
    bonds.creepActivationEnergy = activationEnergy_;
}


// ************************************************************************* //
