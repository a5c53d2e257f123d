// demBench.cpp
// The standard DEM benchmark of src/dem/bench/README.md: a settled dense packing on a wall,
// 1000 relaxation steps with a global drag of 612 N s/m, then exactly 2000 timed steps without
// damping. --shape capsule --aspect A: the same with capsules made from the packing
// (CapsulePacking.h). --bonds: the same with bonds (every touching pair frozen at the first
// step, formation checks every 10 steps, elastic patch with Maxwell creep), the cost of bonds
// against the same grains without. --pour: the flowing benchmark instead (PourPacking.h; no drag,
// 1000 untimed lead-in steps, 4000 timed steps, the neighbour lists rebuilt every few hundred
// steps). --decompose NXxNY under mpirun -np NX*NY: the same problem split over MPI ranks
// (Parameters::decomposition; each rank reads the file and adds its own block of grains;
// the figures are of all ranks; rank 0 prints). The last line is machine-readable:
//   particle_steps_per_s=<number> N=<int> threads=<int> backend=<name> contacts_per_grain=<number>
//   shape=<sphere|capsule> aspect=<number> bonds=<intact bonds per grain> steps=<timed steps>
//   rebuilds=<neighbour rebuilds while timed> skin=<m> problem=<standard|pour>
#include "CapsulePacking.h"
#include "PackingFile.h"
#include "PourPacking.h"
#include "dem/Mpi.h"
#include "dem/System.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace
{

void usage()
{
    std::cerr << "usage: demBench --packing FILE [--relax-steps 1000] [--steps 2000] "
                 "[--threads T] [--backend auto|cpu|cuda] [--skin 2e-3] [--replicate NXxNY]\n"
                 "                [--shape sphere|capsule] [--aspect 3] [--seed 1] "
                 "[--write-packing FILE] [--bonds]\n"
                 "       demBench --pour [--grains 10000 | --packing FILE] [--seed 1] "
                 "[--relax-steps 1000] [--steps 4000] [--skin S] ...\n"
                 "--replicate 10x1: NX x NY copies of the periodic packing side by side, "
                 "box NX L x NY L\n"
                 "--shape capsule: the packing's grains as capsules of the same volume and "
                 "aspect ratio (L + 2r) / (2r), random orientations (--seed), relaxed with soft "
                 "contacts stiffened stage by stage (untimed); --write-packing saves it "
                 "(x y z r h qw qx qy qz per capsule) for --packing\n"
                 "--bonds: bonds on (frozen on contact, checked every 10 steps; elastic patch "
                 "at most as stiff as the contacts, Maxwell creep)\n"
                 "--pour: the flowing benchmark: --grains spheres on a loose lattice falling at "
                 "10 m/s with random velocities (--seed), or the start saved with "
                 "--write-packing (x y z r vx vy vz) as --packing; no drag, --relax-steps are "
                 "an untimed lead-in\n"
                 "--write-packing FILE --steps 0: set up and save the start only\n"
                 "--decompose NXxNY: split the box into NX x NY boxes, one per MPI rank "
                 "(mpirun -np NX*NY demBench ...; spheres and capsules without bonds)\n";
}

const dem::MpiSession* mpi = nullptr; //!< sums over the ranks

//- Translational kinetic energy [J] and sum of |omega| components [rad/s] of the grains (of all
//- ranks).
std::pair<double, double> motionOf(const dem::GrainData& state)
{
    double kinetic = 0.0, rotationRate = 0.0;
    for (std::size_t i = 0; i < state.mass.size(); ++i)
        for (std::size_t d = 0; d < 3; ++d)
        {
            kinetic += 0.5 * state.mass[i] * state.velocity[3 * i + d] * state.velocity[3 * i + d];
            rotationRate += std::fabs(state.angularVelocity[3 * i + d]);
        }
    return {mpi->sum(kinetic), mpi->sum(rotationRate)};
}

//- The grains to start from: the packing file, else (--pour) the generated pour.
dem::Packing startingGrains(const std::string& file, bool pour, const dem::PourSettings& settings,
                            double density)
{
    if (pour && file.empty())
        return dem::pourPacking(settings, density);
    return dem::readPacking(file, density);
}

//- "NXxNY" (e.g. 10x1) as two positive counts.
std::pair<int, int> parseReplicate(const std::string& text)
{
    int nx = 0, ny = 0, used = 0;
    if (std::sscanf(text.c_str(), "%dx%d%n", &nx, &ny, &used) != 2 || used != int(text.size()) ||
        nx < 1 || ny < 1)
        throw dem::Error("--replicate '" + text +
                         "': expected NXxNY with positive whole numbers, e.g. 10x1");
    return {nx, ny};
}

//- The packing tiled nx x ny times across its periodic sides (the copies' contacts across the
//- seams are those of the original across its periodic sides).
void replicate(dem::Packing& packing, int nx, int ny)
{
    const std::vector<dem::GrainInit> cell = packing.grains;
    packing.grains.clear();
    packing.grains.reserve(cell.size() * std::size_t(nx) * std::size_t(ny));
    for (int iy = 0; iy < ny; ++iy)
        for (int ix = 0; ix < nx; ++ix)
            for (dem::GrainInit g : cell)
            {
                g.position[0] += ix * packing.length;
                g.position[1] += iy * packing.length;
                packing.grains.push_back(g);
            }
}

double processCpuSeconds()
{
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

dem::Backend parseBackend(const std::string& name)
{
    if (name == "auto")
        return dem::Backend::automatic;
    if (name == "cpu")
        return dem::Backend::cpu;
    if (name == "cuda")
        return dem::Backend::cuda;
    throw dem::Error("unknown backend '" + name + "' (valid: auto cpu cuda)");
}

} // namespace

int main(int argc, char** argv)
{
    const dem::MpiSession session(&argc, &argv);
    mpi = &session;
    // Rank 0 speaks; the others' output goes nowhere (errors are printed by every rank).
    if (session.rank() != 0 && !std::freopen("/dev/null", "w", stdout))
        return 1;
    std::string packingFile;
    int relaxSteps = 1000, steps = -1, threads = 0; // steps: 2000, 4000 with --pour
    // Verlet skin 2e-3 m = 0.1 d, the benchmark's common setting (bench/README.md): every code
    // is timed with it. A thinner skin (--skin) lists fewer pairs and pays only in this
    // quasi-static problem, where nothing moves; in a flowing bed it means a rebuild every few
    // steps.
    double skin = 2e-3, friction = 0.5;
    dem::Backend backend = dem::Backend::automatic;
    std::pair<int, int> copies{1, 1}, boxes{1, 1};
    std::string shape = "sphere", writeFile;
    bool bonds = false, pour = false;
    dem::CapsulePackingSettings capsules;
    dem::PourSettings pourSettings;
    try
    {
        for (int a = 1; a < argc; ++a)
        {
            const std::string arg = argv[a];
            auto value = [&]() -> std::string
            {
                if (a + 1 >= argc)
                    throw dem::Error("option " + arg + " needs a value");
                return argv[++a];
            };
            if (arg == "--packing")
                packingFile = value();
            else if (arg == "--relax-steps")
                relaxSteps = std::stoi(value());
            else if (arg == "--steps")
                steps = std::stoi(value());
            else if (arg == "--threads")
                threads = std::stoi(value());
            else if (arg == "--backend")
                backend = parseBackend(value());
            else if (arg == "--skin")
                skin = std::stod(value());
            else if (arg == "--replicate")
                copies = parseReplicate(value());
            else if (arg == "--decompose")
                boxes = parseReplicate(value());
            else if (arg == "--shape")
            {
                shape = value();
                if (shape != "sphere" && shape != "capsule")
                    throw dem::Error("--shape '" + shape + "' (valid: sphere capsule)");
            }
            else if (arg == "--aspect")
                capsules.aspect = std::stod(value());
            else if (arg == "--write-packing")
                writeFile = value();
            else if (arg == "--seed")
                capsules.seed = pourSettings.seed = unsigned(std::stoul(value()));
            else if (arg == "--bonds")
                bonds = true;
            else if (arg == "--pour")
                pour = true;
            else if (arg == "--grains")
                pourSettings.grains = std::stol(value());
            else if (arg == "--friction") // profiling aid: 0 skips the tangential spring
                friction = std::stod(value());
            else if (arg == "-h" || arg == "--help")
            {
                usage();
                return 0;
            }
            else
                throw dem::Error("unknown option '" + arg + "'");
        }
        if (packingFile.empty() && !pour)
        {
            usage();
            return 2;
        }
        if (steps < 0)
            steps = pour ? 4000 : 2000;
        if (pour && shape == "capsule")
            throw dem::Error("--pour is a benchmark of spheres (no --shape capsule)");

        const double density = 2600.0;
        dem::Packing packing = startingGrains(packingFile, pour, pourSettings, density);
        replicate(packing, copies.first, copies.second);
        dem::Parameters p;
        p.grainGrain = {1.16e9, 1.16e9, 0.0, 0.0, friction};
        p.grainWall = p.grainGrain;
        p.defaultDensity = density;
        p.gravity = {0.0, 0.0, -9.81};
        p.boxLower = {0.0, 0.0};
        p.boxUpper = {copies.first * packing.length, copies.second * packing.length};
        p.periodic = {true, true};
        p.timeStep = 2.14e-7;
        p.neighbourSkin = skin;
        p.backend = backend;
        p.threads = threads;

        const double drag = 612.0;
        if (shape == "capsule")
            packing = dem::capsulePacking(packing, p, drag, capsules);
        if (!writeFile.empty())
            dem::writePacking(writeFile, packing);
        // --write-packing with --steps 0: the start saved, nothing run (without --write-packing,
        // --steps 0 still makes the System and prints the last line: bin/gpuCheck's probe)
        if (!writeFile.empty() && steps == 0)
        {
            std::printf("demBench: --steps 0: %zu grains set up and written to %s, nothing run\n",
                        packing.grains.size(), writeFile.c_str());
            return 0;
        }
        // The shape of the grains timed (a capsule packing may come from the file)
        double aspect = 1.0;
        for (const dem::GrainInit& g : packing.grains)
            if (g.coreHalfLength > 0.0)
            {
                shape = "capsule";
                aspect = (g.coreHalfLength + g.radius) / g.radius;
                break;
            }
        double interior;
        const double bed = dem::bedSolidFraction(packing, interior);
        if (bonds)
        {
            // The stiffest bond formation may make (r_b^2 = 0.09375 r^2, k_ne A = E pi 0.09375
            // r / 2, the critical step's bound) as stiff as a contact: the benchmark's time step
            // stays allowed.
            double radius = 0.0;
            for (const dem::GrainInit& g : packing.grains)
                radius = std::max(radius, g.radius);
            p.bonds.enabled = true;
            p.bonds.formation = dem::BondFormation::frozenOnContact;
            p.bonds.formationInterval = 10;
            p.bonds.youngsModulus = 2.0 * p.grainGrain.normalStiffness / (M_PI * 0.09375 * radius);
            p.bonds.creep = dem::BondCreep::maxwell;
            p.bonds.contactViscosity = 1e6;
        }

        // (after the capsule set-up above, which every rank runs alike on one process)
        p.decomposition.ranks = {boxes.first, boxes.second};
        if (p.decomposition.rankCount() > 1 && !dem::mpiBuild())
            throw dem::Error("--decompose: this DEM library was built without MPI (install "
                             "libopenmpi-dev and rebuild)");
        if (p.decomposition.rankCount() != session.size())
            throw dem::Error("--decompose " + std::to_string(boxes.first) + "x" +
                             std::to_string(boxes.second) + " needs mpirun -np " +
                             std::to_string(p.decomposition.rankCount()) + ", not " +
                             std::to_string(session.size()) + " rank(s)");
        dem::System system(p);
        {
            // Each rank adds its block of the file's grains (add order kept: rank 0's first);
            // the first step moves them to their owners.
            const std::size_t all = packing.grains.size(), r = std::size_t(session.rank()),
                              ranks = std::size_t(session.size());
            system.addGrains(
                std::vector<dem::GrainInit>(packing.grains.begin() + long(all * r / ranks),
                                            packing.grains.begin() + long(all * (r + 1) / ranks)));
        }
        dem::WallSpec bottom;
        bottom.side = dem::WallSpec::Side::lower;
        bottom.position = 0.0;
        system.addWall(bottom);
        const long n = long(system.grainCount());
        std::printf("demBench: %s x %dx%d, N = %ld, L = %g m, dt = %g s, skin = %g m, "
                    "backend %s, %d thread(s), %s, solid fraction %.3f (bed) / %.3f "
                    "(0.05 < z < 0.30 m)\n",
                    pour && packingFile.empty() ? "pour" : packingFile.c_str(), copies.first,
                    copies.second, n, packing.length, p.timeStep, skin,
                    system.backendName().c_str(), system.threadCount(),
                    shape == "capsule" ? ("capsules of aspect " + std::to_string(aspect)).c_str()
                                       : "spheres",
                    bed, interior);

        if (pour) // the kinetic energy the lead-in starts from (its change is the check)
            std::printf("start: translational kinetic energy %.10g J\n",
                        motionOf(system.grains()).first);
        system.setViscousDrag(pour ? 0.0 : drag);
        system.step(relaxSteps);
        system.setViscousDrag(0.0);
        if (session.size() > 1) // the grains are with their owners now
        {
            const double owned = double(system.grains().mass.size()),
                         ghosts = double(system.ghostCount());
            std::printf("decomposition %dx%d: grains per rank %g (min) %g (max) %g (mean), "
                        "load imbalance max/mean %.3f; ghosts per rank %g (min) %g (max), "
                        "%.1f %% of the owned on average\n",
                        boxes.first, boxes.second, session.min(owned), session.max(owned),
                        double(n) / session.size(), session.max(owned) * session.size() / n,
                        session.min(ghosts), session.max(ghosts),
                        100.0 * session.sum(ghosts) / double(n));
        }
        // The start of the timed phase, for comparisons with other codes (--pour: before the
        // flow turns chaotic)
        const std::pair<double, double> lead = motionOf(system.grains());
        std::printf("after %d %s steps: translational kinetic energy %.10g J, sum |omega| %.10g "
                    "rad/s, %.4f contacts per grain\n",
                    relaxSteps, pour ? "lead-in" : "relaxation", lead.first, lead.second,
                    2.0 * double(system.contactCount()) / double(n));
        const std::size_t rebuildsBefore = system.neighbourRebuildCount();
        const double cpuStart = processCpuSeconds();
        const auto start = std::chrono::steady_clock::now();
        system.step(steps);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double cpuSeconds = processCpuSeconds() - cpuStart;
        const double rate = double(n) * steps / seconds;
        const double contactsPerGrain = 2.0 * double(system.contactCount()) / double(n);
        const double bondsPerGrain = double(system.bondCounts().intact) / double(n);
        const std::size_t rebuilds = system.neighbourRebuildCount() - rebuildsBefore;
        std::printf("%s %d steps, timed %d steps in %.4f s, %zu neighbour rebuild(s) "
                    "while timed (%.3g per 1000 steps), %.3f list pairs per grain\n",
                    pour ? "lead-in" : "relaxation", relaxSteps, steps, seconds, rebuilds,
                    steps > 0 ? 1000.0 * double(rebuilds) / steps : 0.0,
                    session.sum(double(system.pairCount())) / double(n));
        // On a shared machine the CPU time shows what the code costs when it is not waiting.
        std::printf("timed phase used %.4f s of CPU time (%.3g particle-steps per CPU-second)\n",
                    cpuSeconds, double(n) * steps / cpuSeconds);
        // The state after the timed phase, all digits: an optimisation that claims to keep the
        // physics must keep these (same thread count and backend).
        const std::pair<double, double> motion = motionOf(system.grains());
        std::printf("final translational kinetic energy %.17g J, sum |omega| %.17g rad/s\n",
                    motion.first, motion.second);
        std::printf("particle_steps_per_s=%.6g N=%ld threads=%d backend=%s "
                    "contacts_per_grain=%.4f shape=%s aspect=%g bonds=%.4f steps=%d "
                    "rebuilds=%zu skin=%g problem=%s ranks=%d\n",
                    rate, n, system.threadCount(), system.backendName().c_str(), contactsPerGrain,
                    shape.c_str(), aspect, bondsPerGrain, steps, rebuilds, skin,
                    pour ? "pour" : "standard", session.size());
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "demBench: " << e.what() << "\n";
        return 1;
    }
}
