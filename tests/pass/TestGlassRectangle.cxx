// The shading stage and the full-screen composite run only inside the rectangle the glass's
// bounding boxes project to (vtkRefractionDepthRange::ComputeScreenRectangle, two pixels of
// margin). Every pixel the glass changes must lie inside it, with and without anti-aliasing,
// for a ball inside the view and one across the window's edge; the rectangle is smaller than
// the window there, the whole window where a box reaches behind the eye (its projection has
// no bound), and empty for a ball beside the view, which then draws nothing and no error.
#include "vtkRefractionDepthRange.h"
#include "vtkRefractionPass.h"

#include "rfTestScene.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkRenderer.h>

#include <cstdio>
#include <vector>

namespace
{
const int Size = 160;

struct Case
{
  const char* Name;
  double Position[3];
  double Eye[3];
};

bool Inside(const int rectangle[4], int x, int y)
{
  return x >= rectangle[0] && x < rectangle[0] + rectangle[2] && y >= rectangle[1] &&
    y < rectangle[1] + rectangle[3];
}

// The ball drawn opaque by VTK marks where it is (footprint); the glass must cover the
// footprint's interior (pixels whose four neighbours are footprint too: the silhouette's
// partly covered pixels may go either way), and nothing of either may lie outside the
// rectangle.
struct Count
{
  int Footprint = 0;
  int FootprintOutside = 0;
  int Glass = 0;
  int GlassOutside = 0;
  int InteriorMissed = 0;
};

Count Compare(vtkImageData* glass, vtkImageData* opaque, vtkImageData* background,
  const int rectangle[4])
{
  auto footprint = [&](int x, int y) {
    return x < 0 || y < 0 || x >= Size || y >= Size ||
      rftest::PixelDiffers(opaque, background, x, y, 8.0);
  };
  Count count;
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      const bool isGlass = rftest::PixelDiffers(glass, background, x, y, 0.0);
      count.Glass += isGlass ? 1 : 0;
      count.GlassOutside += isGlass && !Inside(rectangle, x, y) ? 1 : 0;
      if (!footprint(x, y))
      {
        continue;
      }
      ++count.Footprint;
      count.FootprintOutside += Inside(rectangle, x, y) ? 0 : 1;
      const bool interior =
        footprint(x - 1, y) && footprint(x + 1, y) && footprint(x, y - 1) && footprint(x, y + 1);
      count.InteriorMissed += interior && !isGlass ? 1 : 0;
    }
  }
  return count;
}
}

int main()
{
  vtkSmartPointer<vtkActor> actor = rftest::MakeSphere(0.5, 48);
  RF_REQUIRE(vtkRefractionPass::MakeGlass(actor, 1.5), "MakeGlass refused IOR 1.5");
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.1);
  vtkSmartPointer<vtkRenderWindow> window = rftest::MakeWindow(renderer, Size, Size);
  const std::vector<vtkProp*> glass = { actor };

  const Case cases[] = {
    { "inside the view", { 0.3, -0.2, 0.0 }, { 0.0, 0.0, 3.0 } },
    { "across the edge", { 0.95, 0.3, 0.0 }, { 0.0, 0.0, 3.0 } },
    // Outside the ball, inside its bounding box: corners of the box lie behind the eye.
    { "box behind the eye", { 0.0, 0.0, 0.0 }, { 0.4, 0.4, 0.4 } },
    { "beside the view", { 6.0, 0.0, 0.0 }, { 0.0, 0.0, 3.0 } },
  };
  for (const Case& c : cases)
  {
    actor->SetPosition(c.Position[0], c.Position[1], c.Position[2]);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(c.Eye[0], c.Eye[1], c.Eye[2]);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->OrthogonalizeViewUp();
    camera->SetViewAngle(30.0);
    camera->SetClippingRange(0.02, 10.0);

    renderer->RemoveAllViewProps();
    renderer->SetPass(nullptr);
    window->Render();
    vtkSmartPointer<vtkImageData> background = rftest::Grab(window);
    renderer->AddActor(actor);
    window->Render();
    vtkSmartPointer<vtkImageData> opaque = rftest::Grab(window);
    int rectangle[4];
    vtkRefractionDepthRange::ComputeScreenRectangle(renderer, glass, Size, Size, 2, rectangle);
    std::printf("%s: rectangle %d %d %d x %d\n", c.Name, rectangle[0], rectangle[1],
      rectangle[2], rectangle[3]);
    const int area = rectangle[2] * rectangle[3];
    if (c.Eye[2] < 1.0)
    {
      RF_REQUIRE(area == Size * Size && rectangle[0] == 0 && rectangle[1] == 0,
        "%s: not the whole window", c.Name);
    }
    else if (c.Position[0] > 5.0)
    {
      RF_REQUIRE(area == 0, "%s: %d pixels", c.Name, area);
    }
    else
    {
      RF_REQUIRE(area > 0 && area < Size * Size * 3 / 4, "%s: %d pixels", c.Name, area);
    }
    for (bool antiAliasing : { false, true })
    {
      vtkNew<vtkRefractionPass> pass;
      pass->SetEnvironmentModeToBuiltin();
      pass->SetAntiAliasing(antiAliasing);
      renderer->SetPass(pass);
      window->Render();
      vtkSmartPointer<vtkImageData> picture = rftest::Grab(window);
      renderer->SetPass(nullptr);
      pass->ReleaseGraphicsResources(window);
      const Count n = Compare(picture, opaque, background, rectangle);
      std::printf("  %s: footprint %d (%d outside the rectangle), glass %d (%d outside), "
                  "%d of the footprint's interior without glass\n",
        antiAliasing ? "anti-aliased" : "pixels", n.Footprint, n.FootprintOutside, n.Glass,
        n.GlassOutside, n.InteriorMissed);
      RF_REQUIRE(n.FootprintOutside == 0 && n.GlassOutside == 0,
        "%s: the ball reaches outside its rectangle", c.Name);
      RF_REQUIRE(n.InteriorMissed == 0, "%s: %d pixels of the ball without glass", c.Name,
        n.InteriorMissed);
      RF_REQUIRE(area == 0 ? n.Glass == 0 : n.Glass > 500, "%s: %d glass pixels", c.Name,
        n.Glass);
    }
  }
  return EXIT_SUCCESS;
}
