#include "vtkRefractionTranslucentStep.h"

#include "vtkDualDepthPeelingPass.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOrderIndependentTranslucentPass.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkTranslucentPass.h"
#include "vtk_glew.h"

vtkStandardNewMacro(vtkRefractionTranslucentStep);

//------------------------------------------------------------------------------
vtkRefractionTranslucentStep::vtkRefractionTranslucentStep() = default;
vtkRefractionTranslucentStep::~vtkRefractionTranslucentStep() = default;

//------------------------------------------------------------------------------
void vtkRefractionTranslucentStep::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Peeling: " << (this->Peeling ? this->Peeling->GetClassName() : "none")
     << "\n";
}

//------------------------------------------------------------------------------
void vtkRefractionTranslucentStep::Render(const vtkRenderState* s)
{
  // What vtkOpenGLRenderer::DeviceRenderTranslucentPolygonalGeometry does (VTK 9.1), with
  // the state's props instead of all of the renderer's; then the renderer's FXAA.
  // Only when a prop has translucent geometry, as the renderer (vtkRenderer::UpdateGeometry):
  // peeling and order-independent translucency clear and composite whole-window targets.
  this->NumberOfRenderedProps = 0;
  bool anyTranslucent = false;
  for (int i = 0; i < s->GetPropArrayCount() && !anyTranslucent; ++i)
  {
    anyTranslucent = s->GetPropArray()[i]->HasTranslucentPolygonalGeometry() != 0;
  }
  if (anyTranslucent)
  {
    vtkRenderPass* pass = this->TranslucentPass(s);
    pass->Render(s);
    this->NumberOfRenderedProps = pass->GetNumberOfRenderedProps();
  }
  // The renderer's FXAA comes next, before volumes and overlays (vtkRenderer::UpdateGeometry);
  // with a render pass set VTK skips it. Not in a multisampled framebuffer, whose samples
  // already smooth the edges: there VTK 9.1's FXAA copies from it and leaves
  // GL_INVALID_OPERATION (without the pass too).
  auto* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  if (!ren || !ren->GetUseFXAA() || s->GetFrameBuffer())
  {
    return;
  }
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  if (samples > 1)
  {
    return;
  }
  if (!this->FXAA)
  {
    this->FXAA = vtkSmartPointer<vtkOpenGLFXAAFilter>::New();
  }
  if (ren->GetFXAAOptions())
  {
    this->FXAA->UpdateConfiguration(ren->GetFXAAOptions());
  }
  this->FXAA->Execute(ren);
}

//------------------------------------------------------------------------------
vtkRenderPass* vtkRefractionTranslucentStep::TranslucentPass(const vtkRenderState* s)
{
  auto* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  if (s->GetFrameBuffer())
  {
    // Inside another pass's framebuffer (a vtkFramebufferPass, say): what a vtkRenderStepsPass
    // does there. Those passes' own targets are what VTK's peeling and order-independent
    // passes would have to match (a float colour target left GL_INVALID_OPERATION).
    if (!this->Unsorted)
    {
      this->Unsorted = vtkSmartPointer<vtkTranslucentPass>::New();
    }
    return this->Unsorted;
  }
  if (ren && ren->GetUseDepthPeeling())
  {
    if (!this->Peeling)
    {
      if (ren->IsDualDepthPeelingSupported())
      {
        this->Peeling = vtkSmartPointer<vtkDualDepthPeelingPass>::New();
      }
      else
      {
        this->Peeling = vtkSmartPointer<vtkDepthPeelingPass>::New();
      }
      vtkNew<vtkTranslucentPass> translucent;
      this->Peeling->SetTranslucentPass(translucent);
    }
    this->Peeling->SetMaximumNumberOfPeels(ren->GetMaximumNumberOfPeels());
    this->Peeling->SetOcclusionRatio(ren->GetOcclusionRatio());
    return this->Peeling;
  }
  if (!this->OrderIndependent)
  {
    this->OrderIndependent = vtkSmartPointer<vtkOrderIndependentTranslucentPass>::New();
    vtkNew<vtkTranslucentPass> translucent;
    this->OrderIndependent->SetTranslucentPass(translucent);
  }
  return this->OrderIndependent;
}

//------------------------------------------------------------------------------
void vtkRefractionTranslucentStep::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->Peeling)
  {
    this->Peeling->ReleaseGraphicsResources(w);
  }
  if (this->OrderIndependent)
  {
    this->OrderIndependent->ReleaseGraphicsResources(w);
  }
  if (this->Unsorted)
  {
    this->Unsorted->ReleaseGraphicsResources(w);
  }
  if (this->FXAA)
  {
    this->FXAA->ReleaseGraphicsResources();
  }
}
