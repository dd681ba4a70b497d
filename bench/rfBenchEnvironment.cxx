#include "rfBenchEnvironment.h"

#include <vtkEquirectangularToCubeMapTexture.h>
#include <vtkHDRReader.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOpenGLTexture.h>
#include <vtksys/SystemTools.hxx>

#include <cmath>
#include <cstdio>

namespace rfbench
{
namespace
{
// A studio made in code, as a float lat-long image (VTK's layout: u = atan2(z, x), v =
// asin(y), row 0 at the bottom): dim walls with a floor grid, a ceiling gradient and three
// soft boxes far brighter than 1, so that the picture has edges to refract and the values a
// real HDR environment has.
vtkSmartPointer<vtkImageData> StudioEnvironment(int width, int height)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_FLOAT, 3);
  auto* texels = static_cast<float*>(image->GetScalarPointer());
  const double lights[3][7] = { // direction, cosine of the half angle, brightness
    { 0.6, 0.6, 0.5, 0.97, 8.0, 7.6, 7.0 }, { -0.7, 0.35, -0.6, 0.985, 2.5, 3.5, 6.0 },
    { 0.0, 0.9, -0.4, 0.95, 4.0, 4.0, 4.0 } };
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      const double theta = ((i + 0.5) / width - 0.5) / 0.1591;
      const double phi = ((j + 0.5) / height - 0.5) / 0.3183;
      const double d[3] = { std::cos(phi) * std::cos(theta), std::sin(phi),
        std::cos(phi) * std::sin(theta) };
      double rgb[3];
      if (d[1] < 0.0)
      {
        // Floor: a grid on the plane y = -1.
        const double x = d[0] / -d[1];
        const double z = d[2] / -d[1];
        const bool line = std::fabs(x - std::round(x)) < 0.04 || std::fabs(z - std::round(z)) < 0.04;
        const double tone = line ? 0.9 : 0.18;
        rgb[0] = tone;
        rgb[1] = tone * 0.95;
        rgb[2] = tone * 0.85;
      }
      else
      {
        const double t = d[1];
        rgb[0] = 0.35 * (1.0 - t) + 0.10 * t;
        rgb[1] = 0.30 * (1.0 - t) + 0.14 * t;
        rgb[2] = 0.25 * (1.0 - t) + 0.30 * t;
      }
      for (const auto& light : lights)
      {
        const double length = std::sqrt(light[0] * light[0] + light[1] * light[1] + light[2] * light[2]);
        const double c = (d[0] * light[0] + d[1] * light[1] + d[2] * light[2]) / length;
        if (c > light[3])
        {
          for (int k = 0; k < 3; ++k)
            rgb[k] = light[4 + k];
        }
      }
      for (int k = 0; k < 3; ++k)
        texels[3 * (j * width + i) + k] = static_cast<float>(rgb[k]);
    }
  }
  return image;
}
}

// The renderer's environment for --environment (nullptr: the pass's built-in one).
// Smoke runs use a smaller image and cube map (the same code, a quarter of the work).
vtkSmartPointer<vtkTexture> MakeEnvironment(
  const std::string& name, bool smoke, std::string& description)
{
  if (name == "builtin")
  {
    description = "the pass's built-in environment (the scene mesh: the renderer's gradient "
                  "background, which the pass and the reference then use)";
    return nullptr;
  }
  vtkSmartPointer<vtkImageData> image;
  if (name == "studio")
  {
    const int width = smoke ? 256 : 1024;
    image = StudioEnvironment(width, width / 2);
    description = "studio (HDR lat-long " + std::to_string(width) + "x" +
      std::to_string(width / 2) + " made in code)";
  }
  else
  {
    vtkNew<vtkHDRReader> reader;
    if (!reader->CanReadFile(name.c_str()))
    {
      std::fprintf(stderr, "--environment: %s is not a Radiance .hdr file VTK can read\n",
        name.c_str());
      return nullptr;
    }
    reader->SetFileName(name.c_str());
    reader->Update();
    image = reader->GetOutput();
    description = vtksys::SystemTools::GetFilenameName(name) + " (HDR lat-long)";
  }
  auto texture = vtkSmartPointer<vtkOpenGLTexture>::New();
  texture->SetInputData(image);
  texture->SetColorModeToDirectScalars(); // floats as they are, not through a lookup table
  texture->InterpolateOn();
  auto cube = vtkSmartPointer<vtkEquirectangularToCubeMapTexture>::New();
  cube->SetInputTexture(texture);
  cube->SetCubeMapSize(smoke ? 128 : 512);
  description += " through vtkEquirectangularToCubeMapTexture (cube map " +
    std::to_string(cube->GetCubeMapSize()) + ")";
  return cube;
}
}
