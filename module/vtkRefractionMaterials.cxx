#include "vtkRefractionMaterials.h"

#include "vtkActor.h"
#include "vtkBoundingBox.h"
#include "vtkCellData.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkMatrix4x4.h"
#include "vtkMapper.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRefractionGlassKeys.h"
#include "vtkRefractionMeshes.h"
#include "vtkRefractionSurfaceModel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>

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
  // A texture that VTK's colour code applies to the colour (the actor's, or the property's
  // other than the PBR maps, which its lighting code reads).
  if (actor->GetTexture())
  {
    return true;
  }
  for (const auto& texture : property->GetAllTextures())
  {
    if (texture.first != "albedoTex" && texture.first != "normalTex" &&
      texture.first != "materialTex" && texture.first != "emissiveTex" &&
      texture.first != "anisotropyTex")
    {
      return true;
    }
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

// The diagonal of a bounding box (0 without bounds).
double Diagonal(const double* b)
{
  if (!b || !(b[0] <= b[1]))
  {
    return 0.0;
  }
  return std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
    (b[5] - b[4]) * (b[5] - b[4]));
}

// The diagonal of model bounds b placed by the actor's matrix (the world box of its corners).
double PlacedDiagonal(vtkProp* prop, const double b[6])
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  const vtkBoundingBox model(b);
  vtkBoundingBox box;
  for (int corner = 0; corner < 8; ++corner)
  {
    double p[4] = { 0.0, 0.0, 0.0, 1.0 };
    model.GetCorner(corner, p);
    if (actor)
    {
      actor->GetMatrix()->MultiplyPoint(p, p);
    }
    box.AddPoint(p[0] / p[3], p[1] / p[3], p[2] / p[3]);
  }
  return box.IsValid() ? box.GetDiagonalLength() : 0.0;
}

// What a prop's sheet pieces are, for the warning: "n of m pieces (boundary L against square
// root of area A, ...)" per mesh with sheet pieces, with the block named in composite data;
// without the measures, what the warning is said again for when it changes.
std::string DescribeSheetPieces(vtkProp* prop, vtkRefractionSurfaceModel* surfaces, bool measures)
{
  std::ostringstream text;
  const bool composite = vtkRefractionMeshes::IsComposite(prop);
  for (const auto& block : vtkRefractionMeshes::GetBlocks(prop))
  {
    const vtkRefractionSurfaceModel::Mesh& mesh = surfaces->GetMesh(block.Mesh);
    if (mesh.SheetPieces == 0)
    {
      continue;
    }
    text << (text.str().empty() ? " " : "; ")
         << vtkRefractionMeshes::DescribeBlock(block, composite) << mesh.SheetPieces << " of "
         << mesh.Pieces << " pieces";
    for (size_t i = 0; measures && i < mesh.SheetMeasures.size(); ++i)
    {
      text << (i ? ", " : " (boundary ") << mesh.SheetMeasures[i].first
           << " against the square root of the area " << mesh.SheetMeasures[i].second;
    }
    if (measures)
    {
      text << (mesh.SheetPieces > static_cast<int>(mesh.SheetMeasures.size()) ? ", ..." : "")
           << ")";
    }
    if (composite && mesh.Mixed())
    {
      text << " drawn as a solid block";
    }
  }
  return text.str();
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
  vtkRefractionSurfaceModel* surfaces, bool dataColour, double absorptionDistance,
  double thinSheetThickness, const std::vector<double>* bounds)
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
  std::vector<std::string> sheetPieces; // per prop in sheets: which pieces
  std::vector<std::pair<size_t, double>> pieceSheets; // material, thickness of its sheet pieces
  this->SheetPieceMaterial.assign(glass.size(), -1);
  std::vector<vtkProp*> mixed; // composite data with open and closed blocks
  std::vector<std::array<int, 3>> mixedCounts; // open blocks, blocks of both, blocks
  double largest = 0.0;
  vtkBoundingBox all;
  for (size_t i = 0; i < glass.size(); ++i)
  {
    vtkProp* prop = glass[i];
    const double* propBounds =
      bounds && bounds->size() >= 6 * (i + 1) ? bounds->data() + 6 * i : prop->GetBounds();
    if (propBounds && propBounds[0] <= propBounds[1])
    {
      all.AddBounds(propBounds);
    }
    this->IOR.push_back(static_cast<float>(vtkRefractionGlassKeys::GetIndexOfRefraction(prop)));
    double rgb[3];
    this->Dispersion = vtkRefractionGlassKeys::GetDispersion(prop, rgb) || this->Dispersion;
    this->RedIOR.push_back(static_cast<float>(rgb[0]));
    this->BlueIOR.push_back(static_cast<float>(rgb[2]));
    vtkInformation* keys = prop->GetPropertyKeys();
    const int model = keys && keys->Has(vtkRefractionGlassKeys::SURFACE_MODEL())
      ? keys->Get(vtkRefractionGlassKeys::SURFACE_MODEL())
      : vtkRefractionGlassKeys::SURFACE_AUTO;
    const vtkRefractionSurfaceModel::Prop surface = surfaces->GetProp(prop);
    const bool sheet = model == vtkRefractionGlassKeys::SURFACE_THIN_SHEET ||
      (model == vtkRefractionGlassKeys::SURFACE_AUTO && surface.Boundary);
    if (model == vtkRefractionGlassKeys::SURFACE_AUTO &&
      ((surface.OpenBlocks > 0 && surface.OpenBlocks < surface.Blocks) ||
        (surface.MixedBlocks > 0 && !surface.PerPiece)))
    {
      mixed.push_back(prop);
      mixedCounts.push_back({ surface.OpenBlocks, surface.MixedBlocks, surface.Blocks });
    }
    const double diagonal = Diagonal(propBounds);
    largest = std::max(largest, diagonal);
    double thickness = 0.0;
    if (sheet)
    {
      thickness = thinSheetThickness > 0.0 ? thinSheetThickness : 0.01 * diagonal;
      thickness = thickness > 0.0 ? thickness : 1e-3;
    }
    if (model == vtkRefractionGlassKeys::SURFACE_AUTO && !sheet && surface.PerPiece)
    {
      // The sheet pieces of a mesh whose pieces disagree: a material of their own (the same
      // glass, a sheet as thick as theirs alone would be), chosen per fragment.
      const vtkRefractionSurfaceModel::Mesh& mesh = surfaces->GetMesh(surface.PerPiece);
      double pieceThickness = thinSheetThickness > 0.0
        ? thinSheetThickness
        : 0.01 * PlacedDiagonal(prop, mesh.SheetBounds);
      pieceThickness = pieceThickness > 0.0 ? pieceThickness : 1e-3;
      pieceSheets.emplace_back(this->IOR.size() - 1, pieceThickness);
    }
    if (model == vtkRefractionGlassKeys::SURFACE_AUTO && (sheet || surface.PerPiece))
    {
      sheets.push_back(prop);
      sheetPieces.push_back(DescribeSheetPieces(prop, surfaces, false));
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
  // The materials of the sheet pieces follow the props' own.
  for (const auto& pieces : pieceSheets)
  {
    const size_t of = pieces.first;
    this->SheetPieceMaterial[of] = static_cast<int>(this->IOR.size());
    this->IOR.push_back(this->IOR[of]);
    this->RedIOR.push_back(this->RedIOR[of]);
    this->BlueIOR.push_back(this->BlueIOR[of]);
    this->Sheet.push_back(static_cast<float>(pieces.second));
    for (int k = 0; k < 4; ++k)
    {
      this->Highlights.push_back(this->Highlights[4 * of + k]);
    }
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
  // Say once which pieces of which props were taken for thin sheets, and why (until the set
  // or its pieces change).
  if (!sheets.empty() &&
    (sheets != this->SheetsReported || sheetPieces != this->SheetPiecesReported))
  {
    std::ostringstream names;
    for (size_t i = 0; i < sheets.size(); ++i)
    {
      names << (i ? "; " : " ") << sheets[i]->GetClassName() << " " << sheets[i] << ":"
            << DescribeSheetPieces(sheets[i], surfaces, true);
    }
    vtkWarningMacro("Glass prop(s)" << names.str()
                                    << ": these connected pieces are open as a whole (their "
                                       "boundary, the edges used by one polygon, is as long as "
                                       "the square root of their area or longer; a piece with "
                                       "small holes stays a solid) and are drawn as thin sheets; "
                                       "any other pieces stay solids "
                                       "(vtkRefractionPass::SetSurfaceModel to choose).");
  }
  this->SheetsReported = sheets;
  this->SheetPiecesReported = sheetPieces;
  if (!mixed.empty() && mixed != this->MixedReported)
  {
    std::ostringstream names;
    for (size_t i = 0; i < mixed.size(); ++i)
    {
      names << " " << mixed[i]->GetClassName() << " " << mixed[i] << " (" << mixedCounts[i][0]
            << " of " << mixedCounts[i][2] << " blocks open, " << mixedCounts[i][1]
            << " of open and closed pieces)";
    }
    vtkWarningMacro("Glass prop(s)" << names.str()
                                    << " hold open and closed blocks (or blocks of open and "
                                       "closed pieces): VTK's composite mapper (9.1, 9.2) uploads no "
                                       "extra vertex data, so composite data is decided per "
                                       "actor, and all are drawn as solids (put the open blocks "
                                       "in an actor of their own to draw them as thin sheets).");
  }
  this->MixedReported = mixed;
}
