// Endurance (label endurance): the demo as the viewer builds it (the metaballs, contoured
// anew every time step, with ISR's distances recomputed), rendered for thousands of frames
// while the window is resized and the method changes, as a user leaves the viewer running.
// What must stay flat:
//  - the process's resident memory: after a first cycle of every size and method (caches
//    filled, shaders compiled), its peak over the second half of the run may exceed its peak
//    over the first half by at most RF_ENDURANCE_RSS_MB (default 12 MB; a leak of 10 kB a
//    frame over 1,500 frames is 15 MB; with a 40 kB leak a frame added by hand, 1,500 frames
//    read 34 MB and failed);
//  - the pass's GPU textures: the same size and method hold the same bytes every time.
// Every frame is checked for OpenGL errors by the test window. Usage: TestEndurance [FRAMES]
// (default 1500, rounded to whole cycles of 300).
#include "../common/rfTestWindow.h"
#include "../common/rf_require.h"
#include "rfViewer.h"
#include "rfViewerOptions.h"
#include "rfViewerScene.h"

#include <vtkRenderWindow.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <utility>

namespace
{
// Resident memory in MB (/proc/self/statm: pages).
double ResidentMB()
{
  std::ifstream statm("/proc/self/statm");
  long long size = 0;
  long long resident = 0;
  statm >> size >> resident;
  return static_cast<double>(resident) * 4096.0 / (1024.0 * 1024.0);
}
}

int main(int argc, char* argv[])
{
  const int sizes[3][2] = { { 64, 64 }, { 96, 72 }, { 72, 96 } };
  const int methods[5] = { vtkRefractionPass::DIR, vtkRefractionPass::SIR,
    vtkRefractionPass::ISR, vtkRefractionPass::SSP, vtkRefractionPass::PEEL };
  const int framesPerMethod = 20;
  const int cycle = 3 * 5 * framesPerMethod;
  const int asked = argc > 1 ? std::atoi(argv[1]) : 1500;
  const int cycles = std::max(2, (asked + cycle - 1) / cycle);
  const char* allowed = std::getenv("RF_ENDURANCE_RSS_MB");
  const double allowedMB = allowed ? std::atof(allowed) : 12.0;

  rfViewerOptions options;
  options.Demo = "metaballs";
  rfViewerSettings settings;
  settings.Width = sizes[0][0];
  settings.Height = sizes[0][1];
  rfviewer::Scene scene;
  RF_REQUIRE(rfviewer::BuildScene(options, settings, scene) == RF_VIEWER_OK,
    "the demo's scene is built");
  RF_REQUIRE(scene.Times.size() > 1, "the demo has time steps (%zu)", scene.Times.size());
  vtkSmartPointer<vtkRenderWindow> window = rftest::NewRenderWindow(sizes[0][0], sizes[0][1]);
  window->AddRenderer(scene.Renderer);
  rfviewer::ShowTime(scene, scene.Times[0]);
  rfviewer::PlaceCamera(scene, settings);

  std::map<std::pair<int, int>, unsigned long long> textureBytes; // (size, method) -> bytes
  double firstHalfPeak = 0.0;
  double secondHalfPeak = 0.0;
  double afterWarmUp = 0.0;
  const int frames = cycles * cycle;
  for (int frame = 0; frame < frames; ++frame)
  {
    const int inCycle = frame % cycle;
    const int size = inCycle / (5 * framesPerMethod);
    const int method = (inCycle / framesPerMethod) % 5;
    if (inCycle % (5 * framesPerMethod) == 0)
    {
      window->SetSize(sizes[size][0], sizes[size][1]);
    }
    scene.Pass->SetMethod(methods[method]);
    rfviewer::ShowTime(scene, scene.Times[static_cast<size_t>(frame) % scene.Times.size()]);
    window->Render();

    // The textures of a size and method, once the method has run a frame there.
    if (inCycle % framesPerMethod == framesPerMethod - 1)
    {
      const auto key = std::make_pair(size, method);
      const unsigned long long bytes = scene.Pass->GetTextureBytes();
      auto known = textureBytes.find(key);
      if (known == textureBytes.end())
      {
        textureBytes[key] = bytes;
      }
      else
      {
        RF_REQUIRE(bytes == known->second,
          "frame %d: %dx%d, method %d holds %llu bytes of textures, %llu the first time", frame,
          sizes[size][0], sizes[size][1], methods[method], bytes, known->second);
      }
    }
    if (frame >= cycle)
    {
      const double mb = ResidentMB();
      if (frame == cycle)
      {
        afterWarmUp = mb;
      }
      double& peak = frame < cycle + (frames - cycle) / 2 ? firstHalfPeak : secondHalfPeak;
      peak = std::max(peak, mb);
    }
  }
  std::printf("%d frames (%d cycles of 3 sizes x 5 methods x %d frames); resident memory after "
              "the first cycle %.1f MB, peak %.1f MB in the first half, %.1f MB in the second; "
              "%zu size and method pairs, their textures the same every time\n",
    frames, cycles, framesPerMethod, afterWarmUp, firstHalfPeak, secondHalfPeak,
    textureBytes.size());
  RF_REQUIRE(secondHalfPeak - firstHalfPeak <= allowedMB,
    "resident memory grew by %.1f MB from the first half's peak to the second's (at most "
    "%.1f)",
    secondHalfPeak - firstHalfPeak, allowedMB);
  return EXIT_SUCCESS;
}
