/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "maxwell.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bondCreepModels
{
    defineTypeNameAndDebug(maxwell, 0);
    addToRunTimeSelectionTable(bondCreepModel, maxwell, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bondCreepModels::maxwell::maxwell(const dictionary& dict)
:
    bondCreepModel(dict, {"contactViscosity", "shear", "twist", "bend"}),
    contactViscosity_(inputChecks::getPositive(dict, "contactViscosity")),
    shear_(dict.getOrDefault<bool>("shear", true)),
    twist_(dict.getOrDefault<bool>("twist", true)),
    bend_(dict.getOrDefault<bool>("bend", true))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bondCreepModels::maxwell::set(dem::BondParameters& bonds) const
{
    bonds.creep = dem::BondCreep::maxwell;
    bonds.contactViscosity = contactViscosity_;
    bonds.shearCreep = shear_;
    bonds.twistCreep = twist_;
    bonds.bendCreep = bend_;
}


// ************************************************************************* //
