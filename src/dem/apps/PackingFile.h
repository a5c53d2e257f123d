// PackingFile.h
// Reader of the benchmark packing files (src/dem/bench/packings): a header line
// "# L Lz N", then one grain per line "x y z r" in metres.
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

} // namespace dem
