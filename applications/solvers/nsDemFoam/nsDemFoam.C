/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
-------------------------------------------------------------------------------
Application
    nsDemFoam

Description
    Transient solver for the incompressible, volume-averaged Navier-Stokes
    equations of a fluid flowing through DEM grains (unresolved CFD-DEM),
    model A (set II) of Zhou et al. (2010), doc/EQUATIONS.md section 11:

        ddt(phi) + div(phi U) = 0
        ddt(phi U) + div(phi U U) - div(phi nu (grad(U) + grad(U)^T)_dev)
          = (-phi grad(p) - (1 - phi) beta (U - Us))/rho

    U is the interstitial fluid velocity, p the pressure minus hydrostatic
    [Pa], phi the porosity deposited by the grains, Us their mean velocity
    and beta the run-time selected drag law's coefficient per unit grain
    volume. A grain of volume V feels V(-grad(p) + beta (u - v) - rho g);
    the fluid gets minus what the grains feel (the reaction), written as
    -grad(p) plus the reaction, which is the right-hand side above with
    momentum conserved to round-off. The drag is semi-implicit: implicit
    in the fluid's momentum equation, explicit on the grains. PIMPLE
    (fvSolution), ordinary OpenFOAM boundary conditions and schemes.

    Required: constant/nsDemProperties (rho, mu, grains { porosityMin;
    porosityMax; fluidForce { type ErgunWenYu; } }), constant/demProperties,
    0/U, 0/p, 0/grains. Written: U, p, phi, porosity, ddt(porosity), Us,
    grad(p), dragCoefficient, grainReaction, the grains.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "pimpleControl.H"
#include "grainCoupling.H"
#include "inputChecks.H"
#include "latestCompleteTime.H"
#include "finiteCheck.H"
#include "stepTimers.H"
#include "solverOptions.H"
#include "zeroGradientFvPatchFields.H"
#include "fixedFluxPressureFvPatchScalarField.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Volume-averaged incompressible Navier-Stokes solver for a fluid"
        " flowing through DEM grains (model A, semi-implicit drag from a"
        " run-time selected drag law)"
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
    #include "createControl.H"
    #include "createFields.H"

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    // Wall clock of the loop by phase (the grains time theirs into it)
    stepTimers& timers = stepTimers::New(mesh);
    timers.start();

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        #include "CourantNo.H"

        // Grains through the step: porosity, its rate, Us at the new time
        grains.advance();
        porosityf = fvc::interpolate(porosity);
        alphaPhi = porosityf*phi;

        // The grains' reaction R: minus their pressure-gradient force,
        // drag and buoyancy. The fluid's momentum takes -grad(p) + R -
        // (1 - phi) rho g (the hydrostatic part p leaves out), with two
        // parts of R made implicit: its pressure-gradient force (1 - phi)
        // grad(p), which joins -grad(p) as -phi grad(p), and its drag
        // -K (U - Us), K = (1 - phi) beta. Their explicit values, with
        // grad(p) and U as the grains saw them, are taken out of R here, so
        // that a converged step has -grad(p) + R exactly.
        grainReaction = grains.reaction();
        const volScalarField K("K", (1 - porosity)*grains.dragCoefficient());
        const dimensionedVector g("g", dimAcceleration, grains.gravity());
        const volVectorField explicitForce
        (
            "explicitForce",
            grainReaction + K*U - (1 - porosity)*(gradp + rho*g)
        );

        while (pimple.loop())
        {
            // Timed to the end of the momentum predictor (UEqn, rAU and
            // the force fluxes live on into the pressure correctors)
            autoPtr<stepTimers::scope> momentumTimer
            (
                new stepTimers::scope(timers, stepTimers::momentum)
            );
            #include "UEqn.H"
            momentumTimer.clear();

            while (pimple.correct())
            {
                stepTimers::scope timed(timers, stepTimers::pressure);
                #include "pEqn.H"
            }
        }
        finiteCheck::cells(p);

        // The flow back to the grains for the next step
        {
            stepTimers::scope timed(timers, stepTimers::gradient);
            gradp = fvc::grad(p);
        }
        grains.setFlow(gradp, U, rho.value(), mu.value());

        // Fields, grains and the grains' restart state last, between the
        // marks that let a restart set aside a half-written time
        grains.write(runTime);

        runTime.printExecutionTime(Info);
    }

    timers.printSummary(Info);
    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
