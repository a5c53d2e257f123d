/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
-------------------------------------------------------------------------------
Application
    darcyDemFoam

Description
    Transient solver for the excess pore pressure p of a compressible fluid
    in a granular packing (Damsgaard et al. 2015, eqs 4-5 in the consistent
    form of doc/EQUATIONS.md section 4):

        beta mu phi ddt(p) = div(k grad(p))
                           - mu/(1 - phi) (ddt(phi) + Us & grad(phi))

    p is the deviation from hydrostatic pressure [Pa], phi the porosity, Us
    the mean grain velocity, k the permeability from a run-time selectable
    model, mu and beta the fluid's viscosity and compressibility. Dilation
    (ddt(phi) > 0) lowers p. The time scheme comes from fvSchemes
    (CrankNicolson recommended), the linear solver from fvSolution.

    The grain phase (porosity, its rate and Us) comes from a run-time
    selectable solidPhase model; the pressure gradient is handed back to it
    every step.

    Required: constant/darcyProperties, 0/p; 0/porosity and 0/Us as the
    solidPhase model asks.
    Written: p, k, porosity, ddt(porosity), Us, grad(p) and qDarcy, the
    Darcy flux phi (v_f - Us) = -(k/mu) grad(p) [m/s].

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "fvOptions.H"
#include "darcyFluid.H"
#include "permeabilityModel.H"
#include "solidPhase.H"
#include "fixedPressureRegion.H"
#include "latestCompleteTime.H"
#include "finiteCheck.H"
#include "stepTimers.H"
#include "solverOptions.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Compressible Darcy pore-pressure solver for water-saturated"
        " granular material (coupled to DEM grains through solidPhase)"
    );

    // No -dry-run (addCheckCaseOptions.H not included), and no mpirun
    // without -parallel: refused with the reason and what to do instead
    // (solverOptions)
    solverOptions::check(argc, argv);

    #include "postProcess.H"

    #include "setRootCaseLists.H"

    // startFrom latestTime: skip (and set aside) times a crash left
    // incomplete, before Time picks the latest
    latestCompleteTime::setAside(args);

    #include "createTime.H"
    #include "createMesh.H"
    #include "createFields.H"

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    // Wall clock of the loop by phase (the grains time theirs into it);
    // the set-up above is left out
    stepTimers& timers = stepTimers::New(mesh);
    timers.start();

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        // Grains to the new time: porosity, its rate, mean grain velocity
        solid->evolve();

        {
            stepTimers::scope timed(timers, stepTimers::pressure);
            k = permeability->k(solid->porosity());

            #include "pEqn.H"
            finiteCheck::cells(p);
        }

        // Pressure gradient back to the grains for the next step
        {
            stepTimers::scope timed(timers, stepTimers::gradient);
            gradp = fvc::grad(p);
            qDarcy = -k/fluid.mu()*gradp;
        }
        solid->setPressureGradient(gradp, fluid.rho());

        // Fields, grains and the grains' restart state last, between the
        // marks that let a restart set aside a half-written time
        solid->write(runTime);

        runTime.printExecutionTime(Info);
    }

    timers.printSummary(Info);
    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
