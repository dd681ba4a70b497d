#include "vtkRefractionMethodSIR.h"

#include "vtkObjectFactory.h"

#include "rfShaders.h"

vtkStandardNewMacro(vtkRefractionMethodSIR);

//------------------------------------------------------------------------------
std::string vtkRefractionMethodSIR::GetShaderSource() const
{
  return rfMethodSIRSource;
}
