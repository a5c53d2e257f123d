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
    translationOnly = 3,    //!< free translation, no rotation (sliding blocks, tests)
    //- moves with its velocity and angular velocity for ever, whatever the loads (a driven
    //- grain: bond and contact tests, kinematic boundaries); capsules turn at that omega.
    //- Set them with System::setGrainVelocities.
    driven = 4
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

//- An axis-aligned plane x[axis] = position bounding the grains from below (lower: normal
//- +e_axis, grains on its + side) or above (upper: normal -e_axis). It moves along its axis.
struct WallSpec
{
    enum class Side
    {
        lower, //!< normal +e_axis, grains on its + side
        upper  //!< normal -e_axis, grains on its - side
    };
    enum class Mode
    {
        fixed,    //!< never moves
        velocity, //!< moves with the prescribed velocity along its axis
        //- mass m under normal stress sigma0 pressing it onto the grains, over its area: z walls
        //- the box's x-y area; x (y) walls the box's y (x) length times the current gap
        //- between the z walls (refused without a lower and an upper z wall)
        stress,
        //- mass m moved by the grains' force and its own weight m g[axis] (the free lid of
        //- Johnson & Hopkins 2005); follows a gravity ramp (System::setGravity)
        free
    };
    Side side = Side::lower;
    Mode mode = Mode::fixed;
    int axis = 2;              //!< 0: an x plane, 1: y, 2: z
    double position = 0.0;     //!< the plane's coordinate along its axis [m]
    double velocity = 0.0;     //!< initial (stress, free) or prescribed (velocity) [m/s]
    double mass = 0.0;         //!< stress and free modes: wall mass [kg]
    double normalStress = 0.0; //!< stress mode: sigma0 [Pa], pressing the wall onto the grains
    bool frictional = true;    //!< false: frictionless wall (no tangential force)
};

//- Models of each bond mechanism (Johnson & Hopkins 2005; doc/EQUATIONS.md, bonds). Each
//- mechanism is a family: none switches it off; a new model is a value here, its evaluator in
//- src/kernels/bonds/ and a branch in BondLaw.
enum class BondCreep
{
    none,
    maxwell //!< grain-boundary creep: shear, twist, bend relax as Maxwell elements (Newtonian)
};
enum class BondCompressiveCreep
{
    none,
    powerLaw //!< normal creep rate 2 Rbar A0 exp(-Q / (R_g T_K)) |sigma_n|^n, both signs
};
enum class BondStrength
{
    none,           //!< bonds never break
    iceTemperature, //!< sigma_ice[MPa] = 0.99648 - 0.045904 T[C] (tension and shear), scaled
    constant        //!< tensileStrength, shearStrength as given
};
enum class BondSintering
{
    none,
    pressureSintering //!< dr_b/dt = (R*/m) (r_b/R*)^(1-m) A(T) sigma_c^3, sigma_c = compressive N/A
};
enum class BondFormation
{
    none,           //!< only bonds added with System::addBonds
    frozenOnContact //!< every touching unbonded pair freezes: r_b^2 uniform in areaFraction r^2
};

//- Where a bond sits and which way it faces (src/kernels/bonds/BondGeometry.h).
enum class BondPoint
{
    closestPoints,   //!< the cores' closest points, taken afresh every step
    bodyFixedPatches //!< the paper's: patch centres held in the grains' body frames, moved by
                     //!< creep; the normal between the cores at the bond's point
};

//- Bonds (frozen ice contacts): a store separate from the neighbour list. Off by default.
struct BondParameters
{
    bool enabled = false; //!< false: no bond store, no bond cost, addBonds refused
    // elastic patch: k_ne = E / (2 Rbar) per unit area; A = pi r_b^2, I = pi r_b^4 / 4, J = 2 I
    double youngsModulus = 0.0;          //!< E [Pa] (> 0 when enabled)
    double shearToNormalStiffness = 0.6; //!< k_se / k_ne
    double normalDampingRatio = 0.0;     //!< dashpot on N, fraction of critical (reduced mass)
    double shearDampingRatio = 0.0;      //!< dashpot on S, fraction of critical
    double temperature = -10.0;          //!< T [degrees C] (strength, creep, sintering)
    BondPoint point = BondPoint::closestPoints; //!< where the bond sits
    // grain-boundary creep: tau_shear = tau_twist = nu_s / (0.6 E), tau_bend = nu_s / E
    BondCreep creep = BondCreep::none;
    double contactViscosity = 0.0;                               //!< nu_s [Pa s] (> 0 with maxwell)
    bool shearCreep = true, twistCreep = true, bendCreep = true; //!< each mechanism on/off
    // normal power-law creep (the paper's ice constants as defaults); A0 and Q also set the
    // sintering rate A(T) sigma^3
    BondCompressiveCreep compressiveCreep = BondCompressiveCreep::none;
    double creepPrefactor = 0.00554458;    //!< A0 [s^-1 Pa^-n] (the paper's, for n = 3)
    double creepActivationEnergy = 70.0e3; //!< Q [J/mol]
    double creepExponent = 3.0;            //!< n of the creep law (> 1), the one A0's units hold
    // strength and strain-softening fracture (r_b shrinks; broken below brokenFraction Rbar)
    BondStrength strength = BondStrength::none;
    double strengthScale = 1.0;   //!< iceTemperature: multiplies sigma_ice (scaled runs)
    double tensileStrength = 0.0; //!< constant [Pa]
    double shearStrength = 0.0;   //!< constant [Pa]
    double softeningRatio = 1.0;  //!< k_2 / k_1, slope of the softening branch over the elastic
    double brokenFraction = 0.05; //!< broken when r_b < brokenFraction Rbar
    // sintering
    BondSintering sintering = BondSintering::none;
    // formation
    BondFormation formation = BondFormation::none;
    std::array<double, 2> areaFraction{0.03125, 0.09375}; //!< r_b^2 / r_min^2 range (uniform)
    int formationInterval = 1; //!< steps between freezing checks (the contact law acts between)
    std::uint64_t seed = 1;    //!< new bonds' r_b: hash of (seed, grain ids), no thread effect
};

//- How a System is split over the ranks of MPI_COMM_WORLD: a regular grid of ranks[0] x ranks[1]
//- boxes over the box's x-y extent (boxLower..boxUpper, equal widths; a non-periodic side's
//- outer boxes reach to infinity). Each rank owns the grains whose centres lie in its box and
//- holds copies (ghosts) of the others' grains within 2 b_max + neighbourSkin of it
//- (src/dem/README.md, "Decomposition over MPI ranks"). 1 x 1: one process, no MPI call.
struct Decomposition
{
    std::array<int, 2> ranks{1, 1};
    int rankCount() const { return ranks[0] * ranks[1]; }
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
    //- A periodic side's length changes at this constant rate [m/s] (0: a fixed box; periodic
    //- sides only, one process): the upper side moves, so that the length at System time t is
    //- boxUpper - boxLower + boxLengthRate (t - boxTime). Space contracts (< 0) or stretches
    //- as in a deforming periodic cell: each grain meets its neighbours' images across the side
    //- moving with their own velocity plus the rate per image (src/dem/README.md).
    std::array<double, 2> boxLengthRate{0.0, 0.0};
    double boxTime = 0.0;       //!< System time at which boxLower..boxUpper is the box [s]
    double timeStep = 1e-7;     //!< DEM step [s]
    double neighbourSkin = 0.0; //!< Verlet skin [m]; rebuild when a grain moved skin/2
    //- Refuse timeStep > maxTimeStepFraction * sqrt(m_min / k_max) (see criticalTimeStep()).
    double maxTimeStepFraction = 0.2;
    double viscousDrag = 0.0; //!< global drag force -c v on every grain [N s/m]
    Backend backend = Backend::automatic;
    int threads = 0; //!< CPU backend threads; 0: OpenMP default (OMP_NUM_THREADS)
    //- Contact (neighbour-pair) storage limit per grain; 0 = grow without limit. Exceeding a
    //- set limit throws dem::Error; storage never drops a pair silently.
    int maxPairsPerGrain = 0;
    BondParameters bonds;
    Decomposition decomposition;
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

//- One bond to add between grains first and second (add-order indices, first != second).
struct BondInit
{
    int first = -1, second = -1;
    double patchRadius = 0.0; //!< r_b [m], > 0
};

} // namespace dem
