"""mpiexec -n RANKS pvbatch BenchGlassMPI.py PLUGIN OUTPUT_DIR [EXTENT] [SIZE] [REPEATS]

Glass across MPI ranks at scale: a large contour of the Wavelet (its whole extent
[-EXTENT, EXTENT]^3, three iso-values: millions of triangles at EXTENT 150), split over the
ranks, shown as Glass in front of the plain-VTK version of the same data (a Surface of it),
rendered at SIZE x SIZE. For each method and for plain rendering, REPEATS timed frames,
interleaved (plain, DIR, SIR, ISR, SSP, PEEL, plain, DIR, ...). Writes OUTPUT_DIR/rows.csv
(appending: one run per rank count) and each method's last picture, which
CompareGlassMPI.py compares with one rank's.

Columns: ranks, method, triangles, size, median_ms, min_ms, max_ms (wall-clock of a still
render on rank 0, which includes the compositing), plain_ms (the median of the plain frames of
the same run), ratio (median_ms / plain_ms), composite_ms (rank 0's G-buffer compositing, the
median), wait_ms (of composite_ms, the time rank 0 was blocked receiving: waiting for slower
ranks and the messages), buffer_bytes (one rank's G-buffers), bytes_per_frame (ranks - 1
buffers sent).
"""
import csv
import os
import statistics
import sys
import time

from paraview import servermanager
from paraview.simple import (Contour, CreateView, Hide, LoadPlugin, Render, SaveScreenshot,
                             SetActiveView, Show, Wavelet)

plugin, output = sys.argv[1], sys.argv[2]
extent = int(sys.argv[3]) if len(sys.argv) > 3 else 150
size = int(sys.argv[4]) if len(sys.argv) > 4 else 512
repeats = int(sys.argv[5]) if len(sys.argv) > 5 else 5
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
os.makedirs(output, exist_ok=True)
LoadPlugin(plugin, remote=False, ns=globals())

view = CreateView("GlassRenderView")
view.ViewSize = [size, size]
view.OrientationAxesVisibility = 0
view.UseFXAA = 0  # as in TestGlassMPI.py: FXAA is not part of the compositing measured here
SetActiveView(view)
wavelet = Wavelet(WholeExtent=[-extent, extent] * 3)
contour = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"],
                  Isosurfaces=[130.0, 160.0, 200.0])
contour.UpdatePipeline()
triangles = contour.GetDataInformation().GetNumberOfCells()
glass = Show(contour, view)
glass.SetRepresentationType("Glass")
glass.IndexOfRefraction = 1.5
glass.ColorArrayName = ["POINTS", ""]
scale = extent / 10.0
view.CameraPosition = [14.0 * scale, 10.0 * scale, 38.0 * scale]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
Render(view)

methods = [("plain", None), ("DIR", 1), ("SIR", 0), ("ISR", 2), ("SSP", 3), ("PEEL", 4)]
times = {name: [] for name, _ in methods}
composite = {name: [] for name, _ in methods}
waiting = {name: [] for name, _ in methods}
buffer_bytes = {name: 0 for name, _ in methods}


def frame(name, value):
    if value is None:
        glass.SetRepresentationType("Surface")
    else:
        glass.SetRepresentationType("Glass")
        view.GlassMethod = value
    Render(view)  # the method's first frame builds its shaders and targets: not timed
    start = time.perf_counter()
    Render(view)
    elapsed = 1000.0 * (time.perf_counter() - start)
    view.UpdatePropertyInformation()
    return elapsed


for repeat in range(repeats):
    for name, value in methods:
        times[name].append(frame(name, value))
        composite[name].append(view.GetProperty("GlassCompositeMilliseconds").GetElement(0))
        waiting[name].append(view.GetProperty("GlassCompositeWaitMilliseconds").GetElement(0))
        buffer_bytes[name] = int(view.GetProperty("GlassCompositeBufferBytes").GetElement(0))
        if repeat == repeats - 1:
            SaveScreenshot(os.path.join(output, "ranks%d_%s.png" % (ranks, name)), view,
                           ImageResolution=[size, size])

path = os.path.join(output, "rows.csv")
new = not os.path.exists(path)
plain = statistics.median(times["plain"])
with open(path, "a", newline="") as handle:
    writer = csv.writer(handle)
    if new:
        writer.writerow(["ranks", "method", "triangles", "size", "median_ms", "min_ms", "max_ms",
                         "plain_ms", "ratio", "composite_ms", "wait_ms", "buffer_bytes",
                         "bytes_per_frame"])
    for name, _ in methods:
        median = statistics.median(times[name])
        writer.writerow([ranks, name, triangles, size, "%.1f" % median,
                         "%.1f" % min(times[name]), "%.1f" % max(times[name]),
                         "%.1f" % plain, "%.2f" % (median / plain),
                         "%.1f" % statistics.median(composite[name]),
                         "%.1f" % statistics.median(waiting[name]), buffer_bytes[name],
                         (ranks - 1) * buffer_bytes[name]])
print("ranks %d, %d triangles, plain %.1f ms" % (ranks, triangles, plain))
