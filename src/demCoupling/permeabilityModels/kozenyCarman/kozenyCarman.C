/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "kozenyCarman.H"
#include "inputChecks.H"
#include "volFields.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace permeabilityModels
{
    defineTypeNameAndDebug(kozenyCarman, 0);
    addToRunTimeSelectionTable(permeabilityModel, kozenyCarman, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::permeabilityModels::kozenyCarman::kozenyCarman
(
    const dictionary& dict,
    const word& prefactorEntry,
    scalar (*kcOf)(const dictionary&)
)
:
    permeabilityModel
    (
        dict,
        {prefactorEntry, "porosityMin", "porosityMax", "kMax"}
    ),
    kc_(kcOf(dict)),
    porosityMin_(inputChecks::getInOpenRange(dict, "porosityMin", 0, 1)),
    porosityMax_(inputChecks::getInOpenRange(dict, "porosityMax", 0, 1)),
    kMax_(dict.found("kMax") ? inputChecks::getPositive(dict, "kMax") : GREAT)
{
    if (porosityMin_ >= porosityMax_)
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'porosityMin' (" << porosityMin_
            << ") and 'porosityMax' (" << porosityMax_ << ") in "
            << dict.name() << " must satisfy porosityMin < porosityMax" << nl
            << exit(FatalIOError);
    }

    Info<< "    kc = " << kc_ << " m^2, porosity clamped to ["
        << porosityMin_ << ", " << porosityMax_ << "]";
    if (kMax_ < GREAT)
    {
        Info<< ", k capped at " << kMax_ << " m^2";
    }
    Info<< endl;
}


Foam::permeabilityModels::kozenyCarman::kozenyCarman(const dictionary& dict)
:
    kozenyCarman
    (
        dict,
        "kc",
        [](const dictionary& d) { return inputChecks::getPositive(d, "kc"); }
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volScalarField>
Foam::permeabilityModels::kozenyCarman::k
(
    const volScalarField& porosity
) const
{
    const volScalarField phi
    (
        max(min(porosity, dimensionedScalar("porosityMax", dimless, porosityMax_)),
            dimensionedScalar("porosityMin", dimless, porosityMin_))
    );

    tmp<volScalarField> tk
    (
        volScalarField::New
        (
            "k",
            min
            (
                dimensionedScalar("kc", dimArea, kc_)*pow3(phi)/sqr(1 - phi),
                dimensionedScalar("kMax", dimArea, kMax_)
            )
        )
    );

    return tk;
}


// ************************************************************************* //
