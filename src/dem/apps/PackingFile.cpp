// PackingFile.cpp
// Reader of the benchmark packing files.
#include "PackingFile.h"

#include "dem/Error.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace dem
{

Packing readPacking(const std::string& path, double density)
{
    std::ifstream in(path);
    if (!in)
        throw Error("cannot open packing file '" + path + "'");
    std::string line;
    Packing packing;
    long expected = -1;
    long lineNumber = 0;
    while (std::getline(in, line))
    {
        ++lineNumber;
        if (line.empty())
            continue;
        std::istringstream fields(line[0] == '#' ? line.substr(1) : line);
        if (line[0] == '#')
        {
            if (expected < 0 && !(fields >> packing.length >> packing.height >> expected))
                throw Error(path + ":" + std::to_string(lineNumber) +
                            ": header must be '# L Lz N'");
            continue;
        }
        GrainInit g;
        if (!(fields >> g.position[0] >> g.position[1] >> g.position[2] >> g.radius))
            throw Error(path + ":" + std::to_string(lineNumber) +
                        ": expected 'x y z r' or 'x y z r h qw qx qy qz'");
        if (fields >> g.coreHalfLength) // a capsule: core half-length and orientation
            if (!(fields >> g.orientation[0] >> g.orientation[1] >> g.orientation[2] >>
                  g.orientation[3]))
                throw Error(path + ":" + std::to_string(lineNumber) +
                            ": a capsule line is 'x y z r h qw qx qy qz'");
        g.density = density;
        packing.grains.push_back(g);
    }
    if (expected < 0)
        throw Error(path + ": missing header '# L Lz N'");
    if (long(packing.grains.size()) != expected)
        throw Error(path + ": header says " + std::to_string(expected) + " grains, file has " +
                    std::to_string(packing.grains.size()));
    return packing;
}

void writePacking(const std::string& path, const Packing& packing)
{
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (!out)
        throw Error("cannot write packing file '" + path + "'");
    std::fprintf(out, "# %.17g %.17g %zu\n", packing.length, packing.height, packing.grains.size());
    for (const GrainInit& g : packing.grains)
    {
        std::fprintf(out, "%.17g %.17g %.17g %.17g", g.position[0], g.position[1], g.position[2],
                     g.radius);
        if (g.coreHalfLength > 0.0)
            std::fprintf(out, " %.17g %.17g %.17g %.17g %.17g", g.coreHalfLength, g.orientation[0],
                         g.orientation[1], g.orientation[2], g.orientation[3]);
        std::fprintf(out, "\n");
    }
    if (std::fclose(out) != 0)
        throw Error("error writing packing file '" + path + "'");
}

} // namespace dem
