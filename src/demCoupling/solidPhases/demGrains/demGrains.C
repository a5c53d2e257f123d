/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "demGrains.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace solidPhases
{
    defineTypeNameAndDebug(demGrains, 0);
    addToRunTimeSelectionTable(solidPhase, demGrains, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidPhases::demGrains::demGrains
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    solidPhase(mesh, dict, grainCoupling::entryNames),
    coupling_
    (
        mesh,
        dict,
        grainCoupling::fluidKind::darcy,
        porosity_,
        porosityRate_,
        Us_
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidPhases::demGrains::evolve()
{
    coupling_.advance();
}


void Foam::solidPhases::demGrains::setPressureGradient
(
    const volVectorField& gradp,
    const dimensionedScalar& rhoFluid
)
{
    coupling_.setPressureGradient(gradp, rhoFluid.value());
}


void Foam::solidPhases::demGrains::fixedPressureCells
(
    labelList& cells,
    scalar& value
) const
{
    coupling_.fixedPressureCells(cells, value);
}


void Foam::solidPhases::demGrains::write(Time& runTime) const
{
    coupling_.write(runTime);
}


// ************************************************************************* //
