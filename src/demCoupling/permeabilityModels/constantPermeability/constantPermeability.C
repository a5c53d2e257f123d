/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "constantPermeability.H"
#include "inputChecks.H"
#include "volFields.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace permeabilityModels
{
    defineTypeNameAndDebug(constantPermeability, 0);
    addToRunTimeSelectionTable
    (
        permeabilityModel,
        constantPermeability,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::permeabilityModels::constantPermeability::constantPermeability
(
    const dictionary& dict
)
:
    permeabilityModel(dict, {"k"}),
    k_(inputChecks::getPositive(dict, "k"))
{
    Info<< "    k = " << k_ << " m^2" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volScalarField>
Foam::permeabilityModels::constantPermeability::k
(
    const volScalarField& porosity
) const
{
    return volScalarField::New
    (
        "k",
        porosity.mesh(),
        dimensionedScalar("k", dimArea, k_)
    );
}


// ************************************************************************* //
