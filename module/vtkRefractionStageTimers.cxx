#include "vtkRefractionStageTimers.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderTimer.h"

vtkStandardNewMacro(vtkRefractionStageTimers);

//------------------------------------------------------------------------------
vtkRefractionStageTimers::vtkRefractionStageTimers() = default;
vtkRefractionStageTimers::~vtkRefractionStageTimers() = default;

//------------------------------------------------------------------------------
void vtkRefractionStageTimers::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Enabled: " << this->Enabled << "\n";
  os << indent << "Stages: " << this->Timers.size() << "\n";
}

//------------------------------------------------------------------------------
void vtkRefractionStageTimers::SetNumberOfStages(int count)
{
  this->Timers.resize(count);
  this->Milliseconds.resize(count, -1.0);
}

//------------------------------------------------------------------------------
void vtkRefractionStageTimers::Start(int stage)
{
  if (!this->Enabled || !vtkOpenGLRenderTimer::IsSupported())
  {
    return;
  }
  auto& timer = this->Timers[stage];
  if (!timer)
  {
    timer = std::make_unique<vtkOpenGLRenderTimer>();
  }
  // Ready() asks GL about both queries: on a timer not started or not stopped yet it would ask
  // about query 0 (GL_INVALID_OPERATION), so only a stopped timer is asked.
  const bool stopped = timer->Started() && timer->Stopped();
  if (stopped && timer->Ready())
  {
    this->Milliseconds[stage] = timer->GetElapsedMilliseconds();
  }
  if (!timer->Started() || (stopped && timer->Ready()))
  {
    timer->Reset();
    timer->Start();
  }
}

//------------------------------------------------------------------------------
void vtkRefractionStageTimers::Stop(int stage)
{
  auto& timer = this->Timers[stage];
  if (this->Enabled && timer && timer->Started() && !timer->Stopped())
  {
    timer->Stop();
  }
}

//------------------------------------------------------------------------------
void vtkRefractionStageTimers::Forget(int stage)
{
  this->Milliseconds[stage] = -1.0;
  this->Timers[stage].reset();
}

//------------------------------------------------------------------------------
double vtkRefractionStageTimers::GetMilliseconds(int stage)
{
  auto& timer = this->Timers[stage];
  if (timer && timer->Stopped() && timer->Ready())
  {
    this->Milliseconds[stage] = timer->GetElapsedMilliseconds();
  }
  return this->Milliseconds[stage];
}

//------------------------------------------------------------------------------
void vtkRefractionStageTimers::ReleaseGraphicsResources()
{
  for (auto& timer : this->Timers)
  {
    if (timer)
    {
      timer->ReleaseGraphicsResources();
      timer.reset();
    }
  }
}
