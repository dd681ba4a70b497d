#include "vtkRefractionMethodSSP.h"

#include "vtkObjectFactory.h"
#include "vtkRefractionPass.h"
#include "vtkShaderProgram.h"

#include "rfShaders.h"

vtkStandardNewMacro(vtkRefractionMethodSSP);

//------------------------------------------------------------------------------
std::string vtkRefractionMethodSSP::GetShaderSource() const
{
  return rfMethodSSPSource;
}

//------------------------------------------------------------------------------
void vtkRefractionMethodSSP::SetUniforms(
  vtkShaderProgram* program, vtkRefractionPass* settings, const double*) const
{
  program->SetUniformf("rfSSPStrength", static_cast<float>(settings->GetSSPStrength()));
  program->SetUniformf("rfSSPFresnelBias", static_cast<float>(settings->GetSSPFresnelBias()));
  program->SetUniformf("rfSSPFresnelPower", static_cast<float>(settings->GetSSPFresnelPower()));
  program->SetUniformf(
    "rfChromaticAberration", static_cast<float>(settings->GetChromaticAberration()));
  program->SetUniformi("rfSSPMask", settings->GetSSPRefractionMask() ? 1 : 0);
}
