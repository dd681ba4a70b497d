#include "vtkGlassRepresentation.h"

#include "vtkObjectFactory.h"
#include "vtkPVLODActor.h"
#include "vtkRefractionPass.h"

vtkStandardNewMacro(vtkGlassRepresentation);

vtkGlassRepresentation::vtkGlassRepresentation()
{
  vtkRefractionPass::MakeGlass(this->Actor, this->IndexOfRefraction);
}

vtkGlassRepresentation::~vtkGlassRepresentation() = default;

void vtkGlassRepresentation::SetIndexOfRefraction(double indexOfRefraction)
{
  if (indexOfRefraction == this->IndexOfRefraction)
  {
    return;
  }
  if (!vtkRefractionPass::MakeGlass(this->Actor, indexOfRefraction))
  {
    vtkErrorMacro("index of refraction " << indexOfRefraction << " rejected; keeping "
                                         << this->IndexOfRefraction);
    vtkRefractionPass::MakeGlass(this->Actor, this->IndexOfRefraction);
    return;
  }
  this->IndexOfRefraction = indexOfRefraction;
  this->Modified();
}

void vtkGlassRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IndexOfRefraction: " << this->IndexOfRefraction << "\n";
}
