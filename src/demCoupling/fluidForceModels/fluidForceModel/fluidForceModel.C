/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "fluidForceModel.H"
#include "selectModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(fluidForceModel, 0);
    defineRunTimeSelectionTable(fluidForceModel, dictionary);
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::fluidForceModel> Foam::fluidForceModel::New
(
    const dictionary& dict
)
{
    if (!dict.isDict("fluidForce"))
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary 'fluidForce' not found in " << dict.name()
            << ": choose the fluid's force on the grains, e.g."
            << " fluidForce { type pressureGradient; }, the type one of "
            << dictionaryConstructorTablePtr_->sortedToc()
            << " (doc/EQUATIONS.md section 7)" << nl
            << exit(FatalIOError);
    }
    return selectModel<fluidForceModel>
    (
        dict.subDict("fluidForce"),
        "fluid force"
    );
}


Foam::autoPtr<Foam::fluidForceModel> Foam::fluidForceModel::New
(
    const dictionary& dict,
    const bool dragLaw
)
{
    autoPtr<fluidForceModel> model(New(dict));
    if (model->isDragLaw() != dragLaw)
    {
        const dictionary& modelDict = dict.subDict("fluidForce");
        FatalIOErrorInFunction(modelDict)
            << "Entry 'type' in " << modelDict.name() << ": '"
            << modelDict.get<word>("type") << "' "
            << (
                   dragLaw
                 ? "is not a drag law; a solver with fluid momentum"
                   " (nsDemFoam) takes one of "
                 : "is a drag law, for a solver with fluid momentum"
                   " (nsDemFoam); a Darcy solver takes one of "
               )
            << typeNames(dragLaw) << " (doc/EQUATIONS.md section 7)" << nl
            << exit(FatalIOError);
    }
    return model;
}


Foam::wordList Foam::fluidForceModel::typeNames(const bool dragLaws)
{
    // Every model constructs from an empty dictionary (none has a required
    // entry), so the kind is asked of the model itself
    DynamicList<word> names;
    for (const word& name : dictionaryConstructorTablePtr_->sortedToc())
    {
        autoPtr<fluidForceModel> model
        (
            dictionaryConstructorTablePtr_->cfind(name)()(dictionary::null)
        );
        if (model->isDragLaw() == dragLaws)
        {
            names.append(name);
        }
    }
    return wordList(std::move(names));
}


// ************************************************************************* //
