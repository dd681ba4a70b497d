// Renders the glass contour through EGL (Refraction::EGL), compares it with a baseline (as VTK
// does and pixel by pixel: the tests' rfTestBaseline.h), traces
// the same glass with the reference tracer (Refraction::Reference) and writes the image with
// Refraction::IO:   GlassContourEGL -V baseline.png -T output_dir
#include "GlassContourScene.h"
#include "rfTestBaseline.h"

#include "vtkRefractionEGL.h"
#include "vtkRefractionImageIO.h"
#include "vtkRefractionReference.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkWindowToImageFilter.h>

#include <cstdio>
#include <cstring>
#include <string>

int main(int argc, char* argv[])
{
  std::string error;
  std::string description;
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window =
    vtkRefractionCreateEGLWindow(200, 200, &error, &description);
  if (!window)
  {
    std::fprintf(stderr, "GlassContourEGL: %s\n", error.c_str());
    return 1;
  }
  std::printf("GlassContourEGL: %s\n", description.c_str());
  GlassContourScene scene = BuildGlassContourScene(window, 200);
  window->Render();
  if (scene.Pass->GetNumberOfGlassProps() != 1)
  {
    std::fprintf(stderr, "GlassContourEGL: the pass drew %d glass props, expected 1\n",
      scene.Pass->GetNumberOfGlassProps());
    return 1;
  }
  const int result = rftest::CompareWithBaseline(argc, argv, window, 0.15);

  vtkNew<vtkRefractionReference> reference;
  if (!reference->Trace(scene.Renderer, 64, 64))
  {
    std::fprintf(stderr, "GlassContourEGL: the reference tracer failed\n");
    return 1;
  }
  double hit[2];
  reference->GetOutput()->GetPointData()->GetArray("Hit")->GetRange(hit);
  if (hit[1] <= 0.0)
  {
    std::fprintf(stderr, "GlassContourEGL: the reference tracer saw no glass\n");
    return 1;
  }

  // -T's folder gets the EGL image written through OpenImageIO.
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::strcmp(argv[i], "-T") == 0)
    {
      vtkNew<vtkWindowToImageFilter> grab;
      grab->SetInput(window);
      grab->ReadFrontBufferOff();
      grab->Update();
      const std::string path = std::string(argv[i + 1]) + "/GlassContourEGL_io.png";
      if (!vtkRefractionImageIO::WriteImage(grab->GetOutput(), nullptr, path, &error))
      {
        std::fprintf(stderr, "GlassContourEGL: %s\n", error.c_str());
        return 1;
      }
    }
  }
  return result;
}
