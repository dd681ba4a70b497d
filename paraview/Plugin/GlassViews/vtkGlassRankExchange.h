/**
 * @class   vtkGlassRankExchange
 * @brief   vtkRefractionPass's rank exchange over ParaView's MPI controller.
 *
 * The pass composites its G-buffers across the ranks that render pieces of the data
 * (pvbatch or pvserver on several MPI ranks); this class is the transport, through the
 * process's vtkMultiProcessController (the global one unless another is set): AllReduce for
 * the ranks' agreements, Send and Receive for the buffers. vtkGlassRenderView installs it on
 * the frames that ParaView composites across ranks (its synchronized renderers enabled).
 */
#ifndef vtkGlassRankExchange_h
#define vtkGlassRankExchange_h

#include "RefractionGlassViewsModule.h" // For export macro
#include "vtkRefractionRankExchange.h"
#include "vtkSmartPointer.h" // For members

class vtkMultiProcessController;

class REFRACTIONGLASSVIEWS_EXPORT vtkGlassRankExchange : public vtkRefractionRankExchange
{
public:
  static vtkGlassRankExchange* New();
  vtkTypeMacro(vtkGlassRankExchange, vtkRefractionRankExchange);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The controller (default: vtkMultiProcessController::GetGlobalController() when used).
  void SetController(vtkMultiProcessController* controller);
  vtkMultiProcessController* GetController();

  int GetRank() override;
  int GetNumberOfRanks() override;
  void AllReduceMax(int* values, int count) override;
  double AllReduceMin(double value) override;
  double AllReduceMax(double value) override;
  bool Send(const unsigned char* data, unsigned long long bytes, int to) override;
  bool Receive(unsigned char* data, unsigned long long bytes, int from) override;

  /// The message tag of the G-buffers.
  static constexpr int BufferTag = 25025;

  /// All-reduces, sends and receives since the last ResetCounts(): every rank of a frame
  /// must make the same all-reduces, or the next collective on the controller (ParaView's or
  /// IceT's) pairs with the wrong call. vtkGlassRenderView logs them each frame.
  int GetAllReduceCount() const { return this->AllReduces; }
  int GetSendCount() const { return this->Sends; }
  int GetReceiveCount() const { return this->Receives; }
  void ResetCounts() { this->AllReduces = this->Sends = this->Receives = 0; }

protected:
  vtkGlassRankExchange();
  ~vtkGlassRankExchange() override;

private:
  vtkGlassRankExchange(const vtkGlassRankExchange&) = delete;
  void operator=(const vtkGlassRankExchange&) = delete;

  vtkSmartPointer<vtkMultiProcessController> Controller;
  int AllReduces = 0;
  int Sends = 0;
  int Receives = 0;
};

#endif
