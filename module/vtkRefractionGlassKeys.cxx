#include "vtkRefractionGlassKeys.h"

#include "vtkActor.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkNew.h"
#include "vtkProp.h"
#include "vtkProperty.h"

#include "rf_validate.h"

vtkInformationKeyMacro(vtkRefractionGlassKeys, GLASS, Integer);
vtkInformationKeyMacro(vtkRefractionGlassKeys, INDEX_OF_REFRACTION, Double);
vtkInformationKeyMacro(vtkRefractionGlassKeys, SURFACE_MODEL, Integer);
vtkInformationKeyRestrictedMacro(vtkRefractionGlassKeys, DISPERSION, DoubleVector, 3);

namespace
{
vtkInformation* GetOrCreateKeys(vtkProp* prop)
{
  vtkInformation* keys = prop->GetPropertyKeys();
  if (!keys)
  {
    vtkNew<vtkInformation> created;
    prop->SetPropertyKeys(created);
    keys = created;
  }
  return keys;
}
}

//------------------------------------------------------------------------------
bool vtkRefractionGlassKeys::MakeGlass(vtkProp* prop, double indexOfRefraction)
{
  if (!prop)
  {
    vtkGenericWarningMacro("vtkRefractionPass::MakeGlass: no prop given.");
    return false;
  }
  const rf_status status = rf_validate_ior(indexOfRefraction);
  if (status != RF_OK)
  {
    vtkErrorWithObjectMacro(prop, "vtkRefractionPass::MakeGlass: index of refraction "
        << indexOfRefraction << " rejected for " << prop->GetClassName() << " " << prop << ": "
        << rf_status_message(status) << ". The prop is not marked as glass.");
    return false;
  }
  vtkInformation* keys = GetOrCreateKeys(prop);
  keys->Set(GLASS(), 1);
  keys->Set(INDEX_OF_REFRACTION(), indexOfRefraction);
  // Glass shows its shape by the highlights of the renderer's lights: an actor whose property
  // still has VTK's default specular terms gets glass's (set Specular 0 after this for none).
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  vtkProperty* property = actor ? actor->GetProperty() : nullptr;
  if (property && property->GetSpecular() == 0.0 && property->GetSpecularPower() == 1.0)
  {
    property->SetSpecular(DefaultGlassSpecular);
    property->SetSpecularPower(DefaultGlassSpecularPower);
  }
  prop->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkRefractionGlassKeys::SetSurfaceModel(vtkProp* prop, int model)
{
  if (!prop)
  {
    return;
  }
  vtkInformation* keys = GetOrCreateKeys(prop);
  if (model == SURFACE_AUTO)
  {
    keys->Remove(SURFACE_MODEL());
  }
  else
  {
    keys->Set(SURFACE_MODEL(), model == SURFACE_THIN_SHEET ? SURFACE_THIN_SHEET : SURFACE_SOLID);
  }
  prop->Modified();
}

//------------------------------------------------------------------------------
void vtkRefractionGlassKeys::ClearGlass(vtkProp* prop)
{
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  if (keys)
  {
    keys->Remove(GLASS());
    keys->Remove(INDEX_OF_REFRACTION());
    keys->Remove(DISPERSION());
    prop->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkRefractionGlassKeys::SetDispersion(vtkProp* prop, double red, double green, double blue)
{
  if (!prop || !IsGlass(prop))
  {
    vtkGenericWarningMacro("vtkRefractionPass::SetDispersion: "
      << (prop ? "the prop is not glass (MakeGlass first)" : "no prop given") << ".");
    return false;
  }
  const double rgb[3] = { red, green, blue };
  for (int c = 0; c < 3; ++c)
  {
    const rf_status status = rf_validate_ior(rgb[c]);
    if (status != RF_OK)
    {
      vtkErrorWithObjectMacro(prop, "vtkRefractionPass::SetDispersion: "
          << (c == 0 ? "red" : c == 1 ? "green" : "blue") << " index of refraction " << rgb[c]
          << " rejected for " << prop->GetClassName() << " " << prop << ": "
          << rf_status_message(status) << ". The prop's dispersion is unchanged.");
      return false;
    }
  }
  vtkInformation* keys = GetOrCreateKeys(prop);
  keys->Set(DISPERSION(), rgb, 3);
  keys->Set(INDEX_OF_REFRACTION(), green);
  prop->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkRefractionGlassKeys::ClearDispersion(vtkProp* prop)
{
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  if (keys && keys->Has(DISPERSION()))
  {
    keys->Remove(DISPERSION());
    prop->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkRefractionGlassKeys::GetDispersion(vtkProp* prop, double rgb[3])
{
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  if (keys && keys->Has(DISPERSION()) && keys->Length(DISPERSION()) == 3)
  {
    keys->Get(DISPERSION(), rgb);
    return true;
  }
  rgb[0] = rgb[1] = rgb[2] = GetIndexOfRefraction(prop);
  return false;
}

//------------------------------------------------------------------------------
bool vtkRefractionGlassKeys::IsGlass(vtkProp* prop)
{
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  return keys && keys->Has(GLASS()) && keys->Get(GLASS()) != 0;
}

//------------------------------------------------------------------------------
double vtkRefractionGlassKeys::GetIndexOfRefraction(vtkProp* prop)
{
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  return keys && keys->Has(INDEX_OF_REFRACTION()) ? keys->Get(INDEX_OF_REFRACTION()) : 1.5;
}
