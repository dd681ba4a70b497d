#!/usr/bin/env python3
"""A contour drawn as refractive glass, from Python.

A contour of a scalar field (Gaussian blobs from vtkGaussianSplatter through
vtkFlyingEdges3D) is marked as glass and drawn by vtkRefractionPass over the built-in
environment, beside an opaque cone. Run it with the package on PYTHONPATH (see docs/user-guide.md, "Using it from Python"):

    python3 examples/glass_contour.py                   # a window (needs a display)
    python3 examples/glass_contour.py --output glass.png --size 400
    python3 examples/glass_contour.py --method sir --output sir.png

build_scene() is what the Python tests render, so this file is tested as it is.
"""

import argparse
import sys

import vtkmodules.vtkInteractionStyle  # noqa: F401  (the interactor's default style)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL render window)
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D
from vtkmodules.vtkFiltersSources import vtkConeSource
from vtkmodules.vtkImagingHybrid import vtkGaussianSplatter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkRenderWindowInteractor,
    vtkWindowToImageFilter,
)

from refraction import vtkRefractionPass

METHODS = {
    "dir": vtkRefractionPass.DIR,
    "sir": vtkRefractionPass.SIR,
    "isr": vtkRefractionPass.ISR,
    "ssp": vtkRefractionPass.SSP,
    "peel": vtkRefractionPass.PEEL,
}
# SH needs a vtkSHTransferFilter before the glass's mapper (a precomputation for static
# meshes), which this re-contoured surface does not have.


def build_scene(size=300, method="dir", index_of_refraction=1.5):
    """Return (window, renderer, glass_actor, glass_pass) for a size x size window."""
    # Four Gaussian blobs splatted into a 48^3 image; their 0.4 contour is one smooth,
    # closed surface (metaballs).
    centres = vtkPoints()
    for centre in ((-0.45, -0.2, 0.0), (0.4, -0.3, 0.1), (0.0, 0.45, -0.1), (0.05, 0.0, 0.45)):
        centres.InsertNextPoint(centre)
    blobs = vtkPolyData()
    blobs.SetPoints(centres)
    field = vtkGaussianSplatter()
    field.SetInputData(blobs)
    field.SetSampleDimensions(48, 48, 48)
    field.SetModelBounds(-1.2, 1.2, -1.2, 1.2, -1.2, 1.2)
    field.SetRadius(0.3)
    field.SetExponentFactor(-4.0)
    field.ScalarWarpingOff()
    field.SetAccumulationModeToSum()
    contour = vtkFlyingEdges3D()
    contour.SetInputConnection(field.GetOutputPort())
    contour.SetValue(0, 0.4)
    contour.ComputeNormalsOn()

    glass_mapper = vtkPolyDataMapper()
    glass_mapper.SetInputConnection(contour.GetOutputPort())
    glass_mapper.ScalarVisibilityOff()
    glass_actor = vtkActor()
    glass_actor.SetMapper(glass_mapper)
    if not vtkRefractionPass.MakeGlass(glass_actor, index_of_refraction):
        raise ValueError("index of refraction %r rejected" % index_of_refraction)

    cone = vtkConeSource()
    cone.SetResolution(48)
    cone.SetHeight(1.2)
    cone.SetRadius(0.4)
    cone.SetCenter(1.1, -0.2, -0.8)
    cone.SetDirection(0.0, 1.0, 0.0)
    cone_mapper = vtkPolyDataMapper()
    cone_mapper.SetInputConnection(cone.GetOutputPort())
    cone_actor = vtkActor()
    cone_actor.SetMapper(cone_mapper)
    cone_actor.GetProperty().SetColor(0.9, 0.45, 0.1)

    glass_pass = vtkRefractionPass()
    glass_pass.SetMethod(METHODS[method])
    # The glass shows this renderer's scene and, where its rays meet nothing, the renderer's
    # background; the built-in sky is named here to make the picture easier to read (and it is
    # what the regression baseline shows).
    glass_pass.SetEnvironmentModeToBuiltin()

    renderer = vtkRenderer()
    renderer.SetBackground(0.1, 0.1, 0.12)
    renderer.AddActor(glass_actor)
    renderer.AddActor(cone_actor)
    renderer.SetPass(glass_pass)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0.3, 0.0, -0.2)
    camera.SetPosition(0.6, 0.8, 4.2)
    camera.SetViewUp(0.0, 1.0, 0.0)
    renderer.ResetCameraClippingRange()

    window = vtkRenderWindow()
    window.SetSize(size, size)
    window.AddRenderer(renderer)
    return window, renderer, glass_actor, glass_pass


def write_png(window, path):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=400, help="window size in pixels")
    parser.add_argument("--method", choices=sorted(METHODS), default="dir")
    parser.add_argument("--ior", type=float, default=1.5, help="index of refraction")
    parser.add_argument("--output", help="render off screen into this PNG instead of a window")
    args = parser.parse_args(argv)
    if args.size < 1:
        parser.error("--size must be at least 1")
    try:
        window, _, _, _ = build_scene(args.size, args.method, args.ior)
    except ValueError as error:
        parser.error(str(error))
    if args.output:
        window.SetOffScreenRendering(1)
        window.Render()
        write_png(window, args.output)
        print("wrote %s" % args.output)
        return 0
    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    window.Render()
    interactor.Start()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
