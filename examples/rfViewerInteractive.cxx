#include "rfViewerInteractive.h"

#include "rfViewer.h"

#include <vtkCallbackCommand.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>

#include <algorithm>
#include <cstdio>

namespace rfviewer
{
namespace
{
struct InteractiveState
{
  Scene* TheScene;
  bool Animate = true;
  int TimeIndex = 0;
};

void OnRenderEnd(vtkObject*, unsigned long, void* clientData, void*)
{
  auto* state = static_cast<InteractiveState*>(clientData);
  SetStatus(*state->TheScene, state->TheScene->Renderer->GetLastRenderTimeInSeconds() * 1e3,
    state->TimeIndex);
}

void OnKey(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* state = static_cast<InteractiveState*>(clientData);
  Scene& scene = *state->TheScene;
  auto* interactor = static_cast<vtkRenderWindowInteractor*>(caller);
  const std::string key = interactor->GetKeySym() ? interactor->GetKeySym() : "";
  const int steps = static_cast<int>(scene.Times.size());
  if (key == "m")
  {
    // DIR -> SIR -> ISR -> SSP -> PEEL -> DIR
    static const int next[] = { vtkRefractionPass::ISR, vtkRefractionPass::SIR,
      vtkRefractionPass::SSP, vtkRefractionPass::PEEL, vtkRefractionPass::DIR };
    scene.Pass->SetMethod(next[scene.Pass->GetMethod()]);
  }
  else if (key == "i" || key == "I")
  {
    const double ior = vtkRefractionPass::GetIndexOfRefraction(scene.Glass);
    const double changed = std::min(10.0, std::max(0.1, ior + (key == "I" ? 0.05 : -0.05)));
    vtkRefractionPass::MakeGlass(scene.Glass, changed);
  }
  else if (key == "plus" || key == "equal" || key == "KP_Add")
  {
    scene.Pass->SetSearchSteps(std::min(scene.Pass->GetSearchSteps() + 1, 16));
  }
  else if (key == "minus" || key == "KP_Subtract")
  {
    scene.Pass->SetSearchSteps(std::max(scene.Pass->GetSearchSteps() - 1, 0));
  }
  else if (key == "space")
  {
    state->Animate = !state->Animate;
  }
  else if ((key == "Right" || key == "Left") && steps > 0)
  {
    // Arrows rather than letters: the interactor style takes 'p' (pick) and others.
    state->Animate = false;
    state->TimeIndex = (state->TimeIndex + (key == "Right" ? 1 : steps - 1)) % steps;
    ShowTime(scene, scene.Times[state->TimeIndex]);
  }
  else
  {
    return;
  }
  interactor->GetRenderWindow()->Render();
  // The same line in the terminal, for a record of what was looked at.
  std::printf("%s\n", scene.Text->GetInput());
  std::fflush(stdout);
}

void OnTimer(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* state = static_cast<InteractiveState*>(clientData);
  Scene& scene = *state->TheScene;
  if (!state->Animate || scene.Times.size() < 2)
  {
    return;
  }
  state->TimeIndex = (state->TimeIndex + 1) % static_cast<int>(scene.Times.size());
  ShowTime(scene, scene.Times[state->TimeIndex]);
  static_cast<vtkRenderWindowInteractor*>(caller)->GetRenderWindow()->Render();
}
}

int RunInteractive(Scene& scene, vtkRenderWindow* window, int timeIndex)
{
  vtkNew<vtkRenderWindowInteractor> interactor;
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);
  interactor->SetRenderWindow(window);
  InteractiveState state{ &scene, true, timeIndex };
  vtkNew<vtkCallbackCommand> keys;
  keys->SetCallback(OnKey);
  keys->SetClientData(&state);
  // Before the style's own handlers: 'i' would otherwise be taken by nothing, but '+'/'-'
  // and others are harmless; keep ours first anyway.
  interactor->AddObserver(vtkCommand::KeyPressEvent, keys, 1.0);
  vtkNew<vtkCallbackCommand> timer;
  timer->SetCallback(OnTimer);
  timer->SetClientData(&state);
  interactor->AddObserver(vtkCommand::TimerEvent, timer);
  vtkNew<vtkCallbackCommand> status;
  status->SetCallback(OnRenderEnd);
  status->SetClientData(&state);
  scene.Renderer->AddObserver(vtkCommand::EndEvent, status);
  interactor->Initialize();
  interactor->CreateRepeatingTimer(40);
  SetStatus(scene, 0.0, timeIndex);
  window->Render();
  std::printf("keys: m method, i/I index of refraction, +/- search steps, space animation, "
              "Right/Left time step\n");
  std::fflush(stdout);
  interactor->Start();
  return RF_VIEWER_OK;
}
}
