#include "vtkGlassBoundsProp.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkGlassBoundsProp);

vtkGlassBoundsProp::vtkGlassBoundsProp()
{
  // Not pickable, not a part of what the camera resets to beyond the data's own bounds.
  this->PickableOff();
}

vtkGlassBoundsProp::~vtkGlassBoundsProp() = default;

void vtkGlassBoundsProp::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PropBounds: " << this->PropBounds[0] << " " << this->PropBounds[1] << " "
     << this->PropBounds[2] << " " << this->PropBounds[3] << " " << this->PropBounds[4] << " "
     << this->PropBounds[5] << "\n";
}
