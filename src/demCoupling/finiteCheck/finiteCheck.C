/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "finiteCheck.H"
#include "Time.H"

#include <cmath>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::finiteCheck::cells(const volScalarField& field)
{
    const scalarField& values = field.primitiveField();
    forAll(values, celli)
    {
        if (!std::isfinite(values[celli]))
        {
            const Time& runTime = field.time();
            FatalErrorInFunction
                << "Field " << field.name() << " is " << values[celli]
                << " in cell " << celli << " (centre "
                << field.mesh().C()[celli] << ") at t = "
                << runTime.timeName() << " s. Stopped before writing this"
                << " time: the last written time is intact; a smaller"
                << " deltaT (system/controlDict) or DEM timeStep usually"
                << " cures it." << nl << exit(FatalError);
        }
    }
}


void Foam::finiteCheck::grains
(
    const dem::GrainData& g,
    const scalar time,
    const fileName& source
)
{
    const size_t n = g.radius.size();
    for (size_t i = 0; i < n; ++i)
    {
        bool finite = true;
        for (int c = 0; c < 3; ++c)
        {
            finite = finite
                && std::isfinite(g.position[3*i + c])
                && std::isfinite(g.velocity[3*i + c]);
        }
        if (!finite)
        {
            FatalErrorInFunction
                << "Grain "
                // its id (line of the grains file), also on a rank of a
                // decomposed run, whose grains are a part in another order
                << label(g.id.size() == n ? size_t(g.id[i]) : i)
                << " (of " << source << ") is at ("
                << g.position[3*i] << " " << g.position[3*i + 1] << " "
                << g.position[3*i + 2] << ") with velocity ("
                << g.velocity[3*i] << " " << g.velocity[3*i + 1] << " "
                << g.velocity[3*i + 2] << ") at t = " << time << " s."
                << " Stopped before writing this time: the last written time"
                << " is intact; a smaller DEM timeStep or a smaller"
                << " maxTimeStepFraction usually cures it." << nl
                << exit(FatalError);
        }
    }
}


// ************************************************************************* //
