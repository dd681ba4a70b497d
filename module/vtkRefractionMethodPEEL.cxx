#include "vtkRefractionMethodPEEL.h"

#include "vtkObjectFactory.h"
#include "vtkRefractionPass.h"

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
