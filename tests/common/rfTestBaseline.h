// The regression-image check every baseline test makes: VTK's, and a closer one beside it.
// Header-only, VTK only: the installed package's consumer programs (tests/install), which know
// nothing of this build, make the same check as the tests.
#ifndef rfTestBaseline_h
#define rfTestBaseline_h

#include "rfTestPNG.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkRegressionTestImage.h>
#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>
#include <vtkTesting.h>
#include <vtkWindowToImageFilter.h>
#include <vtksys/SystemTools.hxx>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace rftest
{
/// A channel difference (of 255) that counts a pixel as changed. Small changes must count: the
/// speckle DIR's exit reflection once left on a sphere differed from the right picture by at
/// most 15 levels, in 60 of 16384 pixels by more than 8 (VTK's error: 0).
constexpr int kBaselineLevels = 8;
/// The share of the pixels that may change by more than kBaselineLevels (32 of 128 x 128).
constexpr double kBaselineChangedShare = 0.002;

/// How a picture differs from the closest of a baseline's variants.
struct BaselineChanges
{
  std::string Closest; // the variant's path; empty when none has the picture's size
  long Changed = -1;   // pixels beyond kBaselineLevels; -1: no variant of the picture's size
  int Largest = 0;     // the largest channel difference
  long Allowed = 0;    // kBaselineChangedShare of the picture's pixels

  bool Passed() const { return this->Changed >= 0 && this->Changed <= this->Allowed; }
};

inline BaselineChanges CountBaselineChanges(vtkImageData* picture, vtkImageData* baseline)
{
  BaselineChanges changes;
  const int* size = picture->GetDimensions();
  const int* baselineSize = baseline->GetDimensions();
  if (size[0] != baselineSize[0] || size[1] != baselineSize[1] ||
    picture->GetNumberOfScalarComponents() < 3 || baseline->GetNumberOfScalarComponents() < 3)
  {
    return changes;
  }
  changes.Changed = 0;
  for (int y = 0; y < size[1]; ++y)
  {
    for (int x = 0; x < size[0]; ++x)
    {
      int largest = 0;
      for (int c = 0; c < 3; ++c)
      {
        const int d = std::abs(static_cast<int>(picture->GetScalarComponentAsDouble(x, y, 0, c)) -
          static_cast<int>(baseline->GetScalarComponentAsDouble(x, y, 0, c)));
        largest = d > largest ? d : largest;
      }
      changes.Changed += largest > kBaselineLevels ? 1 : 0;
      changes.Largest = largest > changes.Largest ? largest : changes.Largest;
    }
  }
  return changes;
}

/// VTK's naming of a baseline's variants: name.png, name_1.png, name_2.png, ...
inline std::string BaselineVariant(const std::string& baseline, int variant)
{
  if (variant == 0)
  {
    return baseline;
  }
  const std::string::size_type dot = baseline.rfind('.');
  const std::string::size_type slash = baseline.find_last_of("/\\");
  const bool hasExtension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string suffix = "_" + std::to_string(variant);
  return hasExtension ? baseline.substr(0, dot) + suffix + baseline.substr(dot) : baseline + suffix;
}

/// The picture against the closest of the baseline's variants that exist.
inline BaselineChanges CompareWithClosestBaseline(vtkImageData* picture, const std::string& baseline)
{
  BaselineChanges best;
  for (int variant = 0;; ++variant)
  {
    const std::string path = BaselineVariant(baseline, variant);
    if (!vtksys::SystemTools::FileExists(path, true))
    {
      break;
    }
    vtkNew<vtkPNGReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    BaselineChanges changes = CountBaselineChanges(picture, reader->GetOutput());
    if (changes.Changed >= 0 && (best.Changed < 0 || changes.Changed < best.Changed))
    {
      best = changes;
      best.Closest = path;
    }
  }
  const int* size = picture->GetDimensions();
  best.Allowed = static_cast<long>(kBaselineChangedShare * size[0] * size[1]);
  return best;
}

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
inline int CompareWithBaseline(int argc, char* argv[], vtkRenderWindow* window, double vtkThreshold)
{
  window->Render();
  if (vtkRegressionTestImageThreshold(window, vtkThreshold) == vtkTesting::FAILED)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkTesting> testing;
  for (int i = 0; i < argc; ++i)
  {
    testing->AddArgument(argv[i]);
  }
  if (!testing->IsValidImageSpecified())
  {
    return EXIT_SUCCESS; // no -V: VTK's test above has said so
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* picture = grab->GetOutput();

  const std::string baseline = testing->GetValidImageFileName();
  const BaselineChanges best = CompareWithClosestBaseline(picture, baseline);
  const int* size = picture->GetDimensions();
  if (best.Changed >= 0)
  {
    std::printf("baseline %s: %ld of %d pixels differ by more than %d levels (at most %ld "
                "may), largest difference %d\n",
      best.Closest.c_str(), best.Changed, size[0] * size[1], kBaselineLevels, best.Allowed,
      best.Largest);
  }
  if (best.Passed())
  {
    return EXIT_SUCCESS;
  }
  if (best.Changed < 0)
  {
    std::fprintf(stderr, "FAILED: no baseline of the picture's size %d x %d beside %s\n",
      size[0], size[1], baseline.c_str());
  }
  else
  {
    std::fprintf(stderr, "FAILED: the picture is not its baseline's, pixel by pixel\n");
  }
  const char* directory = testing->GetTempDirectory();
  if (directory)
  {
    WritePNG(picture, std::string(directory) + "/" +
      vtksys::SystemTools::GetFilenameName(baseline));
  }
  return EXIT_FAILURE;
}
}

#endif
