"""Pictures and checks shared by the ParaView plugin's tests (TestGlass.py, TestGlassGUI.py)."""
import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader


def read_png(path):
    """A PNG as an int32 array of rows x columns x RGB."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(height, width, -1)[:, :, :3].astype(numpy.int32)


def check_that(condition, message):
    """Print the check's outcome; raise on failure (pvbatch and pvpython then exit non-zero)."""
    print(("ok: " if condition else "FAILED: ") + message)
    if not condition:
        raise RuntimeError(message)
