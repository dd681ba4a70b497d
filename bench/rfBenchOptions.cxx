#include "rfBenchOptions.h"

#include <vtksys/CommandLineArguments.hxx>
#include <vtksys/SystemTools.hxx>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace rfbench
{
namespace
{
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
}

bool Parse(int argc, char* argv[], Options& o)
{
  std::string sizes, meshes, methods, frames, repeats, seed, supersample, multisamples;
  std::string peelCapture;
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
  args.AddArgument("--peel-capture", Args::SPACE_ARGUMENT, &peelCapture,
    "How PEEL captures its layers on every row (vtkRefractionPass::SetPeelCapture): auto "
    "(default), peeling (one draw per layer) or k-buffer (two draws, image atomics).");
  args.AddArgument("--environment", Args::SPACE_ARGUMENT, &o.Environment,
    "builtin (the pass's built-in sky, default), studio (an HDR lat-long image made in "
    "code: dim walls, bright soft boxes up to 8), or a lat-long .hdr file; the last two go "
    "through vtkEquirectangularToCubeMapTexture as the renderer's environment.");
  args.AddArgument("--bunny", Args::SPACE_ARGUMENT, &o.Bunny,
    "The Stanford bunny OBJ (default /usr/share/glmark2/models/bunny.obj).");
  args.AddArgument("--from-csv", Args::SPACE_ARGUMENT, &o.FromCsv,
    "Remake results.md and pareto.png from an earlier results.csv, without running.");
  args.AddBooleanArgument("--quick", &o.Quick,
    "The four meshes and nested at 512x512: DIR (5 steps; also with point lookups, with "
    "anti-aliasing, with two total internal reflections followed, with the exit's "
    "reflection followed, and with both), SIR, PEEL with 2, 4 and 8 layers (and 4 and 8 "
    "with two reflections followed), each with its plain render, 3 repeats.");
  args.AddBooleanArgument("--smoke", &o.Smoke,
    "64x64, sphere and torus, 5 frames, every method once: the ctest smoke run.");
  args.AddBooleanArgument("--x11", &o.X11, "Render through an X window instead of EGL.");
  args.AddBooleanArgument("--dump", &o.Dump, "Also write every picture and reference as PNG.");
  args.AddBooleanArgument("--convergence", &o.Convergence,
    "Also trace the full reference at twice --supersample per side and report how far the "
    "supersampled truth is from it (column ref_ss_convergence_psnr; --supersample 2..16).");
  args.AddBooleanArgument("--scaling", &o.Scaling,
    "Instead of the rows: frame time against triangles (8 thousand to 4 million, at 512) and "
    "against pixels (512 to 3840x2160, 79,200 triangles), a glass sphere filling the view, each "
    "method against plain VTK; writes scaling.csv, scaling.md and two plots (--smoke: tiny).");
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
  if (!peelCapture.empty())
  {
    const char* const names[] = { "auto", "peeling", "k-buffer" };
    o.PeelCapture = -1;
    for (int mode = 0; mode < 3; ++mode)
    {
      o.PeelCapture = peelCapture == names[mode] ? mode : o.PeelCapture;
    }
    if (o.PeelCapture < 0)
    {
      std::fprintf(stderr, "--peel-capture: '%s' is not auto, peeling or k-buffer\n",
        peelCapture.c_str());
      return false;
    }
  }
  if (o.Convergence && o.Supersample > 16)
  {
    std::fprintf(stderr, "--convergence traces 2 x --supersample per side: at most 16, not %d\n",
      o.Supersample);
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
}
