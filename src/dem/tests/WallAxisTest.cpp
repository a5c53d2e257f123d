// WallAxisTest.cpp
// Walls on any axis, free walls and gravity changes: a grain resting on an x (y) wall under
// gravity along x (y) loads it with its weight, and so does a capsule on both ends on the
// sixth wall of a closed box; a free lid falls freely, lands on a grain and rests on it with
// its weight; a stress-controlled x wall takes sigma0 times the box's y length times the gap
// between the z walls; under a linear gravity ramp a grain and a free wall follow velocity
// Verlet's closed form; the deposit mirrors at closed x sides; bad walls are refused with the
// valid choices; a state of the 4-wall layout restarts.
#include "TestSupport.h"

#include <cstdio>
#include <string>

using namespace demTest;

namespace
{

class WallAxes : public BackendTest
{
protected:
    //- Dry, frictionless grains with normal damping at half critical for one grain on a wall
    //- (at rest the forces balance to rounding), a box not periodic along `openAxis` (-1: none).
    dem::Parameters dampedParameters(int openAxis) const
    {
        dem::Parameters p = parameters();
        const double m = 2600 * sphereVolume(0.01), k = p.grainWall.normalStiffness;
        p.grainGrain.friction = p.grainWall.friction = 0.0;
        p.grainGrain.normalDamping = p.grainWall.normalDamping = 2 * 0.5 * std::sqrt(k * m);
        p.timeStep = 0.05 * std::sqrt(m / k);
        if (openAxis >= 0)
            p.periodic[std::size_t(openAxis)] = false;
        return p;
    }
};

dem::WallSpec wallOn(int axis, dem::WallSpec::Side side, double position)
{
    dem::WallSpec w;
    w.axis = axis;
    w.side = side;
    w.position = position;
    return w;
}

} // namespace

// A grain at rest on a wall carries its weight into it: grain force on the wall = m g along the
// wall's axis, overlap m |g| / k. x: a lower wall, gravity -x; y: an upper wall, gravity +y.
TEST_P(WallAxes, GrainRestsOnSideWallUnderSideGravity)
{
    const double r = 0.01, g = 9.81;
    for (const int axis : {0, 1})
    {
        dem::Parameters p = dampedParameters(axis);
        const bool lower = axis == 0;
        p.gravity = {0, 0, 0};
        p.gravity[std::size_t(axis)] = lower ? -g : g;
        dem::System s(p);
        dem::GrainInit grain;
        grain.radius = r;
        grain.position = {0.5, 0.5, 0.5};
        grain.position[std::size_t(axis)] = lower ? r : 1.0 - r;
        s.addGrains({grain});
        s.addWall(wallOn(axis, lower ? dem::WallSpec::Side::lower : dem::WallSpec::Side::upper,
                         lower ? 0.0 : 1.0));
        s.step(int(0.02 / p.timeStep)); // 100 decay times of the half-critical contact
        const double m = s.grains().mass[0], k = p.grainWall.normalStiffness;
        const double weight = m * p.gravity[std::size_t(axis)];
        const double overlap = m * g / k;
        const double x = s.grains().position[std::size_t(axis)];
        const double measuredOverlap = lower ? r - x : x - (1.0 - r);
        std::printf("  axis %d: wall force / (m g) - 1 = %.2e, overlap / (m g / k) - 1 = %.2e\n",
                    axis, s.wall(0).grainForce / weight - 1, measuredOverlap / overlap - 1);
        // At rest the contact force balances the weight to rounding; the overlap (~1e-7 m) is
        // a difference of positions ~1 m, so rounding alone allows ~1e-16 / 1e-7 = 1e-9.
        EXPECT_NEAR(s.wall(0).grainForce / weight, 1.0, 1e-9);
        EXPECT_NEAR(measuredOverlap / overlap, 1.0, 1e-6);
        EXPECT_EQ(s.wall(0).spec.axis, axis);
    }
}

// A capsule lying along x on the sixth wall of a closed box (a lower y wall, gravity -y)
// rests on both core ends: the wall carries m g, each end m g / 2 at overlap m g / (2 k);
// its end contacts use the highest wall-contact bits (kMaxWalls = 6).
TEST_P(WallAxes, CapsuleRestsOnBothEndsOnTheSixthWall)
{
    const double r = 0.01, h = 0.015, g = 9.81;
    dem::Parameters p = dampedParameters(0);
    p.periodic = {false, false};
    p.gravity = {0, -g, 0};
    dem::System s(p);
    dem::GrainInit capsule;
    capsule.radius = r;
    capsule.coreHalfLength = h;
    capsule.orientation = {std::sqrt(0.5), 0.0, std::sqrt(0.5), 0.0}; // body z along x
    capsule.position = {0.5, r, 0.5};
    s.addGrains({capsule});
    s.addWall(wallOn(2, dem::WallSpec::Side::lower, 0.0));
    s.addWall(wallOn(2, dem::WallSpec::Side::upper, 1.0));
    s.addWall(wallOn(0, dem::WallSpec::Side::lower, 0.0));
    s.addWall(wallOn(0, dem::WallSpec::Side::upper, 1.0));
    s.addWall(wallOn(1, dem::WallSpec::Side::upper, 1.0));
    const int floor = s.addWall(wallOn(1, dem::WallSpec::Side::lower, 0.0));
    s.step(int(0.05 / p.timeStep));
    const dem::GrainData gd = s.grains();
    const double m = gd.mass[0], k = p.grainWall.normalStiffness;
    const double overlap = m * g / (2 * k);
    std::printf("  capsule on wall %d: wall force / (m g) - 1 = %.2e, height error / overlap = "
                "%.2e\n",
                floor, s.wall(floor).grainForce / (-m * g) - 1,
                (gd.position[1] - (r - overlap)) / overlap);
    EXPECT_EQ(floor, 5);
    EXPECT_NEAR(s.wall(floor).grainForce / (-m * g), 1.0, 1e-9); // at rest, as above
    EXPECT_NEAR((gd.position[1] - (r - overlap)) / overlap, 0.0, 1e-6);
    EXPECT_NEAR(gd.position[0], 0.5, 1e-9); // symmetric: no drift along the wall
}

// A free lid of mass M released above a grain on the floor falls freely (velocity Verlet is
// exact for a constant acceleration: z0 - g t^2 / 2), then comes to rest on the grain: the
// grain pushes it up with M g, the floor carries (M + m) g, and the lid sits at 2 r minus the
// two overlaps M g / k and (M + m) g / k.
TEST_P(WallAxes, FreeLidFallsOntoGrainAndRestsOnItsWeight)
{
    const double r = 0.01, g = 9.81, lidMass = 0.05, drop = 0.002;
    dem::Parameters p = dampedParameters(-1);
    p.gravity = {0, 0, -g};
    dem::System s(p);
    dem::GrainInit grain;
    grain.radius = r;
    grain.position = {0.5, 0.5, r};
    s.addGrains({grain});
    s.addWall(dem::WallSpec());
    dem::WallSpec lid = wallOn(2, dem::WallSpec::Side::upper, 2 * r + drop);
    lid.mode = dem::WallSpec::Mode::free;
    lid.mass = lidMass;
    const int lidIndex = s.addWall(lid);

    const int freeSteps = int(0.9 * std::sqrt(2 * drop / g) / p.timeStep); // before touching
    s.step(freeSteps);
    const double t = s.time(), fallen = 0.5 * g * t * t;
    const dem::WallData falling = s.wall(lidIndex);
    std::printf("  free fall: (z0 - z) / (g t^2 / 2) - 1 = %.2e, v / (-g t) - 1 = %.2e\n",
                (2 * r + drop - falling.position) / fallen - 1, falling.velocity / (-g * t) - 1);
    // Exact but for rounding: ~1e-16 per step over ~1e3 steps of a ~1e-3 m fall
    EXPECT_NEAR((2 * r + drop - falling.position) / fallen, 1.0, 1e-9);
    EXPECT_NEAR(falling.velocity / (-g * t), 1.0, 1e-9);
    EXPECT_EQ(falling.grainForce, 0.0);

    s.step(int(0.2 / p.timeStep)); // lands and settles (the lid rings on two damped springs)
    const double m = s.grains().mass[0], k = p.grainWall.normalStiffness;
    const dem::WallData rest = s.wall(lidIndex);
    const double expectedZ = 2 * r - lidMass * g / k - (lidMass + m) * g / k;
    std::printf("  at rest: lid force / (M g) - 1 = %.2e, floor / ((M + m) g) - 1 = %.2e, "
                "lid z error / overlaps = %.2e, v = %.1e\n",
                rest.grainForce / (lidMass * g) - 1,
                -s.wall(0).grainForce / ((lidMass + m) * g) - 1,
                (rest.position - expectedZ) / (2 * r - expectedZ), rest.velocity);
    EXPECT_NEAR(rest.grainForce / (lidMass * g), 1.0, 1e-6); // the ring decays below 1e-6
    EXPECT_NEAR(-s.wall(0).grainForce / ((lidMass + m) * g), 1.0, 1e-6);
    EXPECT_NEAR((rest.position - expectedZ) / (2 * r - expectedZ), 0.0, 1e-6);
}

// A stress-controlled upper x wall pressing a grain onto a fixed lower x wall: at rest the
// grain pushes it with sigma0 A, A = box y length x gap between the z walls (WallSpec).
TEST_P(WallAxes, StressOnXWallActsOnYLengthTimesZGap)
{
    const double r = 0.01, sigma0 = 50.0, gap = 0.05;
    dem::Parameters p = dampedParameters(0);
    p.boxUpper = {1.0, 0.05};
    dem::System s(p);
    dem::GrainInit grain;
    grain.radius = r;
    grain.position = {r, 0.025, 0.5 * gap};
    s.addGrains({grain});
    s.addWall(wallOn(0, dem::WallSpec::Side::lower, 0.0));
    dem::WallSpec side = wallOn(0, dem::WallSpec::Side::upper, 2 * r);
    side.mode = dem::WallSpec::Mode::stress;
    side.mass = 0.05;
    side.normalStress = sigma0;
    const int sideIndex = s.addWall(side);
    EXPECT_THROW(s.step(1), dem::Error); // no z walls yet: no area
    s.addWall(wallOn(2, dem::WallSpec::Side::lower, 0.0));
    s.addWall(wallOn(2, dem::WallSpec::Side::upper, gap));
    s.step(int(0.2 / p.timeStep));
    const double force = sigma0 * 0.05 * gap;
    std::printf("  x wall: grain force / (sigma0 L_y gap) - 1 = %.2e\n",
                s.wall(sideIndex).grainForce / force - 1);
    EXPECT_NEAR(s.wall(sideIndex).grainForce / force, 1.0, 1e-6); // at rest, as above
    EXPECT_NEAR(s.wall(0).grainForce / -force, 1.0, 1e-6);
}

// Gravity ramped linearly, g(t) = c t, set before every step: velocity Verlet integrates a
// linear acceleration's velocity exactly (the trapezoid rule), v = c T^2 / 2, and its position
// to x0 + c T^3 / 6 - c T dt^2 / 6 (each step misses c dt^3 / 6). A grain and a free x wall
// (no contact) follow both to rounding.
TEST_P(WallAxes, GravityRampFollowsVelocityVerletClosedForm)
{
    const std::array<double, 3> c = {-3.0, 0.0, -9.81}; // [m/s^3]
    dem::Parameters p = parameters();
    p.periodic = {false, true};
    p.timeStep = 1e-4;
    p.maxTimeStepFraction = 1.0; // nothing touches: the contact stiffness does not limit dt
    dem::System s(p);
    dem::GrainInit grain;
    grain.position = {0.5, 0.5, 0.0};
    s.addGrains({grain});
    // The wall and the grain fall alike along x: their gap stays 0.5 m.
    dem::WallSpec wall = wallOn(0, dem::WallSpec::Side::lower, 0.0);
    wall.mode = dem::WallSpec::Mode::free;
    wall.mass = 2.0;
    s.addWall(wall);
    s.step(0); // the initial forces at g(0) = 0
    const int steps = 1000;
    const double dt = p.timeStep, T = steps * dt;
    for (int k = 1; k <= steps; ++k)
    {
        s.setGravity({c[0] * k * dt, c[1] * k * dt, c[2] * k * dt});
        s.step(1);
    }
    const dem::GrainData gd = s.grains();
    auto position = [&](double ci) { return ci * T * T * T / 6 - ci * T * dt * dt / 6; };
    const double vz = gd.velocity[2], z = gd.position[2];
    const dem::WallData w = s.wall(0);
    std::printf("  grain: v_z / (c T^2/2) - 1 = %.2e, z / closed form - 1 = %.2e; wall: v / "
                "(c T^2/2) - 1 = %.2e, x / closed form - 1 = %.2e\n",
                vz / (0.5 * c[2] * T * T) - 1, z / position(c[2]) - 1,
                w.velocity / (0.5 * c[0] * T * T) - 1, w.position / position(c[0]) - 1);
    // Rounding only: ~1e-16 relative per step over 1e3 steps
    EXPECT_NEAR(vz / (0.5 * c[2] * T * T), 1.0, 1e-9);
    EXPECT_NEAR(z / position(c[2]), 1.0, 1e-9);
    EXPECT_NEAR(gd.velocity[0] / (0.5 * c[0] * T * T), 1.0, 1e-9);
    EXPECT_NEAR(w.velocity / (0.5 * c[0] * T * T), 1.0, 1e-9);
    EXPECT_NEAR(w.position / position(c[0]), 1.0, 1e-9);
    EXPECT_EQ(w.grainForce, 0.0);
}

TEST_P(WallAxes, BadWallsAreRefusedWithTheValidChoices)
{
    dem::Parameters p = parameters(); // periodic in x and y
    dem::System s(p);
    auto message = [&](const dem::WallSpec& w)
    {
        try
        {
            s.addWall(w);
        }
        catch (const dem::Error& e)
        {
            return std::string(e.what());
        }
        return std::string();
    };
    dem::WallSpec w;
    w.axis = 3;
    EXPECT_NE(message(w).find("0 (x), 1 (y) or 2 (z)"), std::string::npos) << message(w);
    w.axis = 0;
    EXPECT_NE(message(w).find("not periodic in x"), std::string::npos) << message(w);
    w.axis = 2;
    w.mode = dem::WallSpec::Mode::free;
    EXPECT_NE(message(w).find("free wall"), std::string::npos) << message(w);
    w.mass = 1.0;
    EXPECT_EQ(message(w), "");
    dem::WallSpec turned = w;
    turned.axis = 1;
    EXPECT_THROW(s.setWallMotion(0, turned), dem::Error);
    for (int i = 1; i < 6; ++i)
        s.addWall(w);
    EXPECT_NE(message(w).find("at most 6 walls"), std::string::npos) << message(w);
}

// A box closed in x (walls there, not periodic): the deposit mirrors at the x sides, so a
// grain in the first half cell deposits all of its volume into the first column (a periodic
// wrap would put a share into the last one), and grains along both x sides, spheres and
// capsules, deposit their whole volume (round-off).
TEST_P(WallAxes, DepositInBoxClosedInXMirrorsAtItsSides)
{
    const double box = 0.2, height = 0.15;
    dem::Parameters p = parameters();
    p.periodic = {false, true};
    p.boxUpper = {box, box};
    dem::UniformGrid grid;
    grid.n = {5, 4, 6};
    grid.spacing = {box / 5, box / 4, height / 6};
    grid.periodic = {false, true, false};
    const std::size_t cells = std::size_t(grid.n[0] * grid.n[1] * grid.n[2]);
    {
        dem::System s(p);
        dem::GrainInit grain;
        grain.radius = 0.006;
        grain.position = {0.3 * grid.spacing[0], 1.5 * grid.spacing[1], 2.5 * grid.spacing[2]};
        s.addGrains({grain});
        std::vector<double> solid(cells), porosity(cells);
        s.deposit(grid, 0.0, porosity.data(), nullptr, nullptr, solid.data());
        const std::size_t first = 0 + 5 * (1 + 4 * 2);
        std::printf("  grain at 0.3 dx: first column holds %.17g of its volume\n",
                    solid[first] / sphereVolume(grain.radius));
        EXPECT_NEAR(solid[first] / sphereVolume(grain.radius), 1.0, 1e-14);
    }
    dem::System s(p);
    std::vector<dem::GrainInit> grains;
    for (int i = 0; i < 40; ++i)
    {
        dem::GrainInit g;
        g.radius = 0.005;
        const double x = g.radius + 0.0003 * i;
        g.position = {i % 2 ? x : box - x, 0.005 * i, 0.01 + 0.003 * i};
        if (i % 3 == 0)
        {
            g.coreHalfLength = 0.004; // along z: parallel to the x walls
        }
        grains.push_back(g);
    }
    s.addGrains(grains);
    std::vector<double> solid(cells), porosity(cells);
    s.deposit(grid, 0.0, porosity.data(), nullptr, nullptr, solid.data());
    double volume = 0, deposited = 0;
    for (const dem::GrainInit& g : grains)
        volume += sphereVolume(g.radius) + M_PI * g.radius * g.radius * 2 * g.coreHalfLength;
    for (double v : solid)
        deposited += v;
    std::printf("  grains along both x sides: deposited / volume - 1 = %.2e\n",
                deposited / volume - 1);
    EXPECT_NEAR(deposited / volume, 1.0, 1e-13); // 40 grains' round-off
}

// A state written when grains held wall records for 4 walls (no 'walls.layout', 3 wall
// integers, records of 4 walls, a capsule's second-end bits at 4 + w) restarts into today's
// layout and continues bit-identically: horizontal capsules resting on both ends on a floor
// under a free lid, with a y wall.
TEST_P(WallAxes, StateOfFourWallRecordsRestartsBitIdentically)
{
    dem::Parameters p = dampedParameters(1);
    p.gravity = {0, 0, -9.81};
    auto make = [&]
    {
        dem::System s(p);
        std::vector<dem::GrainInit> grains;
        for (int i = 0; i < 4; ++i)
        {
            dem::GrainInit g;
            g.radius = 0.01;
            g.coreHalfLength = 0.01;
            g.position = {0.1 + 0.05 * i, 0.03 + 0.01 * i, 0.0099};
            g.orientation = {std::sqrt(0.5), std::sqrt(0.5), 0.0, 0.0}; // axis along -y
            g.velocity = {0.01 * i, -0.02, 0.0};
            grains.push_back(g);
        }
        s.addGrains(grains);
        s.addWall(dem::WallSpec());
        dem::WallSpec lid = wallOn(2, dem::WallSpec::Side::upper, 0.0201);
        lid.mode = dem::WallSpec::Mode::free;
        lid.mass = 0.01;
        s.addWall(lid);
        s.addWall(wallOn(1, dem::WallSpec::Side::lower, 0.0));
        return s;
    };
    dem::System reference = make();
    reference.step(300);
    dem::SystemState state = reference.exportState();
    reference.step(300);

    // The same state as the 4-wall layout wrote it (its walls were z planes: the y wall's
    // axis is restored below, after the import, as setWallMotion cannot turn a wall).
    const std::size_t n = 4;
    for (const char* name : {"grain.wallState", "grain.wallStateEnd"})
    {
        std::vector<double>& v = state.reals[name];
        std::vector<double> old;
        for (std::size_t i = 0; i < n; ++i)
            old.insert(old.end(), v.begin() + long(24 * i), v.begin() + long(24 * i + 16));
        v = old;
    }
    int endBits = 0;
    for (std::int64_t& bits : state.integers["grain.wallContacts"])
    {
        endBits |= int(bits >> 6);
        bits = (bits & 0x3f) | ((bits >> 6) << 4);
    }
    EXPECT_NE(endBits, 0); // the second ends touch the floor: their bits are remapped
    std::vector<std::int64_t>& wallInts = state.integers["walls.int"];
    std::vector<std::int64_t> old;
    for (std::size_t w = 0; w < wallInts.size(); w += 4)
        old.insert(old.end(), wallInts.begin() + long(w), wallInts.begin() + long(w + 3));
    wallInts = old;
    state.integers.erase("walls.layout");

    dem::System restarted = make();
    restarted.importState(state);
    EXPECT_EQ(restarted.wall(2).spec.axis, 2); // old states' walls are z planes
    dem::SystemState fixed = restarted.exportState();
    fixed.integers["walls.int"][4 * 2 + 3] = 1; // this test's third wall was a y wall
    restarted.importState(fixed);
    restarted.step(300);
    const dem::GrainData a = reference.grains(), b = restarted.grains();
    EXPECT_TRUE(a.position == b.position && a.velocity == b.velocity &&
                a.angularVelocity == b.angularVelocity);
    EXPECT_EQ(reference.wall(1).position, restarted.wall(1).position);
    EXPECT_EQ(reference.wall(1).grainForce, restarted.wall(1).grainForce);
}

DEM_TEST_ON_ALL_BACKENDS(WallAxes);
