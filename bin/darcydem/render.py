"""Offscreen pictures of the grains with VTK (python3-vtk9): the grains'
surfaces (postProcessing/grains/capsules_<time>.vtp, capsules and spheres
as they are) or, without capsules, Sphere glyphs of grains_<time>.vtp, as
ParaView shows them. Debian's VTK renders offscreen only through an X display:
virtual_display() starts Xvfb when none is set, and is the one place that
does (bin/plotGrains and tests/paraview use it, no xvfb-run wrapper);
snapshot() renders a scene to a PNG and its pixels for both."""

import contextlib
import os
import subprocess

import numpy as np


@contextlib.contextmanager
def virtual_display():
    """DISPLAY for the block: the user's, or a private Xvfb server."""
    if os.environ.get("DISPLAY"):
        yield os.environ["DISPLAY"]
        return
    read_end, write_end = os.pipe()
    server = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-screen", "0",
                               "1024x768x24", "-nolisten", "tcp"],
                              pass_fds=(write_end,), stderr=subprocess.DEVNULL)
    os.close(write_end)
    # Xvfb writes the number, then a newline: read both before closing (it stops
    # if the newline cannot be written)
    with os.fdopen(read_end) as numbers:
        number = numbers.readline().strip()
    if not number:
        raise RuntimeError("Xvfb did not start (bin/install-dependencies installs it)")
    os.environ["DISPLAY"] = ":" + number
    try:
        yield os.environ["DISPLAY"]
    finally:
        del os.environ["DISPLAY"]
        server.terminate()
        server.wait()


def render_surfaces(path, png, title="", size=(1000, 800), elevation=20, azimuth=30,
                    colour_by="displacement"):
    """Render a capsules_<time>.vtp (polygons with point data) coloured by
    the magnitude of colour_by, blue (least) to red (most), with a colour
    bar and a title, to png. Returns the image (height, width, 3)."""
    import vtkmodules.all as vtk
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    normals = vtk.vtkPolyDataNormals()   # smooth shading, as ParaView's Surface
    normals.SetInputConnection(reader.GetOutputPort())
    magnitude = np.linalg.norm(
        vtk_to_numpy(data.GetPointData().GetArray(colour_by)).reshape(data.GetNumberOfPoints(), -1),
        axis=1)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray(colour_by)
    table = vtk.vtkLookupTable()
    table.SetHueRange(0.667, 0.0)
    table.SetVectorModeToMagnitude()
    table.Build()
    mapper.SetLookupTable(table)
    mapper.SetScalarRange(magnitude.min(), max(magnitude.max(), magnitude.min() + 1e-300))
    mapper.ScalarVisibilityOn()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(table)
    bar.SetTitle(f"|{colour_by}| [m]")
    bar.SetNumberOfLabels(4)
    bar.SetLabelFormat("%.3g")
    bar.GetTitleTextProperty().SetColor(0, 0, 0)
    bar.GetLabelTextProperty().SetColor(0, 0, 0)
    bar.SetWidth(0.1)
    bar.SetHeight(0.5)
    bar.SetPosition(0.87, 0.25)
    text = vtk.vtkTextActor()
    text.SetInput(title)
    text.GetTextProperty().SetColor(0, 0, 0)
    text.GetTextProperty().SetFontSize(20)
    text.SetPosition(10, size[1] - 34)
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)
    renderer.AddActor(actor)
    renderer.AddActor2D(bar)
    renderer.AddActor2D(text)
    # z up; seen from the -y side, turned by azimuth and raised by elevation
    bounds = np.array(data.GetBounds()).reshape(3, 2)
    centre = bounds.mean(axis=1)
    el, az = np.radians(elevation), np.radians(azimuth)
    direction = np.array([np.cos(el) * np.sin(az), -np.cos(el) * np.cos(az), np.sin(el)])
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(*(centre + direction))
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera()
    camera.Zoom(1.05)
    return snapshot(renderer, png, size)


def snapshot(renderer, png, size):
    """Render the renderer's scene offscreen at size (width, height) to png
    (inside virtual_display()); returns the image, (height, width, 3) RGB."""
    import vtkmodules.all as vtk
    from vtkmodules.util.numpy_support import vtk_to_numpy
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(*size)
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(png)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    image = grab.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = np.array(vtk_to_numpy(image.GetPointData().GetScalars())).reshape(height, width, 3)
    window.Finalize()   # let go of the X display before the server stops
    return pixels
