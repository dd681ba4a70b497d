// Error against run time: every method and setting on every mesh and resolution, timed
// against a plain VTK render of the same mesh in the same run, and compared with the Embree
// reference: two-interface (the image-space approximation's own error), full (what a user
// sees as wrong) and the full reference supersampled N x N per pixel (the anti-aliased
// truth a camera sees). Writes results.csv, results.md and pareto.png into --out.
//
// The "scene" mesh is the glass sphere in the user's scene: in front of a checkerboard plane
// and three coloured axes, over a gradient background (the pass's renderer environment). Its
// rows are DIR 5 with the refraction of that scene (NG, Wyman 2005) on and off, against
// references that trace the opaque actors too, timed against the plain VTK render of the
// same scene (the sphere drawn opaque, the plane and the axes).
//
// Timing that can be believed: each row (one setting on one mesh at one size) is timed
// together with its own plain render right after it, every row is repeated (--repeats, at
// least 3) and all repeats run in one shuffled order (--seed), so slow phases of the machine
// spread over all rows instead of falling on whichever ran first; the report gives the
// median and the min/max over the repeats. `--help` lists the options.
//
// Rendering goes through EGL (no X server) unless --x11 is given or EGL is not available.
#include "rf_metrics.h"
#include "vtkCheckerboardSource.h"
#include "vtkISRDistanceFilter.h"
#include "vtkMetaballsSource.h"
#include "vtkRefractionEGL.h"
#include "vtkRefractionPass.h"
#include "vtkRefractionReference.h"
#include "vtkSHTransferFilter.h"

#include <vtkActor.h>
#include <vtkAxis.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkChartLegend.h>
#include <vtkChartMatrix.h>
#include <vtkChartXY.h>
#include <vtkCleanPolyData.h>
#include <vtkCommand.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDataArray.h>
#include <vtkEquirectangularToCubeMapTexture.h>
#include <vtkFlyingEdges3D.h>
#include <vtkHDRReader.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLineSource.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkOpenGLRenderTimer.h>
#include <vtkOpenGLTexture.h>
#include <vtkParametricFunctionSource.h>
#include <vtkParametricTorus.h>
#include <vtkPNGWriter.h>
#include <vtkPlot.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRendererCollection.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTable.h>
#include <vtkTimerLog.h>
#include <vtkTubeFilter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVector.h>
#include <vtkWindowToImageFilter.h>
#include <vtk_glew.h>
#include <vtksys/CommandLineArguments.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

namespace
{
struct Options
{
  std::string Out;
  std::vector<int> Sizes{ 256, 512, 1024 };
  std::vector<std::string> Meshes{ "sphere", "torus", "isosurface", "bunny" };
  std::vector<std::string> Methods; // empty: every row of the preset
  int Frames = 30;
  int Repeats = 3;
  int Seed = 1;
  int Supersample = 4;
  int MultiSamples = 0; // the window's (--multisamples)
  bool Smoke = false;
  bool Quick = false;
  bool X11 = false;
  bool Dump = false;
  std::string FromCsv;
  std::string Environment = "builtin";
  std::string Bunny = "/usr/share/glmark2/models/bunny.obj";
};

struct Setting
{
  std::string Method; // none (the pass without glass), SIR, DIR, ISR, SSP, PEEL, SH
  int Steps = 5;
  bool Bounds = false;
  bool Adaptive = false;
  bool Nearest = false;
  bool Paper = false; // the paper's search exactly: no secant refinement
  bool NoScene = false; // SetSceneRefraction(false): the opaque scene is not refracted (NG off)
  bool AntiAliasing = false; // SetAntiAliasing(true): four rays per pixel
  bool PixelComposite = false; // SetMultiSampleSilhouette(false): composited pixel by pixel
  int Bounces = 0;           // SetTIRBounces: total internal reflections followed
  int Layers = 0;            // PEEL: SetPeelLayers (K)
  std::string Label() const
  {
    std::ostringstream s;
    s << Method;
    if (Method == "PEEL")
    {
      s << " " << Layers;
    }
    if (Method == "DIR")
    {
      s << (Adaptive ? " adaptive<=" : " ") << Steps << (Bounds ? " bbox" : "")
        << (Nearest ? " nearest" : "") << (Paper ? " paper" : "");
    }
    s << (NoScene ? " NG off" : "") << (AntiAliasing ? " AA" : "")
      << (PixelComposite ? " px" : "");
    if (Bounces > 0)
    {
      s << " TIR " << Bounces;
    }
    return s.str();
  }
};

// Error of one picture against one reference, on glass pixels, split by TIR.
struct Errors
{
  double Psnr = -1, Rmse = -1, Ssim = -1, PsnrTir = -1, PsnrRest = -1;
};

// Medians and extremes over the repeats of one row.
struct Spread
{
  double Median = -1, Min = -1, Max = -1;
};

struct Row
{
  std::string Mesh;
  vtkIdType Triangles = 0;
  int Size = 0;
  Setting Config;
  int Repeats = 0;
  Spread CpuMs, PlainCpuMs, Ratio;
  double GpuFrameMs = -1, PlainGpuMs = -1;
  std::vector<double> StageMs; // medians, one per vtkRefractionPass timed stage
  double PrecomputeMs = 0, RefTwoMs = 0, RefFullMs = 0, RefFullSSMs = 0, BytesPerPixel = 0;
  Errors Two, Full, TwoSS, FullSS;
  // The two-interface model's own error: its supersampled reference against the supersampled
  // full one, on the row's glass pixels (the floor a method of that model can reach).
  double PsnrModelFullSS = -1;
  double AngMean = 0, AngP95 = 0, AngMax = 0, P2Mean = 0, P2Max = 0, TirShare = 0,
         RefTirShare = 0;
  long Pixels = 0, TirPixels = 0;
};

std::vector<std::string> Split(const std::string& text)
{
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, ','))
  {
    if (!part.empty())
    {
      parts.push_back(part);
    }
  }
  return parts;
}

// A whole decimal number in [lo, hi], or false.
bool ParseInt(const std::string& text, int lo, int hi, int& value)
{
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || v < lo || v > hi)
  {
    return false;
  }
  value = static_cast<int>(v);
  return true;
}

bool Parse(int argc, char* argv[], Options& o)
{
  std::string sizes, meshes, methods, frames, repeats, seed, supersample, multisamples;
  bool help = false;
  using Args = vtksys::CommandLineArguments;
  Args args;
  args.Initialize(argc, argv);
  args.AddArgument("--out", Args::SPACE_ARGUMENT, &o.Out,
    "Folder for results.csv, results.md, pareto.png (default bench/results/<host kind>).");
  args.AddArgument("--sizes", Args::SPACE_ARGUMENT, &sizes,
    "Window sizes in pixels, comma-separated, 8..4096 (default 256,512,1024).");
  args.AddArgument("--meshes", Args::SPACE_ARGUMENT, &meshes,
    "Meshes, comma-separated: sphere, torus, isosurface, bunny (default all four), scene "
    "(the sphere in front of a checkerboard and axes over a gradient background: DIR 5 with "
    "the scene's refraction on and off) and nested (nested contours: the isosurface's blobs, "
    "IOR 1.5, holding the contour of a higher value as a second glass actor of IOR 1.9).");
  args.AddArgument("--methods", Args::SPACE_ARGUMENT, &methods,
    "Keep only the rows of these methods, comma-separated: DIR, SIR, ISR, SSP, PEEL, SH, "
    "none (default: every row of the preset), e.g. --quick --methods DIR.");
  args.AddArgument("--frames", Args::SPACE_ARGUMENT, &frames,
    "Timed frames per repeat of a row, after 5 warm-up frames (default 30).");
  args.AddArgument("--repeats", Args::SPACE_ARGUMENT, &repeats,
    "Repeats of every row, in one shuffled order, 3..100 (default 3).");
  args.AddArgument("--seed", Args::SPACE_ARGUMENT, &seed,
    "Seed of the shuffled row order (default 1).");
  args.AddArgument("--supersample", Args::SPACE_ARGUMENT, &supersample,
    "Rays per pixel side of the anti-aliased references, 2..16 (default 4: 16 rays).");
  args.AddArgument("--multisamples", Args::SPACE_ARGUMENT, &multisamples,
    "Samples per pixel of the window, 0..16 (default 0: single-sampled; VTK's own default is "
    "8). Above 0, --quick adds the rows `DIR 5 px` and `DIR 5 AA px`: the glass composited "
    "pixel by pixel (SetMultiSampleSilhouette(false)) instead of at the window's samples.");
  args.AddArgument("--environment", Args::SPACE_ARGUMENT, &o.Environment,
    "builtin (the pass's built-in sky, default), studio (an HDR lat-long image made in "
    "code: dim walls, bright soft boxes up to 8), or a lat-long .hdr file; the last two go "
    "through vtkEquirectangularToCubeMapTexture as the renderer's environment.");
  args.AddArgument("--bunny", Args::SPACE_ARGUMENT, &o.Bunny,
    "The Stanford bunny OBJ (default /usr/share/glmark2/models/bunny.obj).");
  args.AddArgument("--from-csv", Args::SPACE_ARGUMENT, &o.FromCsv,
    "Remake results.md and pareto.png from an earlier results.csv, without running.");
  args.AddBooleanArgument("--quick", &o.Quick,
    "The four meshes and nested at 512x512: DIR (5 steps; also with anti-aliasing, and with "
    "two total internal reflections followed), SIR, PEEL with 2, 4 and 8 layers (and 4 with "
    "two reflections followed), each with its plain render, 3 repeats.");
  args.AddBooleanArgument("--smoke", &o.Smoke,
    "64x64, sphere and torus, 5 frames, every method once: the ctest smoke run.");
  args.AddBooleanArgument("--x11", &o.X11, "Render through an X window instead of EGL.");
  args.AddBooleanArgument("--dump", &o.Dump, "Also write every picture and reference as PNG.");
  args.AddBooleanArgument("--help", &help, "Print this help.");
  if (!args.Parse())
  {
    std::fprintf(stderr, "RefractionBenchmark: bad command line (--help lists the options)\n");
    return false;
  }
  if (help)
  {
    std::printf("RefractionBenchmark: error against run time of the refraction methods.\n\n%s",
      args.GetHelp());
    std::exit(0);
  }
  if (o.Quick)
  {
    o.Sizes = { 512 };
    o.Meshes = { "sphere", "torus", "isosurface", "bunny", "nested" };
  }
  if (o.Smoke)
  {
    o.Sizes = { 64 };
    o.Meshes = { "sphere", "torus" };
    o.Frames = 5;
    o.Supersample = 2;
  }
  if (!sizes.empty())
  {
    o.Sizes.clear();
    for (const auto& text : Split(sizes))
    {
      int size = 0;
      if (!ParseInt(text, 8, 4096, size))
      {
        std::fprintf(stderr, "--sizes: '%s' is not a size in 8..4096\n", text.c_str());
        return false;
      }
      o.Sizes.push_back(size);
    }
  }
  if (!meshes.empty())
  {
    o.Meshes = Split(meshes);
    for (const auto& name : o.Meshes)
    {
      if (name != "sphere" && name != "torus" && name != "isosurface" && name != "bunny" &&
        name != "scene" && name != "nested")
      {
        std::fprintf(stderr, "--meshes: unknown mesh '%s'\n", name.c_str());
        return false;
      }
    }
  }
  for (const auto& name : Split(methods))
  {
    std::string upper = name;
    for (char& c : upper)
      c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (upper == "NONE")
      upper = "none";
    if (upper != "DIR" && upper != "SIR" && upper != "ISR" && upper != "SSP" && upper != "PEEL" &&
      upper != "SH" && upper != "none")
    {
      std::fprintf(stderr, "--methods: unknown method '%s'\n", name.c_str());
      return false;
    }
    o.Methods.push_back(upper);
  }
  if ((!frames.empty() && !ParseInt(frames, 1, 10000, o.Frames)) ||
    (!repeats.empty() && !ParseInt(repeats, 3, 100, o.Repeats)) ||
    (!seed.empty() && !ParseInt(seed, 0, 2147483647, o.Seed)) ||
    (!supersample.empty() && !ParseInt(supersample, 2, 16, o.Supersample)) ||
    (!multisamples.empty() && !ParseInt(multisamples, 0, 16, o.MultiSamples)))
  {
    std::fprintf(stderr, "--frames (1..10000), --repeats (3..100), --seed (>= 0), "
                         "--supersample (2..16) or --multisamples (0..16): not a number in "
                         "range\n");
    return false;
  }
  if (o.Environment != "builtin" && o.Environment != "studio" &&
    !vtksys::SystemTools::FileExists(o.Environment, true))
  {
    std::fprintf(stderr, "--environment: '%s' is neither builtin, studio nor a file\n",
      o.Environment.c_str());
    return false;
  }
  if (o.Sizes.empty() || o.Meshes.empty())
  {
    std::fprintf(stderr, "no sizes or no meshes to run\n");
    return false;
  }
  return true;
}

std::string HostKind(const std::string& renderer)
{
  if (renderer.find("llvmpipe") != std::string::npos)
  {
    return "cpu-llvmpipe";
  }
  std::string kind;
  for (char c : renderer)
  {
    if (std::isalnum(static_cast<unsigned char>(c)))
      kind += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else if (!kind.empty() && kind.back() != '-')
      kind += '-';
    if (kind.size() > 40)
      break;
  }
  return kind.empty() ? "unknown" : kind;
}

// The nested mesh's inner contour, as a multiple of the metaballs' iso value.
const double kNestedInnerValue = 2.0;

// The mesh, with d_N for ISR added by the filter (which other methods ignore).
vtkSmartPointer<vtkAlgorithm> MakeMesh(const std::string& name, const Options& o)
{
  vtkSmartPointer<vtkAlgorithm> source;
  if (name == "sphere" || name == "scene")
  {
    auto sphere = vtkSmartPointer<vtkSphereSource>::New();
    sphere->SetThetaResolution(o.Smoke ? 48 : 160);
    sphere->SetPhiResolution(o.Smoke ? 48 : 160);
    source = sphere;
  }
  else if (name == "torus")
  {
    vtkNew<vtkParametricTorus> torus;
    torus->SetRingRadius(0.7);
    torus->SetCrossSectionRadius(0.3);
    auto fn = vtkSmartPointer<vtkParametricFunctionSource>::New();
    fn->SetParametricFunction(torus);
    fn->SetUResolution(o.Smoke ? 64 : 192);
    fn->SetVResolution(o.Smoke ? 32 : 96);
    // The parametric source repeats its seam's points (u = 0 and 2 pi, 1e-15 apart) and
    // joins them with triangles of no area; vtkPolyDataNormals' consistency walk then turns
    // some triangles over, and the pass (rightly) draws a mesh wound inconsistently without
    // face culling. Merging the seam first, as one would for any analysis, gives a closed,
    // consistently wound torus.
    auto clean = vtkSmartPointer<vtkCleanPolyData>::New();
    clean->SetInputConnection(fn->GetOutputPort());
    clean->SetTolerance(1e-6);
    auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
    normals->SetInputConnection(clean->GetOutputPort());
    source = normals;
  }
  else if (name == "isosurface" || name == "nested" || name == "nested-inner")
  {
    auto blobs = vtkSmartPointer<vtkMetaballsSource>::New();
    blobs->SetSampleDimensions(o.Smoke ? 32 : 80);
    auto surface = vtkSmartPointer<vtkFlyingEdges3D>::New();
    surface->SetInputConnection(blobs->GetOutputPort());
    surface->SetValue(0, (name == "nested-inner" ? kNestedInnerValue : 1.0) * blobs->GetIsoValue());
    surface->ComputeNormalsOn();
    surface->UpdateTimeStep(0.3 * blobs->GetTimePeriod());
    source = surface;
  }
  else if (name == "bunny")
  {
    std::ifstream probe(o.Bunny);
    if (!probe)
    {
      std::fprintf(stderr, "bunny: %s not found (Debian package glmark2-data); skipped\n",
        o.Bunny.c_str());
      return nullptr;
    }
    auto reader = vtkSmartPointer<vtkOBJReader>::New();
    reader->SetFileName(o.Bunny.c_str());
    auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
    normals->SetInputConnection(reader->GetOutputPort());
    normals->SplittingOff();
    source = normals;
  }
  else
  {
    std::fprintf(stderr, "unknown mesh %s; skipped\n", name.c_str());
    return nullptr;
  }
  auto distances = vtkSmartPointer<vtkISRDistanceFilter>::New();
  distances->SetInputConnection(source->GetOutputPort());
  distances->Update();
  return distances;
}

// The scene mesh's surroundings (the glass sphere has radius 0.5 at the origin): a checkerboard
// of 8 x 8 unlit squares (cell scalars 0 / 1 through a two-colour lookup table) well behind
// it, beyond the ball lens's focal length so that it shows the board upside down, and three
// lit axes (red x, green y, blue z) between them, as tubes: vtkAxesActor is an assembly, which
// the reference does not trace.
std::vector<vtkSmartPointer<vtkActor>> MakeSurroundings()
{
  std::vector<vtkSmartPointer<vtkActor>> actors;
  const double z = -2.0;
  const double half = 1.25;
  vtkNew<vtkCheckerboardSource> board;
  board->SetOrigin(-half, -half, z);
  board->SetPoint1(half, -half, z);
  board->SetPoint2(-half, half, z);
  board->SetResolution(8, 8);
  vtkNew<vtkLookupTable> table;
  table->SetNumberOfTableValues(2);
  table->SetTableValue(0, 0.95, 0.85, 0.3, 1.0);
  table->SetTableValue(1, 0.15, 0.1, 0.35, 1.0);
  table->SetTableRange(0.0, 1.0);
  vtkNew<vtkPolyDataMapper> boardMapper;
  boardMapper->SetInputConnection(board->GetOutputPort());
  boardMapper->SetLookupTable(table);
  boardMapper->SetScalarRange(0.0, 1.0);
  boardMapper->SetScalarModeToUseCellData();
  auto boardActor = vtkSmartPointer<vtkActor>::New();
  boardActor->SetMapper(boardMapper);
  boardActor->GetProperty()->SetAmbient(1.0);
  boardActor->GetProperty()->SetDiffuse(0.0);
  actors.push_back(boardActor);
  const double origin[3] = { 0.15, -0.1, -1.25 };
  const double axisLength[3] = { 0.75, 0.75, 0.6 };
  for (int axis = 0; axis < 3; ++axis)
  {
    double end[3] = { origin[0], origin[1], origin[2] };
    end[axis] += axisLength[axis];
    vtkNew<vtkLineSource> line;
    line->SetPoint1(origin);
    line->SetPoint2(end);
    vtkNew<vtkTubeFilter> tube;
    tube->SetInputConnection(line->GetOutputPort());
    tube->SetRadius(0.04);
    tube->SetNumberOfSides(24);
    tube->CappingOn();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(tube->GetOutputPort());
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0);
    actors.push_back(actor);
  }
  return actors;
}

// The window's colour as floats in [0,1], bottom row first (as the reference).
std::vector<float> GrabColour(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  vtkDataArray* rgb = grab->GetOutput()->GetPointData()->GetScalars();
  std::vector<float> colour(3 * rgb->GetNumberOfTuples());
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      colour[3 * i + c] = static_cast<float>(rgb->GetComponent(i, c) / 255.0);
    }
  }
  return colour;
}

std::vector<float> Floats(vtkImageData* image, const char* name, int components)
{
  vtkDataArray* a = image->GetPointData()->GetArray(name);
  std::vector<float> values(a ? components * a->GetNumberOfTuples() : 0);
  for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < components; ++c)
    {
      values[components * i + c] = static_cast<float>(a->GetComponent(i, c));
    }
  }
  return values;
}

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return -1.0;
  }
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

Spread SpreadOf(const std::vector<double>& v)
{
  Spread s;
  if (!v.empty())
  {
    s.Median = Median(v);
    s.Min = *std::min_element(v.begin(), v.end());
    s.Max = *std::max_element(v.begin(), v.end());
  }
  return s;
}

struct Timing
{
  double Cpu = -1, GpuFrame = -1;
  std::vector<double> Stages; // vtkRefractionPass's timed stages, 0..TIMED_STAGE_COUNT-1
};

// Medians over `frames` frames after 5 warm-up frames: CPU wall time per frame (to
// glFinish) and a GL timer query around the frame, with the pass's own stage timers off (their
// queries flush llvmpipe between stages, which a user's frame does not pay); then the pass's
// stage timers over a third as many frames of their own.
Timing TimeFrames(vtkRenderWindow* window, vtkRefractionPass* pass, int frames)
{
  vtkNew<vtkTimerLog> clock;
  vtkOpenGLRenderTimer frameTimer;
  std::vector<double> cpu, gpu;
  std::vector<std::vector<double>> stages(vtkRefractionPass::TIMED_STAGE_COUNT);
  const bool gpuTimers = vtkOpenGLRenderTimer::IsSupported();
  if (pass)
  {
    pass->SetGPUTiming(false);
  }
  for (int i = 0; i < 5 + frames; ++i)
  {
    clock->StartTimer();
    if (gpuTimers)
    {
      frameTimer.Reset();
      frameTimer.Start();
    }
    window->Render();
    if (gpuTimers)
    {
      frameTimer.Stop();
    }
    glFinish();
    clock->StopTimer();
    if (i < 5)
    {
      continue;
    }
    cpu.push_back(clock->GetElapsedTime() * 1e3);
    if (gpuTimers && frameTimer.Ready())
    {
      gpu.push_back(frameTimer.GetElapsedMilliseconds());
    }
  }
  frameTimer.ReleaseGraphicsResources();
  if (pass && gpuTimers)
  {
    // A stage's query is read back a frame later (vtkRefractionPass::StartTimer).
    pass->SetGPUTiming(true);
    const int stageFrames = std::max(3, frames / 3);
    for (int i = 0; i < 2 + stageFrames; ++i)
    {
      window->Render();
      glFinish();
      for (int s = 0; i >= 2 && s < vtkRefractionPass::TIMED_STAGE_COUNT; ++s)
      {
        const double ms = pass->GetStageMilliseconds(s);
        if (ms >= 0.0)
        {
          stages[s].push_back(ms);
        }
      }
    }
    pass->SetGPUTiming(false);
  }
  Timing t;
  t.Cpu = Median(cpu);
  t.GpuFrame = Median(gpu);
  for (auto& stage : stages)
  {
    t.Stages.push_back(Median(stage));
  }
  return t;
}

struct Reference
{
  std::vector<float> Colour, P2, T2;
  std::vector<unsigned char> Hit, Tir;
  double Seconds = 0;
  double Diagonal = 1;
};

// The reference's ProgressEvent shown on one line (every 10 %), ended when the trace is.
struct ProgressLine
{
  std::string Label;
  int Last = -100;
};

void ShowProgress(vtkObject*, unsigned long, void* client, void* call)
{
  auto* line = static_cast<ProgressLine*>(client);
  const double fraction = *static_cast<double*>(call);
  const int percent = static_cast<int>(100.0 * fraction);
  // On a terminal the line is rewritten in place; in a log only its end is written.
  static const bool terminal = isatty(fileno(stdout)) != 0;
  if (fraction < 1.0 && (!terminal || percent < line->Last + 10))
  {
    return;
  }
  line->Last = percent;
  std::printf("\r  reference %-34s %3d %%%s", line->Label.c_str(), percent,
    fraction >= 1.0 ? "\n" : "");
  std::fflush(stdout);
}

bool Trace(vtkRenderer* renderer, vtkRefractionPass* pass, int size, int mode, int samples,
  const std::string& label, Reference& out)
{
  vtkNew<vtkRefractionReference> reference;
  reference->SetMode(mode);
  reference->SetEnvironmentMode(pass->GetEnvironmentMode()); // the pass's environment
  reference->SetThreads(2);
  reference->SetSamplesPerSide(samples);
  ProgressLine line{ label };
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback(ShowProgress);
  progress->SetClientData(&line);
  reference->AddObserver(vtkCommand::ProgressEvent, progress);
  if (!reference->Trace(renderer, size, size))
  {
    return false;
  }
  vtkImageData* image = reference->GetOutput();
  out.Colour = Floats(image, "Colour", 3);
  for (float& c : out.Colour)
  {
    c = std::min(std::max(c, 0.0f), 1.0f); // what an 8-bit window can show
  }
  out.P2 = Floats(image, "P2", 3);
  out.T2 = Floats(image, "T2", 3);
  const auto hit = Floats(image, "Hit", 1);
  const auto tir = Floats(image, "TIR", 1);
  out.Hit.resize(hit.size());
  out.Tir.resize(tir.size());
  for (size_t i = 0; i < hit.size(); ++i)
  {
    out.Hit[i] = hit[i] > 0.5f ? 1 : 0;
    out.Tir[i] = i < tir.size() && tir[i] > 0.5f ? 1 : 0;
  }
  out.Seconds = reference->GetTraceSeconds();
  out.Diagonal = reference->GetGlassDiagonal();
  return true;
}

// The four references of one mesh at one size.
struct Truth
{
  Reference Two, Full, TwoSS, FullSS;
};

Errors Compare(const std::vector<float>& colour, const Reference& reference,
  const std::vector<unsigned char>& mask, const std::vector<unsigned char>& tirMask,
  const std::vector<unsigned char>& restMask, int size)
{
  const size_t n = static_cast<size_t>(size) * size;
  Errors e;
  rf_psnr(colour.data(), reference.Colour.data(), n, 3, mask.data(), &e.Psnr);
  rf_rmse(colour.data(), reference.Colour.data(), n, 3, mask.data(), &e.Rmse);
  rf_ssim(colour.data(), reference.Colour.data(), size, size, 3, mask.data(), &e.Ssim);
  // Left at -1 where there are no such pixels.
  rf_psnr(colour.data(), reference.Colour.data(), n, 3, tirMask.data(), &e.PsnrTir);
  rf_psnr(colour.data(), reference.Colour.data(), n, 3, restMask.data(), &e.PsnrRest);
  return e;
}

// Errors on the pixels where both the pass and the reference (its pixel centre) see glass;
// TIR pixels are those where the two-interface reference's ray is totally reflected at the
// exit.
void Measure(Row& row, const std::vector<float>& colour, vtkImageData* debug, const Truth& truth,
  int size)
{
  const size_t n = static_cast<size_t>(size) * size;
  const Reference& two = truth.Two;
  const auto flags = Floats(debug, "Flags", 1);
  const auto t2 = Floats(debug, "T2", 3);
  const auto p2 = Floats(debug, "P2", 3);
  std::vector<unsigned char> mask(n, 0), tir(n, 0), refTir(n, 0), rest(n, 0);
  long count = 0, tirCount = 0;
  for (size_t i = 0; i < n; ++i)
  {
    const bool glass = i < flags.size() && flags[i] > 0.5f;
    mask[i] = glass && two.Hit[i] ? 1 : 0;
    tir[i] = glass && flags[i] > 1.5f ? 1 : 0;
    refTir[i] = mask[i] && two.Tir[i] ? 1 : 0;
    rest[i] = mask[i] && !two.Tir[i] ? 1 : 0;
    count += mask[i];
    tirCount += refTir[i];
  }
  row.Pixels = count;
  row.TirPixels = tirCount;
  if (count == 0)
  {
    return;
  }
  row.Two = Compare(colour, truth.Two, mask, refTir, rest, size);
  row.Full = Compare(colour, truth.Full, mask, refTir, rest, size);
  row.TwoSS = Compare(colour, truth.TwoSS, mask, refTir, rest, size);
  row.FullSS = Compare(colour, truth.FullSS, mask, refTir, rest, size);
  rf_psnr(truth.TwoSS.Colour.data(), truth.FullSS.Colour.data(), n, 3, mask.data(),
    &row.PsnrModelFullSS);
  rf_error_stats angle{};
  if (rf_angular_error(t2.data(), two.T2.data(), n, mask.data(), &angle) == RF_OK)
  {
    row.AngMean = angle.mean;
    row.AngP95 = angle.p95;
    row.AngMax = angle.max;
  }
  rf_error_stats position{};
  if (rf_position_error(p2.data(), two.P2.data(), n, mask.data(), two.Diagonal, &position) ==
    RF_OK)
  {
    row.P2Mean = position.mean;
    row.P2Max = position.max;
  }
  rf_flag_share(tir.data(), n, mask.data(), &row.TirShare);
  rf_flag_share(two.Tir.data(), n, mask.data(), &row.RefTirShare);
}

// An RGB float image (bottom row first) as an 8-bit PNG, for a person to compare.
void WritePng(const std::string& path, const std::vector<float>& rgb, int size)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(size, size, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  for (size_t i = 0; i < rgb.size(); ++i)
  {
    out[i] = static_cast<unsigned char>(std::min(std::max(rgb[i], 0.0f), 1.0f) * 255.0f + 0.5f);
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
}

// One CSV column: its name, how a row writes it and how a row reads it back.
struct Column
{
  std::string Name;
  std::function<std::string(const Row&)> Get;
  std::function<void(Row&, const std::string&)> Set;
};

std::string Number(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

std::vector<Column> Columns(int stageCount)
{
  std::vector<Column> c;
  auto text = [&c](const char* name, std::function<std::string(const Row&)> get,
                std::function<void(Row&, const std::string&)> set) {
    c.push_back({ name, std::move(get), std::move(set) });
  };
  auto number = [&c](const std::string& name, std::function<double&(Row&)> field) {
    c.push_back({ name,
      [field](const Row& r) { return Number(field(const_cast<Row&>(r))); },
      [field](Row& r, const std::string& v) { field(r) = std::atof(v.c_str()); } });
  };
  text("mesh", [](const Row& r) { return r.Mesh; }, [](Row& r, const std::string& v) { r.Mesh = v; });
  c.push_back({ "triangles", [](const Row& r) { return std::to_string(r.Triangles); },
    [](Row& r, const std::string& v) { r.Triangles = std::atoll(v.c_str()); } });
  c.push_back({ "size", [](const Row& r) { return std::to_string(r.Size); },
    [](Row& r, const std::string& v) { r.Size = std::atoi(v.c_str()); } });
  text("method", [](const Row& r) { return r.Config.Method; },
    [](Row& r, const std::string& v) { r.Config.Method = v; });
  c.push_back({ "steps", [](const Row& r) { return std::to_string(r.Config.Steps); },
    [](Row& r, const std::string& v) { r.Config.Steps = std::atoi(v.c_str()); } });
  text("depth_range", [](const Row& r) { return std::string(r.Config.Bounds ? "bbox" : "reduction"); },
    [](Row& r, const std::string& v) { r.Config.Bounds = v == "bbox"; });
  c.push_back({ "adaptive", [](const Row& r) { return std::string(r.Config.Adaptive ? "1" : "0"); },
    [](Row& r, const std::string& v) { r.Config.Adaptive = v == "1"; } });
  text("back_surface", [](const Row& r) { return std::string(r.Config.Nearest ? "nearest" : "furthest"); },
    [](Row& r, const std::string& v) { r.Config.Nearest = v == "nearest"; });
  c.push_back({ "secant", [](const Row& r) { return std::string(r.Config.Paper ? "0" : "1"); },
    [](Row& r, const std::string& v) { r.Config.Paper = v == "0"; } });
  c.push_back({ "scene_refraction",
    [](const Row& r) { return std::string(r.Config.NoScene ? "0" : "1"); },
    [](Row& r, const std::string& v) { r.Config.NoScene = v == "0"; } });
  c.push_back({ "tir_bounces", [](const Row& r) { return std::to_string(r.Config.Bounces); },
    [](Row& r, const std::string& v) { r.Config.Bounces = std::atoi(v.c_str()); } });
  c.push_back({ "peel_layers", [](const Row& r) { return std::to_string(r.Config.Layers); },
    [](Row& r, const std::string& v) { r.Config.Layers = std::atoi(v.c_str()); } });
  c.push_back({ "anti_aliasing",
    [](const Row& r) { return std::string(r.Config.AntiAliasing ? "1" : "0"); },
    [](Row& r, const std::string& v) { r.Config.AntiAliasing = v == "1"; } });
  c.push_back({ "multisample_silhouette",
    [](const Row& r) { return std::string(r.Config.PixelComposite ? "0" : "1"); },
    [](Row& r, const std::string& v) { r.Config.PixelComposite = v == "0"; } });
  c.push_back({ "repeats", [](const Row& r) { return std::to_string(r.Repeats); },
    [](Row& r, const std::string& v) { r.Repeats = std::atoi(v.c_str()); } });
  number("cpu_ms", [](Row& r) -> double& { return r.CpuMs.Median; });
  number("cpu_ms_min", [](Row& r) -> double& { return r.CpuMs.Min; });
  number("cpu_ms_max", [](Row& r) -> double& { return r.CpuMs.Max; });
  number("plain_cpu_ms", [](Row& r) -> double& { return r.PlainCpuMs.Median; });
  number("plain_cpu_ms_min", [](Row& r) -> double& { return r.PlainCpuMs.Min; });
  number("plain_cpu_ms_max", [](Row& r) -> double& { return r.PlainCpuMs.Max; });
  number("cpu_ratio", [](Row& r) -> double& { return r.Ratio.Median; });
  number("cpu_ratio_min", [](Row& r) -> double& { return r.Ratio.Min; });
  number("cpu_ratio_max", [](Row& r) -> double& { return r.Ratio.Max; });
  number("gpu_frame_ms", [](Row& r) -> double& { return r.GpuFrameMs; });
  number("plain_gpu_ms", [](Row& r) -> double& { return r.PlainGpuMs; });
  for (int s = 0; s < stageCount; ++s)
  {
    number("gpu_stage" + std::to_string(s) + "_ms", [s](Row& r) -> double& {
      if (static_cast<int>(r.StageMs.size()) <= s)
        r.StageMs.resize(s + 1, -1.0);
      return r.StageMs[s];
    });
  }
  number("precompute_ms", [](Row& r) -> double& { return r.PrecomputeMs; });
  number("ref_two_ms", [](Row& r) -> double& { return r.RefTwoMs; });
  number("ref_full_ms", [](Row& r) -> double& { return r.RefFullMs; });
  number("ref_full_ss_ms", [](Row& r) -> double& { return r.RefFullSSMs; });
  number("bytes_per_pixel", [](Row& r) -> double& { return r.BytesPerPixel; });
  const std::pair<const char*, Errors Row::*> references[] = { { "two", &Row::Two },
    { "full", &Row::Full }, { "two_ss", &Row::TwoSS }, { "full_ss", &Row::FullSS } };
  for (const auto& ref : references)
  {
    const std::string suffix = ref.first;
    Errors Row::*member = ref.second;
    number("psnr_" + suffix, [member](Row& r) -> double& { return (r.*member).Psnr; });
    number("rmse_" + suffix, [member](Row& r) -> double& { return (r.*member).Rmse; });
    number("ssim_" + suffix, [member](Row& r) -> double& { return (r.*member).Ssim; });
    number("psnr_" + suffix + "_tir", [member](Row& r) -> double& { return (r.*member).PsnrTir; });
    number("psnr_" + suffix + "_rest", [member](Row& r) -> double& { return (r.*member).PsnrRest; });
  }
  number("psnr_model_full_ss", [](Row& r) -> double& { return r.PsnrModelFullSS; });
  number("t2_deg_mean", [](Row& r) -> double& { return r.AngMean; });
  number("t2_deg_p95", [](Row& r) -> double& { return r.AngP95; });
  number("t2_deg_max", [](Row& r) -> double& { return r.AngMax; });
  number("p2_rel_mean", [](Row& r) -> double& { return r.P2Mean; });
  number("p2_rel_max", [](Row& r) -> double& { return r.P2Max; });
  number("tir_share", [](Row& r) -> double& { return r.TirShare; });
  number("ref_tir_share", [](Row& r) -> double& { return r.RefTirShare; });
  c.push_back({ "pixels", [](const Row& r) { return std::to_string(r.Pixels); },
    [](Row& r, const std::string& v) { r.Pixels = std::atol(v.c_str()); } });
  c.push_back({ "tir_pixels", [](const Row& r) { return std::to_string(r.TirPixels); },
    [](Row& r, const std::string& v) { r.TirPixels = std::atol(v.c_str()); } });
  return c;
}

bool WriteCsv(const std::string& path, const std::vector<Row>& rows, const std::string& renderer)
{
  std::ofstream f(path);
  const auto columns = Columns(vtkRefractionPass::TIMED_STAGE_COUNT);
  f << "renderer";
  for (const auto& column : columns)
    f << ',' << column.Name;
  f << '\n';
  for (const Row& r : rows)
  {
    f << '"' << renderer << '"';
    for (const auto& column : columns)
      f << ',' << column.Get(r);
    f << '\n';
  }
  f.flush();
  return static_cast<bool>(f);
}

std::vector<std::string> CsvFields(const std::string& text)
{
  std::vector<std::string> out(1);
  bool quoted = false;
  for (char c : text)
  {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

// Rows back from a results.csv written by WriteCsv, to remake results.md and pareto.png.
bool ReadCsv(const std::string& path, std::vector<Row>& rows, std::string& renderer)
{
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line))
  {
    return false;
  }
  const auto header = CsvFields(line);
  int stageCount = 0;
  for (const auto& name : header)
    stageCount += name.rfind("gpu_stage", 0) == 0 ? 1 : 0;
  const auto columns = Columns(stageCount);
  while (std::getline(in, line))
  {
    const auto f = CsvFields(line);
    if (f.size() != header.size())
      continue;
    Row r;
    for (size_t i = 0; i < f.size(); ++i)
    {
      if (header[i] == "renderer")
        renderer = f[i];
      for (const auto& column : columns)
        if (column.Name == header[i])
          column.Set(r, f[i]);
    }
    rows.push_back(r);
  }
  return !rows.empty();
}

std::string Db(double v)
{
  char text[32];
  std::snprintf(text, sizeof(text), v < 0 ? "-" : "%.1f", v);
  return text;
}

bool WriteMarkdown(const std::string& path, const std::vector<Row>& rows,
  const std::string& renderer, const std::string& windowPath, const std::string& run)
{
  std::ofstream f(path);
  char line[1024];
  f << "# Error against run time\n\nRenderer: " << renderer << " (" << windowPath << "). "
    << run << "\n\n"
    << "How to read it. Every row (a setting on a mesh at a size) was timed together with a "
       "plain VTK render of the same mesh right after it, repeated in one shuffled order; "
       "`ms` and `ratio` (glass frame time over that plain render) are medians over the "
       "repeats with [min-max] beside them; each repeat is itself the median of the timed "
       "frames after 5 warm-up frames. Errors are on glass pixels only (where the pass and "
       "the reference's pixel centre both see glass), against the Embree reference: `two` is "
       "the two-interface reference (the approximation's own error), `full` the Whitted "
       "reference (depth 8, Fresnel splits, TIR), `full SS` the full reference averaged over "
       "N x N rays per pixel (the anti-aliased truth a camera sees); `model vs full SS` is the "
       "two-interface reference, supersampled too, against `full SS` on the same pixels: the "
       "best a two-interface method can read there. `AA`: the pass's anti-aliasing "
       "(vtkRefractionPass::SetAntiAliasing); `TIR 2`: two total internal reflections followed "
       "(SetTIRBounces). `TIR` / `rest`: PSNR "
       "against `full SS` on the pixels where the two-interface reference's ray is totally "
       "reflected at the exit, and on the others (`-`: none). Stage times are the pass's GL "
       "timer queries, over frames of their own after the timed frames (the timed frames run "
       "without them: their queries make llvmpipe finish each stage before the next), stage k = vtkRefractionPass's TIMED_* enumerator k (";
  for (int stage = 0; stage < vtkRefractionPass::TIMED_STAGE_COUNT; ++stage)
  {
    f << (stage ? ", " : "") << stage << " " << vtkRefractionPass::GetStageName(stage);
  }
  f << "); on llvmpipe they include work queued before "
        "the stage; -1 marks a stage the method does not run. `B/px` is "
        "vtkRefractionPass::GetTextureBytes() over the pixels.\n\n";
  // Table 1 of the paper: fps per model at 512x512 (or the size nearest it).
  std::map<std::string, std::map<std::string, const Row*>> table;
  int tableSize = 0;
  for (const Row& r : rows)
  {
    if (tableSize == 0 || std::abs(r.Size - 512) < std::abs(tableSize - 512))
      tableSize = r.Size;
  }
  f << "## Table 1 analogue (" << tableSize << "x" << tableSize
    << ", fps from the median CPU frame time; RT in seconds, 2 threads)\n\n"
    << "| model | triangles | pixels | DIR | ISR | SIR | SSP | plain VTK | RT (two-interface) | "
       "RT (full) | RT (full, SS) |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows)
  {
    if (r.Size != tableSize || r.Config.Method == "none" || r.Config.NoScene)
      continue;
    if (r.Config.Method == "DIR" && (r.Config.Steps != 5 || r.Config.Bounds ||
                                      r.Config.Adaptive || r.Config.Nearest || r.Config.Paper))
      continue;
    table[r.Mesh][r.Config.Method] = &r;
  }
  for (auto& entry : table)
  {
    auto fps = [&](const char* m) {
      auto it = entry.second.find(m);
      return it == entry.second.end()
        ? std::string("-")
        : std::to_string(static_cast<int>(1000.0 / it->second->CpuMs.Median + 0.5));
    };
    const Row* any = entry.second.begin()->second;
    std::snprintf(line, sizeof(line),
      "| %s | %lld | %ld | %s | %s | %s | %s | %d | %.2f s | %.2f s | %.2f s |\n",
      entry.first.c_str(), static_cast<long long>(any->Triangles), any->Pixels,
      fps("DIR").c_str(), fps("ISR").c_str(), fps("SIR").c_str(), fps("SSP").c_str(),
      static_cast<int>(1000.0 / any->PlainCpuMs.Median + 0.5), any->RefTwoMs / 1000.0,
      any->RefFullMs / 1000.0, any->RefFullSSMs / 1000.0);
    f << line;
  }
  f << "\n## All rows\n\n| mesh | size | method | ms [min-max] | ratio [min-max] | stage ms | "
       "pre ms | B/px | PSNR two | PSNR full | PSNR full SS | model vs full SS | SSIM full SS | TIR / "
       "rest (full SS) | TIR / rest (two) | T2 deg mean/p95 | TIR px |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows)
  {
    std::string stages;
    for (size_t s = 0; s < r.StageMs.size(); ++s)
    {
      char stage[32];
      std::snprintf(stage, sizeof(stage), "%s%.2f", s ? "/" : "", r.StageMs[s]);
      stages += stage;
    }
    std::snprintf(line, sizeof(line),
      "| %s | %d | %s | %.2f [%.2f-%.2f] | %.2f [%.2f-%.2f] | %s | %.1f | %.0f | %s | %s | %s | "
      "%s | %.3f | %s / %s | %s / %s | %.2f/%.2f | %ld |\n",
      r.Mesh.c_str(), r.Size, r.Config.Label().c_str(), r.CpuMs.Median, r.CpuMs.Min,
      r.CpuMs.Max, r.Ratio.Median, r.Ratio.Min, r.Ratio.Max, stages.c_str(), r.PrecomputeMs,
      r.BytesPerPixel, Db(r.Two.Psnr).c_str(), Db(r.Full.Psnr).c_str(),
      Db(r.FullSS.Psnr).c_str(), Db(r.PsnrModelFullSS).c_str(), r.FullSS.Ssim,
      Db(r.FullSS.PsnrTir).c_str(), Db(r.FullSS.PsnrRest).c_str(), Db(r.Two.PsnrTir).c_str(),
      Db(r.Two.PsnrRest).c_str(), r.AngMean, r.AngP95, r.TirPixels);
    f << line;
  }
  // The noise that remains: the same plain render timed in every job of a mesh and size.
  f << "\n## Noise\n\nThe plain render does the same work in every job of a mesh and size, so "
       "its spread over the run is the machine's noise; a glass row's ratio spread over its "
       "repeats is what a single ratio may be off by.\n\n"
       "| mesh | size | plain ms median [min-max] over rows | widest ratio spread (max/min) |\n"
       "|---|---|---|---|\n";
  std::map<std::pair<std::string, int>, std::vector<const Row*>> groups;
  for (const Row& r : rows)
    groups[{ r.Mesh, r.Size }].push_back(&r);
  for (const auto& g : groups)
  {
    std::vector<double> plain;
    double lo = 1e300, hi = 0, widest = 1.0;
    for (const Row* r : g.second)
    {
      plain.push_back(r->PlainCpuMs.Median);
      lo = std::min(lo, r->PlainCpuMs.Min);
      hi = std::max(hi, r->PlainCpuMs.Max);
      if (r->Ratio.Min > 0)
        widest = std::max(widest, r->Ratio.Max / r->Ratio.Min);
    }
    std::snprintf(line, sizeof(line), "| %s | %d | %.2f [%.2f-%.2f] | %.2f |\n",
      g.first.first.c_str(), g.first.second, Median(plain), lo, hi, widest);
    f << line;
  }
  f.flush();
  return static_cast<bool>(f);
}

bool WritePareto(vtkRenderWindow* window, const std::string& path, const std::vector<Row>& rows)
{
  std::vector<std::string> meshes;
  int plotSize = 0;
  for (const Row& r : rows)
  {
    if (std::find(meshes.begin(), meshes.end(), r.Mesh) == meshes.end())
      meshes.push_back(r.Mesh);
    if (plotSize == 0 || std::abs(r.Size - 512) < std::abs(plotSize - 512))
      plotSize = r.Size;
  }
  if (meshes.empty())
    return true; // nothing to plot
  vtkNew<vtkContextView> view;
  while (window->GetRenderers()->GetFirstRenderer())
  {
    window->RemoveRenderer(window->GetRenderers()->GetFirstRenderer());
  }
  view->SetRenderWindow(window);
  window->SetSize(1200, 900);
  const int columns = meshes.size() > 1 ? 2 : 1;
  const int rowsCount = static_cast<int>((meshes.size() + columns - 1) / columns);
  vtkNew<vtkChartMatrix> matrix;
  view->GetScene()->AddItem(matrix);
  matrix->SetSize(vtkVector2i(columns, rowsCount));
  const char* families[] = { "SIR", "DIR reduction", "DIR bbox", "DIR adaptive", "ISR", "SSP",
    "DIR paper (no secant)", "DIR nearest back", "PEEL", "SH" };
  const unsigned char colours[][3] = { { 120, 120, 120 }, { 31, 119, 180 }, { 255, 127, 14 },
    { 44, 160, 44 }, { 214, 39, 40 }, { 148, 103, 189 }, { 140, 86, 75 }, { 23, 190, 207 },
    { 227, 119, 194 }, { 188, 189, 34 } };
  for (size_t m = 0; m < meshes.size(); ++m)
  {
    vtkChart* chart = matrix->GetChart(vtkVector2i(static_cast<int>(m % columns),
      rowsCount - 1 - static_cast<int>(m / columns)));
    chart->SetTitle(meshes[m] + " " + std::to_string(plotSize) + "x" + std::to_string(plotSize));
    chart->GetAxis(vtkAxis::BOTTOM)->SetTitle("frame time / plain VTK (median of repeats)");
    chart->GetAxis(vtkAxis::LEFT)->SetTitle("RMSE against the supersampled full reference");
    chart->SetShowLegend(m == 0);
    double largest[2] = { 0.0, 0.0 }; // x, y over every plotted point
    for (int family = 0; family < 10; ++family)
    {
      vtkNew<vtkTable> table;
      vtkNew<vtkFloatArray> x;
      vtkNew<vtkFloatArray> y;
      x->SetName("ratio");
      y->SetName(families[family]);
      table->AddColumn(x);
      table->AddColumn(y);
      std::vector<std::pair<double, double>> points;
      for (const Row& r : rows)
      {
        if (r.Mesh != meshes[m] || r.Size != plotSize || r.Config.Method == "none" ||
          r.Config.NoScene)
          continue;
        const std::string& method = r.Config.Method;
        const int f = method == "SH" ? 9
          : method == "PEEL" ? 8
          : method == "SIR" ? 0
          : method == "ISR" ? 4
          : method == "SSP" ? 5
          : r.Config.Paper ? 6 : r.Config.Nearest ? 7 : r.Config.Adaptive ? 3 : r.Config.Bounds ? 2 : 1;
        if (f == family)
          points.emplace_back(r.Ratio.Median, r.FullSS.Rmse);
      }
      if (points.empty())
        continue;
      std::sort(points.begin(), points.end());
      table->SetNumberOfRows(static_cast<vtkIdType>(points.size()));
      for (size_t i = 0; i < points.size(); ++i)
      {
        table->SetValue(static_cast<vtkIdType>(i), 0, points[i].first);
        table->SetValue(static_cast<vtkIdType>(i), 1, points[i].second);
      }
      vtkPlot* plot = chart->AddPlot(points.size() > 1 ? vtkChart::LINE : vtkChart::POINTS);
      plot->SetInputData(table, 0, 1);
      plot->SetColor(colours[family][0], colours[family][1], colours[family][2], 255);
      plot->SetWidth(2.0);
      for (const auto& point : points)
      {
        largest[0] = std::max(largest[0], point.first);
        largest[1] = std::max(largest[1], point.second);
      }
    }
    // From zero with a margin, so that a point is never drawn on the frame (VTK's automatic
    // range puts the extreme points on it).
    for (int a = 0; a < 2; ++a)
    {
      vtkAxis* axis = chart->GetAxis(a == 0 ? vtkAxis::BOTTOM : vtkAxis::LEFT);
      axis->SetBehavior(vtkAxis::FIXED);
      axis->SetRange(0.0, largest[a] > 0.0 ? 1.1 * largest[a] : 1.0);
    }
  }
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(path.c_str());
  writer->Write();
  return writer->GetErrorCode() == 0;
}
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

std::vector<Setting> PresetSettings(const Options& o)
{
  std::vector<Setting> settings;
  Setting antiAliased{ "DIR", 5 };
  antiAliased.AntiAliasing = true;
  Setting bounces{ "DIR", 5 };
  bounces.Bounces = 2;
  auto peel = [](int layers, int tirBounces) {
    Setting setting{ "PEEL", 0 };
    setting.Layers = layers;
    setting.Bounces = tirBounces;
    return setting;
  };
  if (o.Quick)
  {
    settings.push_back({ "DIR", 5 });
    settings.push_back(antiAliased);
    if (o.MultiSamples > 0)
    {
      for (Setting pixelwise : { Setting{ "DIR", 5 }, antiAliased })
      {
        pixelwise.PixelComposite = true;
        settings.push_back(pixelwise);
      }
    }
    settings.push_back(bounces);
    settings.push_back({ "SIR", 0 });
    for (int layers : { 2, 4, 8 })
      settings.push_back(peel(layers, 0));
    settings.push_back(peel(4, 2));
    settings.push_back({ "SH", 0 });
    return settings;
  }
  if (o.Smoke)
  {
    for (const char* method : { "SIR", "DIR", "ISR", "SSP" })
      settings.push_back({ method, 5 });
    settings.push_back(peel(4, 2));
    settings.push_back({ "SH", 0 });
    return settings;
  }
  settings.push_back({ "none", 0 });
  settings.push_back({ "SIR", 0 });
  for (int bounds = 0; bounds < 2; ++bounds)
  {
    for (int s : { 0, 1, 2, 3, 5, 8 })
    {
      settings.push_back({ "DIR", s, bounds == 1 });
    }
  }
  settings.push_back({ "DIR", 8, false, true });
  settings.push_back({ "DIR", 5, false, false, true });
  settings.push_back({ "DIR", 5, false, false, false, true });
  settings.push_back(antiAliased);
  settings.push_back(bounces);
  settings.push_back({ "ISR", 0 });
  settings.push_back({ "SSP", 0 });
  for (int layers : { 2, 4, 8 })
    for (int tirBounces : { 0, 2, 4 })
      settings.push_back(peel(layers, tirBounces));
  settings.push_back({ "SH", 0 });
  return settings;
}

// The preset's rows, less the methods --methods leaves out.
std::vector<Setting> Settings(const Options& o)
{
  std::vector<Setting> settings;
  for (const Setting& setting : PresetSettings(o))
  {
    if (o.Methods.empty() ||
      std::find(o.Methods.begin(), o.Methods.end(), setting.Method) != o.Methods.end())
    {
      settings.push_back(setting);
    }
  }
  return settings;
}

// The scene mesh's rows: DIR 5 refracting the opaque scene (NG) and the same without it.
std::vector<Setting> SceneSettings()
{
  Setting on{ "DIR", 5 };
  Setting off = on;
  off.NoScene = true;
  return { on, off };
}

int MethodId(const std::string& m)
{
  return m == "SIR"   ? vtkRefractionPass::SIR
    : m == "ISR"        ? vtkRefractionPass::ISR
    : m == "SSP"        ? vtkRefractionPass::SSP
    : m == "PEEL"       ? vtkRefractionPass::PEEL
    : m == "SH"         ? vtkRefractionPass::SH
                        : vtkRefractionPass::DIR;
}

void Apply(vtkRefractionPass* pass, const Setting& setting)
{
  pass->SetMethod(MethodId(setting.Method));
  pass->SetSearchSteps(setting.Steps);
  pass->SetDepthRangeMode(setting.Bounds ? vtkRefractionPass::DEPTH_RANGE_BOUNDS
                                         : vtkRefractionPass::DEPTH_RANGE_REDUCTION);
  pass->SetAdaptiveSearch(setting.Adaptive);
  pass->SetBackSurface(setting.Nearest ? vtkRefractionPass::BACK_SURFACE_NEAREST
                                       : vtkRefractionPass::BACK_SURFACE_FURTHEST);
  pass->SetSecantRefinement(!setting.Paper);
  pass->SetSceneRefraction(!setting.NoScene);
  pass->SetAntiAliasing(setting.AntiAliasing);
  pass->SetMultiSampleSilhouette(!setting.PixelComposite);
  pass->SetTIRBounces(setting.Bounces);
  pass->SetPeelLayers(std::max(setting.Layers, 2));
}

// One mesh in the scene: its actor, the opaque actors around it, and what the rows report.
struct Scene
{
  std::string Name;
  vtkSmartPointer<vtkAlgorithm> Mesh;
  vtkSmartPointer<vtkActor> Actor;
  std::vector<vtkSmartPointer<vtkActor>> Surroundings; // the scene mesh's plane and axes
  vtkSmartPointer<vtkActor> Inner; // the nested mesh's inner contour, glass of IOR 1.9
  vtkIdType Triangles = 0;
  double SHSeconds = 0.0; // the SH method's precomputation of the scene's glass
};

// The SH method's precomputation between a mesh and its mapper (order 8, as the paper; no
// cache, so that its time is measured); adds its seconds to `seconds`.
vtkSmartPointer<vtkAlgorithm> WithSHTransfer(
  vtkAlgorithm* mesh, double ior, const Options& o, double& seconds)
{
  auto transfer = vtkSmartPointer<vtkSHTransferFilter>::New();
  transfer->SetInputConnection(mesh->GetOutputPort());
  transfer->SetIndexOfRefraction(ior);
  transfer->SetOrder(8);
  transfer->SetDirections(o.Smoke ? 64 : 1024);
  transfer->SetCacheDirectory("");
  transfer->Update();
  seconds += transfer->GetLastComputeSeconds();
  return transfer;
}

// Makes the scene's glass glass (IOR 1.5, the nested mesh's inner contour 1.9), or clears it.
void SetGlass(const Scene& scene, bool glass)
{
  if (glass)
  {
    // No highlights (MakeGlass's default for an actor at VTK's specular defaults): the
    // reference traces no light sources, and the rows stay comparable with earlier runs.
    vtkRefractionPass::MakeGlass(scene.Actor, 1.5);
    scene.Actor->GetProperty()->SetSpecular(0.0);
    if (scene.Inner)
    {
      vtkRefractionPass::MakeGlass(scene.Inner, 1.9);
      scene.Inner->GetProperty()->SetSpecular(0.0);
    }
    return;
  }
  vtkRefractionPass::ClearGlass(scene.Actor);
  if (scene.Inner)
  {
    vtkRefractionPass::ClearGlass(scene.Inner);
  }
}

// Puts the scene's actor (with its surroundings, if any) in the renderer with the
// benchmark's camera framing the actor, at a size. The four meshes are alone over a black
// background and the pass's built-in environment; the scene mesh has a gradient background,
// which the pass shows as its environment (ENVIRONMENT_RENDERER).
void Show(vtkRenderWindow* window, vtkRenderer* renderer, vtkRefractionPass* pass,
  const Scene& scene, int size)
{
  renderer->RemoveAllViewProps();
  renderer->AddActor(scene.Actor);
  if (scene.Inner)
  {
    renderer->AddActor(scene.Inner);
  }
  for (vtkActor* actor : scene.Surroundings)
  {
    renderer->AddActor(actor);
  }
  const bool surroundings = !scene.Surroundings.empty();
  renderer->SetGradientBackground(surroundings);
  renderer->SetBackground(surroundings ? 0.1 : 0.0, surroundings ? 0.15 : 0.0, surroundings ? 0.3 : 0.0);
  renderer->SetBackground2(0.85, 0.85, 0.9);
  pass->SetEnvironmentMode(surroundings ? vtkRefractionPass::ENVIRONMENT_RENDERER
                                        : vtkRefractionPass::ENVIRONMENT_BUILTIN);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, 1.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(30.0);
  renderer->ResetCamera(scene.Actor->GetBounds()); // the glass, not its surroundings
  camera->Elevation(15.0);
  camera->OrthogonalizeViewUp();
  camera->Dolly(1.25);
  renderer->ResetCameraClippingRange();
  window->SetSize(size, size);
}

// The 1-minute load average (Linux), the first thing to look at when timings scatter.
std::string LoadAverage()
{
  std::ifstream in("/proc/loadavg");
  std::string value;
  return in >> value ? value : std::string("unknown");
}

std::string Clock(double seconds)
{
  char text[32];
  const int s = static_cast<int>(seconds + 0.5);
  std::snprintf(text, sizeof(text), "%d:%02d", s / 60, s % 60);
  return text;
}
}

int main(int argc, char* argv[])
{
  Options options;
  if (!Parse(argc, argv, options))
  {
    return 2;
  }
  const int maxSize = *std::max_element(options.Sizes.begin(), options.Sizes.end());
  vtkSmartPointer<vtkRenderWindow> window;
  std::string windowPath = "GLX window";
  if (!options.X11)
  {
    std::string error;
    window = vtkRefractionCreateEGLWindow(
      std::max(maxSize, 1200), std::max(maxSize, 900), &error, &windowPath);
    if (!window)
    {
      std::fprintf(stderr, "EGL unavailable (%s); using an X window\n", error.c_str());
    }
  }
  if (!window)
  {
    window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetOffScreenRendering(1);
    windowPath = "GLX window";
  }
  // Single-sampled unless --multisamples: every committed figure is of a single-sampled
  // window, and the error is measured against one traced ray per pixel centre. Multisampled,
  // the plain render the rows divide by resolves its samples, and the glass's silhouette is
  // drawn at them (rows without `px`).
  window->SetMultiSamples(options.MultiSamples);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  std::string environmentDescription;
  vtkSmartPointer<vtkTexture> environment =
    MakeEnvironment(options.Environment, options.Smoke, environmentDescription);
  if (!environment && options.Environment != "builtin")
  {
    return 1;
  }
  window->SetSize(options.Sizes.front(), options.Sizes.front());
  window->Render();
  std::string rendererName = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (!options.FromCsv.empty())
  {
    // Remake the report of an earlier run (same folder unless --out says otherwise).
    std::vector<Row> rows;
    std::string recorded;
    if (!ReadCsv(options.FromCsv, rows, recorded))
    {
      std::fprintf(stderr, "cannot read rows from %s\n", options.FromCsv.c_str());
      return 1;
    }
    if (options.Out.empty())
    {
      options.Out = vtksys::SystemTools::GetFilenamePath(options.FromCsv);
      options.Out = options.Out.empty() ? "." : options.Out;
    }
    if (!vtksys::SystemTools::MakeDirectory(options.Out) ||
      !WriteMarkdown(options.Out + "/results.md", rows, recorded, "recorded run",
        "Remade from " + options.FromCsv + ".") ||
      !WritePareto(window, options.Out + "/pareto.png", rows))
    {
      std::fprintf(stderr, "cannot write results.md and pareto.png into %s\n",
        options.Out.c_str());
      return 1;
    }
    std::printf("remade %s/results.md and pareto.png from %zu rows\n", options.Out.c_str(),
      rows.size());
    return 0;
  }
  if (options.Out.empty())
  {
    options.Out = "bench/results/" + HostKind(rendererName);
  }
  if (!vtksys::SystemTools::MakeDirectory(options.Out))
  {
    std::fprintf(stderr, "cannot create %s\n", options.Out.c_str());
    return 1;
  }
  std::printf("renderer %s (%s); results in %s\n", rendererName.c_str(), windowPath.c_str(),
    options.Out.c_str());
  const auto runStart = std::chrono::steady_clock::now();
  auto elapsed = [&runStart]() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - runStart).count();
  };

  const std::vector<Setting> settings = Settings(options);
  if (settings.empty() &&
    std::find(options.Meshes.begin(), options.Meshes.end(), "scene") == options.Meshes.end())
  {
    std::fprintf(stderr, "--methods leaves no rows of the preset to run\n");
    return 2;
  }
  std::vector<Scene> scenes;
  for (const std::string& name : options.Meshes)
  {
    Scene scene;
    scene.Name = name;
    scene.Mesh = MakeMesh(name, options);
    if (!scene.Mesh)
    {
      continue;
    }
    vtkPolyData* poly = vtkPolyData::SafeDownCast(scene.Mesh->GetOutputDataObject(0));
    scene.Triangles = poly->GetNumberOfPolys() + poly->GetNumberOfStrips();
    const bool sh = name != "scene" &&
      std::any_of(settings.begin(), settings.end(), [](const Setting& s) { return s.Method == "SH"; });
    vtkSmartPointer<vtkAlgorithm> drawn = scene.Mesh;
    if (sh)
    {
      std::printf("SH precomputation of %s...\n", name.c_str());
      std::fflush(stdout);
      drawn = WithSHTransfer(scene.Mesh, 1.5, options, scene.SHSeconds);
    }
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(drawn->GetOutputPort());
    mapper->ScalarVisibilityOff();
    scene.Actor = vtkSmartPointer<vtkActor>::New();
    scene.Actor->SetMapper(mapper);
    if (name == "scene")
    {
      scene.Surroundings = MakeSurroundings();
    }
    if (name == "nested")
    {
      vtkSmartPointer<vtkAlgorithm> inner = MakeMesh("nested-inner", options);
      if (sh)
      {
        inner = WithSHTransfer(inner, 1.9, options, scene.SHSeconds);
      }
      vtkNew<vtkPolyDataMapper> innerMapper;
      innerMapper->SetInputConnection(inner->GetOutputPort());
      innerMapper->ScalarVisibilityOff();
      scene.Inner = vtkSmartPointer<vtkActor>::New();
      scene.Inner->SetMapper(innerMapper);
      vtkPolyData* innerPoly = vtkPolyData::SafeDownCast(inner->GetOutputDataObject(0));
      scene.Triangles += innerPoly->GetNumberOfPolys() + innerPoly->GetNumberOfStrips();
    }
    scenes.push_back(scene);
  }
  if (scenes.empty())
  {
    std::fprintf(stderr, "no mesh could be made\n");
    return 1;
  }

  // Set before any timing: VTK converts the lat-long image into its cube map once, on the
  // first frame that uses it, and the plain render does not sample it.
  renderer->SetEnvironmentTexture(environment);
  vtkNew<vtkRefractionPass> pass;
  // Show() sets the environment per mesh: built-in for the four meshes (what their figures
  // have always been measured over), the renderer's background for the scene mesh; each
  // reference follows the pass.
  pass->SetEnvironmentModeToBuiltin();
  const int ss = options.Supersample;

  // Errors do not depend on timing noise: one picture per row, against the four references
  // of its mesh and size, before any timing.
  std::vector<Row> rows;
  for (const Scene& scene : scenes)
  {
    for (int size : options.Sizes)
    {
      Show(window, renderer, pass, scene, size);
      renderer->SetPass(pass);
      SetGlass(scene, true);
      window->Render();
      Truth truth;
      const std::string where = scene.Name + " " + std::to_string(size) + " ";
      const std::string ssLabel = " " + std::to_string(ss) + "x" + std::to_string(ss);
      if (!Trace(renderer, pass, size, vtkRefractionReference::TWO_INTERFACE, 1, where + "two",
            truth.Two) ||
        !Trace(renderer, pass, size, vtkRefractionReference::FULL, 1, where + "full", truth.Full) ||
        !Trace(renderer, pass, size, vtkRefractionReference::TWO_INTERFACE, ss,
          where + "two" + ssLabel, truth.TwoSS) ||
        !Trace(renderer, pass, size, vtkRefractionReference::FULL, ss, where + "full" + ssLabel,
          truth.FullSS))
      {
        std::fprintf(stderr, "%s: the reference could not trace the scene; skipped\n",
          scene.Name.c_str());
        continue;
      }
      for (const Setting& setting : scene.Surroundings.empty() ? settings : SceneSettings())
      {
        Row row;
        row.Mesh = scene.Name;
        row.Triangles = scene.Triangles;
        row.Size = size;
        row.Config = setting;
        row.RefTwoMs = truth.Two.Seconds * 1e3;
        row.RefFullMs = truth.Full.Seconds * 1e3;
        row.RefFullSSMs = truth.FullSS.Seconds * 1e3;
        if (setting.Method != "none")
        {
          Apply(pass, setting);
          pass->DebugOutputOn();
          window->Render();
          pass->DebugOutputOff();
          vtkNew<vtkImageData> debug;
          debug->DeepCopy(pass->GetDebugImage());
          window->Render();
          const std::vector<float> colour = GrabColour(window);
          row.BytesPerPixel =
            static_cast<double>(pass->GetTextureBytes()) / (static_cast<double>(size) * size);
          auto* distances = vtkISRDistanceFilter::SafeDownCast(scene.Mesh);
          row.PrecomputeMs = setting.Method == "ISR" && distances
            ? distances->GetLastComputeSeconds() * 1e3
            : setting.Method == "SH" ? scene.SHSeconds * 1e3 : 0.0;
          Measure(row, colour, debug, truth, size);
          if (options.Dump)
          {
            std::string label = setting.Label();
            for (char& c : label)
              c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
            const std::string stem =
              options.Out + "/" + scene.Name + "_" + std::to_string(size) + "_";
            WritePng(stem + label + ".png", colour, size);
            WritePng(stem + "reference_two.png", truth.Two.Colour, size);
            WritePng(stem + "reference_full.png", truth.Full.Colour, size);
            WritePng(stem + "reference_full_ss.png", truth.FullSS.Colour, size);
          }
          std::printf("  %-10s %4d %-18s PSNR two %5.1f full %5.1f full %dx%d %5.1f "
                      "(TIR %s / rest %s)\n",
            scene.Name.c_str(), size, setting.Label().c_str(), row.Two.Psnr, row.Full.Psnr, ss,
            ss, row.FullSS.Psnr, Db(row.FullSS.PsnrTir).c_str(),
            Db(row.FullSS.PsnrRest).c_str());
          std::fflush(stdout);
        }
        rows.push_back(row);
      }
      SetGlass(scene, false);
    }
  }

  // Timing: every row `Repeats` times, in one seeded shuffled order; each job times the
  // glass and then the plain render of the same mesh at the same size.
  std::vector<std::pair<size_t, int>> jobs;
  for (size_t r = 0; r < rows.size(); ++r)
    for (int k = 0; k < options.Repeats; ++k)
      jobs.emplace_back(r, k);
  std::mt19937 random(static_cast<unsigned>(options.Seed));
  std::shuffle(jobs.begin(), jobs.end(), random);
  std::map<std::string, const Scene*> byName;
  for (const Scene& scene : scenes)
    byName[scene.Name] = &scene;
  struct Samples
  {
    std::vector<double> Cpu, Plain, Ratio, Gpu, PlainGpu;
    std::vector<std::vector<double>> Stages;
  };
  std::vector<Samples> samples(rows.size());
  const double timingStart = elapsed();
  const std::string loadBefore = LoadAverage();
  for (size_t j = 0; j < jobs.size(); ++j)
  {
    Row& row = rows[jobs[j].first];
    const Scene& scene = *byName[row.Mesh];
    Show(window, renderer, pass, scene, row.Size);
    renderer->SetPass(pass);
    if (row.Config.Method == "none")
    {
      SetGlass(scene, false); // the pass with nothing to do
    }
    else
    {
      SetGlass(scene, true);
      Apply(pass, row.Config);
    }
    const Timing glass = TimeFrames(window, pass, options.Frames);
    SetGlass(scene, false);
    renderer->SetPass(nullptr);
    const Timing plain = TimeFrames(window, nullptr, options.Frames);
    Samples& s = samples[jobs[j].first];
    s.Cpu.push_back(glass.Cpu);
    s.Plain.push_back(plain.Cpu);
    s.Ratio.push_back(glass.Cpu / plain.Cpu);
    s.Gpu.push_back(glass.GpuFrame);
    s.PlainGpu.push_back(plain.GpuFrame);
    s.Stages.resize(glass.Stages.size());
    for (size_t k = 0; k < glass.Stages.size(); ++k)
      s.Stages[k].push_back(glass.Stages[k]);
    const double done = elapsed() - timingStart;
    const double eta = done / static_cast<double>(j + 1) * static_cast<double>(jobs.size() - j - 1);
    std::printf("row %zu of %zu: %-10s %4d %-18s %7.2f ms, plain %6.2f ms, ratio %.2f  "
                "(elapsed %s, eta %s)\n",
      j + 1, jobs.size(), row.Mesh.c_str(), row.Size, row.Config.Label().c_str(), glass.Cpu,
      plain.Cpu, glass.Cpu / plain.Cpu, Clock(elapsed()).c_str(), Clock(eta).c_str());
    std::fflush(stdout);
  }
  for (size_t r = 0; r < rows.size(); ++r)
  {
    Row& row = rows[r];
    const Samples& s = samples[r];
    row.Repeats = static_cast<int>(s.Cpu.size());
    row.CpuMs = SpreadOf(s.Cpu);
    row.PlainCpuMs = SpreadOf(s.Plain);
    row.Ratio = SpreadOf(s.Ratio);
    row.GpuFrameMs = Median(s.Gpu);
    row.PlainGpuMs = Median(s.PlainGpu);
    row.StageMs.clear();
    for (const auto& stage : s.Stages)
    {
      // A stage the method does not run has no sample (Median gives -1).
      std::vector<double> ran;
      for (double v : stage)
        if (v >= 0.0)
          ran.push_back(v);
      row.StageMs.push_back(Median(ran));
    }
    row.StageMs.resize(vtkRefractionPass::TIMED_STAGE_COUNT, -1.0);
  }
  const std::string loadAfter = LoadAverage();
  renderer->RemoveAllViewProps();
  std::ostringstream run;
  run << "Environment: " << environmentDescription << ". Run: " << rows.size() << " rows x " << options.Repeats << " repeats (seed "
      << options.Seed << "), " << options.Frames << " timed frames each, references "
      << ss << "x" << ss << " rays per pixel for `SS`; window multisamples "
      << window->GetMultiSamples() << "; "
      << (options.Quick ? "--quick preset; " : options.Smoke ? "--smoke preset; " : "")
      << "took " << Clock(elapsed()) << " (m:s). Machine load (1-minute load average) "
      << loadBefore << " when the timing began and " << loadAfter << " when it ended, on "
      << std::thread::hardware_concurrency() << " logical CPUs: a load "
      << "above the CPU count means other programs shared the cores and every time is "
      << "inflated by them; compare ratios, not milliseconds.";
  if (!WriteCsv(options.Out + "/results.csv", rows, rendererName) ||
    !WriteMarkdown(options.Out + "/results.md", rows, rendererName, windowPath, run.str()) ||
    !WritePareto(window, options.Out + "/pareto.png", rows))
  {
    std::fprintf(stderr, "cannot write the results into %s\n", options.Out.c_str());
    return 1;
  }
  std::printf("wrote %s/results.csv, results.md, pareto.png (%s)\n", options.Out.c_str(),
    Clock(elapsed()).c_str());
  return 0;
}
