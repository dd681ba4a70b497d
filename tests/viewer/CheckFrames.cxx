// Checks the PNGs the viewer and the demo write.
//   image FILE [WIDTH HEIGHT]  readable, of that size, not empty: at least 1 % of the pixels
//                              differ from the corner's colour, in at least 50 colours
//   series FOLDER COUNT        frame_0000.png ... each an image as above, consecutive frames
//                              differ in at least 0.2 % of the pixels
//   follow FOLDER COUNT        frames and the glass's masks (mask_NNNN.png) of a deforming
//                              surface: between consecutive frames the silhouette moves,
//                              nearly every pixel where it moved changes, and nothing changes
//                              away from the glass (the glass follows the surface)
#include "../common/rf_require.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

namespace
{
// A pixel changed when a channel moves by more than this (8-bit).
const int kChange = 8;

vtkSmartPointer<vtkImageData> Read(const std::string& path)
{
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    return nullptr;
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(reader->GetOutput());
  return image;
}

int Channel(vtkImageData* image, int x, int y, int c)
{
  return static_cast<int>(image->GetScalarComponentAsDouble(x, y, 0, c));
}

bool Differs(vtkImageData* a, int ax, int ay, vtkImageData* b, int bx, int by)
{
  for (int c = 0; c < 3; ++c)
  {
    if (std::abs(Channel(a, ax, ay, c) - Channel(b, bx, by, c)) > kChange)
    {
      return true;
    }
  }
  return false;
}

std::string Frame(const std::string& folder, const char* kind, int k)
{
  char name[32];
  std::snprintf(name, sizeof(name), "/%s_%04d.png", kind, k);
  return folder + name;
}

int CheckImage(const std::string& path, int width, int height)
{
  vtkSmartPointer<vtkImageData> image = Read(path);
  RF_REQUIRE(image, "cannot read %s as PNG", path.c_str());
  const int* dims = image->GetDimensions();
  RF_REQUIRE(width <= 0 || (dims[0] == width && dims[1] == height), "%s is %dx%d, not %dx%d",
    path.c_str(), dims[0], dims[1], width, height);
  RF_REQUIRE(image->GetNumberOfScalarComponents() >= 3, "%s is not RGB", path.c_str());
  long different = 0;
  std::set<long> colours;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      if (Differs(image, x, y, image, 0, 0))
      {
        ++different;
        colours.insert((Channel(image, x, y, 0) << 16) | (Channel(image, x, y, 1) << 8) |
          Channel(image, x, y, 2));
      }
    }
  }
  const long pixels = static_cast<long>(dims[0]) * dims[1];
  std::printf("%s: %ld of %ld pixels differ from the corner, %zu colours\n", path.c_str(),
    different, pixels, colours.size());
  RF_REQUIRE(different * 100 >= pixels, "%s is empty (%ld pixels differ from the corner)",
    path.c_str(), different);
  RF_REQUIRE(colours.size() >= 50, "%s shows only %zu colours: not glass", path.c_str(),
    colours.size());
  return EXIT_SUCCESS;
}

int CheckSeries(const std::string& folder, int count)
{
  for (int k = 0; k < count; ++k)
  {
    if (CheckImage(Frame(folder, "frame", k), 0, 0) != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
  }
  for (int k = 0; k + 1 < count; ++k)
  {
    vtkSmartPointer<vtkImageData> a = Read(Frame(folder, "frame", k));
    vtkSmartPointer<vtkImageData> b = Read(Frame(folder, "frame", k + 1));
    const int* dims = a->GetDimensions();
    long changed = 0;
    for (int y = 0; y < dims[1]; ++y)
    {
      for (int x = 0; x < dims[0]; ++x)
      {
        changed += Differs(a, x, y, b, x, y) ? 1 : 0;
      }
    }
    const long pixels = static_cast<long>(dims[0]) * dims[1];
    std::printf("frames %d -> %d: %ld pixels changed\n", k, k + 1, changed);
    RF_REQUIRE(changed * 500 >= pixels, "frames %d and %d are (nearly) the same: %ld pixels", k,
      k + 1, changed);
  }
  return EXIT_SUCCESS;
}

int CheckFollow(const std::string& folder, int count)
{
  const int dilation = 2;
  for (int k = 0; k + 1 < count; ++k)
  {
    vtkSmartPointer<vtkImageData> a = Read(Frame(folder, "frame", k));
    vtkSmartPointer<vtkImageData> b = Read(Frame(folder, "frame", k + 1));
    vtkSmartPointer<vtkImageData> maskA = Read(Frame(folder, "mask", k));
    vtkSmartPointer<vtkImageData> maskB = Read(Frame(folder, "mask", k + 1));
    RF_REQUIRE(a && b && maskA && maskB, "frames or masks %d, %d missing in %s", k, k + 1,
      folder.c_str());
    const int* dims = a->GetDimensions();
    const int w = dims[0];
    const int h = dims[1];
    std::vector<char> inA(w * h), inB(w * h), near(w * h, 0);
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        inA[y * w + x] = Channel(maskA, x, y, 0) > 127;
        inB[y * w + x] = Channel(maskB, x, y, 0) > 127;
      }
    }
    // Near the glass: within a few pixels of either silhouette (edges are not exact).
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        if (!(inA[y * w + x] || inB[y * w + x]))
        {
          continue;
        }
        for (int dy = -dilation; dy <= dilation; ++dy)
        {
          for (int dx = -dilation; dx <= dilation; ++dx)
          {
            const int nx = x + dx;
            const int ny = y + dy;
            if (nx >= 0 && ny >= 0 && nx < w && ny < h)
            {
              near[ny * w + nx] = 1;
            }
          }
        }
      }
    }
    long moved = 0;
    long movedAndChanged = 0;
    long changedAway = 0;
    long changed = 0;
    long glass = 0;
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        const int i = y * w + x;
        const bool change = Differs(a, x, y, b, x, y);
        changed += change ? 1 : 0;
        glass += inB[i] ? 1 : 0;
        if (inA[i] != inB[i])
        {
          ++moved;
          movedAndChanged += change ? 1 : 0;
        }
        if (change && !near[i])
        {
          ++changedAway;
        }
      }
    }
    std::printf("frames %d -> %d: glass %ld px, silhouette moved over %ld px, %ld of them "
                "changed; %ld px changed in all, %ld away from the glass\n",
      k, k + 1, glass, moved, movedAndChanged, changed, changedAway);
    RF_REQUIRE(glass > 100, "frame %d has hardly any glass (%ld px)", k + 1, glass);
    RF_REQUIRE(moved > 0, "the surface did not move between frames %d and %d", k, k + 1);
    RF_REQUIRE(movedAndChanged * 10 >= moved * 9,
      "where the surface moved, only %ld of %ld pixels changed", movedAndChanged, moved);
    RF_REQUIRE(changedAway == 0, "%ld pixels changed away from the glass", changedAway);
  }
  return EXIT_SUCCESS;
}
}

int main(int argc, char* argv[])
{
  const std::string mode = argc > 2 ? argv[1] : "";
  if (mode == "image" && (argc == 3 || argc == 5))
  {
    return CheckImage(argv[2], argc == 5 ? std::atoi(argv[3]) : 0, argc == 5 ? std::atoi(argv[4]) : 0);
  }
  if ((mode == "series" || mode == "follow") && argc == 4)
  {
    const int count = std::atoi(argv[3]);
    return mode == "series" ? CheckSeries(argv[2], count) : CheckFollow(argv[2], count);
  }
  std::fprintf(stderr, "usage: CheckFrames image FILE [W H] | series FOLDER N | follow FOLDER N\n");
  return EXIT_FAILURE;
}
