#include "vtkRefractionMethodISR.h"

#include "vtkObjectFactory.h"

#include "rfShaders.h"

vtkStandardNewMacro(vtkRefractionMethodISR);

//------------------------------------------------------------------------------
std::string vtkRefractionMethodISR::GetShaderSource() const
{
  return std::string(rfBackSurfaceSource) + rfMethodISRSource;
}
