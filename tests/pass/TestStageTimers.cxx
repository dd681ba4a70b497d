// The pass's own stage timers (SetGPUTiming, what the benchmark's stage columns read) on every
// method, switched between methods and on and off between frames: no OpenGL error and no
// message from the pass on any frame (vtkOpenGLRenderTimer::Ready on a timer not yet started
// asks GL about query 0, which raised GL_INVALID_OPERATION on the first timed frame), and
// after a few frames a time for each stage the method runs and none (-1) for the others.
#include "vtkRefractionPass.h"

#include "rfTestWindow.h"
#include "rf_require.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderTimer.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <cstdio>
#include <cstdlib>

namespace
{
void CountMessage(vtkObject*, unsigned long, void* clientData, void* callData)
{
  ++*static_cast<int*>(clientData);
  std::fprintf(stderr, "message from the pass: %s\n", static_cast<const char*>(callData));
}
}

int main()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRefractionPass> pass;
  renderer->SetPass(pass);
  RF_REQUIRE(vtkRefractionPass::MakeGlass(actor, 1.5), "MakeGlass refused IOR 1.5");
  int messages = 0;
  vtkNew<vtkCallbackCommand> onMessage;
  onMessage->SetCallback(CountMessage);
  onMessage->SetClientData(&messages);
  pass->AddObserver(vtkCommand::ErrorEvent, onMessage);
  pass->AddObserver(vtkCommand::WarningEvent, onMessage);
  vtkSmartPointer<vtkRenderWindow> window = rftest::NewRenderWindow(96, 96);
  window->AddRenderer(renderer);
  window->Render(); // a context, to ask whether timer queries exist
  const bool timers = vtkOpenGLRenderTimer::IsSupported();

  struct Case
  {
    int Method;
    const char* Name;
    bool Runs[vtkRefractionPass::TIMED_STAGE_COUNT]; // back/peel, depth range, front, shade
  };
  const Case cases[] = {
    { vtkRefractionPass::DIR, "DIR", { true, true, true, true } },
    { vtkRefractionPass::SIR, "SIR", { false, false, true, true } },
    { vtkRefractionPass::ISR, "ISR", { true, false, true, true } },
    { vtkRefractionPass::SSP, "SSP", { false, false, true, true } },
    { vtkRefractionPass::PEEL, "PEEL", { true, false, true, true } },
    { vtkRefractionPass::DIR, "DIR again", { true, true, true, true } },
  };
  for (int round = 0; round < 2; ++round)
  {
    for (const Case& c : cases)
    {
      pass->SetMethod(c.Method);
      pass->SetGPUTiming(true);
      for (int frame = 0; frame < 4; ++frame)
      {
        window->Render(); // rfTestWindow fails the test on a pending GL error
        RF_REQUIRE(messages == 0, "%s, frame %d: the pass reported %d message(s)", c.Name,
          frame, messages);
      }
      for (int stage = 0; timers && stage < vtkRefractionPass::TIMED_STAGE_COUNT; ++stage)
      {
        const double ms = pass->GetStageMilliseconds(stage);
        std::printf("%s stage %d: %.3f ms\n", c.Name, stage, ms);
        RF_REQUIRE(c.Runs[stage] ? ms >= 0.0 : ms == -1.0,
          "%s: stage %d reads %g ms (%s)", c.Name, stage, ms,
          c.Runs[stage] ? "a stage it runs" : "a stage it does not run");
      }
      // Off for a frame between methods: the timers left started must not trouble the next.
      pass->SetGPUTiming(round == 1);
      window->Render();
      RF_REQUIRE(messages == 0, "%s, timing switched: %d message(s)", c.Name, messages);
    }
  }
  std::printf("stage timers on %s: no GL error, no message\n",
    timers ? "every method" : "(timer queries unsupported: only the frames)");
  return EXIT_SUCCESS;
}
