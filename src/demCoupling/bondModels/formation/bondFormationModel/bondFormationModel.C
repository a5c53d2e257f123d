/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "bondFormationModel.H"
#include "noBondMechanism.H"
#include "selectModel.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(bondFormationModel, 0);
    defineRunTimeSelectionTable(bondFormationModel, dictionary);

    // The family's 'none': the mechanism off
    typedef noBondMechanism<bondFormationModel> noFormation;
    defineTemplateTypeNameAndDebugWithName(noFormation, "none", 0);
    addToRunTimeSelectionTable(bondFormationModel, noFormation, dictionary);
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::bondFormationModel> Foam::bondFormationModel::New(const dictionary& dict)
{
    return selectModel<bondFormationModel>(dict, "bond formation");
}


// ************************************************************************* //
