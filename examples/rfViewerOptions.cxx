#include "rfViewerOptions.h"

#include "rfViewer.h"
#include "vtkRefractionSeriesReader.h"

#include <vtksys/CommandLineArguments.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace
{
// The name messages and --help use: RefractionViewer, or RefractionDemo for the preset.
std::string& ProgramName()
{
  static std::string name = "RefractionViewer";
  return name;
}

bool ParseDouble(const std::string& text, double low, double high, double& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const double parsed = std::strtod(text.c_str(), &end);
  if (errno != 0 || *end != '\0' || !std::isfinite(parsed) || parsed < low || parsed > high)
  {
    return false;
  }
  value = parsed;
  return true;
}

bool ParseInt(const std::string& text, int low, int high, int& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const long parsed = std::strtol(text.c_str(), &end, 10);
  if (errno != 0 || *end != '\0' || parsed < low || parsed > high)
  {
    return false;
  }
  value = static_cast<int>(parsed);
  return true;
}

bool ParseList(const std::string& text, std::vector<double>& values)
{
  values.clear();
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    double value = 0.0;
    if (!ParseDouble(item, -1e300, 1e300, value))
    {
      return false;
    }
    values.push_back(value);
  }
  return !values.empty();
}

// "  --name VALUE         help text wrapped at 92 columns"
std::string Wrap(const std::string& name, const std::string& help)
{
  const size_t column = 26;
  const size_t width = 92;
  std::string out = "  " + name;
  out += out.size() + 1 < column ? std::string(column - out.size(), ' ') : "\n" + std::string(column, ' ');
  size_t lineLength = column;
  std::stringstream words(help);
  std::string word;
  bool first = true;
  while (words >> word)
  {
    if (!first && lineLength + 1 + word.size() > width)
    {
      out += "\n" + std::string(column, ' ');
      lineLength = column;
      first = true;
    }
    out += (first ? "" : " ") + word;
    lineLength += (first ? 0 : 1) + word.size();
    first = false;
  }
  return out + "\n";
}

void PrintHelp(const std::string& options)
{
  std::printf(
    "Usage: %s [options] MESH | SERIES.pvd | FIRST_OF_SERIES --series | FILE FILE ...\n"
    "       %s [options] --demo metaballs|waves\n"
    "\n"
    "Draws a mesh, or a mesh that changes in time, as refractive glass (vtkRefractionPass).\n"
    "Inputs: %s.\n"
    "Several files on the command line, a .pvd collection, or a numbered series\n"
    "(name_0000.vtp, name_0001.vtp, ... with --series) are played as time steps. With\n"
    "--contour the input's point scalars (or --array) are contoured every time step, so a\n"
    "series of volumes (.vti, .vtu) becomes a deforming glass surface.\n"
    "\n"
    "Without --interactive it renders headless (EGL, no X server needed; an X server's\n"
    "off-screen window when EGL is missing and DISPLAY is set) and writes what is asked:\n"
    "--screenshot, --out (a PNG per frame), --contact-sheet, --timing. A progress line is\n"
    "printed while frames are written. In the window: m cycles the method (DIR, SIR, ISR,\n"
    "SSP, PEEL), i / I lower / raise the index of refraction by 0.05, + / - change the search steps,\n"
    "space starts / stops the animation, the arrows Right / Left step through time; the line\n"
    "at the bottom"
    " shows method, settings, the last frame time and the time step.\n"
    "\n"
    "Exit codes: 0 done, 1 rendering or writing failed, 2 wrong option or value,\n"
    "3 no rendering context (no EGL and no display), 4 an input, environment or output\n"
    "path that cannot be used.\n"
    "\n"
    "Options:\n%s\n"
    "Examples:\n"
    "  RefractionViewer bunny.obj --screenshot bunny.png --size 400 --ior 1.33\n"
    "  RefractionViewer run.pvd --contour 0.5 --out frames --contact-sheet sheet.png\n"
    "  RefractionViewer --demo waves --environment sky.exr --interactive\n",
    rfViewerProgram(), rfViewerProgram(), vtkRefractionSeriesReader::GetKnownExtensions(), options.c_str());
}
}

const char* rfViewerProgram()
{
  return ProgramName().c_str();
}

int rfViewerUsage(const std::string& message)
{
  std::fprintf(stderr, "%s: %s (see %s --help)\n", rfViewerProgram(), message.c_str(),
    rfViewerProgram());
  return RF_VIEWER_USAGE;
}

int rfViewerBadInput(const std::string& message)
{
  std::fprintf(stderr, "%s: %s\n", rfViewerProgram(), message.c_str());
  return RF_VIEWER_BAD_INPUT;
}

std::string rfViewerQuote(const std::string& text)
{
  return "'" + text + "'";
}

int rfViewerParseOptions(int argc, char* argv[], const std::vector<std::string>& preset,
  rfViewerOptions& o, rfViewerSettings& s)
{
  std::vector<std::string> words;
  words.emplace_back(argc > 0 ? argv[0] : rfViewerProgram());
  if (argc > 0)
  {
    ProgramName() = vtksys::SystemTools::GetFilenameName(argv[0]);
  }
  words.insert(words.end(), preset.begin(), preset.end());
  for (int i = 1; i < argc; ++i)
  {
    words.emplace_back(argv[i]);
  }
  std::vector<const char*> pointers;
  for (const std::string& word : words)
  {
    pointers.push_back(word.c_str());
  }

  // One table gives vtksys the options and --help its text.
  struct OptionEntry
  {
    const char* Name;
    const char* Value; // the value's placeholder in the help, nullptr for a flag
    std::string* Text;
    bool* Flag;
    const char* Help;
  };
  const OptionEntry table[] = {
    { "--help", nullptr, nullptr, &o.Help,
      "This text." },
    { "--demo", "NAME", &o.Demo, nullptr,
      "Built-in data instead of a file: metaballs (blobs that merge and split) or waves (the wave equation in a box, vtkWaveEquationSource), contoured every time step, over an opaque checkered floor, before a low wall and beside an opaque cone." },
    { "--series", nullptr, nullptr, &o.Series,
      "The input file is one of a numbered series: play every file with the same name and another number." },
    { "--contour", "V[,V...]", &o.Contour, nullptr,
      "Contour the input's point scalars at these values (comma-separated, e.g. 0.5 or 0.2,0.8) every time step." },
    { "--array", "NAME", &o.Array, nullptr,
      "The point array to contour (default: the active scalars)." },
    { "--environment", "IMAGE|builtin", &o.Environment, nullptr,
      "A lat-long environment image (EXR, HDR, PNG) the glass refracts, also shown behind the scene, or 'builtin' for the pass's built-in sky and checkered floor. Without it the glass refracts the scene and the renderer's background (--background)." },
    { "--background", "R,G,B[,R,G,B]", &o.Background, nullptr,
      "The renderer's background: r,g,b or a gradient r,g,b,r2,g2,b2 (bottom, top), 0..1." },
    { "--method", "NAME", &o.Method, nullptr,
      "dir (default: two interfaces, Oliveira and Brauwers), sir (one interface), isr (Wyman's distance estimate), ssp (screen-space perturbation), peel (every interface of --layers depth-peeled layers: glass inside and behind glass, Chi, Wang and Hu). The pass's sixth method, sh (spherical harmonics), needs a vtkSHTransferFilter precomputation of a static mesh, which the viewer does not run (docs/methods.md says how to use it)." },
    { "--ior", "X", &o.IOR, nullptr,
      "Index of refraction of the glass, 0.1 to 10 (default 1.5)." },
    { "--dispersion", "R,G,B", &o.Dispersion, nullptr,
      "Dispersion: red, green and blue indices of refraction, 0.1 to 10 each (the green one replaces --ior; three times the shading work)." },
    { "--steps", "N", &o.Steps, nullptr,
      "Search steps of DIR's binary search, 0 to 16 (default 5)." },
    { "--layers", "K", &o.Layers, nullptr,
      "Layers of the glass peeled for --method peel, 2 to 8 (default 4)." },
    { "--peel-capture", "auto|peeling|k-buffer", &o.PeelCapture, nullptr,
      "How --method peel captures its layers behind the front, the same layers either way (vtkRefractionPass::SetPeelCapture): peeling (one draw of the glass per layer), k-buffer (two draws whatever --layers; 3 or more layers, where OpenGL has image load/store), auto (default: the k-buffer from 6 layers where more than 3 hold glass)." },
    { "--anti-aliasing", nullptr, nullptr, &o.AntiAliasing,
      "Anti-alias the glass: the refraction shaded at the pixels' corners, each pixel the average of its four (vtkRefractionPass::SetAntiAliasing; about 1.1-1.5 times the frame time)." },
    { "--coarse-shading", nullptr, nullptr, &o.CoarseShading,
      "One ray per 2x2 pixels where the glass is smooth, each pixel's own elsewhere (vtkRefractionPass::SetCoarseShading; for large windows on renderers where a ray costs much more than a lookup, blurs what it shows over two pixels; not with --anti-aliasing)." },
    { "--no-exit-reflection", nullptr, nullptr, &o.NoExitReflection,
      "DIR: drop the light the glass's far side reflects back inside (the two-interface model of the paper) instead of following it to where it leaves (vtkRefractionPass::SetExitReflection, on by default: closer to a ray-traced picture for 0-14 % more frame time)." },
    { "--exit-reflection", nullptr, nullptr, &o.ExitReflection,
      "Accepted for older scripts: the exit's reflection is followed by default." },
    { "--smooth-internal-reflections", nullptr, nullptr, &o.SmoothInternalReflections,
      "Where a ray was totally reflected inside the glass, show the pixel's neighbourhood averaged instead of its one ray's colour, which there is noise (vtkRefractionPass::SetSmoothInternalReflections; not with --anti-aliasing)." },
    { "--size", "N|WxH", &o.Size, nullptr,
      "Window or image size in pixels: N or WxH, 1 to 8192 (default 512)." },
    { "--frames", "N", &o.Frames, nullptr,
      "Number of frames to write with --out (default: one per time step, or 1 for a static mesh; more frames than time steps loop the series)." },
    { "--time", "T", &o.Time, nullptr,
      "Time to show for --screenshot, --timing and the first interactive frame (default: the first time step)." },
    { "--out", "FOLDER", &o.OutDir, nullptr,
      "Folder for the PNG sequence frame_0000.png ... (created if missing)." },
    { "--screenshot", "FILE.png", &o.Screenshot, nullptr,
      "Write one PNG of the frame at --time." },
    { "--contact-sheet", "FILE.png", &o.ContactSheet, nullptr,
      "Write a PNG of --sheet-frames frames spread evenly over the sequence, side by side." },
    { "--sheet-columns", "N", &o.SheetColumns, nullptr,
      "Columns of the contact sheet, 1 to 16 (default 4)." },
    { "--sheet-frames", "N", &o.SheetFrames, nullptr,
      "Frames on the contact sheet, 1 to 64 (default 8)." },
    { "--masks", nullptr, nullptr, &o.Masks,
      "With --out, also write mask_NNNN.png: the glass's silhouette, white on black (for compositing, and for the tests)." },
    { "--orbit", "DEG", &o.Orbit, nullptr,
      "Turn the camera by this many degrees a frame (a turntable for static meshes)." },
    { "--azimuth", "DEG", &o.Azimuth, nullptr,
      "Camera azimuth in degrees from the front view (default 0)." },
    { "--elevation", "DEG", &o.Elevation, nullptr,
      "Camera elevation in degrees, -89 to 89 (default 20)." },
    { "--zoom", "X", &o.Zoom, nullptr,
      "Camera zoom after fitting the scene, 0.1 to 10 (default 1.1)." },
    { "--timing", "N", &o.Timing, nullptr,
      "Also time this many frames (after 5 warm-up frames) of DIR, SIR, ISR, SSP, PEEL and of a plain VTK render of the same mesh, in --timing-repeats rounds, and print per method the median over the rounds with its [min-max] and its ratio to the plain render of the same round (0: no timing)." },
    { "--timing-repeats", "R", &o.TimingRepeats, nullptr,
      "Rounds of --timing, 1 to 100 (default 3): each round times every method and the plain render once, in an order shuffled per round (fixed seed), so that a slow phase of the machine spreads over all of them." },
    { "--no-text", nullptr, nullptr, &o.NoText,
      "No status line in the images." },
    { "--interactive", nullptr, nullptr, &o.Interactive,
      "Open a window (needs a display) instead of writing files." },
    { "--egl", nullptr, nullptr, &o.EGL,
      "Accepted for older scripts; no effect." },
  };
  using Args = vtksys::CommandLineArguments;
  Args arguments;
  arguments.Initialize(static_cast<int>(pointers.size()), pointers.data());
  arguments.StoreUnusedArguments(true);
  for (const OptionEntry& entry : table)
  {
    if (entry.Flag)
    {
      arguments.AddBooleanArgument(entry.Name, entry.Flag, entry.Help);
    }
    else
    {
      arguments.AddArgument(entry.Name, Args::SPACE_ARGUMENT, entry.Text, entry.Help);
    }
  }
  if (!arguments.Parse())
  {
    return rfViewerUsage("an option is missing its value");
  }
  if (o.Help)
  {
    std::string help;
    for (const OptionEntry& entry : table)
    {
      help += Wrap(std::string(entry.Name) + (entry.Value ? std::string(" ") + entry.Value : ""),
        entry.Help);
    }
    PrintHelp(help);
    if (!preset.empty())
    {
      std::string words;
      for (const std::string& word : preset)
      {
        words += " " + word;
      }
      std::printf("\n%s is %s with the preset options%s, which any option given overrides.\n",
        rfViewerProgram(), "RefractionViewer", words.c_str());
    }
    return -1;
  }
  int unusedCount = 0;
  char** unused = nullptr;
  arguments.GetUnusedArguments(&unusedCount, &unused);
  for (int i = 1; i < unusedCount; ++i)
  {
    const std::string word = unused[i];
    if (word.size() > 1 && word[0] == '-')
    {
      arguments.DeleteRemainingArguments(unusedCount, &unused);
      return rfViewerUsage("unknown option " + rfViewerQuote(word));
    }
    o.Inputs.push_back(word);
  }
  arguments.DeleteRemainingArguments(unusedCount, &unused);

  const std::string method = vtksys::SystemTools::LowerCase(o.Method);
  static const char* const methods[] = { "sir", "dir", "isr", "ssp", "peel" };
  const auto found = std::find(std::begin(methods), std::end(methods), method);
  if (found == std::end(methods))
  {
    return rfViewerUsage("--method must be dir, sir, isr, ssp or peel, not " +
      rfViewerQuote(o.Method) +
      (method == "sh" ? " (sh needs a vtkSHTransferFilter precomputation the viewer does not run)"
                      : ""));
  }
  s.Method = static_cast<int>(found - std::begin(methods));
  if (!ParseDouble(o.IOR, 0.1, 10.0, s.IOR))
  {
    return rfViewerUsage("--ior needs a number from 0.1 to 10, not " + rfViewerQuote(o.IOR));
  }
  if (!o.Dispersion.empty() &&
    (!ParseList(o.Dispersion, s.Dispersion) || s.Dispersion.size() != 3 ||
      std::any_of(s.Dispersion.begin(), s.Dispersion.end(),
        [](double v) { return !(v >= 0.1 && v <= 10.0); })))
  {
    return rfViewerUsage(
      "--dispersion needs r,g,b indices from 0.1 to 10, not " + rfViewerQuote(o.Dispersion));
  }
  if (!ParseInt(o.Layers, 2, 8, s.Layers))
  {
    return rfViewerUsage("--layers needs a whole number from 2 to 8, not " + rfViewerQuote(o.Layers));
  }
  const std::string capture = vtksys::SystemTools::LowerCase(o.PeelCapture);
  static const char* const captures[] = { "auto", "peeling", "k-buffer" };
  const auto capturing = std::find(std::begin(captures), std::end(captures), capture);
  if (capturing == std::end(captures))
  {
    return rfViewerUsage(
      "--peel-capture must be auto, peeling or k-buffer, not " + rfViewerQuote(o.PeelCapture));
  }
  // The pass's PEEL_CAPTURE_AUTO, _DEPTH_PEELING and _K_BUFFER, in that order.
  s.PeelCapture = static_cast<int>(capturing - std::begin(captures));
  if (!ParseInt(o.Steps, 0, 16, s.Steps))
  {
    return rfViewerUsage("--steps needs a whole number from 0 to 16, not " + rfViewerQuote(o.Steps));
  }
  const size_t x = o.Size.find_first_of("xX");
  if (!(x == std::string::npos
          ? ParseInt(o.Size, 1, 8192, s.Width) && ParseInt(o.Size, 1, 8192, s.Height)
          : ParseInt(o.Size.substr(0, x), 1, 8192, s.Width) &&
            ParseInt(o.Size.substr(x + 1), 1, 8192, s.Height)))
  {
    return rfViewerUsage("--size needs N or WxH pixels, 1 to 8192, not " + rfViewerQuote(o.Size));
  }
  if (!o.Frames.empty() && !ParseInt(o.Frames, 1, 1000000, s.Frames))
  {
    return rfViewerUsage("--frames needs a whole number from 1, not " + rfViewerQuote(o.Frames));
  }
  if (!o.Time.empty())
  {
    s.HaveTime = ParseDouble(o.Time, -1e300, 1e300, s.Time);
    if (!s.HaveTime)
    {
      return rfViewerUsage("--time needs a number, not " + rfViewerQuote(o.Time));
    }
  }
  if (!o.Contour.empty() && !ParseList(o.Contour, s.ContourValues))
  {
    return rfViewerUsage("--contour needs numbers separated by commas, not " + rfViewerQuote(o.Contour));
  }
  std::vector<double> background;
  if (!ParseList(o.Background, background) ||
    (background.size() != 3 && background.size() != 6) ||
    std::any_of(background.begin(), background.end(), [](double v) { return v < 0 || v > 1; }))
  {
    return rfViewerUsage("--background needs r,g,b or r,g,b,r2,g2,b2 from 0 to 1, not " +
      rfViewerQuote(o.Background));
  }
  std::copy(background.begin(), background.end(), s.Background);
  s.Gradient = background.size() == 6;
  if (!ParseInt(o.SheetColumns, 1, 16, s.SheetColumns))
  {
    return rfViewerUsage("--sheet-columns needs a whole number from 1 to 16, not " +
      rfViewerQuote(o.SheetColumns));
  }
  if (!ParseInt(o.SheetFrames, 1, 64, s.SheetFrames))
  {
    return rfViewerUsage("--sheet-frames needs a whole number from 1 to 64, not " + rfViewerQuote(o.SheetFrames));
  }
  if (!ParseDouble(o.Orbit, -360.0, 360.0, s.Orbit))
  {
    return rfViewerUsage("--orbit needs degrees from -360 to 360, not " + rfViewerQuote(o.Orbit));
  }
  if (!ParseDouble(o.Azimuth, -360.0, 360.0, s.Azimuth))
  {
    return rfViewerUsage("--azimuth needs degrees from -360 to 360, not " + rfViewerQuote(o.Azimuth));
  }
  if (!ParseDouble(o.Elevation, -89.0, 89.0, s.Elevation))
  {
    return rfViewerUsage("--elevation needs degrees from -89 to 89, not " + rfViewerQuote(o.Elevation));
  }
  if (!ParseDouble(o.Zoom, 0.1, 10.0, s.Zoom))
  {
    return rfViewerUsage("--zoom needs a number from 0.1 to 10, not " + rfViewerQuote(o.Zoom));
  }
  if (!ParseInt(o.Timing, 0, 100000, s.Timing))
  {
    return rfViewerUsage("--timing needs a whole number of frames from 0, not " + rfViewerQuote(o.Timing));
  }
  if (!ParseInt(o.TimingRepeats, 1, 100, s.TimingRepeats))
  {
    return rfViewerUsage("--timing-repeats needs a whole number of rounds from 1 to 100, not " +
      rfViewerQuote(o.TimingRepeats));
  }
  if (!o.Demo.empty() && o.Demo != "metaballs" && o.Demo != "waves")
  {
    return rfViewerUsage("--demo must be metaballs or waves, not " + rfViewerQuote(o.Demo));
  }
  if (o.Demo.empty() && o.Inputs.empty())
  {
    return rfViewerUsage("no input: give a mesh file, a .pvd series, or --demo metaballs|waves");
  }
  if (!o.Demo.empty() && !o.Inputs.empty())
  {
    return rfViewerUsage("--demo and an input file " + rfViewerQuote(o.Inputs[0]) + " exclude each other");
  }
  if (o.Series && o.Inputs.size() != 1)
  {
    return rfViewerUsage("--series takes one file of the series");
  }
  if (!o.Array.empty() && s.ContourValues.empty())
  {
    return rfViewerUsage("--array names the array to contour: give --contour VALUES too");
  }
  if (o.Masks && o.OutDir.empty())
  {
    return rfViewerUsage("--masks writes beside the frames: give --out FOLDER too");
  }
  if (o.Interactive && !(o.OutDir.empty() && o.Screenshot.empty() && o.ContactSheet.empty() &&
                          s.Timing == 0))
  {
    return rfViewerUsage("--interactive opens a window; --out, --screenshot, --contact-sheet and "
                 "--timing are for headless runs");
  }
  if (!o.Interactive && o.OutDir.empty() && o.Screenshot.empty() && o.ContactSheet.empty() &&
    s.Timing == 0)
  {
    return rfViewerUsage("nothing to do: give --interactive, --screenshot FILE, --out FOLDER, "
                 "--contact-sheet FILE or --timing N");
  }
  return RF_VIEWER_OK;
}

