// Bad input to the refraction pass (label `badinput`): each case puts one bad glass actor (or
// a bad setting) into a scene with a good glass sphere and an opaque cone, and asserts
//  - the message: a vtkErrorMacro or vtkWarningMacro naming the actor (class and address) and
//    the bad value or count, given once per modification, not once per frame;
//  - the rest of the image: the float colour equals a reference render of the scene without
//    the bad actor (or with it as an ordinary actor, where it is drawn as one);
//  - no OpenGL error left by the pass, and no crash.
// Usage: TestBadInput CASE [WORKDIR]
#include "rfTestRig.h"

#ifdef REFRACTION_HAVE_IO
#include "vtkRefractionImageIO.h"
#endif

#include <vtkAssembly.h>
#include <vtkCellArray.h>
#include <vtkGlyph3DMapper.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleKey.h>
#include <vtkInformationIntegerKey.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>
#include <vtkShaderProperty.h>
#include <vtkVertexGlyphFilter.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

using namespace rftest;

namespace
{
constexpr int kSize = 96;
constexpr int kSkipped = 77; // ctest's SKIP_RETURN_CODE for these tests


std::string Address(const void* p)
{
  std::ostringstream s;
  s << p; // as vtkErrorMacro streams a pointer
  return s.str();
}

// A sphere of 48 x 48 facets on the x axis.
vtkSmartPointer<vtkPolyData> Sphere(double x, double radius)
{
  const double centre[3] = { x, 0.0, 0.0 };
  return SpherePoly(centre, radius, 48);
}

// The rest of the scene: a good glass sphere on the right and an opaque cone at the top.
void AddRest(Rig& rig)
{
  rig.Renderer->AddActor(GlassActor(Sphere(1.2, 0.7), 1.5));
  const double top[3] = { 0.0, 1.1, 0.0 };
  auto opaque = ActorFor(ConePoly(top, 0.8, 0.4, 24));
  opaque->GetProperty()->SetColor(0.9, 0.3, 0.2);
  rig.Renderer->AddActor(opaque);
}

void Look(Rig& rig)
{
  const double eye[3] = { 0.0, 0.0, 6.0 };
  const double focal[3] = { 0.0, 0.0, 0.0 };
  const double up[3] = { 0.0, 1.0, 0.0 };
  rig.LookAt(eye, focal, up, 40.0, 1.0, 20.0);
}

// The reference picture: the rest of the scene, plus `subject` if given (a polydata: as an
// ordinary actor).
Frame ReferenceWithProp(vtkProp* subject)
{
  Rig rig(kSize, kSize);
  AddRest(rig);
  if (subject)
  {
    rig.Renderer->AddViewProp(subject);
  }
  Look(rig);
  return rig.Render();
}
Frame Reference(vtkPolyData* subject)
{
  return ReferenceWithProp(subject ? ActorFor(subject).Get() : nullptr);
}

// Largest colour difference between two frames (inf for a size mismatch or NaN).
double ColourDifference(const Frame& a, const Frame& b)
{
  if (a.Colour.size() != b.Colour.size())
  {
    return std::numeric_limits<double>::infinity();
  }
  double worst = 0.0;
  for (size_t i = 0; i < a.Colour.size(); ++i)
  {
    const double d = std::fabs(static_cast<double>(a.Colour[i]) - b.Colour[i]);
    worst = std::max(worst, std::isfinite(d) ? d : std::numeric_limits<double>::infinity());
  }
  return worst;
}

int GlassPixels(const Frame& f)
{
  int n = 0;
  for (int i = 0; i < f.W * f.H; ++i)
  {
    n += f.Glass(i) ? 1 : 0;
  }
  return n;
}

// Renders the scene with `subject` as glass three times; checks the message count against
// `parts` (exactly one), the GL errors, and the picture against `reference`.
int CheckScene(MessageLog* log, Rig& rig, const std::string& kind,
  std::initializer_list<std::string> parts, const Frame& reference, Frame* last = nullptr)
{
  Frame f;
  for (int i = 0; i < 3; ++i)
  {
    f = rig.Render();
    RF_REQUIRE(f.GLErrors == 0, "OpenGL error after the pass (frame %d)", i);
    RF_REQUIRE(f.NonFinite() == 0, "NaN/Inf in the output (frame %d)", i);
  }
  const int matching = log->Count(kind, parts);
  std::printf("%d matching %s message(s) over 3 frames\n", matching, kind.c_str());
  RF_REQUIRE(matching == 1, "expected exactly one %s message naming the actor and the value",
    kind.c_str());
  const double difference = ColourDifference(f, reference);
  std::printf("largest colour difference to the reference: %g\n", difference);
  RF_REQUIRE(difference <= 1e-5, "the rest of the scene does not render as without the actor");
  RF_REQUIRE(GlassPixels(f) > 500, "the good glass sphere is not drawn as glass");
  if (last)
  {
    *last = f;
  }
  return EXIT_SUCCESS;
}

int NonFinitePoints(MessageLog* log, bool infinite)
{
  auto poly = Sphere(-1.2, 0.7);
  const double bad = infinite ? std::numeric_limits<double>::infinity()
                              : std::numeric_limits<double>::quiet_NaN();
  poly->GetPoints()->SetPoint(5, bad, 0.0, 0.0);
  if (infinite)
  {
    poly->GetPoints()->SetPoint(9, 0.0, -bad, 0.0);
  }
  Rig rig(kSize, kSize);
  AddRest(rig);
  auto subject = ActorFor(poly);
  RF_REQUIRE(vtkRefractionPass::MakeGlass(subject, 1.5), "MakeGlass refused a valid IOR");
  rftest::WithoutHighlights(subject);
  rig.Renderer->AddActor(subject);
  Look(rig);
  const Frame reference = Reference(nullptr);
  const std::string count = infinite ? "2 of " : "1 of ";
  if (CheckScene(log, rig, "error",
        { subject->GetClassName(), Address(subject.Get()), count, "NaN, infinite or too large",
          infinite ? "inf" : "nan" },
        reference) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  // A new modification of the data is a new verdict: reported again, once.
  poly->GetPoints()->Modified();
  rig.Render();
  rig.Render();
  RF_REQUIRE(log->Count("error", { Address(subject.Get()), "NaN, infinite or too large" }) == 2,
    "the modified data was not checked again (or reported more than once)");
  // Repaired data is glass again.
  poly->GetPoints()->SetPoint(5, -1.2, 0.0, 0.7);
  poly->GetPoints()->SetPoint(9, -1.2, 0.0, 0.7);
  poly->GetPoints()->Modified();
  rig.Render();
  RF_REQUIRE(rig.Glass->GetNumberOfGlassProps() == 2, "repaired data is not glass again");
  return EXIT_SUCCESS;
}

int EmptyPolyData(MessageLog* log)
{
  vtkNew<vtkPolyData> empty;
  Rig rig(kSize, kSize);
  AddRest(rig);
  auto subject = GlassActor(empty, 1.5);
  rig.Renderer->AddActor(subject);
  Look(rig);
  return CheckScene(log, rig, "warning",
    { subject->GetClassName(), Address(subject.Get()), "empty vtkPolyData", "0 points" }, Reference(nullptr));
}

int WithoutPolygons(MessageLog* log, bool lines)
{
  auto sphere = Sphere(-1.2, 0.7);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  if (lines)
  {
    // Every triangle's outline as a closed polyline: the same points, lines only.
    vtkNew<vtkCellArray> outlines;
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    vtkCellArray* polys = sphere->GetPolys();
    for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
    {
      outlines->InsertNextCell(static_cast<int>(n + 1));
      for (vtkIdType k = 0; k <= n; ++k)
      {
        outlines->InsertCellPoint(ids[k % n]);
      }
    }
    poly->SetPoints(sphere->GetPoints());
    poly->SetLines(outlines);
  }
  else
  {
    vtkNew<vtkVertexGlyphFilter> vertices;
    vertices->SetInputData(sphere);
    vertices->Update();
    poly->DeepCopy(vertices->GetOutput());
  }
  Rig rig(kSize, kSize);
  AddRest(rig);
  auto subject = GlassActor(poly, 1.5);
  rig.Renderer->AddActor(subject);
  Look(rig);
  const std::string count = lines
    ? std::to_string(poly->GetNumberOfLines()) + " lines"
    : std::to_string(poly->GetNumberOfVerts()) + " vertices";
  // Drawn as an ordinary actor: the reference has it as one.
  return CheckScene(log, rig, "warning", { subject->GetClassName(), Address(subject.Get()), "no polygons", count },
    Reference(poly));
}

int BadIndex(MessageLog* log, double ior, const char* printed)
{
  auto poly = Sphere(-1.2, 0.7);
  Rig rig(kSize, kSize);
  AddRest(rig);
  auto subject = ActorFor(poly);
  RF_REQUIRE(!vtkRefractionPass::MakeGlass(subject, ior), "MakeGlass accepted IOR %g", ior);
  RF_REQUIRE(!vtkRefractionPass::IsGlass(subject), "the actor is marked as glass");
  RF_REQUIRE(log->Count("error", { "MakeGlass", subject->GetClassName(), Address(subject.Get()), printed }) ==
      1,
    "MakeGlass did not name the actor and the value %s", printed);
  rig.Renderer->AddActor(subject);
  Look(rig);
  const Frame reference = Reference(poly);
  // The same value set on the keys by hand gets past MakeGlass: the pass reports it (once) and
  // draws the actor as an ordinary one.
  vtkNew<vtkInformation> keys;
  keys->Set(vtkRefractionPass::GLASS(), 1);
  keys->Set(vtkRefractionPass::INDEX_OF_REFRACTION(), ior);
  subject->SetPropertyKeys(keys);
  return CheckScene(log, rig, "error",
    { "Glass prop", subject->GetClassName(), Address(subject.Get()),
      std::string("index of refraction ") + printed, "drawn as opaque" },
    reference);
}

int ZeroViewport(MessageLog* log)
{
  // Renderer A shows glass in a viewport of no pixels; renderer B (the rig's) the rest.
  Rig rig(kSize, kSize);
  AddRest(rig);
  Look(rig);
  vtkNew<vtkRenderer> empty;
  vtkNew<vtkRefractionPass> pass;
  pass->SetEnvironmentModeToBuiltin();
  empty->SetPass(pass);
  empty->SetViewport(0.25, 0.25, 0.25, 0.25);
  empty->SetLayer(0);
  auto glass = GlassActor(Sphere(0.0, 1.0), 1.5);
  empty->AddActor(glass);
  rig.Window->AddRenderer(empty);
  // B renders after A and clears its full viewport, so the picture is B's alone.
  rig.Window->RemoveRenderer(rig.Renderer);
  rig.Window->AddRenderer(rig.Renderer);
  const Frame reference = Reference(nullptr);
  const std::string named = "renderer " + Address(empty.Get());
  if (CheckScene(log, rig, "warning", { named, "0 x 0 pixels", "1 glass prop" }, reference) !=
    EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  // Pixels again: drawn, no warning; none again: one more warning.
  empty->SetViewport(0.0, 0.0, 0.5, 0.5);
  rig.Render();
  RF_REQUIRE(pass->GetNumberOfGlassProps() == 1, "glass not drawn once the viewport has pixels");
  empty->SetViewport(0.5, 0.5, 0.5, 0.5);
  rig.Render();
  rig.Render();
  RF_REQUIRE(log->Count("warning", { named, "0 x 0 pixels" }) == 2,
    "the empty viewport is not reported once per change");
  return EXIT_SUCCESS;
}

#ifdef REFRACTION_HAVE_IO
int MissingEnvironment(MessageLog* log, const std::string& workdir)
{
  // A missing file and a file that is not an image: no image, a message naming the path.
  const std::string missing = workdir + "/no_such_environment.hdr";
  const std::string garbage = workdir + "/not_an_image.exr";
  {
    std::ofstream out(garbage, std::ios::binary);
    out << "this is not an OpenEXR file\n";
  }
  for (const std::string& path : { missing, garbage })
  {
    std::string error;
    auto image = vtkRefractionImageIO::ReadImage(path, &error);
    std::printf("ReadImage(%s): %s\n", path.c_str(), error.c_str());
    RF_REQUIRE(image == nullptr, "an image from %s", path.c_str());
    RF_REQUIRE(error.find(path) != std::string::npos, "the message does not name %s",
      path.c_str());
  }
  // Without a message pointer the failure still reaches VTK's output (a warning).
  RF_REQUIRE(vtkRefractionImageIO::ReadImage(missing, nullptr) == nullptr, "an image");
  RF_REQUIRE(log->Count("", { missing }) == 1, "no message for a failure without an error string");
  // The scene then renders with the built-in environment, exactly as without the attempt.
  Rig rig(kSize, kSize);
  AddRest(rig);
  Look(rig);
  const Frame f = rig.Render();
  RF_REQUIRE(f.GLErrors == 0 && f.NonFinite() == 0, "bad frame");
  RF_REQUIRE(ColourDifference(f, Reference(nullptr)) <= 1e-5, "the scene renders differently");
  RF_REQUIRE(GlassPixels(f) > 500, "the glass is not drawn");
  return EXIT_SUCCESS;
}
#else
int MissingEnvironment(MessageLog*, const std::string&)
{
  std::printf("built without RefractionIO (OpenImageIO): nothing to read an environment with\n");
  return kSkipped;
}
#endif

// The cases' common signature: the message log and a folder to write into.
int NaNPoints(MessageLog* log, const std::string&)
{
  return NonFinitePoints(log, false);
}
int InfPoints(MessageLog* log, const std::string&)
{
  return NonFinitePoints(log, true);
}
int Empty(MessageLog* log, const std::string&)
{
  return EmptyPolyData(log);
}
int LinesOnly(MessageLog* log, const std::string&)
{
  return WithoutPolygons(log, true);
}
int VerticesOnly(MessageLog* log, const std::string&)
{
  return WithoutPolygons(log, false);
}
int IORZero(MessageLog* log, const std::string&)
{
  return BadIndex(log, 0.0, "0");
}
int IORNegative(MessageLog* log, const std::string&)
{
  return BadIndex(log, -1.5, "-1.5");
}
int IORNaN(MessageLog* log, const std::string&)
{
  return BadIndex(log, std::numeric_limits<double>::quiet_NaN(), "nan");
}
int IORInf(MessageLog* log, const std::string&)
{
  return BadIndex(log, std::numeric_limits<double>::infinity(), "inf");
}
int ZeroSizeViewport(MessageLog* log, const std::string&)
{
  return ZeroViewport(log);
}

// A glass actor made translucent: VTK's translucent pass draws it, as an ordinary translucent
// surface, exactly like the same actor without the glass; one warning. `afterGlass`: made
// translucent after one frame drawn as glass: its mapper's program must not keep the glass
// stages' shader code (VTK rebuilds a program only when a pass's stage time is newer).
int Translucent(MessageLog* log, bool afterGlass)
{
  auto poly = Sphere(-1.2, 0.7);
  Rig rig(kSize, kSize);
  AddRest(rig);
  auto subject = ActorFor(poly);
  subject->GetProperty()->SetOpacity(afterGlass ? 1.0 : 0.5);
  RF_REQUIRE(vtkRefractionPass::MakeGlass(subject, 1.5), "MakeGlass refused a valid IOR");
  rftest::WithoutHighlights(subject);
  rig.Renderer->AddActor(subject);
  Look(rig);
  if (afterGlass)
  {
    rig.Render();
    subject->GetProperty()->SetOpacity(0.5);
  }
  auto ordinary = ActorFor(poly);
  ordinary->GetProperty()->SetOpacity(0.5);
  const Frame reference = ReferenceWithProp(ordinary);
  return CheckScene(log, rig, "warning",
    { "Glass actor", Address(subject.Get()), "opacity 0.5", "translucent pass" }, reference);
}
int TranslucentGlass(MessageLog* log, const std::string&)
{
  return Translucent(log, false);
}
int TranslucentAfterGlass(MessageLog* log, const std::string&)
{
  return Translucent(log, true);
}

// Glass the pass cannot draw as glass, drawn as an ordinary actor with one warning:
//   glyph_mapper   glass on a vtkGlyph3DMapper's actor (its glyphs are made while it draws)
//   assembly_part  glass on a part of a vtkAssembly (the assembly draws its parts itself)
vtkSmartPointer<vtkActor> GlyphActor()
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-1.5, -0.3, 0.0);
  points->InsertNextPoint(-0.8, 0.3, 0.0);
  vtkNew<vtkPolyData> centres;
  centres->SetPoints(points);
  vtkNew<vtkSphereSource> glyph;
  glyph->SetRadius(0.3);
  vtkNew<vtkGlyph3DMapper> mapper;
  mapper->SetInputData(centres);
  mapper->SetSourceConnection(glyph->GetOutputPort());
  mapper->ScalingOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}
int GlyphMapper(MessageLog* log, const std::string&)
{
  Rig rig(kSize, kSize);
  AddRest(rig);
  auto subject = GlyphActor();
  RF_REQUIRE(vtkRefractionPass::MakeGlass(subject, 1.5), "MakeGlass refused a valid IOR");
  rftest::WithoutHighlights(subject);
  rig.Renderer->AddActor(subject);
  Look(rig);
  const Frame reference = ReferenceWithProp(GlyphActor());
  return CheckScene(log, rig, "warning",
    { Address(subject.Get()), "vtkOpenGLGlyph3DMapper", "drawn as an ordinary actor" },
    reference);
}
int AssemblyPart(MessageLog* log, const std::string&)
{
  auto poly = Sphere(-1.2, 0.7);
  Rig rig(kSize, kSize);
  AddRest(rig);
  auto part = ActorFor(poly);
  RF_REQUIRE(vtkRefractionPass::MakeGlass(part, 1.5), "MakeGlass refused a valid IOR");
  rftest::WithoutHighlights(part);
  vtkNew<vtkAssembly> assembly;
  assembly->AddPart(part);
  rig.Renderer->AddActor(assembly);
  Look(rig);
  vtkNew<vtkAssembly> plainAssembly;
  plainAssembly->AddPart(ActorFor(poly));
  const Frame reference = ReferenceWithProp(plainAssembly);
  return CheckScene(log, rig, "warning",
    { Address(part.Get()), "is a part of vtkAssembly", Address(assembly.Get()),
      "drawn as an ordinary actor" },
    reference);
}

// A glass actor whose program does not build: its own shader replacement is not GLSL, applied
// before the render passes' (`first`) or after them. VTK 9.1's mapper dereferences a program
// its cache could not build, so without the pass's guard this crashed (plain VTK crashes on
// the same replacement); now one error names the actor, the rest of the scene renders as
// without it, and with the replacement taken away it is glass again.
int ShaderDoesNotBuild(MessageLog* log, bool first)
{
  auto poly = Sphere(-1.2, 0.7);
  Rig rig(kSize, kSize);
  AddRest(rig);
  auto subject = ActorFor(poly);
  RF_REQUIRE(vtkRefractionPass::MakeGlass(subject, 1.5), "MakeGlass refused a valid IOR");
  rftest::WithoutHighlights(subject);
  subject->GetShaderProperty()->AddFragmentShaderReplacement(
    "//VTK::Normal::Dec", first, "//VTK::Normal::Dec\n  this is not GLSL;\n", false);
  rig.Renderer->AddActor(subject);
  Look(rig);
  const Frame reference = Reference(nullptr);
  if (CheckScene(log, rig, "error",
        { subject->GetClassName(), Address(subject.Get()), "glass shader does not build",
          "not drawn" },
        reference) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  subject->GetShaderProperty()->ClearAllFragmentShaderReplacements();
  const Frame repaired = rig.Render();
  RF_REQUIRE(repaired.GLErrors == 0, "OpenGL error after the replacement was taken away");
  const int glass = GlassPixels(repaired) - GlassPixels(reference);
  std::printf("glass pixels with the replacement taken away: %d more\n", glass);
  RF_REQUIRE(glass > 500, "the actor is not glass again without the replacement");
  return EXIT_SUCCESS;
}
int ShaderDoesNotBuildFirst(MessageLog* log, const std::string&)
{
  return ShaderDoesNotBuild(log, true);
}
int ShaderDoesNotBuildAfter(MessageLog* log, const std::string&)
{
  return ShaderDoesNotBuild(log, false);
}

// A glass sphere whose polydata also holds a line (across its inside) and a vertex (cells of
// mixed types) and degenerate triangles (repeated points): drawn without an error, a GL error
// or a non-finite pixel over three frames, with one warning that its line and vertex are not
// drawn, and, through PEEL (which would take the line for two more interfaces), as the
// sphere's polygons alone are.
int MixedCells(MessageLog* log, const std::string&)
{
  auto poly = Sphere(-1.2, 0.7);
  auto mixed = vtkSmartPointer<vtkPolyData>::New();
  mixed->DeepCopy(poly);
  vtkNew<vtkCellArray> lines;
  vtkIdType line[2] = { 0, 0 }; // the leftmost and the rightmost point: across the view
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
  {
    const double x = poly->GetPoint(i)[0];
    line[0] = x < poly->GetPoint(line[0])[0] ? i : line[0];
    line[1] = x > poly->GetPoint(line[1])[0] ? i : line[1];
  }
  lines->InsertNextCell(2, line);
  mixed->SetLines(lines);
  vtkNew<vtkCellArray> verts;
  const vtkIdType vert[1] = { 5 };
  verts->InsertNextCell(1, vert);
  mixed->SetVerts(verts);
  const vtkIdType degenerate[3] = { 7, 7, 8 };
  mixed->GetPolys()->InsertNextCell(3, degenerate);
  const vtkIdType collinear[3] = { 9, 9, 9 };
  mixed->GetPolys()->InsertNextCell(3, collinear);
  Frame polygons;
  {
    Rig rig(kSize, kSize);
    rig.Glass->SetMethod(vtkRefractionPass::PEEL);
    AddRest(rig);
    rig.Renderer->AddActor(GlassActor(poly, 1.5));
    Look(rig);
    polygons = rig.Render();
  }
  Rig rig(kSize, kSize);
  rig.Glass->SetMethod(vtkRefractionPass::PEEL);
  AddRest(rig);
  auto subject = GlassActor(mixed, 1.5);
  rig.Renderer->AddActor(subject);
  Look(rig);
  Frame f;
  for (int i = 0; i < 3; ++i)
  {
    f = rig.Render();
    RF_REQUIRE(f.GLErrors == 0, "OpenGL error after the pass (frame %d)", i);
    RF_REQUIRE(f.NonFinite() == 0, "NaN/Inf in the output (frame %d)", i);
  }
  const int errors = log->Count("error");
  const int warnings = log->Count("warning");
  const int named = log->Count("warning",
    { subject->GetClassName(), Address(subject.Get()), "1 vertices and 1 lines", "not drawn" });
  std::printf("mixed_cells: %d errors, %d warnings, %d naming the actor and its cells\n", errors,
    warnings, named);
  RF_REQUIRE(errors == 0, "errors for a valid mesh of mixed cells (%d)", errors);
  RF_REQUIRE(warnings == 1 && named == 1,
    "expected one warning naming the actor, its vertex and its line (%d warnings, %d named)",
    warnings, named);
  const double difference = ColourDifference(f, polygons);
  std::printf("largest colour difference to the polygons alone: %g\n", difference);
  RF_REQUIRE(difference <= 1e-5, "the line or the vertex changed the glass");
  return EXIT_SUCCESS;
}

// The table of cases (rfBadInputCases.def, which CMake reads too: each is badinput.<name>).
struct Case
{
  const char* Name;
  int (*Function)(MessageLog* log, const std::string& workdir);
};

const Case kCases[] = {
#define RF_BAD_INPUT_CASE(name, function) { name, function },
#include "rfBadInputCases.def"
#undef RF_BAD_INPUT_CASE
};
}

int main(int argc, char* argv[])
{
  const Case* which = nullptr;
  for (const Case& c : kCases)
  {
    which = argc >= 2 && std::strcmp(argv[1], c.Name) == 0 ? &c : which;
  }
  if (!which)
  {
    std::fprintf(stderr, "usage: %s CASE [WORKDIR]; CASE is one of", argv[0]);
    for (const Case& c : kCases)
    {
      std::fprintf(stderr, " %s", c.Name);
    }
    std::fprintf(stderr, "\n");
    return EXIT_FAILURE;
  }
  MessageLog* log = InstallLog();
  const std::string workdir = argc > 2 ? argv[2] : ".";
  const int result = which->Function(log, workdir);
  std::printf("%s: %s (%d error and %d warning messages in all)\n", which->Name,
    result == EXIT_SUCCESS ? "passed" : (result == kSkipped ? "skipped" : "FAILED"),
    log->Count("error"), log->Count("warning"));
  return result;
}
