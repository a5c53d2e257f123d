// CapsuleTestSupport.h
// Shared pieces of the capsule and contact-law tests run through dem::System: orientations,
// capsule mass and inertia (closed forms), the closed forms of the damped and of the clipped
// damped spring, and the measurement of an impact's contact duration and restitution from the
// read-back state.
#pragma once

#include "TestSupport.h"

#include <Eigen/Geometry>

#include <functional>

namespace demTest
{

//- (w, x, y, z) of a rotation by angle about a unit axis.
inline std::array<double, 4> rotation(const Eigen::Vector3d& axis, double angle)
{
    const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, axis.normalized()));
    return {q.w(), q.x(), q.y(), q.z()};
}

inline Eigen::Quaterniond orientationOf(const dem::GrainData& g, std::size_t i)
{
    return Eigen::Quaterniond(g.orientation[4 * i], g.orientation[4 * i + 1],
                              g.orientation[4 * i + 2], g.orientation[4 * i + 3]);
}

inline Eigen::Vector3d vectorOf(const std::vector<double>& v, std::size_t i)
{
    return Eigen::Vector3d(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
}

//- Half-axis vector a = h R(q) e_z of grain i.
inline Eigen::Vector3d halfAxisOf(const dem::GrainData& g, std::size_t i)
{
    return g.coreHalfLength[i] * (orientationOf(g, i) * Eigen::Vector3d::UnitZ());
}

//- A bonded pair's test system (BondSystemTest, BondPatchTest): soft unbonded contacts (never
//- used: the pair is bonded), a 4 cm box about the origin, dt 1e-6 s, bonds of Young's
//- modulus E with k_se/k_ne = 0.6.
inline dem::Parameters iceBondPairParameters(dem::Parameters p, double E)
{
    p.grainGrain = {1e4, 1e4, 0.0, 0.0, 0.5};
    p.grainWall = p.grainGrain;
    p.boxLower = {-0.02, -0.02};
    p.boxUpper = {0.02, 0.02};
    p.timeStep = 1e-6;
    p.bonds.enabled = true;
    p.bonds.youngsModulus = E;
    p.bonds.shearToNormalStiffness = 0.6;
    return p;
}

//- Capsule of radius r, core half-length h, density rho: mass and principal moments
//- (I_perp, I_axial); cylinder m_c = rho pi r^2 L and hemispheres m_h = rho 4/3 pi r^3, L = 2h.
struct CapsuleBody
{
    double mass, inertiaPerpendicular, inertiaAxial;
};

inline CapsuleBody capsuleBody(double r, double h, double rho)
{
    const double L = 2 * h, mc = rho * M_PI * r * r * L, mh = rho * 4.0 / 3.0 * M_PI * r * r * r;
    return {mc + mh, mc * (L * L / 12 + r * r / 4) + mh * (0.4 * r * r + L * L / 4 + 3 * L * r / 8),
            mc * r * r / 2 + 0.4 * mh * r * r};
}

struct ImpactMeasure
{
    double duration = 0, restitution = 0;
};

//- Linear spring-dashpot m* x'' = -k x - gamma x' (unclipped): duration pi / omega_d,
//- restitution exp(-zeta omega_0 pi / omega_d).
inline ImpactMeasure springDashpot(double reducedMass, double k, double gamma)
{
    const double omega0 = std::sqrt(k / reducedMass);
    const double zeta = gamma / (2 * std::sqrt(k * reducedMass));
    const double omegaD = omega0 * std::sqrt(1 - zeta * zeta);
    return {M_PI / omegaD, std::exp(-zeta * omega0 * M_PI / omegaD)};
}

//- Clipped spring-dashpot m* x'' = -max(0, k x + c x'), c = 2 zeta sqrt(k m*) (the snow law's
//- normal part): the force ends at omega_d t_f = pi - 2 arcsin(zeta) with restitution
//- exp(-zeta omega_0 t_f) (derived in SnowContactTest.cpp); the grains then fly apart
//- force-free and the overlap x(t_f) closes after x(t_f) / (e v0): that sum is the geometric
//- contact duration returned here.
inline ImpactMeasure clippedSpring(double reducedMass, double k, double zeta)
{
    const double omega0 = std::sqrt(k / reducedMass);
    const double omegaD = omega0 * std::sqrt(1 - zeta * zeta);
    const double tf = (M_PI - 2 * std::asin(zeta)) / omegaD;
    const double e = std::exp(-zeta * omega0 * tf);
    // x(t_f) / v0 = e^(-zeta omega_0 t_f) sin(omega_d t_f) / omega_d, divided by e.
    return {tf + std::sin(omegaD * tf) / omegaD, e};
}

//- Steps one at a time through an impact: contact from the first step with overlap > 0 to
//- the last, the crossing times interpolated linearly (O(dt^2)); restitution = -(approach
//- speed after) / (approach speed before).
inline ImpactMeasure measureImpact(dem::System& s,
                                   const std::function<double(const dem::GrainData&)>& overlap,
                                   const std::function<double(const dem::GrainData&)>& speed,
                                   int maxSteps = 200000)
{
    const double dt = s.timeStep(), approach = speed(s.grains());
    double previous = overlap(s.grains()), start = -1, end = -1;
    for (int step = 0; step < maxSteps && end < 0; ++step)
    {
        s.step(1);
        const double o = overlap(s.grains());
        if (previous <= 0 && o > 0)
            start = s.time() - dt * o / (o - previous);
        if (previous > 0 && o <= 0)
            end = s.time() - dt * o / (o - previous);
        previous = o;
    }
    EXPECT_GT(start, 0.0) << "no contact";
    EXPECT_GT(end, 0.0) << "the contact did not end";
    return {end - start, -speed(s.grains()) / approach};
}

} // namespace demTest
