#include "vtkRefractionLights.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"

#include <cmath>

vtkStandardNewMacro(vtkRefractionLights);

//------------------------------------------------------------------------------
void vtkRefractionLights::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Lights: " << this->GetNumberOfLights() << "\n";
}

//------------------------------------------------------------------------------
void vtkRefractionLights::Update(vtkRenderer* ren)
{
  this->Positions.clear();
  this->Colours.clear();
  vtkCamera* camera = ren ? ren->GetActiveCamera() : nullptr;
  vtkLightCollection* lights = ren ? ren->GetLights() : nullptr;
  if (!camera || !lights)
  {
    return;
  }
  vtkMatrix4x4* view = camera->GetViewTransformMatrix(); // world to view
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch() || light->GetIntensity() <= 0.0 ||
      this->GetNumberOfLights() >= MaximumLights)
    {
      continue;
    }
    double position[3];
    double focal[3];
    light->GetTransformedPosition(position);
    light->GetTransformedFocalPoint(focal);
    const bool positional = light->GetPositional() != 0;
    double world[4] = { position[0] - focal[0], position[1] - focal[1], position[2] - focal[2],
      0.0 };
    if (positional)
    {
      world[0] = position[0];
      world[1] = position[1];
      world[2] = position[2];
      world[3] = 1.0;
    }
    else if (!(vtkMath::Normalize(world) > 0.0))
    {
      continue; // no direction
    }
    double viewed[4];
    view->MultiplyPoint(world, viewed);
    for (int k = 0; k < 3; ++k)
    {
      this->Positions.push_back(static_cast<float>(viewed[k]));
    }
    this->Positions.push_back(positional ? 1.f : 0.f);
    double colour[3];
    light->GetDiffuseColor(colour);
    for (double c : colour)
    {
      this->Colours.push_back(static_cast<float>(c * light->GetIntensity()));
    }
  }
}
