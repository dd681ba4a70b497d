#include "vtkRefractionMethodPEEL.h"

#include "vtkObjectFactory.h"
#include "vtkRefractionPass.h"
#include "vtkShaderProgram.h"

#include "rfShaders.h"

vtkStandardNewMacro(vtkRefractionMethodPEEL);

//------------------------------------------------------------------------------
int vtkRefractionMethodPEEL::GetPeelLayers(vtkRefractionPass* settings) const
{
  return settings->GetPeelLayers();
}

//------------------------------------------------------------------------------
void vtkRefractionMethodPEEL::AppendDefines(std::ostream& defines, vtkRefractionPass* settings) const
{
  this->Superclass::AppendDefines(defines, settings);
  defines << "#define RF_PEEL_LAYERS " << settings->GetPeelLayers() << "\n"
          << "#define RF_PEEL_BOUNCES " << settings->GetTIRBounces() << "\n";
}

//------------------------------------------------------------------------------
std::string vtkRefractionMethodPEEL::GetShaderSource() const
{
  return rfMethodPEELSource;
}

//------------------------------------------------------------------------------
void vtkRefractionMethodPEEL::SetUniforms(
  vtkShaderProgram* program, vtkRefractionPass* settings, const double boundsDepthRange[2]) const
{
  if (program->IsUniformUsed("rfPeelLayersFound"))
  {
    program->SetUniformi("rfPeelLayersFound", settings->GetPeelLayersFound());
  }
  if (program->IsUniformUsed("rfGlassDepthRange"))
  {
    const float range[2] = { static_cast<float>(boundsDepthRange[0]),
      static_cast<float>(boundsDepthRange[1]) };
    program->SetUniform2f("rfGlassDepthRange", range);
  }
}
