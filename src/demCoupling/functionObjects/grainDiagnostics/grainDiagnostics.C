/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "grainDiagnostics.H"
#include "demCloud.H"
#include "volFields.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Rotational kinetic energy of capsule i, (I_axial w_a^2 + I_perp w_p^2)/2
//- with w_a, w_p the angular velocity along and across its axis and the
//- capsule's principal moments (cylinder of length L = 2h plus a sphere
//- split into the two caps, parallel-axis shifted), density m/V
Foam::scalar capsuleRotationalEnergy(const dem::GrainData& g, const size_t i)
{
    using namespace Foam;
    const scalar r = g.radius[i], L = 2*g.coreHalfLength[i];
    const scalar rho = g.mass[i]/g.volume[i];
    const scalar pi = constant::mathematical::pi;
    const scalar mCore = rho*pi*r*r*L;
    const scalar mCaps = rho*4.0/3.0*pi*pow3(r);
    const scalar axial = mCore*r*r/2 + 2*mCaps*r*r/5;
    const scalar across =
        mCore*(L*L/12 + r*r/4) + mCaps*(2*r*r/5 + L*L/4 + 3*L*r/8);

    const double* q = &g.orientation[4*i];
    const vector axis
    (
        2*(q[1]*q[3] + q[0]*q[2]),
        2*(q[2]*q[3] - q[0]*q[1]),
        1 - 2*(q[1]*q[1] + q[2]*q[2])
    );
    const vector w
    (
        g.angularVelocity[3*i], g.angularVelocity[3*i + 1],
        g.angularVelocity[3*i + 2]
    );
    const scalar wAxial = w & axis;
    return 0.5*(axial*sqr(wAxial) + across*(magSqr(w) - sqr(wAxial)));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(grainDiagnostics, 0);
    addToRunTimeSelectionTable(functionObject, grainDiagnostics, dictionary);
}
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::wordList Foam::functionObjects::grainDiagnostics::columns
(
    const demCloud&
) const
{
    return
    {
        "shearStrain", "tau", "tauOverSigma0", "dilation", "topWall",
        "pMin", "pMean", "pMax", "kineticEnergy", "contactsPerGrain",
        "particleStepsPerS", "solidVolumeError"
    };
}


void Foam::functionObjects::grainDiagnostics::writeRow
(
    Ostream& os,
    const demCloud& cloud
)
{
    const dem::System& dem = cloud.system();
    const dem::GrainData g = cloud.grains();
    const label n = g.radius.size();

    // Sample height between the lowest lower wall and the top wall
    scalar bottom = GREAT;
    for (int w = 0; w < dem.wallCount(); ++w)
    {
        const dem::WallData wall = dem.wall(w);
        if (wall.spec.side == dem::WallSpec::Side::lower)
        {
            bottom = min(bottom, wall.position);
        }
    }

    scalar shiftX = 0, kinetic = 0, grainVolume = 0;
    label nPrescribed = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar r = g.radius[i];
        const scalar m = g.mass[i];
        scalar v2 = 0, w2 = 0;
        for (int d = 0; d < 3; ++d)
        {
            v2 += sqr(g.velocity[3*i + d]);
            w2 += sqr(g.angularVelocity[3*i + d]);
        }
        const scalar h =
            g.coreHalfLength.empty() ? 0 : g.coreHalfLength[i];
        if (h > 0)
        {
            kinetic += 0.5*m*v2 + capsuleRotationalEnergy(g, i);
            grainVolume += g.volume[i];
        }
        else
        {
            kinetic += 0.5*m*v2 + 0.5*(0.4*m*r*r)*w2;
            grainVolume += 4.0/3.0*constant::mathematical::pi*pow3(r);
        }
        if (g.flag[i] == dem::GrainFlag::prescribedVelocity)
        {
            shiftX += g.displacement[3*i];
            ++nPrescribed;
        }
    }

    // Decomposed: each rank's own grains, summed over the ranks
    reduce(shiftX, sumOp<scalar>());
    reduce(kinetic, sumOp<scalar>());
    reduce(grainVolume, sumOp<scalar>());
    reduce(nPrescribed, sumOp<label>());
    const label nAll = returnReduce(n, sumOp<label>());

    const scalar top = cloud.topWallPosition();
    const scalar height =
        (cloud.hasTopWall() && bottom < GREAT) ? top - bottom : 0;
    const scalar strain =
        (nPrescribed && height > 0) ? shiftX/nPrescribed/height : 0;
    const scalar t = dem.time();
    const scalar impulse = dem.prescribedGrainImpulseX();
    const scalar tau =
        -(hasLast_ && t > lastTime_
        ? (impulse - lastImpulse_)/(t - lastTime_)
        : dem.prescribedGrainForceX())/cloud.boxArea();
    lastTime_ = t;
    lastImpulse_ = impulse;
    hasLast_ = true;
    const scalar sigma0 = cloud.topWallStress();

    scalar pMin = 0, pMean = 0, pMax = 0;
    if (mesh_.foundObject<volScalarField>("p"))
    {
        const volScalarField& p = mesh_.lookupObject<volScalarField>("p");
        pMin = gMin(p.primitiveField());
        pMax = gMax(p.primitiveField());
        pMean = gSum(p.primitiveField()*mesh_.V())/gSum(mesh_.V());
    }

    // Conservation of the deposit, before any porosity clamp
    const dem::UniformGrid grid = cloud.couplingGrid();
    std::vector<double> solid(grid.cellCount());
    dem.deposit(grid, 0, nullptr, nullptr, nullptr, solid.data());
    scalar deposited = 0;
    for (const double s : solid)
    {
        deposited += s;
    }

    os  << tab << strain << tab << tau << tab
        << (sigma0 > 0 ? tau/sigma0 : 0) << tab
        << (cloud.hasTopWall() ? (top - cloud.topWallInitialPosition())
            /cloud.meanDiameter() : 0) << tab
        << (cloud.hasTopWall() ? top : 0) << tab
        << pMin << tab << pMean << tab << pMax << tab
        << kinetic << tab
        << (nAll ? 2.0*dem.contactCount()/nAll : 0) << tab
        << cloud.particleStepsPerSecond() << tab
        << (grainVolume > 0 ? deposited/grainVolume - 1 : 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::grainDiagnostics::grainDiagnostics
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    demTable
    (
        name,
        runTime,
        dict,
        typeName,
        "Grain diagnostics (doc/CASE-FORMAT.md, function objects)"
    ),
    lastTime_(0),
    lastImpulse_(0),
    hasLast_(false)
{}


// ************************************************************************* //
