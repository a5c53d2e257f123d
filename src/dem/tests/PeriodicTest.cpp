// PeriodicTest.cpp
// An oblique, spinning impact of a pair that drifts across the periodic x seam, the y seam or
// the xy corner during the contact gives the same forces as the same pair in the interior.
// The skin is 0, so the neighbour list is rebuilt (and grains re-sorted and wrapped) every
// step: the tangential history must survive rebuilds and wrapping.
#include "TestSupport.h"

#include <vector>

using namespace demTest;

namespace
{

class Periodic : public BackendTest
{
protected:
    //- Force history on grain 0 of a pair whose contact point starts at `centre`.
    std::vector<Vec3> forces(const Vec3& centre, std::size_t* rebuilds, double skin = 0.0)
    {
        dem::Parameters p = parameters();
        p.neighbourSkin = skin;
        p.boxUpper = {0.2, 0.2};
        p.timeStep = 2e-7;
        dem::System s(p);
        const double r = 0.01;
        const Vec3 drift = {40.0, 30.0, 0.0}; // crosses 1 cm seams during the contact
        dem::GrainInit a, b;
        a.radius = b.radius = r;
        a.position = {centre[0] - 0.8 * r, centre[1] - 0.6 * r, centre[2]};
        b.position = {centre[0] + 0.8 * r + 1e-6, centre[1] + 0.6 * r + 0.75e-6, centre[2]};
        a.velocity = {drift[0] + 0.1, drift[1] + 0.05, 0.02};
        b.velocity = {drift[0] - 0.1, drift[1] - 0.05, -0.02};
        a.angularVelocity = {0, 0, 20.0};
        b.angularVelocity = {5.0, 0, -10.0};
        for (auto* g : {&a, &b})
            for (int d = 0; d < 2; ++d) // start inside the box
                g->position[d] -= std::floor(g->position[d] / 0.2) * 0.2;
        s.addGrains({a, b});
        std::vector<Vec3> out;
        for (int step = 0; step < 1500; ++step)
        {
            s.step(1);
            const dem::GrainData g = s.grains();
            out.push_back(at(g.force, 0));
            for (int i = 0; i < 2; ++i) // read back inside the box, also between rebuilds
                for (int d = 0; d < 2; ++d)
                {
                    EXPECT_GE(g.position[3 * i + d], 0.0);
                    EXPECT_LT(g.position[3 * i + d], 0.2);
                }
        }
        *rebuilds = s.neighbourRebuildCount();
        return out;
    }
};

} // namespace

TEST_P(Periodic, SeamsGiveInteriorForces)
{
    std::size_t rebuilds = 0;
    const std::vector<Vec3> interior = forces({0.1, 0.1, 0.5}, &rebuilds);
    double peak = 0;
    for (const Vec3& f : interior)
        peak = std::max(peak, norm(f));
    ASSERT_GT(peak, 1.0);
    // History must survive the rebuilds: compare with a run that never rebuilds.
    std::size_t noRebuilds = 0;
    const std::vector<Vec3> kept = forces({0.1, 0.1, 0.5}, &noRebuilds, 0.05);
    double keptWorst = 0;
    for (std::size_t k = 0; k < interior.size(); ++k)
        keptWorst = std::max(keptWorst, norm(sub(kept[k], interior[k])));
    std::printf("  rebuilt every step vs %zu rebuild(s): max |dF| / peak |F| = %.2e\n", noRebuilds,
                keptWorst / peak);
    EXPECT_LE(noRebuilds, 2u);
    EXPECT_LT(keptWorst / peak, 1e-9);
    const std::vector<std::pair<const char*, Vec3>> cases = {{"x seam", {0.195, 0.1, 0.5}},
                                                             {"y seam", {0.1, 0.196, 0.5}},
                                                             {"corner", {0.196, 0.197, 0.5}}};
    for (const auto& [name, centre] : cases)
    {
        const std::vector<Vec3> seam = forces(centre, &rebuilds);
        double worst = 0, tangential = 0;
        for (std::size_t k = 0; k < interior.size(); ++k)
        {
            worst = std::max(worst, norm(sub(seam[k], interior[k])));
            tangential = std::max(tangential, std::fabs(interior[k][2]));
        }
        std::printf("  %s: max |dF| / peak |F| = %.2e over %zu steps, %zu rebuilds\n", name,
                    worst / peak, interior.size(), rebuilds);
        EXPECT_LT(worst / peak, 1e-6) << name;
        EXPECT_GT(tangential, 0.01 * peak) << "the pair must carry tangential force";
        EXPECT_GE(rebuilds, interior.size());
    }
}

DEM_TEST_ON_ALL_BACKENDS(Periodic);
