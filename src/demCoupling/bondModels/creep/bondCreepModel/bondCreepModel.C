/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "bondCreepModel.H"
#include "noBondMechanism.H"
#include "selectModel.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(bondCreepModel, 0);
    defineRunTimeSelectionTable(bondCreepModel, dictionary);

    // The family's 'none': the mechanism off
    typedef noBondMechanism<bondCreepModel> noCreep;
    defineTemplateTypeNameAndDebugWithName(noCreep, "none", 0);
    addToRunTimeSelectionTable(bondCreepModel, noCreep, dictionary);
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::bondCreepModel> Foam::bondCreepModel::New(const dictionary& dict)
{
    return selectModel<bondCreepModel>(dict, "bond creep");
}


// ************************************************************************* //
