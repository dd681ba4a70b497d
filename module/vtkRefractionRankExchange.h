/**
 * @class   vtkRefractionRankExchange
 * @brief   How vtkRefractionPass talks to the other processes that render pieces of one scene.
 *
 * In sort-last parallel rendering (ParaView's pvbatch and pvserver on several MPI ranks) each
 * process draws its piece of the data and the images are composited by depth. Refraction is
 * not a per-piece effect, so the pass composites its G-buffers across the processes first
 * (vtkRefractionGBufferComposite) and shades once, on rank 0, over the whole glass.
 *
 * This class is the transport the pass needs, and nothing more: the rank, the number of
 * ranks, a maximum over small integer vectors (so that every rank takes the same decisions
 * each frame), a minimum and maximum over doubles, and a blocking exchange of byte buffers
 * between two ranks. This base class is one process alone (rank 0 of 1: every reduction is
 * the identity). The ParaView plugin's subclass sends through ParaView's
 * vtkMultiProcessController; the rendering module itself has no parallel dependency.
 *
 * Every rank must render every frame that composites (the calls are collective), which
 * sort-last compositing guarantees; the view that installs an exchange removes it for frames
 * that render on one process.
 */
#ifndef vtkRefractionRankExchange_h
#define vtkRefractionRankExchange_h

#include "vtkObject.h"
#include "vtkRenderingRefractionModule.h" // For export macro

class VTKRENDERINGREFRACTION_EXPORT vtkRefractionRankExchange : public vtkObject
{
public:
  static vtkRefractionRankExchange* New();
  vtkTypeMacro(vtkRefractionRankExchange, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// This process's rank, 0 .. GetNumberOfRanks() - 1.
  virtual int GetRank() { return 0; }
  virtual int GetNumberOfRanks() { return 1; }

  /// Replace each of `count` values by its maximum over all ranks.
  virtual void AllReduceMax(int* values, int count);

  /// Replace `value` by its minimum (or maximum) over all ranks.
  virtual double AllReduceMin(double value) { return value; }
  virtual double AllReduceMax(double value) { return value; }

  /// Send `bytes` bytes to rank `to` / receive exactly `bytes` bytes from rank `from`.
  /// Return false when the transport fails.
  virtual bool Send(const unsigned char* data, unsigned long long bytes, int to);
  virtual bool Receive(unsigned char* data, unsigned long long bytes, int from);

protected:
  vtkRefractionRankExchange();
  ~vtkRefractionRankExchange() override;

private:
  vtkRefractionRankExchange(const vtkRefractionRankExchange&) = delete;
  void operator=(const vtkRefractionRankExchange&) = delete;
};

#endif
