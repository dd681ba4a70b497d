/**
 * @class   vtkRefractionGBufferComposite
 * @brief   Makes rank 0's G-buffers those of the whole glass, from every rank's piece.
 *
 * Sort-last glass (issue 25). Each rank has drawn its piece of the glass into the pass's
 * targets: front surface (depth, normal and material, data colour, ISR's d_N, SH's exit), back
 * surface, PEEL's layers and the opaque scene's colour and depth. This class reads them back
 * into one buffer per rank and reduces the buffers up a binary tree (rank r + s sends to rank
 * r in step s = 1, 2, 4, ...: ceil(log2 ranks) steps, ranks - 1 buffers sent in all), merging
 * each pair pixel by pixel with the rules in rf_composite.h (the nearest front, the furthest
 * back, the K nearest layers, the nearest scene; on ties the lower rank's). Rank 0 uploads the
 * result into its targets and shades once over it; the other ranks shade nothing, and the
 * depth compositing that follows (IceT in ParaView) puts rank 0's glass in front of their
 * opaque pieces exactly where it is in front.
 *
 * The transport is a vtkRefractionRankExchange; the merge runs on the CPU, so the cost is a
 * read-back and, on rank 0, an upload of the targets per frame, plus the tree's messages.
 */
#ifndef vtkRefractionGBufferComposite_h
#define vtkRefractionGBufferComposite_h

#include "vtkObject.h"

#include <vector> // For members

class vtkOpenGLRenderWindow;
class vtkRefractionRankExchange;
class vtkRefractionTargets;

class vtkRefractionGBufferComposite : public vtkObject
{
public:
  static vtkRefractionGBufferComposite* New();
  vtkTypeMacro(vtkRefractionGBufferComposite, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// What this frame's method drew, the same on every rank.
  struct Request
  {
    bool FrontColour = false; ///< FRONT_COLOR (the data's colour)
    bool FrontAux = false;    ///< FRONT_AUX (ISR's d_N)
    bool FrontSH = false;     ///< FRONT_SH
    bool Back = false;        ///< BACK_SURFACE and BACK_Z
    bool BackNearest = false; ///< the nearest back surface rather than the furthest
    int PeelLayers = 1;       ///< FRONT_SURFACE and PEEL_1 .. PEEL_(PeelLayers - 1), the
                              ///< front's material signed (vtkRefractionGeometryStage::
                              ///< SetSignedFront) and unsigned by the composite
    bool Scene = false;       ///< SCENE_COLOR and SCENE_DEPTH
    bool SSPMask = false;     ///< compute SSP's refraction mask into SCENE_COLOR's alpha
    /// When set, the scene's colour where no opaque prop is (depth 1): the background that
    /// a compositor drawing every rank over black leaves out, bottom to top (a gradient).
    bool FillBackground = false;
    double Background[3] = { 0.0, 0.0, 0.0 };
    double Background2[3] = { 0.0, 0.0, 0.0 };
  };

  /**
   * Composite the requested targets over all ranks of `exchange` (collective: every rank
   * calls it with the same request and target sizes). On rank 0 the targets then hold the
   * whole glass. Returns false (with a message) when a transfer fails; the targets are then
   * rank 0's own.
   */
  bool Composite(vtkOpenGLRenderWindow* renWin, vtkRefractionTargets* targets,
    const Request& request, vtkRefractionRankExchange* exchange);

  /// The last frame's wall-clock milliseconds in Composite on this rank (read-back, messages,
  /// merges, upload; the G-buffers' own drawing is finished before the clock starts) and the bytes of one rank's buffer (each rank but 0 sends one per frame).
  double GetMilliseconds() const { return this->Milliseconds; }
  /// Of those, the milliseconds blocked in Receive: waiting for the ranks that send (their
  /// drawing, when they take longer than this rank) and the messages themselves.
  double GetWaitMilliseconds() const { return this->WaitMilliseconds; }
  unsigned long long GetBufferBytes() const { return this->BufferBytes; }

protected:
  vtkRefractionGBufferComposite();
  ~vtkRefractionGBufferComposite() override;

private:
  vtkRefractionGBufferComposite(const vtkRefractionGBufferComposite&) = delete;
  void operator=(const vtkRefractionGBufferComposite&) = delete;

  /// One target's pixels in the buffer.
  struct Plane
  {
    int Target = 0;
    unsigned int Format = 0;     // GL pixel format of the transfer
    unsigned int Type = 0;       // GL pixel type of the transfer
    unsigned int PixelBytes = 0; // bytes per pixel
    bool PackedDepthStencil = false;
    unsigned long long Offset = 0; // into the buffer
  };
  bool Describe(vtkRefractionTargets* targets, const Request& request);
  int Find(int target) const;
  void Merge(unsigned char* kept, const unsigned char* incoming, const Request& request);
  void FillBackground(const Request& request);
  void DepthKeys(const Plane& plane, const unsigned char* buffer, std::vector<float>& keys) const;

  std::vector<Plane> Planes;
  size_t PixelCount = 0;
  size_t Width = 0;
  std::vector<unsigned char> Kept;
  std::vector<unsigned char> Incoming;
  std::vector<unsigned char> Take;
  std::vector<float> KeptKeys;
  std::vector<float> IncomingKeys;
  double Milliseconds = 0.0;
  double WaitMilliseconds = 0.0;
  unsigned long long BufferBytes = 0;
};

#endif
