#include "rfTestBaseline.h"

#include "rfTestPNG.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkRegressionTestImage.h>
#include <vtkSmartPointer.h>
#include <vtkTesting.h>
#include <vtkWindowToImageFilter.h>
#include <vtksys/SystemTools.hxx>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace rftest
{
namespace
{
struct Changes
{
  long Changed = -1; // pixels beyond kBaselineLevels; -1: the sizes differ
  int Largest = 0;   // the largest channel difference
};

Changes CountChanges(vtkImageData* picture, vtkImageData* baseline)
{
  Changes changes;
  const int* size = picture->GetDimensions();
  const int* baselineSize = baseline->GetDimensions();
  if (size[0] != baselineSize[0] || size[1] != baselineSize[1] ||
    baseline->GetNumberOfScalarComponents() < 3)
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

// VTK's naming of a baseline's variants: name.png, name_1.png, name_2.png, ...
std::string BaselineVariant(const std::string& baseline, int variant)
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

vtkSmartPointer<vtkImageData> ReadPNG(const std::string& path)
{
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(reader->GetOutput());
  return image;
}
}

int CompareWithBaseline(int argc, char* argv[], vtkRenderWindow* window, double vtkThreshold)
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
  std::string closest;
  Changes best;
  for (int variant = 0;; ++variant)
  {
    const std::string path = BaselineVariant(baseline, variant);
    if (!vtksys::SystemTools::FileExists(path, true))
    {
      break;
    }
    const Changes changes = CountChanges(picture, ReadPNG(path));
    if (changes.Changed >= 0 && (best.Changed < 0 || changes.Changed < best.Changed))
    {
      best = changes;
      closest = path;
    }
  }
  const int* size = picture->GetDimensions();
  const long allowed = static_cast<long>(kBaselineChangedShare * size[0] * size[1]);
  if (best.Changed >= 0)
  {
    std::printf("baseline %s: %ld of %d pixels differ by more than %d levels (at most %ld "
                "may), largest difference %d\n",
      closest.c_str(), best.Changed, size[0] * size[1], kBaselineLevels, allowed, best.Largest);
  }
  if (best.Changed >= 0 && best.Changed <= allowed)
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
