#include "vtkRefractionMethod.h"

#include "vtkRefractionMethodDIR.h"
#include "vtkRefractionMethodISR.h"
#include "vtkRefractionMethodPEEL.h"
#include "vtkRefractionMethodSH.h"
#include "vtkRefractionMethodSIR.h"
#include "vtkRefractionMethodSSP.h"
#include "vtkRefractionPass.h"
#include "vtkRefractionTargets.h"

//------------------------------------------------------------------------------
vtkSmartPointer<vtkRefractionMethod> vtkRefractionMethod::Create(int method)
{
  switch (method)
  {
    case vtkRefractionPass::SIR:
      return vtkSmartPointer<vtkRefractionMethodSIR>::New();
    case vtkRefractionPass::DIR:
      return vtkSmartPointer<vtkRefractionMethodDIR>::New();
    case vtkRefractionPass::ISR:
      return vtkSmartPointer<vtkRefractionMethodISR>::New();
    case vtkRefractionPass::SSP:
      return vtkSmartPointer<vtkRefractionMethodSSP>::New();
    case vtkRefractionPass::PEEL:
      return vtkSmartPointer<vtkRefractionMethodPEEL>::New();
    case vtkRefractionPass::SH:
      return vtkSmartPointer<vtkRefractionMethodSH>::New();
    default:
      return nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkRefractionMethod::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Name: " << this->GetName() << "\n";
}

//------------------------------------------------------------------------------
void vtkRefractionMethod::AddTargets(std::vector<bool>& wanted, vtkRefractionPass* settings) const
{
  wanted.assign(vtkRefractionTargets::TARGET_COUNT, false);
  wanted[vtkRefractionTargets::FRONT_SURFACE] = true;
  wanted[vtkRefractionTargets::FRONT_DEPTH] = true;
  if (this->NeedsNormalDistance())
  {
    wanted[vtkRefractionTargets::FRONT_AUX] = true;
  }
  if (this->NeedsBackSurface())
  {
    wanted[vtkRefractionTargets::BACK_SURFACE] = true;
    wanted[vtkRefractionTargets::BACK_Z] = true;
  }
  if (this->NeedsSceneColor())
  {
    wanted[vtkRefractionTargets::SCENE_COLOR] = true;
  }
  const int layers = this->GetPeelLayers(settings);
  for (int layer = 1; layer < layers; ++layer)
  {
    wanted[vtkRefractionTargets::PEEL_1 + layer - 1] = true;
  }
  wanted[vtkRefractionTargets::PEEL_Z] = layers > 1;
  wanted[vtkRefractionTargets::PEEL_DEPTHS_A] = layers > 1;
  wanted[vtkRefractionTargets::PEEL_DEPTHS_B] = layers > 4;
  wanted[vtkRefractionTargets::PEEL_STACK] = layers > 1;
  wanted[vtkRefractionTargets::FRONT_SH] = this->NeedsSHTransfer();
}

//------------------------------------------------------------------------------
void vtkRefractionMethod::AppendDefines(std::ostream& defines, vtkRefractionPass*) const
{
  defines << "#define RF_METHOD_" << this->GetName() << "\n";
}

//------------------------------------------------------------------------------
void vtkRefractionMethod::SetUniforms(vtkShaderProgram*, vtkRefractionPass*, const double*) const
{
}
