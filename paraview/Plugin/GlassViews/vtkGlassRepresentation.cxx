#include "vtkGlassRepresentation.h"

#include "vtkObjectFactory.h"
#include "vtkPVLODActor.h"
#include "vtkRefractionPass.h"

vtkStandardNewMacro(vtkGlassRepresentation);

vtkGlassRepresentation::vtkGlassRepresentation()
{
  this->MarkActor(this->IndexOfRefraction, this->Dispersion);
}

vtkGlassRepresentation::~vtkGlassRepresentation() = default;

bool vtkGlassRepresentation::MarkActor(double indexOfRefraction, double dispersion)
{
  if (!(dispersion >= 0.0) || !vtkRefractionPass::MakeGlass(this->Actor, indexOfRefraction))
  {
    return false;
  }
  if (dispersion == 0.0)
  {
    vtkRefractionPass::ClearDispersion(this->Actor);
    return true;
  }
  return vtkRefractionPass::SetDispersion(
    this->Actor, indexOfRefraction - dispersion, indexOfRefraction, indexOfRefraction + dispersion);
}

void vtkGlassRepresentation::SetIndexOfRefraction(double indexOfRefraction)
{
  if (indexOfRefraction == this->IndexOfRefraction)
  {
    return;
  }
  if (!this->MarkActor(indexOfRefraction, this->Dispersion))
  {
    vtkErrorMacro("index of refraction " << indexOfRefraction << " rejected (with dispersion "
                                         << this->Dispersion << "); keeping "
                                         << this->IndexOfRefraction);
    this->MarkActor(this->IndexOfRefraction, this->Dispersion);
    return;
  }
  this->IndexOfRefraction = indexOfRefraction;
  this->Modified();
}

void vtkGlassRepresentation::SetDispersion(double spread)
{
  if (spread == this->Dispersion)
  {
    return;
  }
  if (!this->MarkActor(this->IndexOfRefraction, spread))
  {
    vtkErrorMacro("dispersion " << spread << " rejected (index of refraction "
                                << this->IndexOfRefraction << "); keeping " << this->Dispersion);
    this->MarkActor(this->IndexOfRefraction, this->Dispersion);
    return;
  }
  this->Dispersion = spread;
  this->Modified();
}

void vtkGlassRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IndexOfRefraction: " << this->IndexOfRefraction << "\n";
  os << indent << "Dispersion: " << this->Dispersion << "\n";
}
