"""A finished coupled case seen as ParaView sees it, through the VTK readers
ParaView itself uses (README.md, "Running a tutorial and looking at it"):
vtkOpenFOAMReader on <case>.foam for the fields and vtkXMLPolyDataReader on
the files of the series postProcessing/grains/grains.vtp.series for the
grains, then the README's recipe (Sphere glyphs scaled by radius with factor 2, coloured by
displacement) rendered offscreen to a PNG that is checked and left in the
run directory. Case: tests/cases/grainColumn, 256 grains settling in a
saturated periodic column for 0.02 s, grains written in binary; and the
same column run dry (demFoam) with 60 spheres and capsules mixed from
bin/makeGrains: the capsules' arrays and their surfaces (capsules_<time>.vtp),
which ParaView shows as capsules without any filter."""

import json
import os
import subprocess

import numpy as np
import pytest
import vtkmodules.all as vtk   # python3-vtk9, from bin/install-dependencies
from vtkmodules.util.numpy_support import vtk_to_numpy

from darcydem.case import Case
from darcydem.foamfiles import capsule_axes, grain_files, read_grains, read_vtp
from darcydem.render import snapshot, virtual_display

WRITE_TIMES = [0.01, 0.02]
FIELDS = {"p": 1, "porosity": 1, "k": 1, "Us": 3, "qDarcy": 3}
GRAIN_ARRAYS = {"radius": 1, "coreHalfLength": 1, "orientation": 4, "axis": 3, "volume": 1,
                "velocity": 3, "angularVelocity": 3, "displacement": 3,
                "force": 3, "fluidForce": 3, "contactCount": 1, "flag": 1}
# ParaView's OpenFOAM reader converts fields and points to 32-bit floats
FLOAT32_EPS = 2.0**-24
# the fluid's porosity is clamped to [porosityMin, porosityMax] (0.9 in the template): the
# test opens the clamp to 1 - CLAMP_GAP so that the written porosity holds the whole
# deposit (set as 0.999999)
CLAMP_GAP = 1e-6


@pytest.fixture(scope="module")
def case():
    c = Case("grainColumn", "paraview_readers")
    c.set("system/controlDict", "endTime", 0.02)
    c.set("system/controlDict", "writeInterval", 100)
    c.set("constant/demProperties", "output/format", "binary")
    c.set("constant/darcyProperties", "solidPhase/porosityMax", "%.6f" % (1 - CLAMP_GAP))
    c.run("blockMesh")
    c.run("darcyDemFoam")
    open(c.file("paraview_readers.foam"), "w").close()   # what ParaView opens
    return c


@pytest.fixture(scope="module")
def x_display():
    """The X display Debian's VTK needs to render offscreen (darcydem.render)."""
    with virtual_display() as display:
        yield display


def input_grains(c):
    return np.loadtxt(c.file("0/grains"), comments="#", ndmin=2)


def open_foam(c):
    reader = vtk.vtkOpenFOAMReader()
    reader.SetFileName(c.file("paraview_readers.foam"))
    reader.SkipZeroTimeOn()   # ParaView's default
    reader.UpdateInformation()
    return reader


def test_openfoam_reader_steps_through_every_write(case):
    """Every write time, the fields on all 40 cells, and the deposit seen
    through the reader: sum over cells of (1 - porosity) V_cell is the
    grains' volume (the deposit conserves it), with the radii from the
    grains' file of the same time: fields and grains line up in time."""
    reader = open_foam(case)
    times = vtk_to_numpy(reader.GetTimeValues())
    print(f"OpenFOAM reader times {times}")
    assert times.tolist() == pytest.approx(WRITE_TIMES, rel=1e-12)
    grains = grain_files(case.path)
    assert [t for t, _ in grains] == times.tolist(), "grains and fields at other times"
    for t, (_, grain_file) in zip(times, grains):
        reader.UpdateTimeStep(t)
        mesh = reader.GetOutput().GetBlock(0)
        assert mesh.GetNumberOfCells() == 2 * 2 * 10
        cells = mesh.GetCellData()
        for name, components in FIELDS.items():
            array = cells.GetArray(name)
            assert array is not None, f"{name} missing at t = {t}"
            assert array.GetNumberOfComponents() == components, name
            assert np.all(np.isfinite(vtk_to_numpy(array))), name
        porosity = vtk_to_numpy(cells.GetArray("porosity")).astype(float)
        assert np.all((porosity > 0) & (porosity <= 1))
        sizes = vtk.vtkCellSizeFilter()
        sizes.SetInputData(mesh)
        sizes.Update()
        volume = vtk_to_numpy(sizes.GetOutput().GetCellData().GetArray("Volume"))
        solid = np.sum((1 - porosity) * volume)
        r = read_vtp(grain_file)["radius"]
        expected = np.sum(4 / 3 * np.pi * r**3)
        err = abs(solid - expected) / expected
        # per cell: porosity rounded to float32 (porosity <= 1), the cell volume from
        # float32 points (3 coordinates), and CLAMP_GAP of an empty cell counted as solid
        bound = np.sum(volume) * (4 * FLOAT32_EPS + CLAMP_GAP) / expected
        print(f"t = {t}: solid volume from porosity {solid:.9e} m^3, grains {expected:.9e} m^3,"
              f" relative difference {err:.1e} (bound {bound:.1e})")
        assert err < bound


def test_grain_series_lists_every_write_with_all_arrays(case):
    """The series ParaView opens lists one file per write time; each, read
    by vtkXMLPolyDataReader (binary here), holds every grain of the input
    with its radius unchanged and every documented array."""
    series = json.load(open(case.file("postProcessing/grains/grains.vtp.series")))
    print(f"grains.vtp.series: {series}")
    assert series["file-series-version"] == "1.0"
    grains = grain_files(case.path)
    assert [t for t, _ in grains] == WRITE_TIMES
    initial = input_grains(case)
    for t, path in grains:
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(path)
        reader.Update()
        data = reader.GetOutput()
        assert data.GetNumberOfPoints() == len(initial), path
        assert data.GetNumberOfVerts() == len(initial), path
        points = data.GetPointData()
        for name, components in GRAIN_ARRAYS.items():
            array = points.GetArray(name)
            assert array is not None, f"{name} missing in {path}"
            assert array.GetNumberOfComponents() == components, name
        radius = vtk_to_numpy(points.GetArray("radius"))
        # the radii are written as doubles: the input's, exactly, in any order
        assert np.array_equal(np.sort(radius), np.sort(initial[:, 3])), path
        print(f"t = {t}: {data.GetNumberOfPoints()} grains in {os.path.basename(path)}")


def render_grains(path, png, size=(800, 600), surfaces=False):
    """The README's ParaView recipe with plain VTK: Sphere glyphs (radius 0.5)
    scaled by 'radius' with factor 2, so that each sphere has the grain's
    radius, coloured by the magnitude of 'displacement'; with surfaces, path
    is a capsules_<time>.vtp shown as it is (ParaView's Surface
    representation). Returns the image as an (height, width, 3) array after
    writing it to png, and the displacement magnitudes."""
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    grains = reader.GetOutput()
    if surfaces:
        shown = reader
    else:
        grains.GetPointData().SetActiveScalars("radius")
        sphere = vtk.vtkSphereSource()   # radius 0.5, as ParaView's Sphere glyph
        sphere.SetThetaResolution(16)
        sphere.SetPhiResolution(16)
        glyphs = vtk.vtkGlyph3D()
        glyphs.SetInputData(grains)
        glyphs.SetSourceConnection(sphere.GetOutputPort())
        glyphs.SetScaleModeToScaleByScalar()
        glyphs.SetScaleFactor(2.0)
        glyphs.SetColorModeToColorByScalar()
        glyphs.OrientOff()
        glyphs.Update()
        shown = glyphs
    # ParaView colours by a vector's magnitude: carry the displacement onto
    # the glyphs (vtkGlyph3D copies point data) and map its magnitude
    displacement = grains.GetPointData().GetArray("displacement")
    magnitude = np.linalg.norm(vtk_to_numpy(displacement), axis=1)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(shown.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("displacement")
    mapper.GetLookupTable().SetVectorModeToMagnitude()
    mapper.GetLookupTable().SetHueRange(0.667, 0.0)   # blue (least) to red (most)
    mapper.SetScalarRange(magnitude.min(), magnitude.max())
    mapper.ScalarVisibilityOn()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)
    renderer.AddActor(actor)
    renderer.GetActiveCamera().Elevation(-80)   # look along y at the column's side
    renderer.ResetCamera()
    pixels = snapshot(renderer, png, size)
    return pixels, magnitude


def test_grains_render_as_coloured_spheres(case, x_display):
    """The last write rendered offscreen as the README says: the image shows
    spheres, not points: 256 grains drawn as one-pixel vertices would cover
    at most 256 of the 480000 pixels (0.05 %); spheres of the grains' radii
    in a view fitted to the column cover several per cent. They are
    coloured by displacement: many colours."""
    time, path = grain_files(case.path)[-1]
    png = case.file(f"grains_{time:g}.png")
    pixels, magnitude = render_grains(path, png)
    print(f"rendered {path} to {png}")
    background = np.all(pixels == 255, axis=2)
    covered = 1 - background.mean()
    colours = len(np.unique(pixels[~background], axis=0))
    print(f"displacement magnitude {magnitude.min():.3e} .. {magnitude.max():.3e} m;"
          f" non-background pixels {covered:.3f}, distinct colours {colours}")
    assert magnitude.max() > magnitude.min() > -1, "no displacement to colour by"
    assert covered > 0.02
    assert colours > 10


# --- capsules ---------------------------------------------------------------------------
CAPSULE_COUNT = 60


@pytest.fixture(scope="module")
def capsule_case():
    """The column run dry (demFoam) for 0.02 s with 60 grains, about half
    capsules of aspect 1.5-2.5 (radius 7-8 mm: the 0.1 m box holds twice the longest grain), written in binary at 0.01 and 0.02 s."""
    c = Case("grainColumn", "paraview_capsules")
    os.remove(c.file("constant/darcyProperties"))
    os.remove(c.file("0/p"))
    c.set("system/controlDict", "endTime", 0.02)
    c.set("system/controlDict", "writeInterval", 100)
    c.set("constant/demProperties", "output/format", "binary")
    c.set("constant/demProperties", "timeStep", 5e-6)   # capsules turn: a shorter critical step
    subprocess.run([os.path.join(os.environ["DARCYDEM_PROJECT"], "bin", "makeGrains"),
                    "--box", "0.1", "0.1", "--z", "0", "0.36", "--radius", "0.007", "0.008",
                    "--layout", "random", "--count", str(CAPSULE_COUNT),
                    "--capsule-fraction", "0.5", "--aspect", "1.5", "2.5", "--seed", "2",
                    "-o", c.file("0/grains")], check=True)
    c.run("blockMesh")
    c.run("demFoam")
    return c


def test_capsule_arrays_match_the_grains(capsule_case):
    """grains_<time>.vtp carries each grain's shape as the grains file of
    the same time says it: coreHalfLength the input's exactly (doubles,
    never changed by the run), orientation the written file's exactly (17
    digits round-trip), axis R(q) e_z of that quaternion (round-off of a
    few operations: 1e-15), volume pi r^2 2h + 4/3 pi r^3 (round-off)."""
    initial = read_grains(capsule_case.file("0/grains"))
    capsules = initial["coreHalfLength"] > 0
    print(f"{len(capsules)} grains, {np.count_nonzero(capsules)} capsules")
    assert 0 < np.count_nonzero(capsules) < CAPSULE_COUNT
    for t, path in grain_files(capsule_case.path):
        g = read_vtp(path)
        written = read_grains(capsule_case.file(f"{t:g}/grains"))
        assert np.array_equal(g["coreHalfLength"], initial["coreHalfLength"]), path
        assert np.array_equal(g["radius"], initial["radius"]), path
        assert np.array_equal(g["orientation"][capsules], written["orientation"][capsules])
        assert np.array_equal(written["coreHalfLength"], initial["coreHalfLength"])
        axis_error = np.max(np.abs(g["axis"] - capsule_axes(g["orientation"])))
        r, h = g["radius"], g["coreHalfLength"]
        exact = np.pi * r**2 * 2 * h + 4 / 3 * np.pi * r**3
        volume_error = np.max(np.abs(g["volume"] / exact - 1))
        print(f"t = {t}: axis error {axis_error:.1e}, volume error {volume_error:.1e}")
        assert axis_error < 1e-15
        assert np.max(np.abs(np.linalg.norm(g["axis"], axis=1) - 1)) < 1e-14
        assert volume_error < 1e-14


def surface_ratio_bounds(resolution=8):
    """Area of the tessellated surface over the exact one lies between the
    ratios of its two parts, whatever r and h: the caps (the template at
    radius 1, no core, over 4 pi) and the side (the perimeter of the ring
    of points where cap meets side, over 2 pi: an inscribed polygon)."""
    source = vtk.vtkCapsuleSource()
    source.SetRadius(1)
    source.SetCylinderLength(0)
    source.SetThetaResolution(resolution)
    source.SetPhiResolution(resolution)
    source.Update()
    cap_ratio = surface_area(source.GetOutput()) / (4 * np.pi)
    source.SetCylinderLength(2)
    source.Update()
    p = vtk_to_numpy(source.GetOutput().GetPoints().GetData()).astype(float)
    ring = p[np.abs(p[:, 1] - 1) < 1e-6]
    angle = np.arctan2(ring[:, 2], ring[:, 0])
    ring = ring[np.argsort(angle)]
    perimeter = np.sum(np.linalg.norm(ring - np.roll(ring, 1, axis=0), axis=1))
    side_ratio = perimeter / (2 * np.pi)
    return min(cap_ratio, side_ratio), max(cap_ratio, side_ratio)


def surface_area(data):
    """Area of polygons (triangles and quads) by VTK's own filters."""
    triangles = vtk.vtkTriangleFilter()
    triangles.SetInputData(data)
    mass = vtk.vtkMassProperties()
    mass.SetInputConnection(triangles.GetOutputPort())
    mass.Update()
    return mass.GetSurfaceArea()


def test_capsule_surfaces_are_the_grains(capsule_case):
    """capsules_<time>.vtp, listed in capsules.vtp.series at every write
    time, holds every grain's surface: each point lies at the grain's
    radius from its core segment (float points: 4 float32 epsilons of the
    coordinates), and the total area over the exact one, sum of
    4 pi r^2 + 4 pi r h, lies between the tessellation's cap and side
    ratios (a capsule drawn as a sphere would fall far below)."""
    surfaces = grain_files(capsule_case.path, "capsules")
    grains = grain_files(capsule_case.path)
    assert [t for t, _ in surfaces] == [t for t, _ in grains] == WRITE_TIMES
    low, high = surface_ratio_bounds()
    for (t, path), (_, grain_path) in zip(surfaces, grains):
        g = read_vtp(grain_path)
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(path)
        reader.Update()
        data = reader.GetOutput()
        p = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
        i = vtk_to_numpy(data.GetPointData().GetArray("grain"))
        assert np.array_equal(np.bincount(i), np.full(CAPSULE_COUNT, len(p) // CAPSULE_COUNT))
        x, r, h = g["position"][i], g["radius"][i], g["coreHalfLength"][i]
        a = g["axis"][i] * h[:, None]
        d = p - x
        u = np.clip(np.einsum("ij,ij->i", d, a) / np.maximum(h**2, 1e-300), -1, 1)
        distance = np.linalg.norm(d - u[:, None] * a, axis=1)
        bound = 4 * FLOAT32_EPS * (np.max(np.abs(p), axis=1) + h + r)
        worst = np.max(np.abs(distance - r) / bound)
        r, h = g["radius"], g["coreHalfLength"]
        ratio = surface_area(data) / np.sum(4 * np.pi * r**2 + 4 * np.pi * r * h)
        shown = vtk_to_numpy(data.GetPointData().GetArray("displacement"))
        print(f"t = {t}: {len(p)} points, |distance - r| up to {worst:.2f} of its bound;"
              f" area ratio {ratio:.4f} in [{low:.4f}, {high:.4f}]")
        assert worst <= 1
        assert low - 1e-6 <= ratio <= high + 1e-6
        # displacement written as float: the grain's to float32 rounding
        assert np.allclose(shown, g["displacement"][i], rtol=2 * FLOAT32_EPS, atol=0)


def test_capsules_render_as_coloured_surfaces(capsule_case, x_display):
    """The last capsules_<time>.vtp rendered offscreen as ParaView shows it
    (Surface, coloured by displacement): the surfaces cover a few per cent
    of the image and carry many colours."""
    time, path = grain_files(capsule_case.path, "capsules")[-1]
    png = capsule_case.file(f"capsules_{time:g}.png")
    pixels, magnitude = render_grains(path, png, surfaces=True)
    background = np.all(pixels == 255, axis=2)
    covered = 1 - background.mean()
    colours = len(np.unique(pixels[~background], axis=0))
    print(f"rendered {path} to {png}: non-background pixels {covered:.3f},"
          f" distinct colours {colours}")
    assert covered > 0.02
    assert colours > 10


def test_line_glyphs_draw_the_cores(capsule_case):
    """The README's Glyph recipe for the cores, with VTK's glyph filter
    (ParaView's Glyph is built on it): Glyph Type Line (from (-0.5, 0, 0)
    to (0.5, 0, 0)), Orientation Array 'axis' (turns x onto it), Scale
    Array 'coreHalfLength', Scale Factor 2: the two ends of each glyph are
    the core's ends x -+ h axis, to the precision of the glyph's rotation
    (VTK builds it from an angle, an arccosine near +-1 accurate to about
    sqrt(eps) = 1.5e-8: twice that times the longest half-length)."""
    _, path = grain_files(capsule_case.path)[-1]
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    grains = reader.GetOutput()
    grains.GetPointData().SetActiveScalars("coreHalfLength")
    grains.GetPointData().SetActiveVectors("axis")
    line = vtk.vtkLineSource()
    line.SetPoint1(-0.5, 0, 0)
    line.SetPoint2(0.5, 0, 0)
    line.SetOutputPointsPrecision(vtk.vtkAlgorithm.DOUBLE_PRECISION)   # to check the geometry
    glyphs = vtk.vtkGlyph3D()
    glyphs.SetOutputPointsPrecision(vtk.vtkAlgorithm.DOUBLE_PRECISION)
    glyphs.SetInputData(grains)
    glyphs.SetSourceConnection(line.GetOutputPort())
    glyphs.SetScaleModeToScaleByScalar()
    glyphs.SetScaleFactor(2.0)
    glyphs.SetVectorModeToUseVector()
    glyphs.OrientOn()
    glyphs.Update()
    ends = vtk_to_numpy(glyphs.GetOutput().GetPoints().GetData()).astype(float).reshape(-1, 2, 3)
    g = read_vtp(path)
    a = g["axis"] * g["coreHalfLength"][:, None]
    error = max(np.max(np.abs(ends[:, 0] - (g["position"] - a))),
                np.max(np.abs(ends[:, 1] - (g["position"] + a))))
    print(f"{len(ends)} line glyphs, largest end error {error:.1e} m")
    assert len(ends) == CAPSULE_COUNT
    assert error < 2 * np.sqrt(np.finfo(float).eps) * np.max(g["coreHalfLength"])
