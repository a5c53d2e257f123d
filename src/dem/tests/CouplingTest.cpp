// CouplingTest.cpp
// Grain -> grid deposit and grid -> grain fluid force (doc/EQUATIONS.md sections 6, 7):
//  - deposited solid volume equals sum V_g to round-off, in a periodic box and next to walls;
//  - a rigidly translating packing deposits exactly its velocity;
//  - the predicted porosity equals the porosity of the grains moved by v dt_f;
//  - a uniform force density f = -grad p gives F = -V grad p - rho_f V g on every grain;
//  - the fields are read where each grain is at setFluid and held over the DEM steps;
//  - drag: a uniform beta and u give F = V beta (u - v), and a lone grain relaxes to u as
//    exp(-beta t/rho_s) (the exact solution of m dv/dt = V beta (u - v));
//  - the grains' reaction deposited on the cells sums to minus their fluid forces (momentum
//    conservation), next to walls and across periodic sides;
//  - a wall inside the grid keeps a grain's deposit and fluid on its side: nothing is deposited
//    into cells beyond the wall, and the force is the cells' on the grain's side;
//  - the same with capsules mixed among the spheres (their true volume pi r^2 L + 4/3 pi r^3,
//    spread along the axis: kernels/VolumeSpread.h, its error in VolumeSpreadTest.cpp).
#include "TestSupport.h"
#include "kernels/VolumeSpread.h"

#include <numeric>
#include <random>

using namespace demTest;

namespace
{

class Coupling : public BackendTest
{
protected:
    const double box = 0.2, height = 0.15;

    dem::UniformGrid grid() const
    {
        dem::UniformGrid g;
        g.origin = {0, 0, 0};
        g.n = {5, 4, 6};
        g.spacing = {box / 5, box / 4, height / 6};
        g.periodic = {true, true, false};
        return g;
    }

    //- Random grains in [0, box)^2 x [zLow, zHigh], all with velocity u; with capsules, every
    //- second one a capsule of aspect ratio 1 to 4 (core up to 1.5 cells) in a random
    //- orientation.
    std::vector<dem::GrainInit> grains(int n, double zLow, double zHigh, const Vec3& u,
                                       bool capsules = false) const
    {
        std::mt19937 random(11);
        std::uniform_real_distribution<double> x(0.0, box), z(zLow, zHigh), r(0.004, 0.01),
            aspect(1.0, 4.0);
        std::normal_distribution<double> normal;
        std::vector<dem::GrainInit> out(n);
        for (std::size_t i = 0; i < out.size(); ++i)
        {
            dem::GrainInit& g = out[i];
            g.position = {x(random), x(random), z(random)};
            g.radius = r(random);
            g.velocity = {u[0], u[1], u[2]};
            if (capsules && i % 2 == 1)
            {
                g.coreHalfLength = (aspect(random) - 1.0) * g.radius;
                std::array<double, 4> q{normal(random), normal(random), normal(random),
                                        normal(random)};
                const double norm =
                    std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
                for (double& c : q)
                    c /= norm;
                g.orientation = q;
            }
        }
        return out;
    }

    void expectConserved(const std::vector<dem::GrainInit>& added, const char* where)
    {
        dem::Parameters p = parameters();
        p.boxUpper = {box, box};
        dem::System s(p);
        s.addGrains(added);
        const dem::UniformGrid g = grid();
        std::vector<double> solid(g.cellCount()), porosity(g.cellCount());
        s.deposit(g, 0.0, porosity.data(), nullptr, nullptr, solid.data());
        double grainVolume = 0;
        for (const dem::GrainInit& grain : added)
            grainVolume += trueVolume(grain);
        const double deposited = std::accumulate(solid.begin(), solid.end(), 0.0);
        double fromPorosity = 0;
        for (double phi : porosity)
            fromPorosity += (1.0 - phi) * g.cellVolume();
        std::printf("  %s: relative volume error %.2e (solid), %.2e (porosity)\n", where,
                    deposited / grainVolume - 1.0, fromPorosity / grainVolume - 1.0);
        EXPECT_NEAR(deposited / grainVolume, 1.0, 1e-13) << where;
        EXPECT_NEAR(fromPorosity / grainVolume, 1.0, 1e-12) << where;
    }

    //- pi r^2 L + 4/3 pi r^3 (a sphere: L = 0).
    static double trueVolume(const dem::GrainInit& g)
    {
        return M_PI * g.radius * g.radius * 2.0 * g.coreHalfLength + sphereVolume(g.radius);
    }
};

} // namespace

TEST_P(Coupling, DepositConservesSolidVolume)
{
    expectConserved(grains(300, 0.01, height - 0.01, {0, 0, 0}), "periodic box");
    expectConserved(grains(300, 0.0, 0.012, {0, 0, 0}), "next to the bottom wall");
    expectConserved(grains(300, height - 0.012, height, {0, 0, 0}), "next to the top wall");
}

TEST_P(Coupling, CapsulesDepositTheirTrueVolume)
{
    expectConserved(grains(300, 0.01, height - 0.01, {0, 0, 0}, true), "capsules, periodic box");
    expectConserved(grains(300, 0.0, 0.012, {0, 0, 0}, true), "capsules next to the bottom wall");
    expectConserved(grains(300, height - 0.012, height, {0, 0, 0}, true),
                    "capsules next to the top wall");
}

// The engine deposits a capsule from the points of its axis in its orientation: one capsule
// through dem::System gives the host evaluator's deposit of the same capsule (centre, half-axis
// h R(q) e_z) to round-off (CUDA: atomics in another order, a*b+c fused: 1e-14 of V).
TEST_P(Coupling, CapsuleDepositFollowsItsAxis)
{
    dem::Parameters p = parameters();
    p.boxUpper = {box, box};
    dem::GrainInit capsule;
    capsule.position = {0.003, 0.11, 0.07}; // across the periodic x side
    capsule.radius = 0.006;
    capsule.coreHalfLength = 0.03;
    const double angle = 0.7; // about (0, 1, 1) / sqrt(2)
    capsule.orientation = {std::cos(angle / 2), 0.0, std::sin(angle / 2) / std::sqrt(2.0),
                           std::sin(angle / 2) / std::sqrt(2.0)};
    dem::System s(p);
    s.addGrains({capsule});
    const dem::UniformGrid g = grid();
    std::vector<double> solid(g.cellCount());
    s.deposit(g, 0.0, nullptr, nullptr, nullptr, solid.data());

    namespace k = dem::detail;
    k::GridView view;
    for (int d = 0; d < 3; ++d)
    {
        view.origin[d] = g.origin[d];
        view.spacing[d] = g.spacing[d];
        view.n[d] = g.n[d];
        view.periodic[d] = g.periodic[d];
    }
    const std::array<double, 4>& q = capsule.orientation;
    const k::Vector3d x(capsule.position[0], capsule.position[1], capsule.position[2]),
        a = k::halfAxisOf(capsule.coreHalfLength, q[0], q[1], q[2], q[3]);
    std::vector<double> expected(g.cellCount(), 0.0);
    k::forEachSpreadPoint(x, a, capsule.radius,
                          k::grainVolume(capsule.radius, capsule.coreHalfLength),
                          k::spreadCylinderPoints(view, a),
                          [&](const k::Vector3d& point, double volume)
                          {
                              const k::TrilinearStencil st = k::trilinearStencil(view, point);
                              for (int c = 0; c < 8; ++c)
                                  expected[st.cell[c]] += st.weight[c] * volume;
                          });
    double difference = 0, cellsHit = 0;
    for (std::size_t c = 0; c < g.cellCount(); ++c)
    {
        difference += std::fabs(solid[c] - expected[c]);
        cellsHit += solid[c] > 0.0;
    }
    const double volume = trueVolume(capsule);
    std::printf("  %g cells hit, sum |engine - evaluator| = %.2e V\n", cellsHit,
                difference / volume);
    EXPECT_LT(difference, 1e-14 * volume);
    EXPECT_GT(cellsHit, 8); // spread over more than one point's stencil
}

TEST_P(Coupling, TranslatingPackingDepositsItsVelocity)
{
    const Vec3 u = {0.3, -0.2, 0.05};
    dem::Parameters p = parameters();
    p.boxUpper = {box, box};
    for (bool capsules : {false, true})
    {
        dem::System s(p);
        s.addGrains(grains(300, 0.0, height, u, capsules));
        const dem::UniformGrid g = grid();
        std::vector<double> velocity(3 * g.cellCount()), solid(g.cellCount());
        s.deposit(g, 0.0, nullptr, nullptr, velocity.data(), solid.data());
        double worst = 0;
        for (std::size_t c = 0; c < g.cellCount(); ++c)
        {
            ASSERT_GT(solid[c], 0.0);
            for (int d = 0; d < 3; ++d)
                worst = std::max(worst, std::fabs(velocity[3 * c + d] / u[d] - 1.0));
        }
        std::printf("  %s: max relative error of the mean velocity %.2e\n",
                    capsules ? "spheres and capsules" : "spheres", worst);
        EXPECT_LT(worst, 1e-13) << (capsules ? "with capsules" : "spheres");
    }
}

// Capsules: the prediction moves the axis by v dt_f without turning it (as documented).
TEST_P(Coupling, PredictedPorosityUsesProjectedPositions)
{
    const Vec3 u = {0.3, -0.2, 0.05};
    const double dtFluid = 0.02;
    dem::Parameters p = parameters();
    p.boxUpper = {box, box};
    for (bool capsules : {false, true})
    {
        const std::vector<dem::GrainInit> now = grains(300, 0.01, height - 0.02, u, capsules);
        std::vector<dem::GrainInit> later = now;
        for (dem::GrainInit& grain : later)
            for (int d = 0; d < 3; ++d)
                grain.position[d] += u[d] * dtFluid;
        dem::System a(p), b(p);
        a.addGrains(now);
        b.addGrains(later);
        const dem::UniformGrid g = grid();
        std::vector<double> predicted(g.cellCount()), moved(g.cellCount()), current(g.cellCount());
        a.deposit(g, dtFluid, current.data(), predicted.data(), nullptr);
        b.deposit(g, 0.0, moved.data(), nullptr, nullptr);
        double worst = 0, change = 0;
        for (std::size_t c = 0; c < g.cellCount(); ++c)
        {
            worst = std::max(worst, std::fabs(predicted[c] - moved[c]));
            change = std::max(change, std::fabs(predicted[c] - current[c]));
        }
        std::printf("  %s: max |phi_pred - phi(x + v dt)| = %.2e (porosity change %.2e)\n",
                    capsules ? "spheres and capsules" : "spheres", worst, change);
        EXPECT_LT(worst, 1e-13);
        EXPECT_GT(change, 1e-3);
    }
}

// With capsules: f = -V grad p - rho_f V g with the true volume pi r^2 L + 4/3 pi r^3, both in
// the step (the force read back after it) and in the fluid-force read-back.
TEST_P(Coupling, UniformPressureGradientAndBuoyancy)
{
    dem::Parameters p = parameters();
    p.boxUpper = {box, box};
    p.gravity = {0, 0, -9.81};
    for (bool capsules : {false, true})
    {
        dem::System s(p);
        std::vector<dem::GrainInit> lattice = grains(50, 0, 0, {0, 0, 0}, capsules); // radii vary
        for (std::size_t i = 0; i < lattice.size(); ++i) // apart: no contacts
        {
            lattice[i].position = {0.02 + 0.04 * (i % 5), 0.02 + 0.04 * (i / 5 % 5),
                                   0.03 + 0.05 * (i / 25)};
            lattice[i].coreHalfLength = capsules && i % 2 ? 0.8 * lattice[i].radius : 0.0;
        }
        s.addGrains(lattice);
        const dem::UniformGrid g = grid();
        const Vec3 gradP = {1e3, -2e3, 5e3};
        const double rhoFluid = 1000.0;
        std::vector<double> field(3 * g.cellCount());
        for (std::size_t c = 0; c < g.cellCount(); ++c)
            for (int d = 0; d < 3; ++d)
                field[3 * c + d] = -gradP[d];
        dem::FluidFields fluid;
        fluid.forceDensity = field.data();
        fluid.buoyancyDensity = rhoFluid;
        s.setFluid(g, fluid);
        s.step(1);
        const dem::GrainData out = s.grains();
        double worst = 0, worstReadBack = 0;
        for (std::size_t i = 0; i < out.radius.size(); ++i)
        {
            const double volume = trueVolume(lattice[i]);
            for (int d = 0; d < 3; ++d)
            {
                const double fluid = -volume * gradP[d] - rhoFluid * volume * p.gravity[d];
                const double expected = out.mass[i] * p.gravity[d] + fluid;
                worst = std::max(worst,
                                 std::fabs(out.force[3 * i + d] - expected) / std::fabs(expected));
                worstReadBack = std::max(
                    worstReadBack, std::fabs(out.fluidForce[3 * i + d] - fluid) / std::fabs(fluid));
            }
        }
        std::printf("  %s: max relative force error %.2e, fluid force read-back %.2e\n",
                    capsules ? "spheres and capsules" : "spheres", worst, worstReadBack);
        // A few roundings of terms of one size: 1e-12
        EXPECT_LT(worst, 1e-12);
        EXPECT_LT(worstReadBack, 1e-12);
        s.clearFluid();
        s.step(1);
        EXPECT_NEAR(s.grains().force[2], out.mass[0] * p.gravity[2], 1e-12);
    }
}

// Walls inside the grid (a distributor above the inlet, a lid below the mesh's top): each
// deposit point is kept half a cell inside the walls, so no grain volume reaches cells beyond
// the wall it sits on (doc/EQUATIONS.md 6). A lower wall on a cell face (z = 2 dz) with a
// grain 0.2 dz above it: without this, 0.3 of its volume would be in the layer below the wall;
// with it the grain's layer holds all (the mirror the grid applies at its own sides). An
// upper wall inside a cell (z = 4.4 dz) with a grain 0.3 dz below it: nothing above the wall's
// cell. A force density that is f_in on the grains' side and 1000 f_in beyond: the grains feel
// V f_in, and the reaction (per cell volume) is deposited only on their side and sums to minus
// their forces.
TEST_P(Coupling, WallsInsideTheGridKeepDepositAndFluidOnTheGrainsSide)
{
    dem::Parameters p = parameters();
    p.boxUpper = {box, box};
    p.gravity = {0, 0, 0};
    const dem::UniformGrid g = grid();
    const double dz = g.spacing[2];
    dem::System s(p);
    dem::WallSpec floor, lid;
    floor.position = 2.0 * dz;
    lid.side = dem::WallSpec::Side::upper;
    lid.position = 4.4 * dz;
    s.addWall(floor);
    s.addWall(lid);
    dem::GrainInit low, high;
    low.radius = high.radius = 0.004;
    low.position = {0.5 * g.spacing[0], 0.5 * g.spacing[1], 2.2 * dz};
    high.position = {2.5 * g.spacing[0], 1.5 * g.spacing[1], 4.1 * dz};
    s.addGrains({low, high});
    const long layer = long(g.n[0]) * g.n[1];
    std::vector<double> solid(g.cellCount()), porosity(g.cellCount());
    s.deposit(g, 0.0, porosity.data(), nullptr, nullptr, solid.data());
    const double volume = sphereVolume(low.radius);
    auto layerSum = [&](const std::vector<double>& v, int k)
    {
        double sum = 0;
        for (long c = k * layer; c < (k + 1) * layer; ++c)
            sum += v[c];
        return sum;
    };
    std::printf("  solid per z layer / V:");
    for (int k = 0; k < g.n[2]; ++k)
        std::printf(" %.6f", layerSum(solid, k) / volume);
    std::printf("\n");
    EXPECT_EQ(layerSum(solid, 0) + layerSum(solid, 1), 0.0); // beyond the floor
    EXPECT_NEAR(layerSum(solid, 2) / volume, 1.0, 1e-14);    // the low grain, all of it
    EXPECT_EQ(layerSum(solid, 5), 0.0);                      // beyond the lid's cell
    // The high grain's point held at 4.4 dz - dz/2 = 3.9 dz: 0.6 of it in layer 3, 0.4 in 4
    EXPECT_NEAR(layerSum(solid, 3) / volume, 0.6, 1e-12);
    EXPECT_NEAR(layerSum(solid, 4) / volume, 0.4, 1e-12);

    const double fIn = 2e3;
    std::vector<double> field(3 * g.cellCount(), 0.0);
    for (long c = 0; c < long(g.cellCount()); ++c)
    {
        const int k = int(c / layer);
        field[3 * c + 2] = (k >= 2 && k <= 4 ? 1.0 : 1e3) * fIn;
    }
    dem::FluidFields fluid;
    fluid.forceDensity = field.data();
    s.setFluid(g, fluid);
    const dem::GrainData out = s.grains();
    std::vector<double> reaction(3 * g.cellCount());
    s.depositFluidReaction(g, reaction.data());
    double reactionBeyond = 0, reactionSum = 0;
    for (long c = 0; c < long(g.cellCount()); ++c)
    {
        const int k = int(c / layer);
        reactionSum += reaction[3 * c + 2];
        if (k < 2 || k > 4)
            reactionBeyond += std::fabs(reaction[3 * c + 2]);
    }
    for (int i = 0; i < 2; ++i)
    {
        std::printf("  grain %d: fluid force / (V f_in) = %.15f\n", i,
                    out.fluidForce[3 * i + 2] / (volume * fIn));
        EXPECT_NEAR(out.fluidForce[3 * i + 2] / (volume * fIn), 1.0, 1e-13);
    }
    EXPECT_EQ(reactionBeyond, 0.0);
    EXPECT_NEAR(reactionSum * g.cellVolume() / (-2.0 * volume * fIn), 1.0, 1e-13);

    // Asked to cross the walls (UniformGrid::depositInsideWalls false): the plain trilinear
    // weights, 0.3 of the low grain below the floor's face
    dem::UniformGrid across = g;
    across.depositInsideWalls = false;
    s.deposit(across, 0.0, porosity.data(), nullptr, nullptr, solid.data());
    EXPECT_NEAR(layerSum(solid, 1) / volume, 0.3, 1e-12);
    EXPECT_NEAR(layerSum(solid, 2) / volume, 0.7, 1e-12);
}

// The fields are read where a grain is when they are handed over (setFluid) and held over the
// fluid step's DEM steps (doc/EQUATIONS.md 7): a grain crossing a field that varies along z keeps
// the force of its start until the next setFluid, which takes the force of its new place; a grain
// added after setFluid feels the fluid too. f = a + b z is linear inside the cells, so the
// trilinear value is exact: the force is V (a + b z) to round-off.
TEST_P(Coupling, FluidLoadIsTakenWhereTheGrainIsWhenTheFieldsAreSet)
{
    dem::Parameters p = parameters();
    p.boxUpper = {box, box};
    p.gravity = {0, 0, 0};
    dem::System s(p);
    dem::GrainInit grain;
    grain.position = {0.1, 0.1, 0.04};
    grain.radius = 0.004;
    grain.velocity = {0, 0, 10.0}; // 1e-5 m per step with the tests' dt of 1e-6 s
    s.addGrain(grain);
    const dem::UniformGrid g = grid();
    const double a = 50.0, b = 2e4; // N/m^3 and N/m^4
    std::vector<double> field(3 * g.cellCount(), 0.0);
    for (int k = 0; k < g.n[2]; ++k)
        for (int j = 0; j < g.n[1]; ++j)
            for (int i = 0; i < g.n[0]; ++i)
                field[3 * (i + g.n[0] * (j + g.n[1] * k)) + 2] = a + b * (k + 0.5) * g.spacing[2];
    dem::FluidFields fluid;
    fluid.forceDensity = field.data();
    s.setFluid(g, fluid);
    const double volume = 4.0 / 3.0 * M_PI * std::pow(grain.radius, 3);
    const auto forceAt = [&](double z) { return volume * (a + b * z); };
    const int steps = 1000; // 1 cm of the 2.5-cm cells: the field at the grain changes by 40 %
    s.step(steps);
    const dem::GrainData held = s.grains();
    const double z = held.position[2], m = held.mass[0];
    EXPECT_GT(z - grain.position[2], 0.009);
    // held: the force of the start; its velocity gained F dt/m per step
    EXPECT_NEAR(held.fluidForce[2], forceAt(grain.position[2]), 1e-12 * forceAt(z));
    EXPECT_NEAR(held.velocity[2], 10.0 + forceAt(grain.position[2]) * steps * p.timeStep / m, 1e-9);
    s.setFluid(g, fluid); // the next fluid step: the force where the grain is now
    EXPECT_NEAR(s.grains().fluidForce[2], forceAt(z), 1e-12 * forceAt(z));
    grain.position = {0.05, 0.05, 0.11};
    s.addGrain(grain); // after setFluid
    EXPECT_NEAR(s.grains().fluidForce[5], forceAt(0.11), 1e-12 * forceAt(0.11));
}

TEST_P(Coupling, DragRelaxesAGrainToTheFluidVelocity)
{
    // One sphere, no gravity, in a uniform flow u with drag coefficient beta per unit grain
    // volume: m dv/dt = V beta (u - v), so v(t) = u + (v0 - u) exp(-beta t/rho_s). The step
    // (Verlet, drag at the packed velocity) is first order in dt beta/rho_s; with
    // beta dt/rho_s = 1e-3 the error after one relaxation time is below 1e-3 of |v0 - u|.
    dem::Parameters p = parameters();
    p.boxUpper = {box, box};
    p.gravity = {0, 0, 0};
    dem::System s(p);
    dem::GrainInit grain;
    grain.position = {0.1, 0.1, 0.07};
    grain.radius = 0.005;
    grain.density = 2600;
    grain.velocity = {0, 0, 0};
    s.addGrain(grain);
    const dem::UniformGrid g = grid();
    const Vec3 u = {0.02, -0.01, 0.005};
    const double beta = 1e-3 * grain.density / p.timeStep; // beta dt/rho_s = 1e-3
    std::vector<double> force(3 * g.cellCount(), 0.0), drag(g.cellCount(), beta),
        velocity(3 * g.cellCount());
    for (std::size_t c = 0; c < g.cellCount(); ++c)
        for (int d = 0; d < 3; ++d)
            velocity[3 * c + d] = u[d];
    dem::FluidFields fluid;
    fluid.forceDensity = force.data();
    fluid.dragCoefficient = drag.data();
    fluid.velocity = velocity.data();
    s.setFluid(g, fluid);
    const int steps = 1000; // one relaxation time rho_s/beta
    s.step(steps);
    const dem::GrainData out = s.grains();
    const double decay = std::exp(-beta * steps * p.timeStep / grain.density);
    double worst = 0;
    for (int d = 0; d < 3; ++d)
        worst = std::max(worst, std::fabs(out.velocity[d] - u[d] * (1.0 - decay)));
    const double speed = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    std::printf("  drag: |v - v_exact| = %.2e of |u| after one relaxation time\n", worst / speed);
    EXPECT_LT(worst, 1e-3 * speed);
    // The read-back is the force of the next step: V beta (u - v)
    const double volume = 4.0 / 3.0 * M_PI * grain.radius * grain.radius * grain.radius;
    for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(out.fluidForce[d], volume * beta * (u[d] - out.velocity[d]),
                    1e-12 * volume * beta * speed);
}

TEST_P(Coupling, ReactionConservesMomentum)
{
    // Grains anywhere (at the walls, across the periodic sides), capsules among them, in a
    // non-uniform force density with drag: sum_c reaction_c V_cell = -sum_g F_g.
    dem::Parameters p = parameters();
    p.boxUpper = {box, box};
    p.gravity = {0, 0, -9.81};
    for (bool capsules : {false, true})
    {
        dem::System s(p);
        s.addGrains(grains(60, 0.0, height, {0.01, 0.0, -0.02}, capsules));
        const dem::UniformGrid g = grid();
        std::vector<double> force(3 * g.cellCount()), drag(g.cellCount()),
            velocity(3 * g.cellCount());
        for (std::size_t c = 0; c < g.cellCount(); ++c)
        {
            drag[c] = 1e4 * (1.0 + 0.1 * double(c % 7));
            for (int d = 0; d < 3; ++d)
            {
                force[3 * c + d] = 1e3 * std::sin(0.7 * double(c) + d);
                velocity[3 * c + d] = 0.01 * std::cos(0.3 * double(c) - d);
            }
        }
        dem::FluidFields fluid;
        fluid.forceDensity = force.data();
        fluid.dragCoefficient = drag.data();
        fluid.velocity = velocity.data();
        fluid.buoyancyDensity = 1000.0;
        s.setFluid(g, fluid);
        std::vector<double> reaction(3 * g.cellCount());
        s.depositFluidReaction(g, reaction.data());
        const dem::GrainData out = s.grains();
        double worst = 0;
        for (int d = 0; d < 3; ++d)
        {
            double onGrains = 0, onCells = 0, scale = 0;
            for (std::size_t i = 0; i < out.radius.size(); ++i)
            {
                onGrains += out.fluidForce[3 * i + d];
                scale += std::fabs(out.fluidForce[3 * i + d]);
            }
            for (std::size_t c = 0; c < g.cellCount(); ++c)
                onCells += reaction[3 * c + d] * g.cellVolume();
            worst = std::max(worst, std::fabs(onGrains + onCells) / scale);
        }
        std::printf("  %s: |sum reaction V_cell + sum F| = %.2e of sum |F|\n",
                    capsules ? "spheres and capsules" : "spheres", worst);
        // Round-off of sums of 60 grains x 8 cells: 1e-12
        EXPECT_LT(worst, 1e-12);
        s.clearFluid();
        s.depositFluidReaction(g, reaction.data());
        EXPECT_EQ(*std::max_element(reaction.begin(), reaction.end()), 0.0);
        EXPECT_EQ(*std::min_element(reaction.begin(), reaction.end()), 0.0);
    }
}

DEM_TEST_ON_ALL_BACKENDS(Coupling);
