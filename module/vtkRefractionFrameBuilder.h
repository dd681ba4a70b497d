/**
 * @class   vtkRefractionFrameBuilder
 * @brief   Describes a frame to the shading stage: camera, environment, background, materials.
 *
 * Each frame the pass asks for a vtkRefractionShadeStage::Frame; this class reads the camera's
 * matrices as VTK's shaders see them, the environment's frame and cube map, the background,
 * and takes the materials' and lights' figures, and keeps what the frame points to until the
 * next frame.
 */
#ifndef vtkRefractionFrameBuilder_h
#define vtkRefractionFrameBuilder_h

#include "vtkObject.h"
#include "vtkNew.h"                   // For members
#include "vtkRefractionShadeStage.h" // For Frame

class vtkMatrix4x4;
class vtkOpenGLRenderer;
class vtkRefractionLights;
class vtkRefractionMaterials;
class vtkTexture;

class vtkRefractionFrameBuilder : public vtkObject
{
public:
  static vtkRefractionFrameBuilder* New();
  vtkTypeMacro(vtkRefractionFrameBuilder, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The frame of the renderer's current camera and environment. `reporter` (the pass) says
   * once that an environment texture is no cube map. `rendererBackground`: without a cube map
   * the background is the environment (vtkRefractionPass::ENVIRONMENT_RENDERER).
   * `multiSampleSilhouette`: composite at the samples where the bound framebuffer has them.
   * The lights are read only where some glass shows highlights.
   */
  vtkRefractionShadeStage::Frame Build(vtkOpenGLRenderer* ren, vtkObject* reporter,
    bool rendererBackground, bool sceneRefraction, bool multiSampleSilhouette,
    vtkRefractionMaterials* materials, vtkRefractionLights* lights,
    const double* boundsDepthRange);

protected:
  vtkRefractionFrameBuilder();
  ~vtkRefractionFrameBuilder() override;

private:
  vtkRefractionFrameBuilder(const vtkRefractionFrameBuilder&) = delete;
  void operator=(const vtkRefractionFrameBuilder&) = delete;

  void UpdateCamera(vtkOpenGLRenderer* ren);
  // Whether the framebuffer bound for drawing stores floats (radiance, for a tone mapping pass
  // that follows) rather than display values.
  static bool DrawFramebufferHoldsRadiance();
  vtkTexture* GetCubeEnvironment(vtkOpenGLRenderer* ren, vtkObject* reporter);

  vtkNew<vtkMatrix4x4> ProjectionGL;
  vtkNew<vtkMatrix4x4> InverseProjectionGL;
  float ViewToWorld[9] = { 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f };
  float EnvironmentMatrix[9] = { 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f };
  bool Parallel = false;
  bool WarnedEnvironment = false;
};

#endif
