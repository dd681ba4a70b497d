// The regression-image check every baseline test makes: VTK's, and a closer one beside it.
#ifndef rfTestBaseline_h
#define rfTestBaseline_h

#include <vtkRenderWindow.h>

namespace rftest
{
/**
 * Renders the window and compares its picture with the baseline named by -V (and its
 * variants name_1.png, name_2.png, ..., as VTK does), returning EXIT_SUCCESS or EXIT_FAILURE.
 *
 * First VTK's regression test at `vtkThreshold`. It forgives what a one-pixel shift explains
 * (each pixel is matched with the best of its neighbours), so a refraction that moves every
 * checker edge by a pixel, or a rim that turns from stair steps to a smooth edge, reads as
 * error 0 there. Then, against the closest variant, pixel by pixel: at most
 * kBaselineChangedShare of the pixels may differ from it by more than kBaselineLevels in a
 * channel. llvmpipe renders the same picture twice to the bit, so what this admits is room
 * for another CPU's rounding, not for a changed picture. On failure the picture is written
 * into -T as NAME.png (NAME: the baseline's), beside VTK's own files, for a person to look at
 * before it replaces a baseline.
 */
int CompareWithBaseline(int argc, char* argv[], vtkRenderWindow* window, double vtkThreshold);

/// A channel difference (of 255) that counts a pixel as changed. Small changes must count: the
/// speckle DIR's exit reflection once left on a sphere differed from the right picture by at
/// most 15 levels, in 60 of 16384 pixels by more than 8 (VTK's error: 0).
constexpr int kBaselineLevels = 8;
/// The share of the pixels that may change by more than kBaselineLevels (32 of 128 x 128).
constexpr double kBaselineChangedShare = 0.002;
}

#endif
