"""pvbatch TestGlass.py CASE PLUGIN OUTPUT_DIR

The RefractionGlass plugin in ParaView itself: one case per run (ctest runs each as
paraview.CASE), pictures written into OUTPUT_DIR. A failure raises (pvbatch then exits
non-zero); success ends the script.

Cases
  scene       a contour as Glass in front of an opaque striped wall: glass of index 1 shows
              exactly the wall and the background (invisible glass), glass of 1.5 shows the
              wall's stripes displaced (refracted), without scene refraction no stripes.
  types       Glass for each data type the Surface representation shows: polydata, the outer
              surface of an unstructured grid, a structured grid and image data, multiblock
              and partitioned data.
  colour      ParaView's colouring (an array through its colour map) tints the glass.
  properties  each Glass property of the view and the representation changes the picture.
  timeseries  the wave equation (the plugin's source) written as a .pvd time series, read
              back, contoured and shown as Glass: frames differ where the surface moved, and
              nowhere else.
  state       the Python state (a trace of the session) records the Glass settings; a state
              file saved with Glass loads and renders the same picture.
  viewfeatures  the glass view draws opaque and translucent data as ParaView's Render View
              does, with FXAA, SSAO, tone mapping and the orientation axes each flipped (each
              changes the Render View's picture, so the comparison is not empty).
  selection   selecting cells on the surface over the whole view selects what ParaView's
              Render View selects (the opaque wall's cells, less those the contour hides: the
              glass is picked as its surface).
"""
import os
import sys

import numpy
from paraview.vtk import vtkCollection

from paraview import servermanager
from paraview.simple import (Calculator, ColorBy, Contour, CreateView, Delete,
                             GetAnimationScene, GetRenderViews, GroupDatasets, Hide, LoadPlugin,
                             LoadState, Plane, ProgrammableSource, PVDReader, Render,
                             ResetSession, SaveData, SaveScreenshot, SaveState,
                             SelectSurfaceCells, SetActiveView, Show, Sphere, Tetrahedralize,
                             Wavelet)

# The shared helpers next to this script, whatever folders pvbatch or pvpython put on the path.
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from glass_images import check_that, read_png  # noqa: E402

SIZE = 240


class Scene:
    """A Render View With Glass, a fixed camera, and pictures saved by name."""

    def __init__(self, plugin, output_dir):
        self.output_dir = output_dir
        os.makedirs(output_dir, exist_ok=True)
        LoadPlugin(plugin, remote=False, ns=globals())
        self.view = CreateView("GlassRenderView")
        self.view.ViewSize = [SIZE, SIZE]
        self.view.OrientationAxesVisibility = 0
        SetActiveView(self.view)
        # paraview.simple resets the camera at a session's first Render: have it done here, so
        # that the cameras the cases set are the ones they get.
        Render(self.view)

    def look(self, distance=45.0):
        self.view.CameraPosition = [0.0, 0.0, distance]
        self.view.CameraFocalPoint = [0.0, 0.0, 0.0]
        self.view.CameraViewUp = [0.0, 1.0, 0.0]
        self.view.CameraParallelProjection = 0

    def picture(self, name):
        Render(self.view)
        path = os.path.join(self.output_dir, name + ".png")
        SaveScreenshot(path, self.view, ImageResolution=[SIZE, SIZE])
        return read_png(path)

    def glass_props(self):
        self.view.UpdatePropertyInformation()
        return self.view.GetProperty("NumberOfGlassProps").GetElement(0)

    def texture_bytes(self):
        self.view.UpdatePropertyInformation()
        return self.view.GetProperty("GlassTextureBytes").GetElement(0)


def wall(view):
    """An opaque wall behind the glass, striped through a colour map."""
    plane = Plane(Origin=[-20, -20, -15], Point1=[20, -20, -15], Point2=[-20, 20, -15],
                  XResolution=200, YResolution=2)
    stripes = Calculator(Input=plane, ResultArrayName="stripes", Function="sin(coordsX*1.5)")
    display = Show(stripes, view)
    ColorBy(display, ("POINTS", "stripes"))
    return display


def blob():
    """A closed contour of the Wavelet: a rippled blob about 14 units across."""
    return Contour(Input=Wavelet(), ContourBy=["POINTS", "RTData"], Isosurfaces=[200.0])


def solid(display):
    """Colour a display by its solid colour (ColorBy(display, None) fails on a display that is
    already uncoloured)."""
    display.ColorArrayName = ["POINTS", ""]


def show_glass(source, view, ior=1.5):
    display = Show(source, view)
    display.SetRepresentationType("Glass")
    display.IndexOfRefraction = ior
    return display


def differing(a, b, tolerance=8):
    """Pixels where two pictures differ by more than tolerance in some channel."""
    return numpy.abs(a - b).max(axis=2) > tolerance


def psnr(a, b):
    """Peak signal-to-noise ratio of two 8-bit pictures, in dB (100 for identical ones)."""
    mse = numpy.mean((a - b) ** 2.0)
    return 100.0 if mse == 0 else 10.0 * numpy.log10(255.0 ** 2 / mse)


def grown(mask, steps=1):
    """The mask and the pixels up to steps pixels next to it."""
    result = mask.copy()
    for _ in range(steps):
        before = result.copy()
        result[1:, :] |= before[:-1, :]
        result[:-1, :] |= before[1:, :]
        result[:, 1:] |= before[:, :-1]
        result[:, :-1] |= before[:, 1:]
    return result


def case_scene(scene):
    view = scene.view
    background_colour = scene.picture("scene_background")[0, 0]
    wall(view)
    glass_source = blob()
    scene.look()
    without = scene.picture("scene_without_glass")
    display = show_glass(glass_source, view)
    display.SetRepresentationType("Surface")
    surface = scene.picture("scene_surface")
    footprint = differing(surface, without)
    check_that(footprint.sum() > 0.05 * SIZE * SIZE,
            "the contour covers %d pixels" % footprint.sum())

    display.SetRepresentationType("Glass")
    solid(display)
    display.IndexOfRefraction = 1.0
    invisible = scene.picture("scene_glass_ior1")
    check_that(scene.glass_props() == 1, "the view drew one glass prop")
    # Index 1 bends nothing; untinted glass lets the wall and the background through as they
    # are (measured: at most 2 levels apart on llvmpipe, from the capture's rounding).
    worst = numpy.abs(invisible - without).max()
    check_that(worst <= 4, "glass of index 1 shows the wall and background unchanged "
            "(largest difference %d levels)" % worst)

    display.IndexOfRefraction = 1.5
    refracted = scene.picture("scene_glass")
    changed = differing(refracted, without) & footprint
    check_that(changed.sum() > 0.3 * footprint.sum(),
            "glass of index 1.5 changes %d of the %d pixels it covers"
            % (changed.sum(), footprint.sum()))
    # The footprint here counts the silhouette's partly covered pixels too (a surface over a
    # few of a pixel's samples changes it by a level or two; the glass is drawn from the
    # pixel's centre and can cover it whole), and the pixels FXAA (on in ParaView by default)
    # blends with the silhouette: up to 3 pixels away (measured: 2).
    touched = grown(differing(surface, without, tolerance=0), 3)
    outside = differing(refracted, without) & ~touched
    check_that(not outside.any(), "the glass changes nothing outside its footprint (%d pixels "
            "outside it differ)" % outside.sum())
    # The wall seen through the glass: its stripes are red and blue (the colour map's ends),
    # so the refracted footprint holds both strongly red and strongly blue pixels.
    inside = refracted[footprint]
    reddish = (inside[:, 0] > inside[:, 2] + 60).mean()
    bluish = (inside[:, 2] > inside[:, 0] + 60).mean()
    check_that(reddish > 0.1 and bluish > 0.1, "the refracted stripes show through the glass "
            "(%.0f %% red, %.0f %% blue pixels)" % (100 * reddish, 100 * bluish))

    view.GlassSceneRefraction = 0
    no_scene = scene.picture("scene_glass_no_scene_refraction")
    inside = no_scene[footprint]
    reddish = (inside[:, 0] > inside[:, 2] + 60).mean()
    check_that(reddish < 0.02, "without scene refraction the stripes do not show (%.1f %% red)"
            % (100 * reddish))
    # ... and the glass shows the environment: the view's background colour.
    off = numpy.abs(inside - background_colour).max(axis=1)
    check_that(numpy.median(off) <= 12, "without scene refraction the glass shows the "
            "background (median %d levels from it)" % numpy.median(off))


def case_types(scene):
    view = scene.view
    scene.look(60.0)
    wavelet = Wavelet(WholeExtent=[-6, 6, -6, 6, -6, 6])
    sources = {
        "polydata": blob(),
        "unstructured grid": Tetrahedralize(Input=wavelet),
        "image data": wavelet,
        "multiblock": GroupDatasets(Input=[blob(), Sphere(Center=[12, 0, 0], Radius=4)]),
    }
    structured = ProgrammableSource(OutputDataSetType="vtkStructuredGrid")
    structured.Script = """
from vtkmodules.vtkCommonDataModel import vtkStructuredGrid
from vtkmodules.vtkCommonCore import vtkPoints
points = vtkPoints()
n = 12
for k in range(n):
    for j in range(n):
        for i in range(n):
            points.InsertNextPoint(i - 5.5 + 0.3 * j, j - 5.5, k - 5.5)
output = self.GetOutput()
output.SetDimensions(n, n, n)
output.SetPoints(points)
"""
    structured.ScriptRequestInformation = """
from paraview import util
util.SetOutputWholeExtent(self, [0, 11, 0, 11, 0, 11])
"""
    sources["structured grid"] = structured
    try:
        from paraview.simple import ConvertToPartitionedDataSetCollection
        sources["partitioned"] = ConvertToPartitionedDataSetCollection(Input=sources["multiblock"])
    except ImportError:
        print("note: this ParaView has no ConvertToPartitionedDataSetCollection; "
              "partitioned data not tried")
    background = None
    for name, source in sources.items():
        display = Show(source, view)
        # Show resets the camera for the first object in a view: look again each time.
        scene.look(60.0)
        if background is None:
            Hide(source, view)
            background = scene.picture("types_background")
            Show(source, view)
            scene.look(60.0)
        display.SetRepresentationType("Surface")
        solid(display)
        surface = scene.picture("types_%s_surface" % name.replace(" ", "_"))
        display.SetRepresentationType("Glass")
        check_that(display.Representation == "Glass", "%s offers the representation Glass" % name)
        display.GlassDispersion = 0.0
        glass = scene.picture("types_%s_glass" % name.replace(" ", "_"))
        footprint = differing(surface, background)
        check_that(scene.glass_props() == 1, "%s: the view drew one glass prop" % name)
        check_that(footprint.sum() > 200, "%s covers %d pixels" % (name, footprint.sum()))
        check_that(differing(glass, surface)[footprint].mean() > 0.5,
                "%s as Glass differs from Surface in %.0f %% of its pixels"
                % (name, 100 * differing(glass, surface)[footprint].mean()))
        check_that(differing(glass, background)[footprint].mean() > 0.05,
                "%s as Glass is visible over the background (%.0f %% of its pixels)"
                % (name, 100 * differing(glass, background)[footprint].mean()))
        Hide(source, view)


def case_colour(scene):
    view = scene.view
    scene.look()
    display = show_glass(blob(), view)
    solid(display)
    display.AmbientColor = [1.0, 1.0, 1.0]
    display.DiffuseColor = [1.0, 1.0, 1.0]
    clear = scene.picture("colour_white")
    ColorBy(display, ("POINTS", "RTData"))
    display.RescaleTransferFunctionToDataRange(True, False)
    lut = display.LookupTable
    lut.ApplyPreset("Blue Orange (divergent)", True)
    coloured = scene.picture("colour_rtdata")
    changed = differing(clear, coloured)
    check_that(changed.sum() > 0.02 * SIZE * SIZE,
            "colouring by RTData tints the glass (%d pixels change)" % changed.sum())
    view.GlassTintFromColours = 0
    untinted = scene.picture("colour_untinted")
    check_that(not differing(untinted, clear).any(),
            "with GlassTintFromColours off the coloured glass is clear again")


def case_properties(scene):
    view = scene.view
    wall(view)
    scene.look()
    # Two nested shells, so that a second layer of glass exists for PEEL to find.
    shells = Contour(Input=Wavelet(), ContourBy=["POINTS", "RTData"], Isosurfaces=[200.0, 240.0])
    display = show_glass(shells, view)
    ColorBy(display, ("POINTS", "RTData"))
    reference = scene.picture("properties_default")

    def changes(name, set_value, reset, expect=True, why=""):
        set_value()
        picture = scene.picture("properties_" + name)
        reset()
        count = differing(picture, reference).sum()
        check_that(count > 20 if expect else True,
                "%s changes %d pixels%s" % (name, count, (" " + why) if why else ""))

    for method in ["SIR", "ISR", "SSP", "PEEL"]:
        changes("GlassMethod=" + method, lambda: setattr(view, "GlassMethod", method),
                lambda: setattr(view, "GlassMethod", "DIR"))
    changes("GlassEnvironment=Built-in sky",
            lambda: setattr(view, "GlassEnvironment", "Built-in sky"),
            lambda: setattr(view, "GlassEnvironment", "Background"))
    changes("GlassSceneRefraction=0", lambda: setattr(view, "GlassSceneRefraction", 0),
            lambda: setattr(view, "GlassSceneRefraction", 1))
    changes("GlassTintFromColours=0", lambda: setattr(view, "GlassTintFromColours", 0),
            lambda: setattr(view, "GlassTintFromColours", 1))
    changes("GlassAbsorptionDistance=2", lambda: setattr(view, "GlassAbsorptionDistance", 2.0),
            lambda: setattr(view, "GlassAbsorptionDistance", 0.0))
    changes("GlassAntiAliasing=1", lambda: setattr(view, "GlassAntiAliasing", 1),
            lambda: setattr(view, "GlassAntiAliasing", 0))
    changes("GlassCoarseShading=1", lambda: setattr(view, "GlassCoarseShading", 1),
            lambda: setattr(view, "GlassCoarseShading", 0))
    changes("GlassExitReflection=0", lambda: setattr(view, "GlassExitReflection", 0),
            lambda: setattr(view, "GlassExitReflection", 1))
    changes("IndexOfRefraction=1.33", lambda: setattr(display, "IndexOfRefraction", 1.33),
            lambda: setattr(display, "IndexOfRefraction", 1.5))
    changes("GlassDispersion=0.05", lambda: setattr(display, "GlassDispersion", 0.05),
            lambda: setattr(display, "GlassDispersion", 0.0))
    # Layers and bounces act only where they apply: layers in PEEL, bounces where a ray meets
    # total internal reflection (dense glass).
    view.GlassMethod = "PEEL"
    reference = scene.picture("properties_peel_4")
    changes("GlassLayers=2 (PEEL)", lambda: setattr(view, "GlassLayers", 2),
            lambda: setattr(view, "GlassLayers", 4))
    # The capture changes how the layers are found, not which: the k-buffer's picture is
    # depth peeling's, and it holds the slots' bytes (4 a pixel for each of the 7 layers behind
    # the front, and a row) beside peeling's targets.
    view.GlassLayers = 8
    view.GlassPeelCapture = "Depth peeling"
    peeled = scene.picture("properties_peel_8_peeling")
    peeled_bytes = scene.texture_bytes()
    view.GlassPeelCapture = "k-buffer"
    sorted_layers = scene.picture("properties_peel_8_k_buffer")
    slot_bytes = scene.texture_bytes() - peeled_bytes
    view.GlassPeelCapture = "Auto"
    view.GlassLayers = 4
    check_that(slot_bytes == 4 * SIZE * (SIZE * 7 + 1),
            "GlassPeelCapture=k-buffer holds %d bytes more than depth peeling (%d expected)"
            % (slot_bytes, 4 * SIZE * (SIZE * 7 + 1)))
    check_that(not differing(sorted_layers, peeled, tolerance=0).any(),
            "GlassPeelCapture=k-buffer draws depth peeling's picture (%d pixels differ)"
            % differing(sorted_layers, peeled, tolerance=0).sum())
    view.GlassMethod = "DIR"
    display.IndexOfRefraction = 2.4
    reference = scene.picture("properties_ior_2.4")
    changes("GlassTIRBounces=2 (index 2.4)", lambda: setattr(view, "GlassTIRBounces", 2),
            lambda: setattr(view, "GlassTIRBounces", 0))
    changes("GlassSmoothInternalReflections=1 (index 2.4)",
            lambda: setattr(view, "GlassSmoothInternalReflections", 1),
            lambda: setattr(view, "GlassSmoothInternalReflections", 0))


def case_timeseries(scene):
    view = scene.view
    path = os.path.join(scene.output_dir, "waves", "waves.pvd")
    # The plugin's source (labelled "Wave Equation"; LoadPlugin defined it in this module).
    waves = WaveEquation(SampleDimensions=32, NumberOfTimeSteps=5, EndTime=0.4)
    # Inline binary, not ParaView's default appended data: with Debian bookworm's expat
    # 2.5.0-1+deb12u5 (reparse deferral), ParaView 5.11 cannot read appended XML files back
    # ("not well-formed (invalid token)"), a ParaView/expat problem, not the plugin's.
    SaveData(path, proxy=waves, WriteTimeSteps=1, DataMode="Binary")
    Delete(waves)
    reader = PVDReader(FileName=path)
    check_that(len(reader.TimestepValues) == 5,
            "the .pvd holds %d time steps" % len(reader.TimestepValues))
    surface_source = Contour(Input=reader, ContourBy=["POINTS", "u"], Isosurfaces=[0.08])
    display = show_glass(surface_source, view)
    view.GlassEnvironment = "Built-in sky"
    view.CameraPosition = [0.0, -1.0, 5.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    animation = GetAnimationScene()
    animation.UpdateAnimationUsingDataTimeSteps()
    frames = []
    surfaces = []
    for index, time in enumerate(reader.TimestepValues[:3]):
        animation.AnimationTime = time
        display.SetRepresentationType("Surface")
        surfaces.append(scene.picture("timeseries_surface_%d" % index))
        display.SetRepresentationType("Glass")
        frames.append(scene.picture("timeseries_glass_%d" % index))
    for index in range(1, len(frames)):
        moved = differing(surfaces[index], surfaces[index - 1])
        glass_changed = differing(frames[index], frames[index - 1])
        check_that(glass_changed.sum() > 50,
                "frame %d differs from frame %d in %d pixels" % (index, index - 1,
                                                                 glass_changed.sum()))
        # Where neither frame has glass the picture is the environment, which does not move.
        # The covered pixels come from the Surface pictures of both frames.
        background = scene_background_mask(surfaces[index - 1], surfaces[index])
        check_that(not glass_changed[background].any(),
                "frame %d changes nothing outside the glass (%d pixels where the surface "
                "moved)" % (index, moved.sum()))


def scene_background_mask(first, second):
    """Pixels that show the plain background in both Surface pictures: the top-left pixel's
    colour, which the camera keeps clear of the data."""
    corner = first[0, 0]
    return (numpy.abs(first - corner).max(axis=2) <= 1) & (numpy.abs(second - corner).max(axis=2) <= 1)


def case_state(scene):
    from paraview import smstate
    view = scene.view
    wall(view)
    scene.look()
    display = show_glass(blob(), view, ior=1.33)
    display.GlassDispersion = 0.02
    view.GlassMethod = "ISR"
    view.GlassEnvironment = "Built-in sky"
    # The Python state (File > Save State as .py, a trace of the whole session) records the
    # Glass settings. (Attribute changes made from Python are not traced by ParaView at all;
    # the GUI's are, through the same properties.)
    python_state = smstate.get_state()
    for line in ["Representation = 'Glass'", "IndexOfRefraction = 1.33",
                 "GlassDispersion = 0.02", "GlassMethod = 'ISR'",
                 "GlassEnvironment = 'Built-in sky'"]:
        check_that(line in python_state, "the Python state records %s" % line)
    before = scene.picture("state_before")
    path = os.path.join(scene.output_dir, "glass.pvsm")
    SaveState(path)
    ResetSession()
    LoadState(path)
    views = [v for v in GetRenderViews() if v.GetXMLName() == "GlassRenderView"]
    check_that(len(views) == 1, "the state file restores the Render View With Glass")
    scene.view = views[0]
    SetActiveView(scene.view)
    scene.view.ViewSize = [SIZE, SIZE]
    check_that(scene.view.GlassMethod == "ISR", "the state keeps GlassMethod (%s)"
            % scene.view.GlassMethod)
    after = scene.picture("state_after")
    worst = numpy.abs(after - before).max()
    check_that(worst <= 2, "the loaded state renders the same picture (largest difference %d)"
            % worst)


def case_viewfeatures(scene):
    glass_view = scene.view
    plain_view = CreateView("RenderView")
    plain_view.ViewSize = [SIZE, SIZE]
    views = [plain_view, glass_view]
    for view in views:
        view.OrientationAxesVisibility = 0
        wall(view)
        Show(blob(), view)
        # Translucent geometry, which ParaView draws with depth peeling.
        veil = Show(Sphere(Center=[4.0, 2.0, 5.0], Radius=5.0, ThetaResolution=32), view)
        veil.Opacity = 0.4
    # Each setting flipped from its default (ParaView's settings turn FXAA on by default; in
    # Python UseSSAO is UseAmbientOcclusion, after its label). Bit-identical but with tone
    # mapping and FXAA together: ParaView's Render View then applies FXAA twice (its pass
    # chain's FXAA pass, and the renderer's own in vtkRenderer::UpdateGeometry), the glass
    # view once (measured 42.7 dB); tone mapping without FXAA is bit-identical again.
    flips = [{}, {"UseFXAA": 0}, {"UseAmbientOcclusion": 1}, {"UseToneMapping": 1},
             {"UseToneMapping": 1, "UseFXAA": 0}, {"OrientationAxesVisibility": 1}]
    baseline = None
    for flip in flips:
        label = ", ".join("%s=%d" % item for item in flip.items()) or "the defaults"
        pictures = []
        for view in views:
            defaults = {name: getattr(view, name) for name in flip}
            for name, value in flip.items():
                setattr(view, name, value)
            view.CameraPosition = [8.0, 6.0, 30.0]
            view.CameraFocalPoint = [0.0, 0.0, -5.0]
            view.CameraViewUp = [0.0, 1.0, 0.0]
            scene.view = view
            pictures.append(scene.picture("viewfeatures_%s_%s" % (
                label.replace(", ", "_").replace(" ", "_"), view.GetXMLName())))
            for name, value in defaults.items():
                setattr(view, name, value)
        if baseline is None:
            baseline = pictures[0]
        else:
            changed = differing(pictures[0], baseline, tolerance=0).sum()
            check_that(changed > 20, "%s changes %d pixels of the Render View" % (label, changed))
        same = psnr(pictures[0], pictures[1])
        wanted = 40.0 if flip == {"UseToneMapping": 1} else 100.0
        check_that(same >= wanted, "with %s the glass view draws the opaque scene as the "
                   "Render View does (%.1f dB, at least %.0f wanted)" % (label, same, wanted))
    scene.view = glass_view


def select_cells(view, sources):
    """Selects the cells on the surface over the whole view (as SelectSurfaceCells does) and
    returns, per name of `sources` (name: source) that the selection reached, its selection
    source's kind and every property's value as text."""
    Render(view)
    representations = vtkCollection()
    selections = vtkCollection()
    view.SelectSurfaceCells([0, 0, SIZE - 1, SIZE - 1], representations, selections, 0)
    result = {}
    for index in range(representations.GetNumberOfItems()):
        selected = representations.GetItemAsObject(index).GetProperty("Input").GetProxy(0)
        names = [name for name, source in sources.items() if source.SMProxy == selected]
        selection = servermanager._getPyProxy(selections.GetItemAsObject(index))
        values = {name: str(selection.GetPropertyValue(name))
                  for name in selection.ListProperties()}
        result[names[0] if names else "other"] = (selection.SMProxy.GetXMLName(), values)
    return result


def case_selection(scene):
    glass_view = scene.view
    plain_view = CreateView("RenderView")
    plain_view.ViewSize = [SIZE, SIZE]
    plain_view.OrientationAxesVisibility = 0
    plane = Plane(Origin=[-20, -20, -15], Point1=[20, -20, -15], Point2=[-20, 20, -15],
                  XResolution=40, YResolution=40)
    glass_source = blob()
    Show(plane, plain_view)
    Show(glass_source, plain_view)
    Show(plane, glass_view)
    show_glass(glass_source, glass_view)
    sources = {"contour": glass_source, "wall": plane}
    selected = {}
    for view in (plain_view, glass_view):
        view.CameraPosition = [0.0, 0.0, 45.0]
        view.CameraFocalPoint = [0.0, 0.0, 0.0]
        view.CameraViewUp = [0.0, 1.0, 0.0]
        scene.view = view
        scene.picture("selection_%s" % view.GetXMLName())
        selected[view.GetXMLName()] = select_cells(view, sources)
    scene.view = glass_view
    plain = selected["RenderView"]
    glass = selected[glass_view.GetXMLName()]
    print("selected in the Render View: %s" % plain)
    print("selected in the glass view: %s" % glass)
    # ParaView 5.11 reports the wall's cells only (not the contour's, in either view); the
    # wall's cells behind the contour are missing from both, so the glass occludes as the
    # surface does.
    check_that("wall" in plain, "the Render View selects cells of the wall")
    check_that(glass == plain, "the glass view selects what the Render View selects")


CASES = {"scene": case_scene, "types": case_types, "colour": case_colour,
         "properties": case_properties, "timeseries": case_timeseries, "state": case_state,
         "viewfeatures": case_viewfeatures, "selection": case_selection}

if len(sys.argv) != 4 or sys.argv[1] not in CASES:
    raise RuntimeError(__doc__)
CASES[sys.argv[1]](Scene(sys.argv[2], sys.argv[3]))
