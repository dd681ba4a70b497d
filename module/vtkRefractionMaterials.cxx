#include "vtkRefractionMaterials.h"

#include "vtkActor.h"
#include "vtkBoundingBox.h"
#include "vtkCellData.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkMapper.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRefractionGeometryStage.h"
#include "vtkRefractionMeshes.h"
#include "vtkRefractionPass.h"

#include <algorithm>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkRefractionMaterials);

namespace
{
// Whether a glass prop's pixels can be anything but white: a colour, scalar colours, edges.
bool HasDataColour(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (!actor)
  {
    return false;
  }
  vtkProperty* property = actor->GetProperty();
  double colour[3];
  property->GetDiffuseColor(colour);
  if (property->GetEdgeVisibility() || colour[0] < 1.0 || colour[1] < 1.0 || colour[2] < 1.0 ||
    property->GetDiffuse() < 1.0 || property->GetAmbient() > 0.0)
  {
    return true;
  }
  // Per-block colours of composite data (vtkCompositeDataDisplayAttributes), or scalars in
  // the data (any block).
  vtkMapper* mapper = actor->GetMapper();
  auto* composite = vtkCompositePolyDataMapper2::SafeDownCast(mapper);
  if (composite && composite->GetCompositeDataDisplayAttributes() &&
    composite->GetCompositeDataDisplayAttributes()->HasBlockColors())
  {
    return true;
  }
  if (!mapper || !mapper->GetScalarVisibility())
  {
    return false;
  }
  if (mapper->GetArrayName() && mapper->GetArrayName()[0] != 0)
  {
    return true;
  }
  for (const auto& block : vtkRefractionMeshes::GetBlocks(prop))
  {
    if (block.Mesh->GetPointData()->GetScalars() || block.Mesh->GetCellData()->GetScalars())
    {
      return true;
    }
  }
  return false;
}

// The diagonal of a prop's bounding box (0 without bounds).
double Diagonal(vtkProp* prop)
{
  const double* b = prop->GetBounds();
  if (!b || !(b[0] <= b[1]))
  {
    return 0.0;
  }
  return std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
    (b[5] - b[4]) * (b[5] - b[4]));
}
}

//------------------------------------------------------------------------------
void vtkRefractionMaterials::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Materials: " << this->IOR.size() << "\n";
  os << indent << "DataColour: " << this->DataColour << "\n";
  os << indent << "Dispersion: " << this->Dispersion << "\n";
  os << indent << "AbsorptionDistance: " << this->AbsorptionDistance << "\n";
}

//------------------------------------------------------------------------------
void vtkRefractionMaterials::Update(const std::vector<vtkProp*>& glass,
  vtkRefractionGeometryStage* surfaces, bool dataColour, double absorptionDistance,
  double thinSheetThickness)
{
  this->IOR.clear();
  this->RedIOR.clear();
  this->BlueIOR.clear();
  this->Dispersion = false;
  this->Sheet.clear();
  this->Highlights.clear();
  this->HasHighlights = false;
  this->DataColour = false;
  std::vector<vtkProp*> sheets;
  std::vector<vtkProp*> mixed; // composite data with open and closed blocks
  std::vector<std::pair<int, int>> mixedCounts;
  double largest = 0.0;
  vtkBoundingBox all;
  for (vtkProp* prop : glass)
  {
    const double* bounds = prop->GetBounds();
    if (bounds && bounds[0] <= bounds[1])
    {
      all.AddBounds(bounds);
    }
    this->IOR.push_back(static_cast<float>(vtkRefractionPass::GetIndexOfRefraction(prop)));
    double rgb[3];
    this->Dispersion = vtkRefractionPass::GetDispersion(prop, rgb) || this->Dispersion;
    this->RedIOR.push_back(static_cast<float>(rgb[0]));
    this->BlueIOR.push_back(static_cast<float>(rgb[2]));
    vtkInformation* keys = prop->GetPropertyKeys();
    const int model = keys && keys->Has(vtkRefractionPass::SURFACE_MODEL())
      ? keys->Get(vtkRefractionPass::SURFACE_MODEL())
      : vtkRefractionPass::SURFACE_AUTO;
    int openBlocks = 0;
    int blocks = 0;
    const bool open = surfaces->HasBoundary(prop, &openBlocks, &blocks);
    const bool sheet = model == vtkRefractionPass::SURFACE_THIN_SHEET ||
      (model == vtkRefractionPass::SURFACE_AUTO && open);
    if (model == vtkRefractionPass::SURFACE_AUTO && openBlocks > 0 && openBlocks < blocks)
    {
      mixed.push_back(prop);
      mixedCounts.emplace_back(openBlocks, blocks);
    }
    const double diagonal = Diagonal(prop);
    largest = std::max(largest, diagonal);
    double thickness = 0.0;
    if (sheet)
    {
      thickness = thinSheetThickness > 0.0 ? thinSheetThickness : 0.01 * diagonal;
      thickness = thickness > 0.0 ? thickness : 1e-3;
      if (model == vtkRefractionPass::SURFACE_AUTO)
      {
        sheets.push_back(prop);
      }
    }
    this->Sheet.push_back(static_cast<float>(thickness));
    vtkActor* actor = vtkActor::SafeDownCast(prop);
    vtkProperty* property = actor ? actor->GetProperty() : nullptr;
    const double specular = property ? property->GetSpecular() : 0.0;
    double specularColour[3] = { 1.0, 1.0, 1.0 };
    if (property)
    {
      property->GetSpecularColor(specularColour);
    }
    for (double c : specularColour)
    {
      this->Highlights.push_back(static_cast<float>(specular * c));
    }
    this->Highlights.push_back(static_cast<float>(property ? property->GetSpecularPower() : 1.0));
    this->HasHighlights = this->HasHighlights || specular > 0.0;
    this->DataColour = this->DataColour || (dataColour && HasDataColour(prop));
  }
  this->LargestDiagonal = largest;
  this->ExtentDiagonal = all.IsValid() ? all.GetDiagonalLength() : 0.0;
  // The tint: light keeps the data's colour after this distance inside the glass.
  // A distance in world units that belongs to the material: derived once from the glass's
  // size when the user gives none, then kept, so that a deforming object does not change the
  // colour of its parts that stay put (re-derived only when the user's setting changes).
  if (absorptionDistance != this->RequestedAbsorptionDistance)
  {
    this->RequestedAbsorptionDistance = absorptionDistance;
    this->DerivedAbsorptionDistance = 0.0;
  }
  this->AbsorptionDistance = 0.0;
  if (this->DataColour)
  {
    if (absorptionDistance > 0.0)
    {
      this->AbsorptionDistance = absorptionDistance;
    }
    else
    {
      if (!(this->DerivedAbsorptionDistance > 0.0))
      {
        this->DerivedAbsorptionDistance = largest > 0.0 ? 0.5 * largest : 1.0;
      }
      this->AbsorptionDistance = this->DerivedAbsorptionDistance;
    }
  }
  // Say once which props were taken for thin sheets (until the set changes).
  if (!sheets.empty() && sheets != this->SheetsReported)
  {
    std::ostringstream names;
    for (vtkProp* prop : sheets)
    {
      names << " " << prop->GetClassName() << " " << prop;
    }
    vtkWarningMacro("Glass prop(s)" << names.str()
                                    << " are open as a whole (edges used by one polygon, as "
                                       "long as the square root of the area or longer; small "
                                       "holes leave a solid): drawn as thin sheets "
                                       "(vtkRefractionPass::SetSurfaceModel to choose).");
  }
  this->SheetsReported = sheets;
  if (!mixed.empty() && mixed != this->MixedReported)
  {
    std::ostringstream names;
    for (size_t i = 0; i < mixed.size(); ++i)
    {
      names << " " << mixed[i]->GetClassName() << " " << mixed[i] << " (" << mixedCounts[i].first
            << " of " << mixedCounts[i].second << " blocks open)";
    }
    vtkWarningMacro("Glass prop(s)" << names.str()
                                    << " hold open and closed blocks: the surface model is "
                                       "decided per actor, so all are drawn as solids (put the "
                                       "open blocks in an actor of their own to draw them as "
                                       "thin sheets).");
  }
  this->MixedReported = mixed;
}
