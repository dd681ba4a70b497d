#include "vtkRefractionMeshes.h"

#include "vtkActor.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkMapper.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkSmartPointer.h"

#include <string>

vtkStandardNewMacro(vtkRefractionMeshes);

//------------------------------------------------------------------------------
void vtkRefractionMeshes::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
vtkMapper* vtkRefractionMeshes::GetMapper(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  return actor ? actor->GetMapper() : nullptr;
}

//------------------------------------------------------------------------------
bool vtkRefractionMeshes::IsComposite(vtkProp* prop)
{
  vtkMapper* mapper = GetMapper(prop);
  return mapper && vtkCompositeDataSet::SafeDownCast(mapper->GetInputDataObject(0, 0));
}

//------------------------------------------------------------------------------
bool vtkRefractionMeshes::DrawsSurfaces(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  return !actor || actor->GetProperty()->GetRepresentation() == VTK_SURFACE;
}

//------------------------------------------------------------------------------
std::vector<vtkRefractionMeshes::Block> vtkRefractionMeshes::GetBlocks(
  vtkProp* prop, bool withEmpty)
{
  std::vector<Block> blocks;
  vtkMapper* mapper = GetMapper(prop);
  vtkDataObject* input = mapper ? mapper->GetInputDataObject(0, 0) : nullptr;
  if (auto* poly = vtkPolyData::SafeDownCast(input))
  {
    if (withEmpty || poly->GetNumberOfPoints() > 0)
    {
      blocks.push_back(Block{ poly, 0 });
    }
    return blocks;
  }
  auto* composite = vtkCompositeDataSet::SafeDownCast(input);
  if (!composite)
  {
    return blocks;
  }
  auto* compositeMapper = vtkCompositePolyDataMapper2::SafeDownCast(mapper);
  vtkCompositeDataDisplayAttributes* attributes =
    compositeMapper ? compositeMapper->GetCompositeDataDisplayAttributes() : nullptr;
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(composite->NewIterator());
  it->SkipEmptyNodesOn();
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    auto* poly = vtkPolyData::SafeDownCast(it->GetCurrentDataObject());
    if (!poly || (!withEmpty && poly->GetNumberOfPoints() == 0))
    {
      continue;
    }
    if (attributes && attributes->HasBlockVisibility(poly) &&
      !attributes->GetBlockVisibility(poly))
    {
      continue;
    }
    blocks.push_back(Block{ poly, it->GetCurrentFlatIndex() });
  }
  return blocks;
}

//------------------------------------------------------------------------------
std::string vtkRefractionMeshes::DescribeBlock(const Block& block, bool composite)
{
  return composite ? "block " + std::to_string(block.FlatIndex) + " of " : std::string();
}
