#!/usr/bin/env python3
"""Python tests of the wrapped modules (ctest label "python").

    TestPythonGlass.py contour EXAMPLES_DIR [--package-under DIR] -V BASELINE.png -T OUTPUT_DIR
        renders examples/glass_contour.py's scene and compares it with the baseline through
        VTK's vtkTesting (the C++ tests' machinery); the same scene drawn without the glass
        must differ from it (the pass really drew glass from Python). With --package-under,
        the package "refraction" must be imported from DIR (the installed one, not the build
        tree's).
    TestPythonGlass.py reference EXAMPLES_DIR
        the Reference module from Python: vtkISRDistanceFilter adds positive, finite d_N to
        the contour, and vtkRefractionReference traces the scene's glass.

Exit status 0 on success; a message and 1 on failure.
"""

import math
import os
import sys

THRESHOLD = 0.15  # VTK's default; two llvmpipe runs give error 0
# VTK's test forgives what a one-pixel shift explains; then, as the C++ tests do
# (tests/common/rfTestBaseline.h), pixel by pixel against the closest of the baseline's
# variants: at most this share of the pixels may differ by more than BASELINE_LEVELS.
BASELINE_LEVELS = 8
BASELINE_CHANGED_SHARE = 0.002
# Glass against plain shading of the same scene: measured 110 on llvmpipe; a pass that drew
# nothing (the actor not seen as glass) gives 0.
MIN_GLASS_DIFFERENCE = 10.0
SIZE = 200


def fail(message):
    print("FAILED: " + message)
    return 1


def grab(window):
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

    capture = vtkWindowToImageFilter()
    capture.SetInput(window)
    capture.ReadFrontBufferOff()
    capture.Update()
    return capture.GetOutput()


def thresholded_error(image_a, image_b):
    from vtkmodules.vtkImagingCore import vtkImageDifference

    difference = vtkImageDifference()
    difference.SetInputData(image_a)
    difference.SetImageData(image_b)
    difference.Update()
    return difference.GetThresholdedError()


def baseline_variant(baseline, variant):
    """VTK's naming of a baseline's variants: name.png, name_1.png, name_2.png, ..."""
    if variant == 0:
        return baseline
    stem, extension = os.path.splitext(baseline)
    return "%s_%d%s" % (stem, variant, extension)


def count_changes(picture, baseline):
    """Pixels of picture that differ from baseline by more than BASELINE_LEVELS in a channel,
    and the largest difference; None where the sizes differ."""
    if picture.GetDimensions() != baseline.GetDimensions():
        return None
    a = picture.GetPointData().GetScalars()
    b = baseline.GetPointData().GetScalars()
    if a.GetNumberOfComponents() < 3 or b.GetNumberOfComponents() < 3:
        return None
    changed = 0
    largest = 0
    for i in range(a.GetNumberOfTuples()):
        d = max(abs(int(a.GetComponent(i, c)) - int(b.GetComponent(i, c))) for c in range(3))
        changed += 1 if d > BASELINE_LEVELS else 0
        largest = max(largest, d)
    return changed, largest


def compare_pixel_by_pixel(picture, baseline, output_dir):
    from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter

    best = None
    variant = 0
    while os.path.isfile(baseline_variant(baseline, variant)):
        reader = vtkPNGReader()
        reader.SetFileName(baseline_variant(baseline, variant))
        reader.Update()
        changes = count_changes(picture, reader.GetOutput())
        if changes is not None and (best is None or changes[0] < best[0]):
            best = (changes[0], changes[1], baseline_variant(baseline, variant))
        variant += 1
    width, height, _ = picture.GetDimensions()
    allowed = int(BASELINE_CHANGED_SHARE * width * height)
    if best is not None:
        print("baseline %s: %d of %d pixels differ by more than %d levels (at most %d may), "
              "largest difference %d" % (best[2], best[0], width * height, BASELINE_LEVELS,
                                         allowed, best[1]))
        if best[0] <= allowed:
            return True
    if output_dir:
        writer = vtkPNGWriter()
        writer.SetInputData(picture)
        writer.SetFileName(os.path.join(output_dir, os.path.basename(baseline)))
        writer.Write()
        print("wrote %s" % writer.GetFileName())
    return False


def test_contour(glass_contour, argv):
    from refraction import vtkRefractionPass
    from vtkmodules.vtkTestingRendering import vtkTesting

    window, renderer, glass_actor, glass_pass = glass_contour.build_scene(SIZE)
    window.SetOffScreenRendering(1)
    window.Render()
    if not vtkRefractionPass.IsGlass(glass_actor):
        return fail("MakeGlass from Python did not mark the actor")
    glass_image = grab(window)

    testing = vtkTesting()
    for argument in argv:
        testing.AddArgument(argument)
    testing.SetRenderWindow(window)
    result = testing.RegressionTest(THRESHOLD)
    if result != vtkTesting.PASSED:
        return fail("image differs from the baseline (vtkTesting result %d)" % result)
    if not compare_pixel_by_pixel(glass_image, testing.GetValidImageFileName(),
                                  testing.GetTempDirectory()):
        return fail("the picture is not its baseline's, pixel by pixel")

    # The same scene with the actor no longer glass: plain VTK shading.
    vtkRefractionPass.ClearGlass(glass_actor)
    window.Render()
    plain_error = thresholded_error(glass_image, grab(window))
    print("glass against plain rendering: thresholded error %.1f" % plain_error)
    if not plain_error > MIN_GLASS_DIFFERENCE:
        return fail("the glass image is no different from the plain one")

    # The optional settings reach Python: dispersion on the actor's keys, anti-aliasing on
    # the pass; each changes the picture.
    vtkRefractionPass.MakeGlass(glass_actor, 1.5)
    if not vtkRefractionPass.SetDispersion(glass_actor, 1.44, 1.5, 1.58):
        return fail("SetDispersion refused valid indices")
    rgb = [0.0, 0.0, 0.0]
    if not vtkRefractionPass.GetDispersion(glass_actor, rgb) or rgb != [1.44, 1.5, 1.58]:
        return fail("GetDispersion gave %s" % rgb)
    glass_pass.SetAntiAliasing(True)
    window.Render()
    optional_error = thresholded_error(glass_image, grab(window))
    print("dispersion and anti-aliasing against the plain glass: thresholded error %.1f"
          % optional_error)
    if not optional_error > 0.0:
        return fail("dispersion and anti-aliasing change nothing")
    return 0


def test_reference(glass_contour):
    from refraction import vtkISRDistanceFilter, vtkRefractionReference

    window, renderer, glass_actor, _ = glass_contour.build_scene(64)
    window.SetOffScreenRendering(1)
    window.Render()

    distances = vtkISRDistanceFilter()
    distances.SetInputConnection(glass_actor.GetMapper().GetInputConnection(0, 0))
    distances.Update()
    array = distances.GetOutput().GetPointData().GetArray(vtkISRDistanceFilter.GetArrayName())
    if array is None or array.GetNumberOfTuples() == 0:
        return fail("vtkISRDistanceFilter added no %s array" % vtkISRDistanceFilter.GetArrayName())
    low, high = array.GetRange()
    print("d_N over %d points: %.4f .. %.4f (%.4f s)"
          % (array.GetNumberOfTuples(), low, high, distances.GetLastComputeSeconds()))
    # The contour is a closed surface inside a 2.4-wide box: every inward ray meets it again.
    if not (math.isfinite(low) and math.isfinite(high) and low > 0.0 and high < 2.4 * math.sqrt(3)):
        return fail("d_N out of (0, box diagonal): %g .. %g" % (low, high))

    reference = vtkRefractionReference()
    if not reference.Trace(renderer, 64, 64):
        return fail("vtkRefractionReference.Trace returned False")
    hits = reference.GetOutput().GetPointData().GetArray("Hit").GetRange()
    print("reference: %d glass actor(s), %d triangles, Hit range %s"
          % (reference.GetNumberOfGlassActors(), reference.GetNumberOfTriangles(), hits))
    if reference.GetNumberOfGlassActors() != 1 or hits[1] <= 0.0:
        return fail("the reference tracer saw no glass")
    return 0


def main(argv):
    if len(argv) < 2 or argv[0] not in ("contour", "reference"):
        print(__doc__)
        return 2
    sys.path.insert(0, os.path.abspath(argv[1]))
    import glass_contour

    if argv[0] == "contour":
        rest = argv[2:]
        if rest[:1] == ["--package-under"]:
            import refraction

            expected = os.path.realpath(rest[1])
            found = os.path.realpath(refraction.__file__)
            print("refraction imported from %s" % found)
            if not found.startswith(expected + os.sep):
                return fail("refraction imported from %s, not from under %s" % (found, expected))
            rest = rest[2:]
        return test_contour(glass_contour, rest)
    return test_reference(glass_contour)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
