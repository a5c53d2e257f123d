/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "bondPointModel.H"
#include "selectModel.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(bondPointModel, 0);
    defineRunTimeSelectionTable(bondPointModel, dictionary);

}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::bondPointModel> Foam::bondPointModel::New(const dictionary& dict)
{
    return selectModel<bondPointModel>(dict, "bond point");
}


// ************************************************************************* //
