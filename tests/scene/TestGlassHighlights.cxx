// Highlights (issue 23): glass over a plain background shows its shape by the highlights of
// the renderer's lights. A glass ball of Specular 1, SpecularPower 100 over a dark background:
//   headlight    the brightest spot lies where the headlight's mirror direction meets the eye
//                (the point facing the camera); with Specular 0 there is none, and away from
//                the spot the two pictures are the same
//   scene_light  a directional scene light from the upper right (the headlight off): the spot
//                lies on the ball's point whose normal halves the light and the eye directions
//   index_1      glass of index 1 mirrors nothing: no spot (Fresnel reflectance 0)
#include "vtkRefractionPass.h"

#include "rfTestScene.h"
#include "rf_require.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
const int kSize = 128;

struct Spot
{
  int X = 0;
  int Y = 0;
  double Value = 0.0; // the smallest channel of the whitest pixel
};

// The brightest white: the largest smallest-channel of any pixel, and the centroid of the
// pixels within 5 levels of it (a saturated spot is many pixels).
Spot Brightest(vtkImageData* image)
{
  Spot spot;
  auto whiteness = [image](int x, int y) {
    double value = 255.0;
    for (int c = 0; c < 3; ++c)
    {
      value = std::min(value, image->GetScalarComponentAsDouble(x, y, 0, c));
    }
    return value;
  };
  for (int y = 0; y < kSize; ++y)
  {
    for (int x = 0; x < kSize; ++x)
    {
      spot.Value = std::max(spot.Value, whiteness(x, y));
    }
  }
  double sx = 0.0;
  double sy = 0.0;
  int n = 0;
  for (int y = 0; y < kSize; ++y)
  {
    for (int x = 0; x < kSize; ++x)
    {
      if (whiteness(x, y) >= spot.Value - 5.0)
      {
        sx += x;
        sy += y;
        ++n;
      }
    }
  }
  spot.X = static_cast<int>(std::lround(sx / n));
  spot.Y = static_cast<int>(std::lround(sy / n));
  return spot;
}

struct Scene
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRefractionPass> Pass;
  vtkSmartPointer<vtkActor> Ball;
  vtkSmartPointer<vtkRenderWindow> Window;

  explicit Scene(double ior)
  {
    const double centre[3] = { 0.0, 0.0, 0.0 };
    this->Ball = rftest::ActorFor(rftest::SpherePoly(centre, 1.0, 96));
    vtkRefractionPass::MakeGlass(this->Ball, ior);
    this->Ball->GetProperty()->SetSpecular(1.0);
    this->Ball->GetProperty()->SetSpecularPower(100.0);
    this->Renderer->AddActor(this->Ball);
    this->Renderer->SetBackground(0.1, 0.1, 0.12);
    this->Renderer->SetPass(this->Pass);
    this->Window = rftest::MakeWindow(this->Renderer, kSize, kSize);
    rftest::LookAtOrigin(this->Renderer, 6.0, 0.0);
  }

  vtkSmartPointer<vtkImageData> Render()
  {
    this->Window->Render();
    return rftest::Grab(this->Window);
  }

  void ToPixel(const double world[3], int& x, int& y)
  {
    this->Renderer->SetWorldPoint(world[0], world[1], world[2], 1.0);
    this->Renderer->WorldToDisplay();
    double display[3];
    this->Renderer->GetDisplayPoint(display);
    x = static_cast<int>(std::lround(display[0]));
    y = static_cast<int>(std::lround(display[1]));
  }
};

int Headlight()
{
  Scene scene(1.5);
  auto lit = scene.Render();
  scene.Ball->GetProperty()->SetSpecular(0.0);
  auto unlit = scene.Render();
  const Spot spot = Brightest(lit);
  const Spot none = Brightest(unlit);
  int x = 0;
  int y = 0;
  const double facing[3] = { 0.0, 0.0, 1.0 };
  scene.ToPixel(facing, x, y);
  // Away from the spot (beyond 12 pixels) the highlight adds nothing visible.
  int far = 0;
  for (int py = 0; py < kSize; ++py)
  {
    for (int px = 0; px < kSize; ++px)
    {
      if ((px - x) * (px - x) + (py - y) * (py - y) > 144)
      {
        for (int c = 0; c < 3; ++c)
        {
          const double change = lit->GetScalarComponentAsDouble(px, py, 0, c) -
            unlit->GetScalarComponentAsDouble(px, py, 0, c);
          far = std::max(far, static_cast<int>(std::abs(change)));
        }
      }
    }
  }
  std::printf("headlight: brightest spot %.0f at (%d, %d), expected at (%d, %d); with Specular 0 "
              "the brightest is %.0f; largest change beyond 12 px of the spot: %d\n",
    spot.Value, spot.X, spot.Y, x, y, none.Value, far);
  RF_REQUIRE(spot.Value >= 200.0, "no highlight (%.0f)", spot.Value);
  RF_REQUIRE(std::abs(spot.X - x) <= 2 && std::abs(spot.Y - y) <= 2,
    "the highlight is at (%d, %d), not at (%d, %d)", spot.X, spot.Y, x, y);
  RF_REQUIRE(none.Value < 120.0, "a bright spot without specular (%.0f)", none.Value);
  RF_REQUIRE(far <= 8, "the highlight changes the picture far from its spot (%d)", far);
  return EXIT_SUCCESS;
}

int SceneLight()
{
  Scene scene(1.5);
  scene.Renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(false);
  light->SetPosition(1.0, 1.0, 1.0);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  scene.Renderer->AddLight(light);
  auto picture = scene.Render();
  const Spot spot = Brightest(picture);
  // The mirror point: the normal halves the directions to the light and to the eye.
  double toLight[3] = { 1.0, 1.0, 1.0 };
  double toEye[3] = { 0.0, 0.0, 1.0 };
  vtkMath::Normalize(toLight);
  double normal[3] = { toLight[0] + toEye[0], toLight[1] + toEye[1], toLight[2] + toEye[2] };
  vtkMath::Normalize(normal);
  int x = 0;
  int y = 0;
  scene.ToPixel(normal, x, y);
  std::printf("scene_light: brightest spot %.0f at (%d, %d), expected at (%d, %d)\n", spot.Value,
    spot.X, spot.Y, x, y);
  RF_REQUIRE(spot.Value >= 200.0, "no highlight (%.0f)", spot.Value);
  RF_REQUIRE(std::abs(spot.X - x) <= 2 && std::abs(spot.Y - y) <= 2,
    "the highlight is at (%d, %d), not at (%d, %d)", spot.X, spot.Y, x, y);
  return EXIT_SUCCESS;
}

int IndexOne()
{
  Scene scene(1.0);
  const Spot spot = Brightest(scene.Render());
  std::printf("index_1: brightest pixel %.0f\n", spot.Value);
  RF_REQUIRE(spot.Value < 120.0, "glass of index 1 shows a highlight (%.0f)", spot.Value);
  return EXIT_SUCCESS;
}
}

int main(int argc, char* argv[])
{
  const std::string name = argc > 1 ? argv[1] : "";
  if (name == "headlight")
  {
    return Headlight();
  }
  if (name == "scene_light")
  {
    return SceneLight();
  }
  if (name == "index_1")
  {
    return IndexOne();
  }
  std::fprintf(stderr, "unknown case '%s'\n", name.c_str());
  return EXIT_FAILURE;
}
