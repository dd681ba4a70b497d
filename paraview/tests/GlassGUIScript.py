"""Run by the ParaView GUI client (paraview --script=GlassGUIScript.py --exit), started by
TestGlassGUI.py with PV_PLUGIN_PATH naming the plugin's folder and RF_GUI_OUTPUT a folder for
what it writes: the plugin must already be loaded (as a user's PV_PLUGIN_PATH loads it). It
replaces the layout's Render View by a Render View With Glass, shows a contour of the wave
equation as Glass over the built-in sky with an opaque box behind it, and saves
gui_glass.png and gui_surface.png (the same contour as Surface) and gui_result.txt (the
plugin and view it found)."""
import os

from paraview import servermanager
from paraview.simple import (AssignViewToLayout, Box, Contour, CreateView, Delete,
                             GetActiveView, GetLayout, Render, SaveScreenshot, SetActiveView,
                             Show)

output = os.environ["RF_GUI_OUTPUT"]
lines = []
prototype = servermanager.ProxyManager().GetPrototypeProxy("views", "GlassRenderView")
lines.append("glass view defined: %d" % (prototype is not None))
if prototype is not None:
    layout = GetLayout()
    old = GetActiveView()
    if old is not None:
        Delete(old)
    view = CreateView("GlassRenderView")
    AssignViewToLayout(view=view, layout=layout, hint=0)
    SetActiveView(view)
    view.OrientationAxesVisibility = 1
    view.GlassEnvironment = "Built-in sky"
    from paraview import simple  # the plugin's source is defined there once loaded
    waves = simple.WaveEquation(NumberOfTimeSteps=10, EndTime=1.0)
    contour = Contour(Input=waves, ContourBy=["POINTS", "u"], Isosurfaces=[0.08])
    box = Box(XLength=2.5, YLength=2.5, ZLength=0.1, Center=[0.0, 0.0, -1.6])
    Show(box, view)
    display = Show(contour, view)
    display.SetRepresentationType("Glass")
    view.CameraPosition = [0.0, -1.5, 5.0]
    view.CameraFocalPoint = [0.0, 0.0, -0.3]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    Render(view)
    SaveScreenshot(os.path.join(output, "gui_glass.png"), view, ImageResolution=[400, 300])
    view.UpdatePropertyInformation()
    lines.append("glass props: %d" % view.GetProperty("NumberOfGlassProps").GetElement(0))
    display.SetRepresentationType("Surface")
    Render(view)
    SaveScreenshot(os.path.join(output, "gui_surface.png"), view, ImageResolution=[400, 300])
    display.SetRepresentationType("Glass")
    Render(view)
with open(os.path.join(output, "gui_result.txt"), "w") as result:
    result.write("\n".join(lines) + "\n")
