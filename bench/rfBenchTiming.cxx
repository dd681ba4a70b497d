#include "rfBenchTiming.h"

#include "vtkRefractionPass.h"

#include <vtkNew.h>
#include <vtkOpenGLRenderTimer.h>
#include <vtkRenderWindow.h>
#include <vtkTimerLog.h>
#include <vtk_glew.h>

#include <algorithm>

namespace rfbench
{
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
}
