// Glass under the settings a VTK user gives an actor: its property (interpolation, PBR,
// culling, a backface property, representation, points as spheres, lines as tubes, edges and
// vertices shown, lighting off), its mapper (clipping planes, coincident topology, scalars,
// scalars through a texture) and its own shader replacements. A glass sphere over the
// built-in environment in VTK's default window, two frames; every frame is checked for OpenGL
// errors (rftest::MakeWindow). Three kinds of case:
//   SAME     a setting the glass has no use for: the picture equals the default glass's
//            (before, a backface property left VTK's uniform of the back faces' opacity at
//            0 and every back face of the capture was discarded: the ray left the glass at
//            its front)
//   CHANGED  a setting that changes what is glass (clipped away, edges drawn over it) or
//            tints it (scalars, a texture: before, an actor's texture did not tint it): the
//            glass is drawn (differs from the environment alone over at least kPixels
//            pixels) and differs from the default glass over at least kPixels pixels
//   DRAWN    the glass is drawn and nothing fails (lines or points as glass; the highlight
//            of flat facets or unlit glass)
// Usage: TestGlassActorSettings CASE
#include "vtkRefractionPass.h"

#include "rfTestScene.h"
#include "rf_require.h"

#include <vtkActor.h>
#include <vtkElevationFilter.h>
#include <vtkImageCanvasSource2D.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPlane.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShaderProperty.h>
#include <vtkTexture.h>
#include <vtkTextureMapToSphere.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>

namespace
{
const int kSize = 128;
const int kPixels = 200;

enum Expect
{
  SAME,
  CHANGED,
  DRAWN
};

// A red and white texture (the texture and PBR albedo cases).
vtkSmartPointer<vtkTexture> Texture()
{
  vtkNew<vtkImageCanvasSource2D> canvas;
  canvas->SetScalarTypeToUnsignedChar();
  canvas->SetNumberOfScalarComponents(3);
  canvas->SetExtent(0, 63, 0, 63, 0, 0);
  canvas->SetDrawColor(255, 255, 255);
  canvas->FillBox(0, 63, 0, 63);
  canvas->SetDrawColor(255, 0, 0);
  canvas->FillBox(0, 31, 0, 31);
  canvas->Update();
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(canvas->GetOutput());
  return texture;
}

using Setting = std::function<void(vtkActor*, vtkPolyDataMapper*, vtkProperty*)>;

struct Case
{
  const char* Name;
  Expect Expected;
  Setting Apply;
};

const Case kCases[] = {
  { "pbr",
    SAME,
    [](vtkActor*, vtkPolyDataMapper*, vtkProperty* p)
    {
      p->SetInterpolationToPBR();
      p->SetMetallic(0.5);
      p->SetRoughness(0.3);
    } },
  { "phong",
    SAME,
    [](vtkActor*, vtkPolyDataMapper*, vtkProperty* p) { p->SetInterpolationToPhong(); } },
  { "backface_property",
    SAME,
    [](vtkActor* a, vtkPolyDataMapper*, vtkProperty*)
    {
      vtkNew<vtkProperty> back;
      back->SetColor(1.0, 0.0, 0.0);
      a->SetBackfaceProperty(back);
    } },
  { "backface_culling",
    SAME,
    [](vtkActor*, vtkPolyDataMapper*, vtkProperty* p) { p->BackfaceCullingOn(); } },
  { "frontface_culling",
    SAME,
    [](vtkActor*, vtkPolyDataMapper*, vtkProperty* p) { p->FrontfaceCullingOn(); } },
  { "coincident_offset",
    SAME,
    [](vtkActor*, vtkPolyDataMapper* m, vtkProperty*)
    {
      m->SetResolveCoincidentTopologyToPolygonOffset();
      m->SetRelativeCoincidentTopologyPolygonOffsetParameters(2.0, 2.0);
    } },
  { "vertex_visibility",
    SAME,
    [](vtkActor*, vtkPolyDataMapper*, vtkProperty* p)
    {
      p->VertexVisibilityOn();
      p->SetPointSize(5.0);
    } },
  { "shader_replacements",
    SAME,
    [](vtkActor* a, vtkPolyDataMapper*, vtkProperty*)
    {
      a->GetShaderProperty()->AddFragmentShaderReplacement(
        "//VTK::Normal::Dec", true, "//VTK::Normal::Dec\nfloat userFirst = 1.0;\n", false);
      a->GetShaderProperty()->AddFragmentShaderReplacement(
        "//VTK::Picking::Impl", DRAWN, "//VTK::Picking::Impl\n  float userAfter = 1.0;\n", false);
    } },
  { "flat",
    DRAWN,
    [](vtkActor*, vtkPolyDataMapper*, vtkProperty* p) { p->SetInterpolationToFlat(); } },
  { "lighting_off",
    DRAWN,
    [](vtkActor*, vtkPolyDataMapper*, vtkProperty* p) { p->LightingOff(); } },
  { "clipping_plane",
    CHANGED,
    [](vtkActor*, vtkPolyDataMapper* m, vtkProperty*)
    {
      vtkNew<vtkPlane> plane;
      plane->SetOrigin(0.5, 0.0, 0.0);
      plane->SetNormal(-1.0, 0.0, 0.0);
      m->AddClippingPlane(plane);
    } },
  { "wireframe",
    DRAWN,
    [](vtkActor*, vtkPolyDataMapper*, vtkProperty* p) { p->SetRepresentationToWireframe(); } },
  { "points",
    DRAWN,
    [](vtkActor*, vtkPolyDataMapper*, vtkProperty* p)
    {
      p->SetRepresentationToPoints();
      p->SetPointSize(4.0);
    } },
  { "points_as_spheres",
    DRAWN,
    [](vtkActor*, vtkPolyDataMapper*, vtkProperty* p)
    {
      p->SetRepresentationToPoints();
      p->SetPointSize(6.0);
      p->RenderPointsAsSpheresOn();
    } },
  { "lines_as_tubes",
    CHANGED,
    [](vtkActor*, vtkPolyDataMapper*, vtkProperty* p)
    {
      p->EdgeVisibilityOn();
      p->SetEdgeColor(1.0, 1.0, 0.0); // not the background's black
      p->SetLineWidth(2.0);
      p->RenderLinesAsTubesOn();
    } },
  { "texture",
    CHANGED,
    [](vtkActor* a, vtkPolyDataMapper*, vtkProperty*) { a->SetTexture(Texture()); } },
  { "pbr_albedo",
    DRAWN,
    [](vtkActor*, vtkPolyDataMapper*, vtkProperty* p)
    {
      p->SetInterpolationToPBR();
      p->SetBaseColorTexture(Texture());
    } },
  { "scalars",
    CHANGED,
    [](vtkActor*, vtkPolyDataMapper* m, vtkProperty*) { m->ScalarVisibilityOn(); } },
  { "scalars_texture",
    CHANGED,
    [](vtkActor*, vtkPolyDataMapper* m, vtkProperty*)
    {
      m->ScalarVisibilityOn();
      m->InterpolateScalarsBeforeMappingOn();
    } },
};

// The sphere with texture coordinates and elevation scalars, as glass with `setting` (none:
// the default glass; no glass actor at all: the environment alone), over the built-in
// environment; the second frame.
vtkSmartPointer<vtkImageData> Render(const Case* setting, bool withGlass)
{
  const double centre[3] = { 0.0, 0.0, 0.0 };
  vtkNew<vtkTextureMapToSphere> coordinates;
  coordinates->SetInputData(rftest::SpherePoly(centre, 1.0, 48));
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(coordinates->GetOutputPort());
  elevation->Update();
  auto actor = rftest::ActorFor(elevation->GetOutputPort());
  if (setting)
  {
    setting->Apply(
      actor, vtkPolyDataMapper::SafeDownCast(actor->GetMapper()), actor->GetProperty());
  }
  vtkRefractionPass::MakeGlass(actor, 1.5);
  vtkNew<vtkRenderer> renderer;
  if (withGlass)
  {
    renderer->AddActor(actor);
  }
  vtkNew<vtkRefractionPass> pass;
  pass->SetEnvironmentModeToBuiltin(); // structure behind the glass everywhere
  renderer->SetPass(pass);
  auto window = rftest::MakeWindow(renderer, kSize, kSize);
  rftest::LookAtOrigin(renderer, 6.0, 20.0);
  window->Render();
  window->Render();
  return rftest::Grab(window);
}
}

int main(int argc, char* argv[])
{
  const Case* which = nullptr;
  for (const Case& c : kCases)
  {
    which = argc > 1 && std::strcmp(argv[1], c.Name) == 0 ? &c : which;
  }
  if (!which)
  {
    std::fprintf(stderr, "usage: %s CASE; CASE is one of", argv[0]);
    for (const Case& c : kCases)
    {
      std::fprintf(stderr, " %s", c.Name);
    }
    std::fprintf(stderr, "\n");
    return EXIT_FAILURE;
  }
  auto picture = Render(which, true);
  auto glass = Render(nullptr, true);
  const int changed = rftest::DifferingPixels(picture, glass, 1);
  std::printf(
    "%s: %d pixels differ from the default glass by more than 1 level\n", which->Name, changed);
  if (which->Expected == SAME)
  {
    RF_REQUIRE(changed == 0, "the setting changes the glass");
    return EXIT_SUCCESS;
  }
  auto environment = Render(nullptr, false);
  const int drawn = rftest::DifferingPixels(picture, environment, 2);
  std::printf("%s: %d pixels differ from the environment alone\n", which->Name, drawn);
  RF_REQUIRE(drawn >= kPixels, "the glass is not drawn");
  RF_REQUIRE(
    which->Expected != CHANGED || changed >= kPixels, "the setting does not change the glass");
  return EXIT_SUCCESS;
}
