/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
-------------------------------------------------------------------------------
    Writing the grains at write times: restart state and ParaView files.
\*---------------------------------------------------------------------------*/

#include "demCloud.H"
#include "demStateFile.H"
#include "grainVtkWriter.H"
#include "Time.H"
#include "OSspecific.H"

#include <fstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Grains in the input format 'x y z r', exact to the last digit, so that
//- a new case can start from them (without contact history)
void writeGrainsFile(const Foam::fileName& path, const dem::GrainData& g)
{
    std::ofstream os(path);
    os.precision(17);
    os  << "# darcyDem grains: x y z r [m], one grain per line (written at"
        << " a write time; demState beside it holds the complete state)\n";
    for (size_t i = 0; i < g.radius.size(); ++i)
    {
        os  << g.position[3*i] << ' ' << g.position[3*i + 1] << ' '
            << g.position[3*i + 2] << ' ' << g.radius[i] << '\n';
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::demCloud::writeObject
(
    IOstream::streamFormat,
    IOstream::versionNumber,
    IOstream::compressionType,
    const bool
) const
{
    const Time& runTime = mesh_.time();
    const fileName dir(runTime.timePath());
    mkDir(dir);

    dem::SystemState state(system_->exportState());
    state.reals[topWall0Key] = {topWall0_};
    state.reals[displacement0Key] = displacement0_;
    writeDemState(dir/"demState", state);

    const dem::GrainData g(grains());
    writeGrainsFile(dir/"grains", g);

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

    return true;
}


// ************************************************************************* //
