/**
 * @class   vtkGlassRenderView
 * @brief   ParaView's render view drawing through vtkRefractionPass.
 *
 * The pass is the geometry pass of the view's synchronized renderers (set again before each
 * local render, should the view have replaced it); representations of type "Glass"
 * (vtkGlassRepresentation) are drawn as refractive glass, every other one as in a plain
 * render view. What ParaView's own default pass gets from the renderer is given to the
 * pass's delegate before each render: SSAO (a vtkSSAOPass as its opaque step, with the
 * renderer's radius, bias, kernel and blur) and depth peeling of translucent geometry (a
 * vtkDualDepthPeelingPass) and FXAA (the pass inside a vtkOpenGLFXAAPass, unless tone mapping
 * puts ParaView's own FXAA pass around it); tone mapping and the orientation axes are passes
 * and renderers around this one and work as in the Render View.
 *
 * ParaView 5.11 gives a representation no way to add a render pass to the ordinary Render
 * View (vtkPVSynchronizedRenderer owns and rebuilds the view's pass chain), hence this view.
 *
 * On several MPI ranks, on the frames ParaView composites across them (its synchronized
 * renderers enabled: sort-last with IceT), the pass gets a vtkGlassRankExchange: the ranks'
 * G-buffers are composited and rank 0 shades the whole glass, so the picture does not depend
 * on how the data are distributed. The renderer's background, which IceT draws each rank
 * without, is given to the pass for what the glass refracts.
 */
#ifndef vtkGlassRenderView_h
#define vtkGlassRenderView_h

#include "RefractionGlassViewsModule.h" // For export macro
#include "vtkPVRenderView.h"
#include "vtkSmartPointer.h" // For members

class vtkGlassBoundsProp;
class vtkGlassRankExchange;
class vtkRefractionPass;
class vtkSSAOPass;
class vtkDualDepthPeelingPass;
class vtkOpenGLFXAAPass;

class REFRACTIONGLASSVIEWS_EXPORT vtkGlassRenderView : public vtkPVRenderView
{
public:
  static vtkGlassRenderView* New();
  vtkTypeMacro(vtkGlassRenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The pass's method: vtkRefractionPass::SIR (0), DIR (1, default), ISR (2), SSP (3),
  /// PEEL (4).
  void SetGlassMethod(int method);
  int GetGlassMethod();
  ///@}

  ///@{
  /// The pass's settings (see vtkRefractionPass): EnvironmentMode, SceneRefraction,
  /// DataColour, AbsorptionDistance, AntiAliasing, CoarseShading, PeelLayers, PeelCapture,
  /// TIRBounces, ExitReflection and SmoothInternalReflections.
  void SetGlassEnvironment(int mode);
  int GetGlassEnvironment();
  void SetGlassSceneRefraction(int on);
  int GetGlassSceneRefraction();
  void SetGlassTintFromColours(int on);
  int GetGlassTintFromColours();
  void SetGlassAbsorptionDistance(double distance);
  double GetGlassAbsorptionDistance();
  void SetGlassAntiAliasing(int on);
  int GetGlassAntiAliasing();
  void SetGlassCoarseShading(int on);
  int GetGlassCoarseShading();
  void SetGlassLayers(int layers);
  int GetGlassLayers();
  void SetGlassPeelCapture(int mode);
  int GetGlassPeelCapture();
  void SetGlassTIRBounces(int bounces);
  int GetGlassTIRBounces();
  void SetGlassExitReflection(int on);
  int GetGlassExitReflection();
  void SetGlassSmoothInternalReflections(int on);
  int GetGlassSmoothInternalReflections();
  ///@}

  /// Glass props the pass drew in the last render (for tests).
  int GetNumberOfGlassProps();

  /// Bytes of the GPU render targets the pass holds for the last render's method
  /// (vtkRefractionPass::GetTextureBytes).
  double GetGlassTextureBytes();

  /// The pass itself.
  vtkRefractionPass* GetGlassPass();

  ///@{
  /// Across MPI ranks (pvbatch or pvserver on several ranks), the last frame's G-buffer
  /// compositing on this rank: milliseconds, bytes of one rank's buffers (each rank but 0
  /// sends one per frame), and the number of ranks it composited (1: none).
  double GetGlassCompositeMilliseconds();
  double GetGlassCompositeWaitMilliseconds();
  /// Composite across ranks (default on); off, each rank refracts its own piece only.
  void SetGlassAcrossRanks(int on);
  int GetGlassAcrossRanks();
  double GetGlassCompositeBufferBytes();
  int GetGlassCompositeRanks();
  ///@}

protected:
  vtkGlassRenderView();
  ~vtkGlassRenderView() override;

  void AboutToRenderOnLocalProcess(bool interactive) override;

  /// Give the pass a delegate that draws the rest of the scene as the renderer's own
  /// settings ask (SSAO, depth peeling).
  void ConfigureDelegate();

  vtkSmartPointer<vtkRefractionPass> GlassPass;
  vtkSmartPointer<vtkSSAOPass> SSAOPass;
  vtkSmartPointer<vtkDualDepthPeelingPass> PeelingPass;
  vtkSmartPointer<vtkOpenGLFXAAPass> FXAAPass;
  vtkSmartPointer<vtkOpenGLFXAAPass> CompositedFXAAPass; ///< IceT's image pass, across ranks
  vtkSmartPointer<vtkGlassRankExchange> RankExchange;
  vtkSmartPointer<vtkGlassBoundsProp> BoundsProp;
  int CompositeRanks = 1;
  bool AcrossRanks = true;
  int DelegateSSAO = -1;
  int DelegatePeeling = -1;

private:
  vtkGlassRenderView(const vtkGlassRenderView&) = delete;
  void operator=(const vtkGlassRenderView&) = delete;
};

#endif
