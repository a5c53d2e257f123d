/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
-------------------------------------------------------------------------------
Application
    demFoam

Description
    Dry grains: the DEM part of darcyDemFoam alone, on the same case format
    (constant/demProperties, <startTime>/grains or demState, a uniform
    Cartesian mesh that sets the periodic box and the output grid). No pore
    fluid: no darcyProperties, no p. Used for packing preparation, dry shear
    and snow runs. Writes porosity and Us (the grains deposited on the mesh)
    and the grains (demState, grains, postProcessing/grains/grains_<time>.vtp
    and its series) at write times. Prints every step's time, as
    darcyDemFoam does, and the grains' progress every few seconds.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "grainCoupling.H"
#include "boxFollowingMesh.H"
#include "latestCompleteTime.H"
#include "stepTimers.H"
#include "solverOptions.H"
#include "zeroGradientFvPatchFields.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote("DEM grains without pore fluid (dry runs)");

    // No -dry-run (addCheckCaseOptions.H not included), and no mpirun
    // without -parallel: refused with the reason and what to do instead
    // (solverOptions)
    solverOptions::check(argc, argv);

    #include "setRootCaseLists.H"

    // startFrom latestTime: skip (and set aside) times a crash left
    // incomplete, before Time picks the latest
    latestCompleteTime::setAside(args);

    #include "createTime.H"
    #include "createMesh.H"

    // The grains deposited on the mesh, written at write times
    volScalarField porosity
    (
        IOobject
        (
            "porosity",
            runTime.timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("porosity", dimless, 1),
        zeroGradientFvPatchScalarField::typeName
    );
    volScalarField porosityRate
    (
        IOobject
        (
            "ddt(porosity)",
            runTime.timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar("porosityRate", dimless/dimTime, Zero),
        zeroGradientFvPatchScalarField::typeName
    );
    volVectorField Us
    (
        IOobject
        (
            "Us",
            runTime.timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedVector("Us", dimVelocity, Zero),
        zeroGradientFvPatchVectorField::typeName
    );

    // Dry: no fluid force, deposited at write times only
    grainCoupling grains
    (
        mesh,
        dictionary(),
        grainCoupling::fluidKind::dry,
        porosity,
        porosityRate,
        Us
    );

    // A deforming periodic box ('boxLengthRate') stretches the mesh with it
    boxFollowingMesh boxMotion(mesh, grains.cloud());

    // Wall clock of the loop by phase, as darcyDemFoam prints it (no fluid:
    // no pressure, gradient or exchange); the set-up above is left out
    stepTimers& timers = stepTimers::New(mesh);
    timers.start();

    Info<< "\nStarting time loop\n" << endl;

    // Every fluid step prints its time, as darcyDemFoam and OpenFOAM's
    // solvers do: a step is many DEM steps (deltaT/timeStep), so the log
    // grows by a few lines per deltaT of simulated time, not per DEM step
    while (runTime.run())
    {
        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        grains.advance();
        boxMotion.update();

        if (runTime.writeTime())
        {
            Info<< "Grains: " << grains.cloud().system().contactCount()
                << " contacts, " << grains.cloud().particleStepsPerSecond()
                << " particle-steps/s" << endl;
        }

        grains.write(runTime);

        runTime.printExecutionTime(Info);
    }

    timers.printSummary(Info);
    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
