/**
 * @class   vtkRefractionStageTimers
 * @brief   GPU time of the pass's stages, by GL timer queries (vtkRefractionPass::GPUTiming).
 *
 * One vtkOpenGLRenderTimer a stage, made on the first measurement. A query's result is read
 * a frame later, when it is ready, so that timing never waits for the GPU: each stage keeps its
 * last completed measurement (-1 when none).
 */
#ifndef vtkRefractionStageTimers_h
#define vtkRefractionStageTimers_h

#include "vtkObject.h"

#include <memory> // For members
#include <vector> // For members

class vtkOpenGLRenderTimer;

class vtkRefractionStageTimers : public vtkObject
{
public:
  static vtkRefractionStageTimers* New();
  vtkTypeMacro(vtkRefractionStageTimers, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The number of stages timed (stages are numbered from 0).
  void SetNumberOfStages(int count);

  /// Whether Start and Stop measure (queries cost a little: off unless asked for).
  vtkSetMacro(Enabled, bool);
  vtkGetMacro(Enabled, bool);

  void Start(int stage);
  void Stop(int stage);
  /// A stage that does not run this frame reports no time (not another method's).
  void Forget(int stage);
  /// The stage's last completed measurement in milliseconds, -1 when none.
  double GetMilliseconds(int stage);

  void ReleaseGraphicsResources();

protected:
  vtkRefractionStageTimers();
  ~vtkRefractionStageTimers() override;

private:
  vtkRefractionStageTimers(const vtkRefractionStageTimers&) = delete;
  void operator=(const vtkRefractionStageTimers&) = delete;

  bool Enabled = false;
  std::vector<std::unique_ptr<vtkOpenGLRenderTimer>> Timers;
  std::vector<double> Milliseconds;
};

#endif
