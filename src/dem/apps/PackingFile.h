// PackingFile.h
// Reader and writer of the benchmark packing files (src/dem/bench/packings): a header line
// "# L Lz N", then one grain per line "x y z r" in metres; a moving sphere adds its velocity,
// "x y z r vx vy vz" [m/s] (the flowing benchmark's start, demBench --pour --write-packing); a
// capsule adds its core half-length and orientation, "x y z r h qw qx qy qz" (demBench --shape
// capsule --write-packing).
#pragma once

#include "dem/Parameters.h"

#include <string>
#include <vector>

namespace dem
{

struct Packing
{
    double length = 0; //!< periodic box length in x and y [m]
    double height = 0; //!< far-away bound in z [m]
    std::vector<GrainInit> grains;
};

//- Throws dem::Error naming the file and line on any format problem.
Packing readPacking(const std::string& path, double density);

//- Full double precision (the equilibrium overlaps are ~1e-9 m).
void writePacking(const std::string& path, const Packing& packing);

} // namespace dem
