// CapsulePacking.h
// The capsule packing of demBench --shape capsule: the sphere packing's grains turned into
// capsules of the same volume and aspect ratio A = (L + 2r) / (2r) (r = R (2 / (3A - 1))^(1/3),
// L = 2 (A - 1) r), each in a random orientation, at the spheres' positions, first shrunk to
// fit inside their sphere (no overlaps) and grown to full size in steps with soft, damped
// contacts (placed at full size, crossing cores would stay stuck in deep overlaps); then the
// bed settles and the stiffness is raised stage by stage to the benchmark's (as the sphere
// packings were made: a sudden change would release the stored elastic energy and throw the
// bed up). Contact dashpots near critical damping (the drag acts on translation only) take
// out the energy each stage releases, translation and spin alike; every stage runs until the
// kinetic energy has decayed, and the packing ends at rest at the benchmark's stiffness.
#pragma once

#include "PackingFile.h"
#include "dem/Parameters.h"

namespace dem
{

struct CapsulePackingSettings
{
    double aspect = 3.0;
    unsigned seed = 1;
    //- Stiffness of the first stage relative to the benchmark's; each further stage
    //- x stiffeningFactor, the last one the benchmark's.
    double firstStiffnessFraction = 1e-5, stiffeningFactor = 10.0;
    //- Growth: growthRuns runs of growthSteps (drag and dashpots), each after growing the
    //- capsules by an equal factor to full size.
    int growthRuns = 8, growthSteps = 250;
    //- Every stage: at least settleSteps (first stage, the raised bed falls back) or checkSteps
    //- steps, then chunks of checkSteps until the kinetic energy is below
    //- restEnergy x N (m g)^2 / k, at most maxStageSteps. At k_bench, N (m g)^2 / k is 1e-7 J
    //- for N = 10,000: less than the sphere bed keeps after the benchmark's relaxation
    //- (5.8e-7 J).
    int settleSteps = 2000, checkSteps = 500, maxStageSteps = 8000;
    double restEnergy = 1.0;
    //- Drag of the stages after the first, relative to the benchmark's (the first has none).
    double stageDragFraction = 0.5;
    //- Contact dashpots while settling, as a fraction of critical damping for the pair's mass.
    double dampingRatio = 0.7;
    //- Verlet skins [m] of the growth and first stage, and of the stiffer stages.
    double growthSkin = 1e-3, settleSkin = 2e-4;
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
