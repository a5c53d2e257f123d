// PackingFile.cpp
// Reader and writer of the benchmark packing files.
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
                        ": expected 'x y z r', 'x y z r vx vy vz' or 'x y z r h qw qx qy qz'");
        // After the radius: nothing (a sphere at rest), a velocity, or a capsule's core
        // half-length and orientation
        double extra[5];
        int extras = 0;
        while (extras < 5 && fields >> extra[extras])
            ++extras;
        if (extras == 3)
            g.velocity = {extra[0], extra[1], extra[2]};
        else if (extras == 5)
        {
            g.coreHalfLength = extra[0];
            g.orientation = {extra[1], extra[2], extra[3], extra[4]};
        }
        else if (extras != 0)
            throw Error(path + ":" + std::to_string(lineNumber) +
                        ": a sphere line is 'x y z r' or 'x y z r vx vy vz', a capsule line "
                        "'x y z r h qw qx qy qz'");
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
    // Velocities on every line as soon as one grain moves (spheres only; spins are not kept)
    bool moving = false, capsules = false;
    for (const GrainInit& g : packing.grains)
    {
        moving = moving || g.velocity[0] != 0.0 || g.velocity[1] != 0.0 || g.velocity[2] != 0.0;
        capsules = capsules || g.coreHalfLength > 0.0;
    }
    if (moving && capsules)
        throw Error("packing file '" + path + "': capsules are written without velocities");
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (!out)
        throw Error("cannot write packing file '" + path + "'");
    std::fprintf(out, "# %.17g %.17g %zu\n", packing.length, packing.height, packing.grains.size());
    for (const GrainInit& g : packing.grains)
    {
        std::fprintf(out, "%.17g %.17g %.17g %.17g", g.position[0], g.position[1], g.position[2],
                     g.radius);
        if (moving)
            std::fprintf(out, " %.17g %.17g %.17g", g.velocity[0], g.velocity[1], g.velocity[2]);
        if (g.coreHalfLength > 0.0)
            std::fprintf(out, " %.17g %.17g %.17g %.17g %.17g", g.coreHalfLength, g.orientation[0],
                         g.orientation[1], g.orientation[2], g.orientation[3]);
        std::fprintf(out, "\n");
    }
    if (std::fclose(out) != 0)
        throw Error("error writing packing file '" + path + "'");
}

} // namespace dem
