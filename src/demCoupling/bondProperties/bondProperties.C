/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "bondProperties.H"
#include "inputChecks.H"
#include "bondCreepModel.H"
#include "bondCompressiveCreepModel.H"
#include "bondStrengthModel.H"
#include "bondSinteringModel.H"
#include "bondFormationModel.H"
#include "bondPointModel.H"
#include "wordList.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The mechanism families: their entry in 'bonds'
const Foam::wordList mechanismNames
({
    "creep", "compressiveCreep", "strength", "sintering", "formation", "point"
});

//- The elastic patch's entries
const Foam::wordList constantNames
({
    "youngsModulus", "shearToNormalStiffness", "normalDampingRatio",
    "shearDampingRatio", "temperature"
});


//- The Family model of mechanism key, or its default (the dem::BondParameters
//- default, named fallback: 'none' for a mechanism) when 'bonds' has no such
//- entry
template<class Family>
void setMechanism
(
    const Foam::dictionary& bonds,
    const Foam::word& key,
    dem::BondParameters& parameters,
    const Foam::word& fallback = "none"
)
{
    using namespace Foam;
    if (!bonds.found(key))
    {
        Info<< "    bond " << key << " " << fallback << " (no '" << key
            << "' entry)" << endl;
        return;
    }
    if (!bonds.isDict(key))
    {
        FatalIOErrorInFunction(bonds)
            << "Entry '" << key << "' in " << bonds.name()
            << " must be a dictionary { type ...; }" << nl
            << exit(FatalIOError);
    }
    Family::New(bonds.subDict(key))->set(parameters);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::bondProperties::checkEntryNames(const dictionary& bonds)
{
    wordList names(constantNames);
    names.append(mechanismNames);
    inputChecks::checkKnownEntries(bonds, names);
}


void Foam::bondProperties::selectMechanisms(const dictionary& bonds)
{
    setMechanism<bondCreepModel>(bonds, "creep", parameters_);
    setMechanism<bondCompressiveCreepModel>
    (
        bonds, "compressiveCreep", parameters_
    );
    setMechanism<bondStrengthModel>(bonds, "strength", parameters_);
    setMechanism<bondSinteringModel>(bonds, "sintering", parameters_);
    setMechanism<bondFormationModel>(bonds, "formation", parameters_);
    setMechanism<bondPointModel>(bonds, "point", parameters_, "closestPoints");
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bondProperties::bondProperties(const dictionary& demProperties)
:
    parameters_(),
    writeVtk_(false)
{
    if (!demProperties.found("bonds"))
    {
        if
        (
            demProperties.isDict("output")
         && demProperties.subDict("output").getOrDefault<bool>("bonds", false)
        )
        {
            Info<< "    output bonds yes: no bonds to write (no 'bonds' entry in "
                << demProperties.name() << ")" << endl;
        }
        return;
    }
    if (!demProperties.isDict("bonds"))
    {
        FatalIOErrorInFunction(demProperties)
            << "Entry 'bonds' in " << demProperties.name()
            << " must be a dictionary { youngsModulus ...; creep {...} ... }"
            << nl << exit(FatalIOError);
    }

    const dictionary& bonds = demProperties.subDict("bonds");
    checkEntryNames(bonds);
    Info<< "Reading bonds (" << bonds.name() << ")" << endl;

    dem::BondParameters& p = parameters_;
    p.enabled = true;
    p.youngsModulus = inputChecks::getPositive(bonds, "youngsModulus");
    p.shearToNormalStiffness = inputChecks::getInInterval
    (
        bonds, "shearToNormalStiffness", p.shearToNormalStiffness, 0, 1,
        true, false
    );
    p.normalDampingRatio =
        inputChecks::getInRange(bonds, "normalDampingRatio", 0, 0, 1);
    p.shearDampingRatio =
        inputChecks::getInRange(bonds, "shearDampingRatio", 0, 0, 1);
    p.temperature = inputChecks::getInInterval
    (
        bonds, "temperature", p.temperature, -273.15, 0, true, false
    );

    selectMechanisms(bonds);

    writeVtk_ = true;
    if (demProperties.found("output"))
    {
        writeVtk_ =
            demProperties.subDict("output").getOrDefault<bool>("bonds", true);
    }
}


// ************************************************************************* //
