/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "frozenOnContact.H"
#include "inputChecks.H"
#include "OStringStream.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bondFormationModels
{
    defineTypeNameAndDebug(frozenOnContact, 0);
    addToRunTimeSelectionTable(bondFormationModel, frozenOnContact, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bondFormationModels::frozenOnContact::frozenOnContact(const dictionary& dict)
:
    bondFormationModel(dict, {"areaFraction", "interval", "seed"}),
    areaFraction_
    (
        dict.getOrDefault<FixedList<scalar, 2>>
        (
            "areaFraction",
            FixedList<scalar, 2>
            ({
                dem::BondParameters().areaFraction[0],
                dem::BondParameters().areaFraction[1]
            })
        )
    ),
    interval_(dict.getOrDefault<label>("interval", 1)),
    seed_(dict.getOrDefault<label>("seed", 1))
{
    // A patch no larger than the smaller grain's cross-section
    if
    (
        !(areaFraction_[0] > 0 && areaFraction_[0] <= areaFraction_[1]
       && areaFraction_[1] <= 1)
    )
    {
        // Ten digits: the pair as the user wrote it
        OStringStream found;
        found.precision(10);
        found<< "(" << areaFraction_[0] << " " << areaFraction_[1] << ")";
        FatalIOErrorInFunction(dict)
            << "Entry 'areaFraction' in " << dict.name() << " must be"
            << " (min max) with 0 < min <= max <= 1, found "
            << found.str().c_str() << nl << exit(FatalIOError);
    }
    if (interval_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'interval' in " << dict.name() << " must be >= 1,"
            << " found " << interval_ << nl << exit(FatalIOError);
    }
    if (seed_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'seed' in " << dict.name() << " must be >= 0, found "
            << seed_ << nl << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bondFormationModels::frozenOnContact::set(dem::BondParameters& bonds) const
{
    bonds.formation = dem::BondFormation::frozenOnContact;
    bonds.areaFraction = {areaFraction_[0], areaFraction_[1]};
    bonds.formationInterval = int(interval_);
    bonds.seed = std::uint64_t(seed_);
}


// ************************************************************************* //
