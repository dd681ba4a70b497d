// vtkRefractionPass's published per-prop glass API (MakeGlass, the keys, dispersion, surface
// model): the settings live on the prop's keys, written and read by vtkRefractionGlassKeys,
// which the stages include instead of the pass; these functions forward there. The pass's
// class, in a file of its own so that vtkRefractionPass.cxx stays the ordering of the stages.
#include "vtkRefractionPass.h"

#include "vtkRefractionGlassKeys.h"

//------------------------------------------------------------------------------
// The glass settings live on the prop's keys, written and read by vtkRefractionGlassKeys (which
// the stages include instead of this class); the published API forwards there.
static_assert(static_cast<int>(vtkRefractionPass::SURFACE_AUTO) ==
      static_cast<int>(vtkRefractionGlassKeys::SURFACE_AUTO) &&
    static_cast<int>(vtkRefractionPass::SURFACE_SOLID) ==
      static_cast<int>(vtkRefractionGlassKeys::SURFACE_SOLID) &&
    static_cast<int>(vtkRefractionPass::SURFACE_THIN_SHEET) ==
      static_cast<int>(vtkRefractionGlassKeys::SURFACE_THIN_SHEET),
  "vtkRefractionPass::SurfaceModelType and vtkRefractionGlassKeys::SurfaceModelType differ");
static_assert(
  vtkRefractionPass::DefaultGlassSpecular == vtkRefractionGlassKeys::DefaultGlassSpecular &&
    vtkRefractionPass::DefaultGlassSpecularPower ==
      vtkRefractionGlassKeys::DefaultGlassSpecularPower,
  "vtkRefractionPass's and vtkRefractionGlassKeys's default glass specular terms differ");

vtkInformationIntegerKey* vtkRefractionPass::GLASS()
{
  return vtkRefractionGlassKeys::GLASS();
}

vtkInformationDoubleKey* vtkRefractionPass::INDEX_OF_REFRACTION()
{
  return vtkRefractionGlassKeys::INDEX_OF_REFRACTION();
}

vtkInformationIntegerKey* vtkRefractionPass::SURFACE_MODEL()
{
  return vtkRefractionGlassKeys::SURFACE_MODEL();
}

vtkInformationDoubleVectorKey* vtkRefractionPass::DISPERSION()
{
  return vtkRefractionGlassKeys::DISPERSION();
}

const char* vtkRefractionPass::GetISRDistanceArrayName()
{
  return vtkRefractionGlassKeys::GetISRDistanceArrayName();
}

bool vtkRefractionPass::MakeGlass(vtkProp* prop, double indexOfRefraction)
{
  return vtkRefractionGlassKeys::MakeGlass(prop, indexOfRefraction);
}

void vtkRefractionPass::SetSurfaceModel(vtkProp* prop, int model)
{
  vtkRefractionGlassKeys::SetSurfaceModel(prop, model);
}

void vtkRefractionPass::ClearGlass(vtkProp* prop)
{
  vtkRefractionGlassKeys::ClearGlass(prop);
}

bool vtkRefractionPass::SetDispersion(vtkProp* prop, double red, double green, double blue)
{
  return vtkRefractionGlassKeys::SetDispersion(prop, red, green, blue);
}

void vtkRefractionPass::ClearDispersion(vtkProp* prop)
{
  vtkRefractionGlassKeys::ClearDispersion(prop);
}

bool vtkRefractionPass::GetDispersion(vtkProp* prop, double rgb[3])
{
  return vtkRefractionGlassKeys::GetDispersion(prop, rgb);
}

bool vtkRefractionPass::IsGlass(vtkProp* prop)
{
  return vtkRefractionGlassKeys::IsGlass(prop);
}

double vtkRefractionPass::GetIndexOfRefraction(vtkProp* prop)
{
  return vtkRefractionGlassKeys::GetIndexOfRefraction(prop);
}


