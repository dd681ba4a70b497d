#include "vtkRefractionOpaqueStep.h"

#include "vtkObjectFactory.h"
#include "vtkRefractionPass.h"

vtkStandardNewMacro(vtkRefractionOpaqueStep);

//------------------------------------------------------------------------------
void vtkRefractionOpaqueStep::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Owner: " << this->Owner << "\n";
  os << indent << "Original: " << this->Original.Get() << "\n";
}

//------------------------------------------------------------------------------
void vtkRefractionOpaqueStep::Render(const vtkRenderState* s)
{
  if (this->Owner)
  {
    this->NumberOfRenderedProps = this->Owner->RenderOpaqueAndGlass(s, this->Original);
  }
  else if (this->Original)
  {
    this->Original->Render(s);
    this->NumberOfRenderedProps = this->Original->GetNumberOfRenderedProps();
  }
}

//------------------------------------------------------------------------------
void vtkRefractionOpaqueStep::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->Original)
  {
    this->Original->ReleaseGraphicsResources(w);
  }
}
