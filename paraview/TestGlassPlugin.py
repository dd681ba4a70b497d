"""pvbatch TestGlassPlugin.py PLUGIN OUTPUT_DIR

Loads the RefractionGlass plugin, shows a contour of the Wavelet source as Glass in a
GlassRenderView, and checks that the view's pass drew one glass prop and that the picture
differs from the same contour shown as Surface. Writes glass.png and surface.png into
OUTPUT_DIR. Exit status 0 on success.
"""
import os
import sys

from paraview.simple import (Contour, CreateView, LoadPlugin, Render, SaveScreenshot, Show,
                             Wavelet)
from paraview.vtk.vtkImagingCore import vtkImageDifference
from paraview.vtk.vtkIOImage import vtkPNGReader

# Glass against Surface: identical pictures give 0 (VTK's thresholded image error).
MIN_GLASS_DIFFERENCE = 10.0


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def main(plugin, output_dir):
    os.makedirs(output_dir, exist_ok=True)
    LoadPlugin(plugin, remote=False, ns=globals())
    view = CreateView("GlassRenderView")
    view.ViewSize = [200, 200]
    view.OrientationAxesVisibility = 0

    wavelet = Wavelet()
    contour = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[157.0])
    display = Show(contour, view)
    display.SetRepresentationType("Glass")
    display.IndexOfRefraction = 1.5
    view.ResetCamera()
    Render(view)
    glass_path = os.path.join(output_dir, "glass.png")
    SaveScreenshot(glass_path, view, ImageResolution=[200, 200])
    glass_props = view.GetClientSideObject().GetNumberOfGlassProps()

    display.SetRepresentationType("Surface")
    Render(view)
    surface_path = os.path.join(output_dir, "surface.png")
    SaveScreenshot(surface_path, view, ImageResolution=[200, 200])

    difference = vtkImageDifference()
    difference.SetInputData(read_png(glass_path))
    difference.SetImageData(read_png(surface_path))
    difference.Update()
    error = difference.GetThresholdedError()
    print("glass props drawn: %d; Glass against Surface: thresholded error %.1f" % (glass_props, error))
    if glass_props != 1:
        print("FAILED: the view's pass drew %d glass props, expected 1" % glass_props)
        return 1
    if not error > MIN_GLASS_DIFFERENCE:
        print("FAILED: Glass looks like Surface")
        return 1
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
