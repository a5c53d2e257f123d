"""The wallStress and packingStatistics function objects and the bonds'
VTK output (issue 11) on real demFoam runs, checked against conservation
laws and against each other: tests/cases/grainColumn (256 spheres,
2600 kg/m^3, periodic 0.1 m x 0.1 m box, fixed base, a lid under a normal
stress sigma0 = 1e4 Pa) settled to rest under gravity, the same with bonds
frozen on contact, and tests/cases/wallBox (walls on x, a free lid)."""

import os

import numpy as np
import pytest

from darcydem.case import Case
from darcydem.foamfiles import grain_files, read_columns, read_vtp, read_vtp_lines

DEM = "constant/demProperties"
G = 9.81
AREA = 0.1 * 0.1            # the periodic box's x-y area [m^2]
SIGMA0 = 1e4                # the lid's normal stress in the template [Pa]
STIFFNESS = 1e6             # the template's k_n [N/m]
DRAG = 0.5                  # viscous drag [N s/m], brings the packing to rest
WALL_COLUMNS = ["time"] + [f"{w}_{q}" for w in ("bottom", "top")
                           for q in ("position", "force", "stress")]
PACKING_COLUMNS = ["time", "density", "solidFraction", "coordinationNumber", "bondsIntact",
                   "bondsFormed", "bondsBroken", "bondsApart", "meanPatchRadius",
                   "lidPosition", "lidVelocity", "strainRate", "bulkViscosity"]
FUNCTIONS = """{
    wallStress { type wallStress; libs ("libdemCoupling.so");
                 writeControl timeStep; writeInterval 10; }
    packing    { type packingStatistics; libs ("libdemCoupling.so");
                 writeControl timeStep; writeInterval 10; }
}"""


def settled_column(name, end_time=1.0):
    """grainColumn run by demFoam to end_time with the two function objects
    every 10 fluid steps and the grains written every 0.1 s."""
    c = Case("grainColumn", name)
    c.set("system/controlDict", "endTime", end_time)
    c.set("system/controlDict", "deltaT", 1e-3)
    c.set("system/controlDict", "writeInterval", 100)
    c.set("system/controlDict", "functions", FUNCTIONS)
    c.set(DEM, "viscousDrag", DRAG)
    c.run("blockMesh")
    c.run("demFoam")
    return c


def grain_masses(c):
    """Masses and volumes of the start grains (spheres, 0/grains)."""
    r = np.loadtxt(c.file("0/grains"), comments="#", ndmin=2)[:, 3]
    volume = 4 / 3 * np.pi * r**3
    return 2600 * volume, volume


def test_lid_and_base_carry_the_load_of_a_packing_at_rest():
    """Momentum balance of the packing at rest (t = 1 s): the lid's stress is
    sigma0, the grains push the base down with sigma0 A + M g. Tolerance:
    the contact forces the grains' remaining motion can carry, sum of
    (sqrt(k m_i) + c) |v_i| over the grains at that time (a grain moving at
    v on a spring k vibrates with force amplitude v sqrt(k m); the drag
    adds c v), from the grains' velocities written at the same time.
    Definitions, to round-off (1e-12): stress = force / box area, the lid
    of wallStress is the lid of packingStatistics, density = M / (A lid),
    solid fraction = V / (A lid), strain rate = -v_lid / lid (base at 0),
    bulk viscosity = lid stress / strain rate; coordination number = the
    grains' contacts (contactCount of the grains' .vtp) / grains; no
    bonds."""
    c = settled_column("packing_at_rest")
    walls = read_columns(c.file("postProcessing/wallStress/0/wallStress.dat"))
    packing = read_columns(c.file("postProcessing/packing/0/packing.dat"))
    assert list(walls) == WALL_COLUMNS and list(packing) == PACKING_COLUMNS

    mass, volume = grain_masses(c)
    weight = mass.sum() * G
    t, vtp = grain_files(c.path)[-1]
    grains = read_vtp(vtp)
    speed = np.linalg.norm(grains["velocity"], axis=1)
    bound = np.sum((np.sqrt(STIFFNESS * mass) + DRAG) * speed)
    row = np.flatnonzero(np.isclose(walls["time"], t, rtol=0, atol=1e-9))[-1]
    lid_error = walls["top_force"][row] - SIGMA0 * AREA
    base_error = walls["bottom_force"][row] + SIGMA0 * AREA + weight
    print(f"t = {t} s: lid force {walls['top_force'][row]:.9g} N (sigma0 A = {SIGMA0 * AREA} N),"
          f" base force {walls['bottom_force'][row]:.9g} N (-(sigma0 A + M g) ="
          f" {-(SIGMA0 * AREA + weight):.9g} N); errors {lid_error:.2e}, {base_error:.2e} N;"
          f" bound from the grains' motion {bound:.2e} N; density {packing['density'][row]:.6g}")
    assert abs(lid_error) < bound and abs(base_error) < bound
    assert bound < 1e-3 * weight      # at rest: the bound itself is small

    for wall in ("bottom", "top"):
        np.testing.assert_allclose(walls[f"{wall}_stress"], walls[f"{wall}_force"] / AREA,
                                   rtol=1e-12, atol=0)
    lid = walls["top_position"]
    np.testing.assert_array_equal(packing["lidPosition"], lid)
    np.testing.assert_allclose(packing["density"], mass.sum() / (AREA * lid), rtol=1e-12)
    np.testing.assert_allclose(packing["solidFraction"], volume.sum() / (AREA * lid), rtol=1e-12)
    np.testing.assert_allclose(packing["strainRate"], -packing["lidVelocity"] / lid, rtol=1e-12)
    moving = packing["strainRate"] != 0
    np.testing.assert_allclose(packing["bulkViscosity"][moving],
                               walls["top_stress"][moving] / packing["strainRate"][moving],
                               rtol=1e-12)
    assert packing["coordinationNumber"][row] == grains["contactCount"].sum() / len(mass)
    for column in ("bondsIntact", "bondsFormed", "bondsBroken", "bondsApart",
                   "meanPatchRadius"):
        assert np.all(packing[column] == 0)


def minimum_image(d, box):
    """Differences d (n, 3) to their nearest periodic images in x and y."""
    d = d.copy()
    for k in (0, 1):
        d[:, k] -= box[k] * np.round(d[:, k] / box[k])
    return d


STRENGTHS = {
    "unbreakable": "{ type none; }",
    # weak (about 16 N on a mean patch): bonds break as the column settles under the lid
    "weak": "{ type constant; tensileStrength 1e6; shearStrength 1e6; }",
}


@pytest.mark.parametrize("strength", STRENGTHS)
def test_bonds_frozen_on_contact_written_for_paraview_and_counted(strength):
    """Grains falling in the column freeze together where they touch
    (formation frozenOnContact; bonds that never break, or weak ones that
    break as the column settles and re-freeze). At every write
    time the bonds' .vtp (read by VTK's own reader, listed in
    bonds.vtp.series) holds one line per intact bond counted by
    packingStatistics; its lines run from the first grain's centre to the
    nearest image of the second's (round-off of the coordinates, 1e-12 of
    the box); every patch radius is the one the formation drew from
    areaFraction (r_b^2 / r_min^2 in [0.03125, 0.09375], round-off; a
    softening bond's only shrinks); the counts conserve bonds (intact =
    formed - broken; unbreakable: broken = 0, weak: broken > 0); bondsApart is the number of bonds whose spheres do not touch and
    the coordination number 2 (touching pairs + apart) / grains, with the
    touching pairs from the grains' contactCount."""
    c = Case("grainColumn", f"bonded_column_{strength}")
    c.set("system/controlDict", "endTime", 0.1)
    c.set("system/controlDict", "deltaT", 1e-3)
    c.set("system/controlDict", "writeInterval", 100)
    c.set("system/controlDict", "functions", FUNCTIONS)
    c.set(DEM, "viscousDrag", DRAG)
    # E: a bond of the mean patch (r_b^2 = r^2/16) about as stiff as the
    # contacts (k_ne pi r_b^2 = E pi r / 32 ~ 9e5 N/m for r = 9 mm)
    c.set(DEM, "bonds", "{ youngsModulus 1e9; normalDampingRatio 0.2; shearDampingRatio 0.2;"
                        f" strength {STRENGTHS[strength]} formation {{ type frozenOnContact;"
                        f" areaFraction (0.03125 0.09375); interval 10; seed 3; }} }}")
    c.run("blockMesh")
    c.run("demFoam")

    packing = read_columns(c.file("postProcessing/packing/0/packing.dat"))
    np.testing.assert_array_equal(packing["bondsIntact"],
                                  packing["bondsFormed"] - packing["bondsBroken"])
    if strength == "unbreakable":
        assert np.all(packing["bondsBroken"] == 0)
    else:
        assert packing["bondsBroken"][-1] > 0
    box = np.array([0.1, 0.1])

    bond_files = grain_files(c.path, "bonds")
    grain_times = dict(grain_files(c.path))
    assert [t for t, _ in bond_files] == sorted(grain_times)
    for t, path in bond_files:
        bonds = read_vtp_lines(path)
        grains = read_vtp(grain_times[t])
        row = np.flatnonzero(np.isclose(packing["time"], t, rtol=0, atol=1e-9))[-1]
        n = len(bonds["lines"])
        assert n == packing["bondsIntact"][row]
        if n == 0:
            continue
        a, b = bonds["first"], bonds["second"]
        ends = bonds["points"][bonds["lines"]]
        x = grains["position"]
        np.testing.assert_allclose(ends[:, 0], x[a], rtol=0, atol=1e-12 * box[0])
        np.testing.assert_allclose(ends[:, 1] - ends[:, 0], minimum_image(x[b] - x[a], box),
                                   rtol=0, atol=1e-12 * box[0])
        r = grains["radius"]
        fraction = bonds["patchRadius"]**2 / np.minimum(r[a], r[b])**2
        intact = bonds["softening"] == 0
        assert np.all(fraction[intact] >= 0.03125 * (1 - 1e-12))
        assert fraction.max() <= 0.09375 * (1 + 1e-12)
        np.testing.assert_allclose(packing["meanPatchRadius"][row],
                                   bonds["patchRadius"].mean(), rtol=1e-12)
        apart = np.sum(np.linalg.norm(ends[:, 1] - ends[:, 0], axis=1) > r[a] + r[b])
        assert packing["bondsApart"][row] == apart
        touching = grains["contactCount"].sum() / 2
        assert packing["coordinationNumber"][row] == 2 * (touching + apart) / len(r)
        print(f"{strength}, t = {t} s: {n} bonds ({packing['bondsFormed'][row]:.0f} formed,"
              f" {packing['bondsBroken'][row]:.0f} broken, {np.sum(~intact)} softening),"
              f" {apart} apart, r_b^2/r_min^2 in "
              f"[{fraction.min():.5f}, {fraction.max():.5f}], coordination number "
              f"{packing['coordinationNumber'][row]:.3f}")
    assert packing["bondsIntact"][-1] > 0


CREEP_COLUMNS = ["time", "bondsIntact", "normal", "shear", "twist", "bend",
                 "meanNormal", "meanShear", "meanTwist", "meanBend"]
MECHANISMS = {"normal": "creepNormal", "shear": "creepShear", "twist": "creepTwist",
              "bend": "creepBend"}


def test_bond_creep_per_mechanism_keeps_what_broken_bonds_crept():
    """The bondCreep function object on the weak bonded column of the test
    above with grain-boundary creep on shear and twist (tau = nu_s / (0.6
    E) = 0.01 s, a tenth of the run) and bend creep off: bonds freeze,
    creep and break as the column settles. Conservation: the sample's sums
    never decrease (creep counts in magnitude, and a bond that breaks keeps
    its creep in them), and they hold at least what the intact bonds crept;
    the means at each write time are the means of the bonds' own creep in
    their .vtp (round-off, 1e-12); a mechanism without creep law (normal:
    no power law; bend: switched off) creeps exactly nothing."""
    c = Case("grainColumn", "bond_creep_column")
    c.set("system/controlDict", "endTime", 0.1)
    c.set("system/controlDict", "deltaT", 1e-3)
    c.set("system/controlDict", "writeInterval", 20)
    c.set("system/controlDict", "functions", FUNCTIONS[:-1] + """
    creep      { type bondCreep; libs ("libdemCoupling.so");
                 writeControl timeStep; writeInterval 10; }
}""")
    c.set(DEM, "viscousDrag", DRAG)
    c.set(DEM, "bonds", "{ youngsModulus 1e9; normalDampingRatio 0.2; shearDampingRatio 0.2;"
                        " creep { type maxwell; contactViscosity 6e6; shear yes; twist yes;"
                        " bend no; }"
                        f" strength {STRENGTHS['weak']} formation {{ type frozenOnContact;"
                        " areaFraction (0.03125 0.09375); interval 10; seed 3; } }")
    c.run("blockMesh")
    c.run("demFoam")

    creep = read_columns(c.file("postProcessing/creep/0/creep.dat"))
    packing = read_columns(c.file("postProcessing/packing/0/packing.dat"))
    assert list(creep) == CREEP_COLUMNS
    np.testing.assert_array_equal(creep["bondsIntact"], packing["bondsIntact"])
    for mechanism in ("shear", "twist"):
        total = creep[mechanism]
        assert np.all(np.diff(total) >= 0), f"{mechanism} creep decreased"
        intact = creep["mean" + mechanism.capitalize()] * creep["bondsIntact"]
        assert np.all(total >= intact * (1 - 1e-12))
        assert total[-1] > 0
    for mechanism in ("normal", "bend"):
        assert np.all(creep[mechanism] == 0) and np.all(creep["mean" + mechanism.capitalize()] == 0)
    assert packing["bondsBroken"][-1] > 0        # the breaking bonds' creep was kept

    checked = 0
    for t, path in grain_files(c.path, "bonds"):
        bonds = read_vtp_lines(path)
        row = np.flatnonzero(np.isclose(creep["time"], t, rtol=0, atol=1e-9))
        if len(bonds["lines"]) == 0 or len(row) == 0:
            continue
        for mechanism, array in MECHANISMS.items():
            np.testing.assert_allclose(creep["mean" + mechanism.capitalize()][row[-1]],
                                       bonds[array].mean(), rtol=1e-12, atol=0)
        checked += 1
    assert checked > 0
    print(f"t = {creep['time'][-1]} s: {packing['bondsBroken'][-1]:.0f} bonds broken,"
          f" {creep['bondsIntact'][-1]:.0f} intact; shear creep {creep['shear'][-1]:.4e} m"
          f" (intact bonds {creep['meanShear'][-1] * creep['bondsIntact'][-1]:.4e} m),"
          f" twist {creep['twist'][-1]:.4e} rad; checked against {checked} .vtp files")


def write_layered_grains(path, seed=1):
    """72 spheres of radius 4 to 4.5 mm in 6 layers of 3 x 4 inside
    wallBox's walls (x in [0, 0.04], periodic y of 0.04), alternate layers
    shifted by half a spacing in x, so that they settle into each other and
    press on the side walls."""
    rng = np.random.default_rng(seed)
    with open(path, "w") as f:
        f.write("# x y z r: 6 layers of 3 x 4 spheres, alternate layers shifted in x\n")
        for k in range(6):
            for i in range(3):
                for j in range(4):
                    x = 0.006 + 0.010 * i + (0.005 if k % 2 else 0.0)
                    r = rng.uniform(0.004, 0.0045)
                    f.write(f"{x:.6f} {0.005 + 0.010 * j:.6f} {0.006 + 0.010 * k:.6f} {r:.6f}\n")


def test_free_lid_and_side_walls_in_balance():
    """tests/cases/wallBox with 72 spheres: walls on x (0 and 0.04 m),
    periodic y (0.04 m), a fixed base and a free lid of mass m under gravity
    ramped from zero over 0.05 s, settled to rest with drag; the walls are
    frictionless (the files hold normal forces only). Momentum
    balance at rest (end of the run): the lid carries its weight (lid
    stress m g / A, A the x-y area between the x walls), the base the lid's
    and the grains' weight, and the x walls' forces cancel; tolerance as
    for the stress lid above, the force the grains' remaining motion
    carries. Areas by their definition at every row (round-off): a z wall
    Ly (x_right - x_left), an x wall Ly (lid - base); density over the
    volume between the six bounds."""
    lid_mass, ly, drag = 0.05, 0.04, 0.1
    c = Case("wallBox", "packing_free_lid")
    write_layered_grains(c.file("0/grains"))
    c.set("system/controlDict", "endTime", 0.5)
    c.set("system/controlDict", "deltaT", 1e-3)
    c.set("system/controlDict", "writeInterval", 500)
    c.set("system/controlDict", "functions", FUNCTIONS)
    c.set(DEM, "viscousDrag", drag)
    c.set(DEM, "timeStep", 5e-6)     # 0.19 sqrt(m_min/k) for the 4 mm grains
    # The files hold the walls' normal forces: frictional walls would take part of the
    # weight by friction on the sides (Janssen) and of the side thrust on the base
    for wall in ("bottom", "left", "right"):
        c.set(DEM, f"walls/{wall}/frictional", "no")
    c.run("blockMesh")
    c.run("demFoam")
    walls = read_columns(c.file("postProcessing/wallStress/0/wallStress.dat"))
    packing = read_columns(c.file("postProcessing/packing/0/packing.dat"))
    assert list(walls) == ["time"] + [f"{w}_{q}" for w in ("bottom", "left", "right", "lid")
                                      for q in ("position", "force", "stress")]

    mass, volume = grain_masses(c)
    t, vtp = grain_files(c.path)[-1]
    grains = read_vtp(vtp)
    speed = np.linalg.norm(grains["velocity"], axis=1)
    bound = np.sum((np.sqrt(STIFFNESS * mass) + drag) * speed)
    row = np.flatnonzero(np.isclose(walls["time"], t, rtol=0, atol=1e-9))[-1]
    lid_error = walls["lid_force"][row] - lid_mass * G
    base_error = walls["bottom_force"][row] + (lid_mass + mass.sum()) * G
    side_error = walls["left_force"][row] + walls["right_force"][row]
    print(f"t = {t} s: lid force {walls['lid_force'][row]:.9g} N (m g = {lid_mass * G:.9g}),"
          f" lid stress {walls['lid_stress'][row]:.6g} Pa, base {walls['bottom_force'][row]:.9g}"
          f" N, sides {walls['left_force'][row]:.4e} and {walls['right_force'][row]:.4e} N;"
          f" errors {lid_error:.2e}, {base_error:.2e}, {side_error:.2e} N; bound {bound:.2e} N")
    assert max(abs(lid_error), abs(base_error), abs(side_error)) < bound
    assert bound < 1e-3 * lid_mass * G
    assert walls["right_force"][row] > 100 * bound     # the sides do carry a load

    width = walls["right_position"] - walls["left_position"]
    height = walls["lid_position"] - walls["bottom_position"]
    for wall in ("bottom", "lid"):
        np.testing.assert_allclose(walls[f"{wall}_stress"] * ly * width,
                                   walls[f"{wall}_force"], rtol=1e-12, atol=0)
    for wall in ("left", "right"):
        np.testing.assert_allclose(walls[f"{wall}_stress"] * ly * height,
                                   walls[f"{wall}_force"], rtol=1e-12, atol=0)
    np.testing.assert_allclose(packing["density"], mass.sum() / (ly * width * height),
                               rtol=1e-12)
    np.testing.assert_allclose(packing["solidFraction"], volume.sum() / (ly * width * height),
                               rtol=1e-12)
    np.testing.assert_allclose(packing["strainRate"], -packing["lidVelocity"] / height,
                               rtol=1e-12)


def test_bonds_output_can_be_switched_off():
    """output { bonds no; }: the grains are written, the bonds not (and with
    bonds and no such entry they are: the test above)."""
    c = Case("grainColumn", "bonds_output_off")
    c.set("system/controlDict", "endTime", 0.01)
    c.set("system/controlDict", "deltaT", 1e-3)
    c.set("system/controlDict", "writeInterval", 10)
    c.set(DEM, "bonds", "{ youngsModulus 1e9; formation { type frozenOnContact; } }")
    c.set(DEM, "output", "{ format binary; bonds no; }")
    c.run("blockMesh")
    c.run("demFoam")
    written = sorted(os.listdir(c.file("postProcessing/grains")))
    print("postProcessing/grains/:", written)
    assert "grains.vtp.series" in written
    assert not any(name.startswith("bonds") for name in written)
