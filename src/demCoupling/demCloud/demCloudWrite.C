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

    grainVtkWriter::writeVtp(dir/"grains.vtp", grains(), asciiOutput_);
    grainVtkWriter::writePvd(runTime);

    return true;
}


// ************************************************************************* //
