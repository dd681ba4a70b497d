/**
 * @class   vtkRefractionGeometryStage
 * @brief   Draws the glass props through VTK's own mappers into the glass G-buffer.
 *
 * The mapper-side part of vtkRefractionPass: it injects shaders/rfGeometryFS.glsl into the
 * mappers' shaders through VTK's //VTK:: tags (as vtkSSAOPass and vtkDualDepthPeelingPass
 * do) and draws the glass props for one of three stages: the front G-buffer (normal, depth,
 * material, ISR's d_N), the back-surface capture of DIR, or SSP's refraction mask. All three
 * share one program per mapper (a uniform selects), so switching stages rebuilds nothing.
 * GL state is set through vtkOpenGLState and restored after each stage.
 */
#ifndef vtkRefractionGeometryStage_h
#define vtkRefractionGeometryStage_h

#include "vtkOpenGLRenderPass.h"
#include "vtkNew.h"       // For members
#include "vtkRefractionPeelCount.h"   // For members
#include "vtkRefractionPieceSheets.h" // For members
#include "vtkRefractionProgramGuard.h" // For members
#include "vtkRefractionSHTransfer.h" // For members
#include "vtkRefractionSurfaceModel.h" // For members
#include "vtkWeakPointer.h" // For members

#include <map>    // For members
#include <string> // For members
#include <vector> // For members

class vtkMapper;
class vtkMatrix4x4;
class vtkOpenGLRenderer;
class vtkOpenGLState;
class vtkPolyData;
class vtkProp;
class vtkRefractionTargets;
class vtkTextureObject;

class vtkRefractionGeometryStage : public vtkOpenGLRenderPass
{
public:
  static vtkRefractionGeometryStage* New();
  vtkTypeMacro(vtkRefractionGeometryStage, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum StageType
  {
    STAGE_NONE = 0,
    STAGE_FRONT = 1,
    STAGE_BACK = 2,
    STAGE_MASK = 3,
    STAGE_PEEL = 4,
    STAGE_COMPOSITE = 5,
    STAGE_PEEL_DEPTHS = 6, ///< the k-buffer's first draw: the layers' depths (DrawPeelLayers)
    STAGE_PEEL_LAYERS = 7  ///< its second: the layers' normals and materials
  };

  /**
   * Settings of the next draws: the glass props (their position is their material index),
   * whether the G-buffer carries ISR's d_N, whether the back capture keeps the nearest
   * back-facing surface, whether layers are peeled, the camera's inverse projection (GL
   * layout) and projection type.
   */
  void Configure(const std::vector<vtkProp*>& glass, bool normalDistance, bool dataColour,
    bool backNearest, bool peel, bool shTransfer, vtkMatrix4x4* inverseProjection,
    bool parallel);

  /// The front G-buffer (FRONT_SURFACE, FRONT_COLOR, FRONT_AUX and FRONT_SH when configured,
  /// FRONT_DEPTH).
  void DrawFront(vtkOpenGLRenderer* ren, vtkRefractionTargets* targets);
  /// The back capture (BACK_SURFACE, BACK_Z).
  void DrawBack(vtkOpenGLRenderer* ren, vtkRefractionTargets* targets);
  /// PEEL's layer `layer` (1..7: PEEL_1..PEEL_7), peeled behind the layer before it (layer
  /// 0 is FRONT_SURFACE, drawn first) of `layers` (K): the nearest surface behind it, except
  /// with K = 2, where the one layer behind the front is the furthest surface, as DIR's back
  /// capture (the two-interface model: the ray leaves where the glass ends, not at the next
  /// surface of a glass holding more). Returns whether any fragment of the glass was kept
  /// (an occlusion query, read at once): an empty layer leaves nothing for the ones behind it.
  /// With `askWhetherEmpty` false no query is made (true is returned): across MPI ranks every
  /// layer is drawn anyway, and the read would wait for each layer for nothing. With
  /// `behind`, also whether a layer can follow this one: false where no pixel kept two
  /// fragments or more (vtkRefractionPeelCount), so that the next layer would be empty.
  bool DrawPeel(vtkOpenGLRenderer* ren, vtkRefractionTargets* targets, int layer, int layers,
    bool askWhetherEmpty = true, bool* behind = nullptr);
  /**
   * PEEL's layers 1 .. K - 1 behind the front (drawn first), and how many of the K layers
   * hold glass anywhere (the front counts). Peeled one draw per layer (DrawPeel, stopping,
   * when `stopAtEmpty`, at the first empty one or after the first behind which no pixel holds
   * another surface), or, configured with SetPeelKBuffer, in two draws
   * whatever K: the depths sorted into PEEL_SLOTS with image atomics, then each layer's
   * texels. The same texels either way.
   */
  int DrawPeelLayers(
    vtkOpenGLRenderer* ren, vtkRefractionTargets* targets, int layers, bool stopAtEmpty);
  /// The draws of the glass the last DrawPeelLayers made (one per layer peeled; the
  /// k-buffer's two).
  int GetPeelDraws() const { return this->PeelDraws; }
  /// Whether the last DrawPeelLayers drew each layer's one facing only: one glass prop whose
  /// surfaces every sight line enters and leaves by turns
  /// (vtkRefractionSurfaceModel::Alternates), so that layer k behind the front is a surface
  /// the ray leaves through when k is odd (or the furthest), one it enters when k is even.
  bool GetPeelByFacing() const { return this->PeelByFacing; }
  /// Whether the last DrawPeelLayers' glass could be peeled one facing at a time, whichever
  /// capture drew it (the k-buffer keeps both facings): what AUTO chooses the capture by.
  bool GetPeelFacingPossible() const { return this->PeelFacingPossible; }
  /// Whether this context can sort `layers` layers of `height` rows with image atomics (GL
  /// 4.2's image load/store and 3.3's float bits, or their ARB extensions), with K image
  /// units for the fragment shader and a texture (K - 1) times the height, plus one row.
  static bool SupportsPeelKBuffer(vtkOpenGLRenderWindow* renWin, int height, int layers);
  /// K where DrawPeelLayers sorts the layers with image atomics (3 and more, where
  /// SupportsPeelKBuffer; PEEL_SLOTS must then be allocated), 0 where it peels them one draw
  /// per layer. Takes effect at Configure.
  void SetPeelKBuffer(int layers) { this->PeelKBuffer = layers; }
  /// SSP's refraction mask into the alpha of the framebuffer bound now.
  void DrawMask(vtkOpenGLRenderer* ren);
  /// The glass props into the framebuffer bound now (the renderer's viewport) for `stage`,
  /// with the GL state the caller set.
  void DrawOnScreen(vtkOpenGLRenderer* ren, int stage);
  /// STAGE_COMPOSITE's inputs: the texture units of FRONT_SURFACE and GLASS_COLOR, and
  /// whether GLASS_COLOR holds the pixels' corners (anti-aliasing). The corners are built into
  /// the program (RF_COMPOSITE_CORNERS): as a uniform, llvmpipe fetched the four corners for
  /// every fragment, also without anti-aliasing.
  void SetCompositeInputs(int surfaceUnit, int colourUnit, bool corners)
  {
    this->CompositeInputs[0] = surfaceUnit;
    this->CompositeInputs[1] = colourUnit;
    if (this->CompositeInputs[2] != (corners ? 1 : 0))
    {
      this->CompositeInputs[2] = corners ? 1 : 0;
      this->DefinesTime.Modified();
    }
  }

  /// Props drawn by the last draw.
  int GetNumberOfDrawnProps() const { return this->NumberOfRenderedProps; }

  /// Per glass prop, the material of its thin-sheet pieces, or -1
  /// (vtkRefractionMaterials::GetSheetPieceMaterial); set before Configure.
  void SetSheetPieceMaterials(const std::vector<int>& materials)
  {
    this->SheetPieceMaterial = materials;
  }
  /// Compositing PEEL's layers across ranks: the front layer's material carries the sign the
  /// peeled layers' do (+ where the outward side faces the viewer), since a rank's front
  /// surface may become a deeper layer of the whole; vtkRefractionGBufferComposite removes the
  /// sign from the merged front layer. Takes effect at the next Configure.
  void SetSignedFront(bool signedFront) { this->SignedFront = signedFront; }
  /// Whether the frame draws STAGE_COMPOSITE (vtkRefractionSampleComposite): only then is the
  /// composite's code compiled into the mapper's program (llvmpipe runs both sides of a
  /// branch, so it would cost every G-buffer draw its fetches). Takes effect at the next draw.
  void SetSampleComposite(bool sampleComposite) { this->SampleComposite = sampleComposite; }
  /// Whether the composite's code is compiled in only for the composite's draw (two programs
  /// a frame, a shader-source rebuild at each switch) instead of into every draw of a frame
  /// that draws it (vtkRefractionPass::SetCompositeProgram). A composite program of its own
  /// holds the composite's code alone (RF_COMPOSITE_ONLY), so a change rebuilds the program.
  void SetSeparateCompositeProgram(bool separate)
  {
    if (separate != this->SeparateCompositeProgram)
    {
      this->SeparateCompositeProgram = separate;
      this->DefinesTime.Modified();
    }
  }
  /// The glass meshes' surface model (solid or thin sheet, per connected piece).
  vtkRefractionSurfaceModel* GetSurfaceModel() { return this->SurfaceModel; }

  void Render(const vtkRenderState* s) override;
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* vao = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override;
  void ReleaseGraphicsResources(vtkWindow* w) override;
  /// The SH method's smoothing of the weights (vtkRefractionPass::SetSHSmoothing).
  void SetSHSmoothing(double width) { this->SHTransfer->SetSmoothing(width); }
  /// Bytes of the SH method's coefficient textures.
  unsigned long long GetSHBytes() const { return this->SHTransfer->GetBytes(); }

protected:
  vtkRefractionGeometryStage();
  ~vtkRefractionGeometryStage() override;

private:
  vtkRefractionGeometryStage(const vtkRefractionGeometryStage&) = delete;
  void operator=(const vtkRefractionGeometryStage&) = delete;

  /// With `anyKeptQuery` (not 0), the draw inside that GL_ANY_SAMPLES_PASSED query. With
  /// `keptTwice`, the draw's kept fragments are counted in the depth target's stencil and it
  /// says whether any pixel kept two or more (vtkRefractionPeelCount; true where they could
  /// not be counted).
  void DrawIntoTargets(vtkOpenGLRenderer* ren, vtkRefractionTargets* targets,
    const std::vector<int>& colours, int depth, double clearDepth, unsigned int depthFunc,
    int stage, unsigned int anyKeptQuery = 0, bool* keptTwice = nullptr);
  void DrawProps(vtkOpenGLRenderer* ren, int stage);
  /// The k-buffer's two draws (DrawPeelLayers); returns the layers found.
  int DrawPeelKBuffer(vtkOpenGLRenderer* ren, vtkRefractionTargets* targets, int layers);
  /// Binds PEEL_SLOTS and the layers to image units 0 .. K - 1 (nullptr targets: unbinds).
  void BindPeelImages(vtkRefractionTargets* targets, int layers);
  /// Whether every mesh of the prop has ISR's d_N array.
  bool HasNormalDistance(vtkProp* prop);
  /// Whether the prop's outward side is the GL front face on screen (winding and mirroring).
  bool IsOutwardFront(vtkProp* prop);
  void CullHiddenFaces(vtkProp* prop);
  void MapNormalDistance(vtkProp* prop);
  /// Our code into the glass mapper's finished fragment shader; false where its tags are
  /// missing.
  bool ReplaceGlassShaderValues(std::string& fragmentShader);

  std::vector<vtkProp*> Glass;
  std::map<vtkProp*, int> MaterialIndex;
  std::vector<int> SheetPieceMaterial;
  std::map<vtkProp*, int> SheetMaterialIndex; ///< props whose sheet pieces are told apart
  vtkNew<vtkRefractionPieceSheets> PieceSheets;
  bool UsePieceSheets = false;
  vtkNew<vtkRefractionSurfaceModel> SurfaceModel;
  vtkOpenGLState* State = nullptr;
  vtkOpenGLRenderer* Renderer = nullptr; ///< during a draw
  std::vector<vtkWeakPointer<vtkMapper>> NormalDistanceMappers;
  vtkNew<vtkRefractionSHTransfer> SHTransfer;
  bool UseSHTransfer = false;
  bool NormalDistance = false;
  bool DataColour = false;
  bool BackNearest = false;
  bool Peel = false;
  int PeelKBuffer = 0;           ///< asked for (SetPeelKBuffer)
  int PeelKBufferConfigured = 0; ///< compiled into the mappers' program (Configure)
  bool SignedFront = false;
  bool SampleComposite = false;
  bool SeparateCompositeProgram = false;
  bool CompositeProgram = false; ///< the mapper's program holds the composite (DrawProps)
  vtkTextureObject* PeelPrevious = nullptr; ///< the layer the one being drawn peels behind
  unsigned int PeelQuery = 0;               ///< DrawPeel's occlusion query (0: none yet)
  vtkNew<vtkRefractionPeelCount> PeelCount; ///< whether a layer can follow (DrawPeel)
  int PeelDraws = 0;                        ///< GetPeelDraws
  bool PeelByFacing = false;                ///< GetPeelByFacing
  bool PeelFacingPossible = false;          ///< GetPeelFacingPossible
  int PeelLayer = 0;         ///< the layer DrawPeel draws (0: none)
  bool PeelFurthest = false; ///< it keeps the furthest surface behind the one before
  bool Parallel = false;
  vtkNew<vtkMatrix4x4> InverseProjection;
  int Stage = STAGE_NONE;
  int CompositeInputs[3] = { 0, 0, 0 };
  int Width = 0;
  int Height = 0;
  int Origin[2] = { 0, 0 };
  std::string Defines;
  vtkTimeStamp DefinesTime;
  vtkNew<vtkRefractionProgramGuard> ProgramGuard;
  /// Props whose glass program did not build, reported once until it builds again.
  std::vector<vtkWeakPointer<vtkProp>> BuildFailures;
};

#endif
