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
// The pieces are one file per concern, in namespace rfbench: the command line
// (rfBenchOptions), the rows (rfBenchSettings, rfBenchRow), the scenes (rfBenchScene,
// rfBenchEnvironment), timing (rfBenchTiming), the error against the reference
// (rfBenchReference, rfBenchPicture) and the report (rfBenchCsv, rfBenchReport); this file
// runs them.
#include "rfBenchCsv.h"
#include "rfBenchEnvironment.h"
#include "rfBenchOptions.h"
#include "rfBenchPicture.h"
#include "rfBenchReference.h"
#include "rfBenchPareto.h"
#include "rfBenchReport.h"
#include "rfBenchScaling.h"
#include "rfBenchRow.h"
#include "rfBenchScene.h"
#include "rfBenchSettings.h"
#include "rfBenchTiming.h"
#include "vtkISRDistanceFilter.h"
#include "vtkRefractionEGL.h"
#include "vtkRefractionPass.h"
#include "vtkRefractionReference.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>
#include <vtk_glew.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace rfbench;

namespace
{
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
  int surfaceWidth = std::max(maxSize, 1200), surfaceHeight = std::max(maxSize, 900);
  if (options.Scaling)
  {
    ScalingWindowSize(options, surfaceWidth, surfaceHeight);
  }
  vtkSmartPointer<vtkRenderWindow> window;
  std::string windowPath = "GLX window";
  if (!options.X11)
  {
    std::string error;
    window =
      vtkRefractionCreateEGLWindow(surfaceWidth, surfaceHeight, &error, &windowPath);
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
    // What the run recorded about itself (its settings, duration and the machine's load) is
    // in the report it wrote, not in the CSV: a report remade in place keeps that line.
    const std::string markdown = options.Out + "/results.md";
    const char* const remade = " Its sections were remade from ";
    std::string runLine = ReadRunLine(markdown);
    runLine = runLine.empty()
      ? RunLine(recorded, "recorded run", "Remade from " + options.FromCsv + ".")
      : runLine.substr(0, runLine.find(remade)) + remade + options.FromCsv + " (--from-csv).";
    if (!vtksys::SystemTools::MakeDirectory(options.Out) ||
      !WriteMarkdown(markdown, rows, runLine) ||
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
    options.Out = "bench/results/" + HostKind(rendererName) + (options.Scaling ? "-scaling" : "");
  }
  if (!vtksys::SystemTools::MakeDirectory(options.Out))
  {
    std::fprintf(stderr, "cannot create %s\n", options.Out.c_str());
    return 1;
  }
  std::printf("renderer %s (%s); results in %s\n", rendererName.c_str(), windowPath.c_str(),
    options.Out.c_str());
  if (options.Scaling)
  {
    renderer->SetEnvironmentTexture(environment);
    return RunScaling(window, renderer, options, rendererName) ? 0 : 1;
  }
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
  pass->SetPeelCapture(options.PeelCapture);
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
      truth.SolidBackground = !renderer->GetGradientBackground();
      const std::string where = scene.Name + " " + std::to_string(size) + " ";
      const std::string ssLabel = " " + std::to_string(ss) + "x" + std::to_string(ss);
      if (!Trace(renderer, pass, size, vtkRefractionReference::TWO_INTERFACE, 1, where + "two",
            truth.Two) ||
        !Trace(renderer, pass, size, vtkRefractionReference::FULL, 1, where + "full", truth.Full) ||
        !Trace(renderer, pass, size, vtkRefractionReference::TWO_INTERFACE, ss,
          where + "two" + ssLabel, truth.TwoSS) ||
        !Trace(renderer, pass, size, vtkRefractionReference::FULL, ss, where + "full" + ssLabel,
          truth.FullSS) ||
        (options.Convergence &&
          !Trace(renderer, pass, size, vtkRefractionReference::FULL, 2 * ss,
            where + "full " + std::to_string(2 * ss) + "x" + std::to_string(2 * ss),
            truth.FullDoubleSS)) ||
        (ss / 2 >= 2 &&
          !Trace(renderer, pass, size, vtkRefractionReference::FULL, ss / 2,
            where + "full " + std::to_string(ss / 2) + "x" + std::to_string(ss / 2),
            truth.FullHalfSS)))
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
        row.FewRaysSide = truth.FullHalfSS.Colour.empty() ? 0 : ss / 2;
        if (setting.Method != "none")
        {
          Apply(pass, setting);
          pass->DebugOutputOn();
          window->Render();
          pass->DebugOutputOff();
          if (!pass->GetDebugImage())
          {
            // The pass said why (its programs' errors above); a row without its picture
            // would score the scene without glass.
            std::fprintf(stderr, "%s %d %s: the pass drew no glass; row skipped\n",
              scene.Name.c_str(), size, setting.Label().c_str());
            continue;
          }
          vtkNew<vtkImageData> debug;
          debug->DeepCopy(pass->GetDebugImage());
          window->Render();
          const std::vector<float> colour = GrabColour(window);
          if (setting.Method == "PEEL")
          {
            row.PeelLayersFound = pass->GetPeelLayersFound();
            row.PeelDraws = pass->GetPeelLayersDrawn();
          }
          // The one-ray references are held against one lookup direction per pixel too; the
          // supersampled ones against the picture as the row draws it.
          std::vector<float> pointColour = colour;
          if (pass->GetFilteredLookups())
          {
            pass->FilteredLookupsOff();
            window->Render();
            pointColour = GrabColour(window);
            pass->FilteredLookupsOn();
          }
          row.BytesPerPixel =
            static_cast<double>(pass->GetTextureBytes()) / (static_cast<double>(size) * size);
          auto* distances = vtkISRDistanceFilter::SafeDownCast(scene.Mesh);
          row.PrecomputeMs = setting.Method == "ISR" && distances
            ? distances->GetLastComputeSeconds() * 1e3
            : setting.Method == "SH" ? scene.SHSeconds * 1e3 : 0.0;
          Measure(row, colour, pointColour, debug, truth, size);
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
      << window->GetMultiSamples() << "; PEEL's layers captured by "
      << (options.PeelCapture == vtkRefractionPass::PEEL_CAPTURE_DEPTH_PEELING ? "depth peeling"
           : options.PeelCapture == vtkRefractionPass::PEEL_CAPTURE_K_BUFFER
           ? "the k-buffer where supported"
           : "the default (auto)")
      << "; " << (options.Quick ? "--quick preset; " : options.Smoke ? "--smoke preset; " : "")
      << "took " << Clock(elapsed()) << " (m:s). Machine load (1-minute load average) "
      << loadBefore << " when the timing began and " << loadAfter << " when it ended, on "
      << std::thread::hardware_concurrency() << " logical CPUs: a load "
      << "above the CPU count means other programs shared the cores and every time is "
      << "inflated by them; compare ratios, not milliseconds.";
  if (!WriteCsv(options.Out + "/results.csv", rows, rendererName) ||
    !WriteMarkdown(options.Out + "/results.md", rows, RunLine(rendererName, windowPath, run.str())) ||
    !WritePareto(window, options.Out + "/pareto.png", rows))
  {
    std::fprintf(stderr, "cannot write the results into %s\n", options.Out.c_str());
    return 1;
  }
  std::printf("wrote %s/results.csv, results.md, pareto.png (%s)\n", options.Out.c_str(),
    Clock(elapsed()).c_str());
  return 0;
}
