// dem/Parameters.h
// Plain parameter structs of the DEM library (no CUDA, Thrust or Eigen types): contact material,
// periodic box, walls, grains and the System's construction parameters. SI units throughout.
#pragma once

#include <array>
#include <cstdint>

namespace dem
{

//- Which implementation runs the kernels. automatic: CUDA when a device answers, else CPU.
enum class Backend
{
    automatic,
    cpu,
    cuda
};

//- How a grain moves.
enum class GrainFlag : std::int32_t
{
    free = 0,               //!< translation and rotation from forces
    fixed = 1,              //!< v = omega = 0 for ever
    prescribedVelocity = 2, //!< vx, vy prescribed, no rotation, free along z
    translationOnly = 3     //!< free translation, no rotation (sliding blocks, tests)
};

//- The contact laws (a run-time family; doc/EQUATIONS.md section 1 and the snow section).
enum class ContactLaw
{
    linearSpring, //!< linear spring-dashpot, Coulomb friction (Damsgaard et al. 2015)
    snow          //!< unfrozen ice contact of Johnson & Hopkins (2005): k_n from E and the radii
};

//- A contact law and its constants. linearSpring uses the stiffnesses and dampings given here;
//- snow derives them per pair: k_n = E pi Rbar / 2 (Rbar the mean radius; a wall counts as the
//- grain's radius), k_t = tangentialToNormalStiffness k_n, dashpots as fractions of critical
//- damping for the pair's reduced mass; its normal force never pulls.
struct ContactMaterial
{
    double normalStiffness = 1.16e9;     //!< k_n [N/m]
    double tangentialStiffness = 1.16e9; //!< k_t [N/m]
    double normalDamping = 0.0;          //!< gamma_n [N s/m], force -gamma_n * approach speed
    double tangentialDamping = 0.0;      //!< gamma_t [N s/m]
    double friction = 0.5;               //!< mu, |f_t| <= mu |f_n|
    ContactLaw law = ContactLaw::linearSpring;
    // snow only:
    double youngsModulus = 0.0;               //!< E [Pa]
    double tangentialToNormalStiffness = 0.6; //!< k_t / k_n
    double normalDampingRatio = 0.0;          //!< c_n / (2 sqrt(m* k_n))
    double tangentialDampingRatio = 0.0;      //!< c_t / (2 sqrt(m* k_t))
};

//- A plane z = position bounding the grains from below (lower) or above (upper).
struct WallSpec
{
    enum class Side
    {
        lower, //!< normal +z, grains above it
        upper  //!< normal -z, grains below it
    };
    enum class Mode
    {
        fixed,    //!< never moves
        velocity, //!< moves with the prescribed velocity along z
        stress    //!< mass m under normal stress sigma0 over the box area (upper walls push down)
    };
    Side side = Side::lower;
    Mode mode = Mode::fixed;
    double position = 0.0;     //!< z of the plane [m]
    double velocity = 0.0;     //!< initial (stress) or prescribed (velocity) z-velocity [m/s]
    double mass = 0.0;         //!< stress mode: wall mass [kg]
    double normalStress = 0.0; //!< stress mode: sigma0 [Pa], pressing the wall onto the grains
    bool frictional = true;    //!< false: frictionless wall (no tangential force)
};

//- The System's construction parameters.
struct Parameters
{
    ContactMaterial grainGrain;
    ContactMaterial grainWall;
    double defaultDensity = 2600.0;                 //!< used when a grain gives density <= 0
    std::array<double, 3> gravity{0.0, 0.0, -9.81}; //!< [m/s^2]
    //- Box: x in [lower[0], upper[0]), y in [lower[1], upper[1]); z unbounded except by walls.
    std::array<double, 2> boxLower{0.0, 0.0};
    std::array<double, 2> boxUpper{1.0, 1.0};
    std::array<bool, 2> periodic{true, true}; //!< periodic in x and y
    double timeStep = 1e-7;                   //!< DEM step [s]
    double neighbourSkin = 0.0; //!< Verlet skin [m]; rebuild when a grain moved skin/2
    //- Refuse timeStep > maxTimeStepFraction * sqrt(m_min / k_max) (see criticalTimeStep()).
    double maxTimeStepFraction = 0.2;
    double viscousDrag = 0.0; //!< global drag force -c v on every grain [N s/m]
    Backend backend = Backend::automatic;
    int threads = 0; //!< CPU backend threads; 0: OpenMP default (OMP_NUM_THREADS)
    //- Contact (neighbour-pair) storage limit per grain; 0 = grow without limit. Exceeding a
    //- set limit throws dem::Error; storage never drops a pair silently.
    int maxPairsPerGrain = 0;
};

//- One grain to add: a sphere, or a capsule (a core segment of length 2 coreHalfLength along
//- the body z axis, dilated by radius). Spheres and capsules mix freely in one System.
struct GrainInit
{
    std::array<double, 3> position{0.0, 0.0, 0.0}; //!< centre (the core segment's midpoint)
    double radius = 0.01;
    double coreHalfLength = 0.0; //!< half the core segment's length [m]; 0: a sphere
    //- Body-to-global rotation as a unit quaternion (w, x, y, z); the capsule axis is
    //- rotate(orientation, (0, 0, 1)). Normalised when added (refused far from unit length).
    std::array<double, 4> orientation{1.0, 0.0, 0.0, 0.0};
    double density = 0.0; //!< <= 0: Parameters::defaultDensity
    std::array<double, 3> velocity{0.0, 0.0, 0.0};
    std::array<double, 3> angularVelocity{0.0, 0.0, 0.0};
    GrainFlag flag = GrainFlag::free;
};

} // namespace dem
