"""pvpython TestGlassGUI.py PARAVIEW PLUGIN_DIR OUTPUT_DIR

Starts the ParaView GUI client (PARAVIEW, under the caller's X display: ctest runs under
xvfb-run) with PV_PLUGIN_PATH=PLUGIN_DIR, as a user who loads the plugin that way, running
GlassGUIScript.py; then checks what the GUI wrote: the plugin was loaded, the glass view drew
one glass prop, and its picture differs from the same contour as Surface while showing the
opaque box and sky through it. Raises on failure."""
import os
import subprocess
import sys

import numpy

# The shared helpers next to this script, whatever folders pvbatch or pvpython put on the path.
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from glass_images import check_that, read_png  # noqa: E402


if len(sys.argv) != 4:
    raise RuntimeError(__doc__)
paraview, plugin_dir, output = sys.argv[1:]
os.makedirs(output, exist_ok=True)
for name in ("gui_result.txt", "gui_glass.png", "gui_surface.png"):
    if os.path.exists(os.path.join(output, name)):
        os.remove(os.path.join(output, name))
environment = dict(os.environ, PV_PLUGIN_PATH=plugin_dir, RF_GUI_OUTPUT=output)
script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "GlassGUIScript.py")
# --dr: no settings or recent files of a user's home; the GUI starts as on a new account.
completed = subprocess.run([paraview, "--dr", "--script=" + script, "--exit"], env=environment,
                           timeout=600)
check_that(completed.returncode == 0, "the ParaView GUI ran the script and exited with %d"
           % completed.returncode)
with open(os.path.join(output, "gui_result.txt")) as result:
    text = result.read()
print(text)
check_that("glass view defined: 1" in text, "PV_PLUGIN_PATH loaded the plugin in the GUI")
check_that("glass props: 1" in text, "the GUI's glass view drew one glass prop")
glass = read_png(os.path.join(output, "gui_glass.png"))
surface = read_png(os.path.join(output, "gui_surface.png"))
changed = numpy.abs(glass - surface).max(axis=2) > 8
# The contour covers about 5 % of the 400 x 300 picture (measured 5.5 %), nearly all of it
# changed as Glass.
check_that(changed.mean() > 0.03, "Glass differs from Surface in %.1f %% of the picture"
           % (100 * changed.mean()))
# The Surface is dark blue; as Glass the light box and sky behind show through it, tinted.
lighter = glass[changed].mean(axis=1) > surface[changed].mean(axis=1) + 30
check_that(lighter.mean() > 0.5, "the box and sky show through the glass (%.0f %% of its "
           "pixels are lighter than the Surface's)" % (100 * lighter.mean()))
