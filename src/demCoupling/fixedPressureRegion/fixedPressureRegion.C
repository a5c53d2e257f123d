/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "fixedPressureRegion.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fixedPressureRegion::resetHistory
(
    volScalarField& p,
    const label celli
) const
{
    // Only the levels the time scheme keeps (Euler one, CrankNicolson and
    // backward two); oldTime() first moves the levels on to this step
    if (p.nOldTimes() > 0)
    {
        p.oldTime().primitiveFieldRef()[celli] = value_;
    }
    if (p.nOldTimes() > 1)
    {
        p.oldTime().oldTime().primitiveFieldRef()[celli] = value_;
    }

    // CrankNicolson's old time derivative (name as its ddt0_ registers it)
    const word ddt0Name("ddt0(" + p.name() + ')');
    const fvMesh& mesh = p.mesh();
    if (mesh.foundObject<volScalarField>(ddt0Name))
    {
        mesh.lookupObjectRef<volScalarField>(ddt0Name)
            .primitiveFieldRef()[celli] = 0;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fixedPressureRegion::fixedPressureRegion
(
    const fvMesh& mesh,
    const solidPhase& solid
)
:
    fixed_(),
    nCells_(mesh.nCells()),
    value_(0)
{
    solid.fixedPressureCells(cells_, value_);
    fixed_ = bitSet(nCells_, cells_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fixedPressureRegion::update
(
    const solidPhase& solid,
    volScalarField& p
)
{
    scalar value = 0;
    solid.fixedPressureCells(cells_, value);

    bitSet fixedNow(nCells_, cells_);

    for (const label celli : fixed_)
    {
        if (!fixedNow.test(celli))
        {
            resetHistory(p, celli);
        }
    }

    fixed_.transfer(fixedNow);
    value_ = value;
}


void Foam::fixedPressureRegion::constrain(fvScalarMatrix& pEqn) const
{
    if (cells_.size())
    {
        pEqn.setValues(cells_, scalarField(cells_.size(), value_));
    }
}


// ************************************************************************* //
