/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "bondCompressiveCreepModel.H"
#include "noBondMechanism.H"
#include "selectModel.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(bondCompressiveCreepModel, 0);
    defineRunTimeSelectionTable(bondCompressiveCreepModel, dictionary);

    // The family's 'none': the mechanism off
    typedef noBondMechanism<bondCompressiveCreepModel> noCompressiveCreep;
    defineTemplateTypeNameAndDebugWithName(noCompressiveCreep, "none", 0);
    addToRunTimeSelectionTable(bondCompressiveCreepModel, noCompressiveCreep, dictionary);
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::bondCompressiveCreepModel> Foam::bondCompressiveCreepModel::New(const dictionary& dict)
{
    return selectModel<bondCompressiveCreepModel>(dict, "bond compressive creep");
}


// ************************************************************************* //
