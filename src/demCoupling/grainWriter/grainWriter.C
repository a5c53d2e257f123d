/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "grainWriter.H"
#include "grainGather.H"
#include "demStart.H"
#include "demStateFile.H"
#include "demLibraryCall.H"
#include "atomicFile.H"
#include "grainsFile.H"
#include "finiteCheck.H"
#include "grainVtkWriter.H"
#include "bondVtkWriter.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::fileName Foam::grainWriter::outputDir("postProcessing/grains");


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::grainWriter::grainWriter
(
    const Time& runTime,
    const demSettings& settings
)
:
    runTime_(runTime),
    settings_(settings)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::grainWriter::writeGrains
(
    const dem::GrainData& ownGrains,
    const dem::System& system
) const
{
    // Test hook: stop among OpenFOAM's field files of this time
    atomicFile::killPoint("amongFields");

    const Time& runTime = runTime_;

    // Backs up the DEM step's own check: nothing non-finite is written (the
    // time then has no demState and stays incomplete); each rank checks its
    // own grains
    finiteCheck::grains
    (
        ownGrains, runTime.value(), settings_.dict().objectPath()
    );

    // Decomposed: every grain in the case's own files, written by the master
    // (the time of the case directory itself, beside reconstructPar's
    // fields; each processor directory holds its rank's demState)
    if (Pstream::parRun())
    {
        // The load balance of the grains' boxes (they do not follow the
        // grains: a bed settling to one side loads its ranks unevenly)
        const label n = ownGrains.id.size();
        const label fewest = returnReduce(n, minOp<label>());
        const label most = returnReduce(n, maxOp<label>());
        const label all = returnReduce(n, sumOp<label>());
        Info<< "Grains per rank: " << fewest << " to " << most
            << " (the most over the mean: "
            << (all ? scalar(most)*Pstream::nProcs()/all : scalar(1)) << ")"
            << endl;
    }

    const dem::GrainData g(grainGather::toMaster(ownGrains));
    // (collective: the bonds are read on every rank, written by the master)
    const dem::BondData bonds
    (
        settings_.bonds().writeVtk()
      ? grainGather::toMaster
        (
            demLibraryCall("reading the bonds", [&]{ return system.bonds(); })
        )
      : dem::BondData()
    );
    if (!Pstream::master())
    {
        return;
    }
    const fileName dir(runTime.globalPath()/runTime.timeName());
    mkDir(dir);
    grainsFile(dir/"grains").write(g);
    // ParaView files in <case>/postProcessing/grains: a VTK file series
    // lists files beside it, not in the time directories, and VTK/, where
    // foamToVTK writes, is removed whole by 'foamToVTK -overwrite'
    const fileName vtkDir(runTime.globalPath()/outputDir);
    mkDir(vtkDir);
    const fileName vtp(vtkDir/("grains_" + runTime.timeName() + ".vtp"));
    grainVtkWriter::writeVtp(vtp, g, settings_.asciiOutput());
    // the time as the directory names it (not runTime.value() with its
    // round-off), the time ParaView's OpenFOAM reader gives the fields;
    // the series writes it as that name
    grainVtkWriter::writeSeries
    (
        vtkDir/"grains.vtp.series",
        vtp,
        readScalar(runTime.timeName())
    );
    // Capsules drawn as such: their surfaces beside the grains
    if
    (
        settings_.surfaceOutput(label(g.radius.size()))
     && grainVtkWriter::hasCapsules(g)
    )
    {
        const fileName surfaces
        (
            vtkDir/("capsules_" + runTime.timeName() + ".vtp")
        );
        grainVtkWriter::writeSurfaceVtp
        (
            surfaces, g, settings_.asciiOutput()
        );
        grainVtkWriter::writeSeries
        (
            vtkDir/"capsules.vtp.series",
            surfaces,
            readScalar(runTime.timeName())
        );
    }
    if (settings_.bonds().writeVtk())
    {
        const fileName bondsVtp(vtkDir/("bonds_" + runTime.timeName() + ".vtp"));
        // The periodic lengths now (a deforming box's have changed)
        dem::Parameters box(system.parameters());
        box.boxUpper = system.boxUpper();
        bondVtkWriter::writeVtp
        (
            bondsVtp,
            bonds,
            g,
            box,
            settings_.asciiOutput()
        );
        grainVtkWriter::writeSeries
        (
            vtkDir/"bonds.vtp.series",
            bondsVtp,
            readScalar(runTime.timeName())
        );
    }
}


void Foam::grainWriter::writeState
(
    const dem::System& system,
    const scalar topWall0,
    const std::vector<double>& displacement0,
    const dem::UniformGrid& grid
) const
{
    const Time& runTime = runTime_;
    if (!runTime.writeTime())
    {
        return;
    }
    const fileName dir(runTime.timePath());
    mkDir(dir);

    dem::SystemState state
    (
        demLibraryCall
        (
            "exporting the grains' state", [&]{ return system.exportState(); }
        )
    );
    demStart::addOwnEntries
    (
        state, topWall0, displacement0, grid, system.parameters()
    );
    demStateFile(dir/"demState").write(state);

    // Decomposed: also the whole system as one process's state in the case
    // directory, beside the grains file (a run on one process continues
    // from a reconstructed time; the neighbour lists are rebuilt at its
    // first step, the contacts' histories and the bonds kept)
    if (Pstream::parRun())
    {
        dem::SystemState whole
        (
            demLibraryCall
            (
                "gathering the grains' state",
                [&]{ return system.exportGatheredState(); }
            )
        );
        if (Pstream::master())
        {
            const fileName caseDir(runTime.globalPath()/runTime.timeName());
            mkDir(caseDir);
            demStart::addOwnEntries
            (
                whole, topWall0, displacement0, grid, system.parameters()
            );
            demStateFile(caseDir/"demState").write(whole);
        }
    }
}


// ************************************************************************* //
