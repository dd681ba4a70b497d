#include "vtkRefractionMethodSH.h"

#include "vtkObjectFactory.h"

#include "rfShaders.h"

vtkStandardNewMacro(vtkRefractionMethodSH);

//------------------------------------------------------------------------------
std::string vtkRefractionMethodSH::GetShaderSource() const
{
  return rfMethodSHSource;
}
