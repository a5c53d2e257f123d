/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "bondSinteringModel.H"
#include "noBondMechanism.H"
#include "selectModel.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(bondSinteringModel, 0);
    defineRunTimeSelectionTable(bondSinteringModel, dictionary);

    // The family's 'none': the mechanism off
    typedef noBondMechanism<bondSinteringModel> noSintering;
    defineTemplateTypeNameAndDebugWithName(noSintering, "none", 0);
    addToRunTimeSelectionTable(bondSinteringModel, noSintering, dictionary);
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::bondSinteringModel> Foam::bondSinteringModel::New(const dictionary& dict)
{
    return selectModel<bondSinteringModel>(dict, "bond sintering");
}


// ************************************************************************* //
