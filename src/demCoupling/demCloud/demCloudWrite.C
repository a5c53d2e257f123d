/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
-------------------------------------------------------------------------------
    Writing the grains at write times: ParaView files and the input-format
    grains with the fields (writeObject), then the restart state last
    (writeState). Every file is written whole or not at all (atomicFile).
\*---------------------------------------------------------------------------*/

#include "demCloud.H"
#include "demStateFile.H"
#include "demLibraryCall.H"
#include "atomicFile.H"
#include "grainsFile.H"
#include "finiteCheck.H"
#include "grainVtkWriter.H"
#include "bondVtkWriter.H"
#include "Time.H"
#include "OSspecific.H"


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::demCloud::writeObject
(
    IOstream::streamFormat,
    IOstream::versionNumber,
    IOstream::compressionType,
    const bool
) const
{
    // Test hook: stop among OpenFOAM's field files of this time
    atomicFile::killPoint("amongFields");

    const Time& runTime = mesh_.time();
    const fileName dir(runTime.timePath());
    mkDir(dir);

    const dem::GrainData g(grains());
    // Backs up the DEM step's own check: nothing non-finite is written (the
    // time then has no demState and stays incomplete)
    finiteCheck::grains(g, runTime.value(), properties_.objectPath());
    grainsFile(dir/"grains").write(g);
    // ParaView files in <case>/VTK, where OpenFOAM's foamToVTK writes too:
    // a VTK file series lists files beside it, not in the time directories
    const fileName vtkDir(runTime.path()/"VTK");
    mkDir(vtkDir);
    const fileName vtp(vtkDir/("grains_" + runTime.timeName() + ".vtp"));
    grainVtkWriter::writeVtp(vtp, g, asciiOutput_);
    // the time as the directory names it (not runTime.value() with its
    // round-off), the time ParaView's OpenFOAM reader gives the fields
    grainVtkWriter::writeSeries
    (
        vtkDir/"grains.vtp.series",
        vtp,
        readScalar(runTime.timeName())
    );
    // Capsules drawn as such: their surfaces beside the grains
    if (surfaceOutput_ && grainVtkWriter::hasCapsules(g))
    {
        const fileName surfaces
        (
            vtkDir/("capsules_" + runTime.timeName() + ".vtp")
        );
        grainVtkWriter::writeSurfaceVtp(surfaces, g, asciiOutput_);
        grainVtkWriter::writeSeries
        (
            vtkDir/"capsules.vtp.series",
            surfaces,
            readScalar(runTime.timeName())
        );
    }
    if (bonds_.writeVtk())
    {
        const fileName bondsVtp(vtkDir/("bonds_" + runTime.timeName() + ".vtp"));
        bondVtkWriter::writeVtp
        (
            bondsVtp,
            demLibraryCall("reading the bonds", [&]{ return system_->bonds(); }),
            g,
            system_->parameters(),
            asciiOutput_
        );
        grainVtkWriter::writeSeries
        (
            vtkDir/"bonds.vtp.series",
            bondsVtp,
            readScalar(runTime.timeName())
        );
    }

    return true;
}


void Foam::demCloud::writeState() const
{
    const Time& runTime = mesh_.time();
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
            "exporting the grains' state", [&]{ return system_->exportState(); }
        )
    );
    state.reals[topWall0Key] = {topWall0_};
    state.reals[displacement0Key] = displacement0_;
    state.reals[periodicBoxKey] = periodicBox();
    demStateFile(dir/"demState").write(state);
}


// ************************************************************************* //
