#include "rfViewerOutput.h"

#include "rfSpread.h"
#include "rfViewer.h"

#include <vtkCamera.h>
#include <vtkImageAppend.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkTimerLog.h>
#include <vtkWindowToImageFilter.h>
#include <vtk_glew.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <unistd.h>

namespace rfviewer
{
namespace
{
// A progress line for long runs: rewritten in place on a terminal, one line per tenth in a log.
class ProgressLine
{
public:
  ProgressLine(const char* label, int total)
    : Label(label)
    , Total(total)
    , Terminal(isatty(fileno(stdout)) != 0)
  {
  }
  void Update(int done)
  {
    const int percent = this->Total > 0 ? 100 * done / this->Total : 100;
    if (this->Terminal)
    {
      std::printf("\r%s %d/%d (%d%%)", this->Label, done, this->Total, percent);
      if (done == this->Total)
      {
        std::printf("\n");
      }
      std::fflush(stdout);
    }
    else if (percent / 10 > this->LastTenth || done == this->Total)
    {
      this->LastTenth = percent / 10;
      std::printf("%s %d/%d (%d%%)\n", this->Label, done, this->Total, percent);
      std::fflush(stdout);
    }
  }

private:
  const char* Label;
  int Total;
  bool Terminal;
  int LastTenth = -1;
};

// The glass drawn as the ordinary VTK actor it is, for as long as this lives; its glass keys
// (index of refraction, dispersion: ClearGlass removes both) are put back after, so that what
// renders next renders the same glass.
class PlainActorScope
{
public:
  explicit PlainActorScope(vtkProp* glass)
    : Glass(glass)
    , IndexOfRefraction(vtkRefractionPass::GetIndexOfRefraction(glass))
    , HasDispersion(vtkRefractionPass::GetDispersion(glass, this->Dispersion))
  {
    vtkRefractionPass::ClearGlass(glass);
  }
  ~PlainActorScope()
  {
    vtkRefractionPass::MakeGlass(this->Glass, this->IndexOfRefraction);
    if (this->HasDispersion)
    {
      vtkRefractionPass::SetDispersion(
        this->Glass, this->Dispersion[0], this->Dispersion[1], this->Dispersion[2]);
    }
  }
  PlainActorScope(const PlainActorScope&) = delete;
  PlainActorScope& operator=(const PlainActorScope&) = delete;

private:
  vtkProp* Glass;
  double IndexOfRefraction;
  double Dispersion[3] = { 0, 0, 0 };
  bool HasDispersion;
};

double RenderMilliseconds(vtkRenderWindow* window)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  window->Render();
  glFinish();
  timer->StopTimer();
  return timer->GetElapsedTime() * 1e3;
}

vtkSmartPointer<vtkImageData> Grab(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

bool WritePNG(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    std::fprintf(stderr, "%s: cannot write %s\n", rfViewerProgram(), path.c_str());
    return false;
  }
  return true;
}

// The glass's silhouette: the glass actor alone, flat white on black.
vtkSmartPointer<vtkImageData> GrabMask(Scene& scene, vtkRenderWindow* window)
{
  vtkRenderer* renderer = scene.Renderer;
  double background[3];
  renderer->GetBackground(background);
  const bool gradient = renderer->GetGradientBackground();
  std::vector<vtkProp*> hidden;
  for (vtkProp* prop : { static_cast<vtkProp*>(scene.Cone.Get()),
         static_cast<vtkProp*>(scene.Floor.Get()), static_cast<vtkProp*>(scene.Sky.Get()),
         static_cast<vtkProp*>(scene.Text.Get()) })
  {
    if (prop && prop->GetVisibility())
    {
      prop->SetVisibility(false);
      hidden.push_back(prop);
    }
  }
  PlainActorScope plain(scene.Glass);
  vtkProperty* property = scene.Glass->GetProperty();
  property->LightingOff();
  property->SetColor(1.0, 1.0, 1.0);
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->GradientBackgroundOff();
  // The pass draws the glass where a pixel's centre is covered; a multisampled window would
  // blend the plain actor's edge pixels by coverage instead, so the mask is single-sampled.
  const int samples = window->GetMultiSamples();
  window->SetMultiSamples(0);
  window->Render();
  vtkSmartPointer<vtkImageData> mask = Grab(window);
  window->SetMultiSamples(samples);
  property->LightingOn();
  renderer->SetBackground(background);
  renderer->SetGradientBackground(gradient);
  for (vtkProp* prop : hidden)
  {
    prop->SetVisibility(true);
  }
  return mask;
}

vtkSmartPointer<vtkImageData> ContactSheet(
  const std::vector<vtkSmartPointer<vtkImageData>>& tiles, int columns)
{
  const int rows = static_cast<int>((tiles.size() + columns - 1) / columns);
  vtkNew<vtkImageAppend> sheet;
  sheet->SetAppendAxis(1);
  // VTK's rows go up: append the last row of tiles first so that the first frame is top left.
  for (int row = rows - 1; row >= 0; --row)
  {
    vtkNew<vtkImageAppend> line;
    line->SetAppendAxis(0);
    for (int column = 0; column < columns; ++column)
    {
      const size_t index = static_cast<size_t>(row) * columns + column;
      if (index < tiles.size())
      {
        line->AddInputData(tiles[index]);
      }
      else
      {
        vtkNew<vtkImageData> blank;
        blank->CopyStructure(tiles[0]);
        blank->AllocateScalars(tiles[0]->GetScalarType(), tiles[0]->GetNumberOfScalarComponents());
        std::memset(blank->GetScalarPointer(), 0,
          static_cast<size_t>(blank->GetNumberOfPoints()) *
            blank->GetNumberOfScalarComponents() * blank->GetScalarSize());
        line->AddInputData(blank);
      }
    }
    line->Update();
    auto copy = vtkSmartPointer<vtkImageData>::New();
    copy->DeepCopy(line->GetOutput());
    sheet->AddInputData(copy);
  }
  sheet->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(sheet->GetOutput());
  return image;
}

// What --timing times, in the order it prints them: the pass's methods, then the plain VTK
// render of the same mesh (PlainRender: the glass drawn as the ordinary actor it is).
const int TimedMethods[] = { vtkRefractionPass::DIR, vtkRefractionPass::SIR,
  vtkRefractionPass::ISR, vtkRefractionPass::SSP, vtkRefractionPass::PEEL };
const int PlainRender = -1;
// Fixed, so that two runs time in the same order (the benchmark's --seed defaults to 1 too).
const unsigned TimingSeed = 1;

// The median frame time of `frames` frames after 5 warm-up frames, which absorb what a switch
// of method costs once (its shaders, its buffers); the camera turns a degree a frame.
double MedianFrameMilliseconds(Scene& scene, vtkRenderWindow* window, int frames)
{
  std::vector<double> times;
  for (int i = 0; i < 5 + frames; ++i)
  {
    scene.Renderer->GetActiveCamera()->Azimuth(1.0);
    const double ms = RenderMilliseconds(window);
    if (i >= 5)
    {
      times.push_back(ms);
    }
  }
  return rftiming::Median(times);
}

// One block of a round: the median frame time of a method of the pass, or of the plain render.
double TimeBlock(Scene& scene, vtkRenderWindow* window, int method, int frames)
{
  if (method == PlainRender)
  {
    PlainActorScope plain(scene.Glass);
    return MedianFrameMilliseconds(scene, window, frames);
  }
  scene.Pass->SetMethod(method);
  return MedianFrameMilliseconds(scene, window, frames);
}

// Per method (PlainRender included) one block time per round, and per method of the pass its
// ratio to the plain render of the same round.
struct TimingRounds
{
  std::map<int, std::vector<double>> Milliseconds;
  std::map<int, std::vector<double>> RatioToPlain;
};

// Every round times every method and the plain render once, in an order shuffled per round:
// a slow phase of a shared machine then spreads over all of them instead of falling on
// whichever ran first, and each ratio is taken against the plain render of its own round
// (bench/RefractionBenchmark.cxx times its rows the same way).
TimingRounds TimeRounds(Scene& scene, vtkRenderWindow* window, const rfViewerSettings& s)
{
  std::vector<int> order(std::begin(TimedMethods), std::end(TimedMethods));
  order.push_back(PlainRender);
  std::mt19937 random(TimingSeed);
  ProgressLine progress("timing rounds", s.TimingRepeats);
  TimingRounds rounds;
  for (int round = 0; round < s.TimingRepeats; ++round)
  {
    std::shuffle(order.begin(), order.end(), random);
    std::map<int, double> ms;
    for (int method : order)
    {
      ms[method] = TimeBlock(scene, window, method, s.Timing);
    }
    for (const auto& block : ms)
    {
      rounds.Milliseconds[block.first].push_back(block.second);
      if (block.first != PlainRender)
      {
        rounds.RatioToPlain[block.first].push_back(block.second / ms[PlainRender]);
      }
    }
    progress.Update(round + 1);
  }
  scene.Pass->SetMethod(s.Method);
  return rounds;
}

// The method's name with the setting its time depends on, as the timing lines show it.
std::string MethodLabel(int method, const rfViewerSettings& s)
{
  switch (method)
  {
    case vtkRefractionPass::DIR:
      return "DIR (" + std::to_string(s.Steps) + " steps)";
    case vtkRefractionPass::SIR:
      return "SIR";
    case vtkRefractionPass::ISR:
      return "ISR";
    case vtkRefractionPass::SSP:
      return "SSP";
    case vtkRefractionPass::PEEL:
      return "PEEL (" + std::to_string(s.Layers) + " layers)";
    default:
      return "plain VTK";
  }
}

// "[22.00-33.00]": the extremes over the rounds.
std::string Extremes(const rftiming::Spread& spread)
{
  char text[64];
  std::snprintf(text, sizeof(text), "[%.2f-%.2f]", spread.Min, spread.Max);
  return text;
}

// "  DIR (5 steps)     24.10 ms [22.00-33.00]   1.80x plain [1.62-2.41]" and what follows;
// the plain render's line has no ratio.
void PrintTimingLine(const std::string& label, const rftiming::Spread& ms,
  const rftiming::Spread* ratio, const std::string& extra)
{
  std::printf("  %-16s %8.2f ms ", label.c_str(), ms.Median);
  if (ratio)
  {
    std::printf("%-15s %5.2fx plain %s", Extremes(ms).c_str(), ratio->Median,
      Extremes(*ratio).c_str());
  }
  else
  {
    std::printf("%s", Extremes(ms).c_str());
  }
  std::printf("%s\n", extra.c_str());
}

void ReportTiming(Scene& scene, vtkRenderWindow* window, const rfViewerSettings& s)
{
  const bool text = scene.Text->GetVisibility() != 0;
  scene.Text->SetVisibility(false);
  const vtkIdType triangles =
    vtkPolyData::SafeDownCast(scene.Surface->GetOutputDataObject(0))->GetNumberOfPolys();
  const TimingRounds rounds = TimeRounds(scene, window, s);
  scene.Text->SetVisibility(text);
  std::printf("frame times of %d frames x %d rounds, interleaved, at %dx%d, %lld triangles, "
              "renderer: %s\n",
    s.Timing, s.TimingRepeats, s.Width, s.Height, static_cast<long long>(triangles),
    reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  std::printf("  each round times every method and plain VTK once, in a shuffled order (seed %u);\n"
              "  a round's time is the median of its frames after 5 warm-up frames; ms and the\n"
              "  ratio (to the plain render of the same round) are medians over the rounds with\n"
              "  [min-max] beside them\n",
    TimingSeed);
  for (int method : TimedMethods)
  {
    char extra[128] = "";
    if (method == vtkRefractionPass::ISR)
    {
      std::snprintf(extra, sizeof(extra),
        ", plus %.2f ms of d_N ray casting each time the surface changes",
        scene.Distances->GetLastComputeSeconds() * 1e3);
    }
    const rftiming::Spread ratio = rftiming::SpreadOf(rounds.RatioToPlain.at(method));
    PrintTimingLine(MethodLabel(method, s), rftiming::SpreadOf(rounds.Milliseconds.at(method)),
      &ratio, extra);
  }
  PrintTimingLine(MethodLabel(PlainRender, s),
    rftiming::SpreadOf(rounds.Milliseconds.at(PlainRender)), nullptr, "");
}
}

int RunHeadless(const rfViewerOptions& o, const rfViewerSettings& s, Scene& scene, vtkRenderWindow* window,
  int firstIndex)
{
  // The first frame compiles shaders and converts the environment: not a frame time to show.
  scene.Text->SetInput("");
  window->Render();
  if (!o.Screenshot.empty())
  {
    const double ms = RenderMilliseconds(window);
    SetStatus(scene, ms, firstIndex);
    window->Render();
    if (!WritePNG(Grab(window), o.Screenshot))
    {
      return RF_VIEWER_FAILED;
    }
    std::printf("wrote %s (%dx%d)\n", o.Screenshot.c_str(), s.Width, s.Height);
  }

  const bool sequence = !o.OutDir.empty() || !o.ContactSheet.empty();
  if (sequence)
  {
    const int steps = static_cast<int>(scene.Times.size());
    const int frames = s.Frames > 0 ? s.Frames : std::max(steps, 1);
    // The frames that go on the contact sheet, spread evenly from the first to the last.
    std::vector<int> sheetFrames;
    const int tiles = std::min(frames, s.SheetFrames);
    for (int k = 0; k < tiles; ++k)
    {
      sheetFrames.push_back(tiles > 1 ? static_cast<int>(std::lround(
                                          static_cast<double>(k) * (frames - 1) / (tiles - 1)))
                                      : 0);
    }
    std::vector<vtkSmartPointer<vtkImageData>> sheet;
    ProgressLine progress("frames", frames);
    double lastMs = RenderMilliseconds(window);
    for (int frame = 0; frame < frames; ++frame)
    {
      const int index = steps > 0 ? frame % steps : 0;
      if (steps > 0)
      {
        ShowTime(scene, scene.Times[index]);
      }
      if (frame > 0 && s.Orbit != 0.0)
      {
        scene.Renderer->GetActiveCamera()->Azimuth(s.Orbit);
      }
      scene.Renderer->ResetCameraClippingRange();
      // The status line shows the time of the frame before (it is drawn within the frame).
      SetStatus(scene, lastMs, index);
      lastMs = RenderMilliseconds(window);
      vtkSmartPointer<vtkImageData> image = Grab(window);
      if (!o.OutDir.empty())
      {
        char name[32];
        std::snprintf(name, sizeof(name), "frame_%04d.png", frame);
        if (!WritePNG(image, o.OutDir + "/" + name))
        {
          return RF_VIEWER_FAILED;
        }
        if (o.Masks)
        {
          std::snprintf(name, sizeof(name), "mask_%04d.png", frame);
          if (!WritePNG(GrabMask(scene, window), o.OutDir + "/" + name))
          {
            return RF_VIEWER_FAILED;
          }
        }
      }
      if (std::find(sheetFrames.begin(), sheetFrames.end(), frame) != sheetFrames.end())
      {
        sheet.push_back(image);
      }
      progress.Update(frame + 1);
    }
    if (!o.OutDir.empty())
    {
      std::printf("wrote %d frames to %s/frame_NNNN.png (%dx%d)%s\n", frames, o.OutDir.c_str(),
        s.Width, s.Height, o.Masks ? " and mask_NNNN.png" : "");
    }
    if (!o.ContactSheet.empty())
    {
      const int columns = std::min(s.SheetColumns, static_cast<int>(sheet.size()));
      if (!WritePNG(ContactSheet(sheet, columns), o.ContactSheet))
      {
        return RF_VIEWER_FAILED;
      }
      std::printf("wrote %s (%zu frames, %d columns)\n", o.ContactSheet.c_str(), sheet.size(),
        columns);
    }
  }

  if (s.Timing > 0)
  {
    ShowTime(scene, scene.Times.empty() ? 0.0 : scene.Times[firstIndex]);
    ReportTiming(scene, window, s);
  }
  return RF_VIEWER_OK;
}

// Output paths are checked before anything is rendered, so that a typo costs no time.
int CheckOutputs(const rfViewerOptions& o)
{
  if (!o.OutDir.empty())
  {
    if (vtksys::SystemTools::FileExists(o.OutDir, true))
    {
      return rfViewerBadInput("--out: " + rfViewerQuote(o.OutDir) + " is a file, not a folder");
    }
    if (!vtksys::SystemTools::MakeDirectory(o.OutDir))
    {
      return rfViewerBadInput("--out: cannot create the folder " + rfViewerQuote(o.OutDir));
    }
  }
  for (const std::string* file : { &o.Screenshot, &o.ContactSheet })
  {
    if (file->empty())
    {
      continue;
    }
    const std::string folder = vtksys::SystemTools::GetFilenamePath(*file);
    if (!folder.empty() && !vtksys::SystemTools::FileIsDirectory(folder))
    {
      return rfViewerBadInput("cannot write " + rfViewerQuote(*file) + ": no folder " + rfViewerQuote(folder));
    }
    if (vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(*file)) !=
      ".png")
    {
      return rfViewerBadInput("cannot write " + rfViewerQuote(*file) + ": images are written as .png");
    }
  }
  return RF_VIEWER_OK;
}
}
