// CapsulePacking.h
// The capsule packing of demBench --shape capsule: the sphere packing's grains turned into
// capsules of the same volume and aspect ratio A = (L + 2r) / (2r) (r = R (2 / (3A - 1))^(1/3),
// L = 2 (A - 1) r), each in a random orientation, at the spheres' positions, first shrunk to
// fit inside their sphere (no overlaps) and grown to full size in steps with soft, damped
// contacts (placed at full size, crossing cores would stay stuck in deep overlaps); then the
// bed settles and the stiffness is raised stage by stage to the benchmark's (as the sphere
// packings were made: a sudden change would release the stored elastic energy and throw the
// bed up). The drag acts on translation only, so every run ends with a quench (velocities and
// spins set to zero, contact histories dropped): spinning capsules would otherwise keep the
// bed stirred.
#pragma once

#include "PackingFile.h"
#include "dem/Parameters.h"

namespace dem
{

struct CapsulePackingSettings
{
    double aspect = 3.0;
    unsigned seed = 1;
    //- Stiffness of the first stage relative to the benchmark's; each further stage x 10.
    double firstStiffnessFraction = 1e-5;
    //- First stage: growthRuns damped runs of growthSteps, each after growing the capsules by
    //- an equal factor to full size, a lightly damped run in which the bed (raised by the
    //- growth) settles, then the quenched runs of every stage.
    int growthRuns = 8, growthSteps = 250, settleSteps = 2000, runSteps = 2500, runsPerStage = 1;
    double settleDragFraction = 0.05;
};

//- The capsule packing made from spheres with the benchmark's parameters (material, box,
//- gravity, backend, threads; time step and drag scaled per stage), ending at the benchmark's
//- stiffness; velocities zero. Prints one line per stage.
Packing capsulePacking(const Packing& spheres, const Parameters& benchmark, double drag,
                       const CapsulePackingSettings& settings);

//- Solid volume of the grains over the bed's volume L^2 z_top (z_top: the highest point of
//- any grain), and over the layer 0.05 < z < 0.30 m counted by grain centres.
double bedSolidFraction(const Packing& packing, double& interior);

} // namespace dem
