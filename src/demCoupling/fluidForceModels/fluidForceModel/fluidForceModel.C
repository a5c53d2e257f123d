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


// ************************************************************************* //
