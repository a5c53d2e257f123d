/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "bondStrengthModel.H"
#include "noBondMechanism.H"
#include "selectModel.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(bondStrengthModel, 0);
    defineRunTimeSelectionTable(bondStrengthModel, dictionary);

    // The family's 'none': the mechanism off
    typedef noBondMechanism<bondStrengthModel> noStrength;
    defineTemplateTypeNameAndDebugWithName(noStrength, "none", 0);
    addToRunTimeSelectionTable(bondStrengthModel, noStrength, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bondStrengthModel::fracture::fracture(const dictionary& dict)
:
    softeningRatio_
    (
        inputChecks::getPositiveOrDefault
        (
            dict, "softeningRatio", dem::BondParameters().softeningRatio
        )
    ),
    brokenFraction_
    (
        inputChecks::getInInterval
        (
            dict,
            "brokenFraction",
            dem::BondParameters().brokenFraction,
            0,
            1,
            false,
            true
        )
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::bondStrengthModel::fracture::withEntryNames
(
    const wordList& modelNames
)
{
    wordList names(modelNames);
    names.append(wordList({"softeningRatio", "brokenFraction"}));
    return names;
}


void Foam::bondStrengthModel::fracture::set(dem::BondParameters& bonds) const
{
    bonds.softeningRatio = softeningRatio_;
    bonds.brokenFraction = brokenFraction_;
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::bondStrengthModel> Foam::bondStrengthModel::New(const dictionary& dict)
{
    return selectModel<bondStrengthModel>(dict, "bond strength");
}


// ************************************************************************* //
