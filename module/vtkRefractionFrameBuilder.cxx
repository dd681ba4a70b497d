#include "vtkRefractionFrameBuilder.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLTexture.h"
#include "vtkRefractionLights.h"
#include "vtkRefractionMaterials.h"
#include "vtkRefractionSampleComposite.h"
#include "vtk_glew.h"

#include <limits>

vtkStandardNewMacro(vtkRefractionFrameBuilder);

//------------------------------------------------------------------------------
vtkRefractionFrameBuilder::vtkRefractionFrameBuilder() = default;
vtkRefractionFrameBuilder::~vtkRefractionFrameBuilder() = default;

//------------------------------------------------------------------------------
void vtkRefractionFrameBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Parallel: " << this->Parallel << "\n";
}

//------------------------------------------------------------------------------
vtkRefractionShadeStage::Frame vtkRefractionFrameBuilder::Build(vtkOpenGLRenderer* ren,
  vtkObject* reporter, bool rendererBackground, bool sceneRefraction, bool multiSampleSilhouette,
  vtkRefractionMaterials* materials, vtkRefractionLights* lights, const double* boundsDepthRange)
{
  this->UpdateCamera(ren);
  vtkTexture* cube = this->GetCubeEnvironment(ren, reporter);
  vtkRefractionShadeStage::Frame frame;
  frame.Projection = this->ProjectionGL;
  frame.InverseProjection = this->InverseProjectionGL;
  frame.ViewToWorld = this->ViewToWorld;
  frame.EnvironmentMatrix = this->EnvironmentMatrix;
  frame.Parallel = this->Parallel;
  frame.EnvironmentCube = cube;
  frame.EnvironmentBackground = rendererBackground && !cube;
  ren->GetBackground(frame.Background);
  if (ren->GetGradientBackground())
  {
    ren->GetBackground2(frame.Background2);
  }
  else
  {
    ren->GetBackground(frame.Background2);
  }
  frame.SceneRefraction = sceneRefraction;
  // The framebuffer the scene is drawn into (bound now): multisampled, the glass goes in at
  // its samples.
  frame.SampleComposite =
    multiSampleSilhouette && vtkRefractionSampleComposite::GetDrawFramebufferSamples() > 1;
  frame.SampleCeiling = vtkRefractionFrameBuilder::DrawFramebufferHoldsRadiance()
    ? std::numeric_limits<float>::max()
    : 1.f;
  frame.AbsorptionDistance = materials->GetAbsorptionDistance();
  frame.GlassDiagonal = materials->GetLargestDiagonal();
  frame.GlassExtent = materials->GetExtentDiagonal();
  if (materials->GetDispersion())
  {
    frame.RedIndex = &materials->GetRedIndex();
    frame.BlueIndex = &materials->GetBlueIndex();
  }
  frame.BoundsDepthRange = boundsDepthRange;
  if (materials->GetHasHighlights())
  {
    lights->Update(ren);
    frame.Highlights = &materials->GetHighlights();
    frame.Lights = lights;
  }
  return frame;
}

//------------------------------------------------------------------------------
bool vtkRefractionFrameBuilder::DrawFramebufferHoldsRadiance()
{
  GLint bound = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
  if (bound == 0)
  {
    return false; // a window's own buffers are fixed point
  }
  GLint drawBuffer = GL_NONE;
  glGetIntegerv(GL_DRAW_BUFFER0, &drawBuffer);
  if (drawBuffer == GL_NONE)
  {
    return false;
  }
  // The component type of an attachment point with nothing attached is an invalid query.
  GLint object = GL_NONE;
  glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, static_cast<GLenum>(drawBuffer),
    GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &object);
  if (object == GL_NONE)
  {
    return false;
  }
  GLint type = GL_NONE;
  glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, static_cast<GLenum>(drawBuffer),
    GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
  return type == GL_FLOAT;
}

//------------------------------------------------------------------------------
vtkTexture* vtkRefractionFrameBuilder::GetCubeEnvironment(
  vtkOpenGLRenderer* ren, vtkObject* reporter)
{
  vtkTexture* environment = ren->GetEnvironmentTexture();
  const bool cube = environment && environment->GetCubeMap() &&
    vtkOpenGLTexture::SafeDownCast(environment) != nullptr;
  if (environment && !cube && !this->WarnedEnvironment)
  {
    vtkWarningWithObjectMacro(reporter,
      "The renderer's environment texture is not an OpenGL cube map (wrap a "
      "lat-long image in vtkEquirectangularToCubeMapTexture); using the built-in "
      "environment.");
  }
  this->WarnedEnvironment = environment && !cube;
  return cube ? environment : nullptr;
}

//------------------------------------------------------------------------------
void vtkRefractionFrameBuilder::UpdateCamera(vtkOpenGLRenderer* ren)
{
  vtkOpenGLCamera* camera = vtkOpenGLCamera::SafeDownCast(ren->GetActiveCamera());
  vtkMatrix4x4* wcvc = nullptr;
  vtkMatrix3x3* normalMatrix = nullptr;
  vtkMatrix4x4* vcdc = nullptr;
  vtkMatrix4x4* wcdc = nullptr;
  camera->GetKeyMatrices(ren, wcvc, normalMatrix, vcdc, wcdc);
  // VTK's key matrices are already laid out for glUniformMatrix: pass them as VTK does.
  this->ProjectionGL->DeepCopy(vcdc);
  vtkMatrix4x4::Invert(vcdc, this->InverseProjectionGL);
  // Row-major R (world to view) read as column-major by GLSL is R^T, view to world.
  vtkMatrix4x4* view = camera->GetViewTransformMatrix();
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      this->ViewToWorld[r * 3 + c] = static_cast<float>(view->GetElement(r, c));
    }
  }
  // The environment's frame, laid out as vtkOpenGLRenderer lays out envMatrix.
  double up[3];
  double right[3];
  double front[3];
  ren->GetEnvironmentUp(up);
  ren->GetEnvironmentRight(right);
  vtkMath::Cross(right, up, front);
  for (int i = 0; i < 3; ++i)
  {
    this->EnvironmentMatrix[i * 3 + 0] = static_cast<float>(right[i]);
    this->EnvironmentMatrix[i * 3 + 1] = static_cast<float>(up[i]);
    this->EnvironmentMatrix[i * 3 + 2] = static_cast<float>(front[i]);
  }
  this->Parallel = camera->GetParallelProjection() != 0;
}
