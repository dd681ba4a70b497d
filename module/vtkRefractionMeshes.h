/**
 * @class   vtkRefractionMeshes
 * @brief   The polydata a glass prop draws: one for a vtkPolyDataMapper, every visible leaf
 *          for a vtkCompositePolyDataMapper2.
 *
 * Readers of .vtm, Exodus and every ParaView surface hand a vtkCompositeDataSet (multiblock,
 * partitioned) to a vtkCompositePolyDataMapper2; the pass's CPU side (validation, colour,
 * surface model, winding, ISR's distances) reads the meshes through this class, so that
 * composite data is ordinary input. Leaves that are not polydata, are empty, or are hidden
 * through the mapper's vtkCompositeDataDisplayAttributes are left out, as the mapper leaves
 * them out.
 */
#ifndef vtkRefractionMeshes_h
#define vtkRefractionMeshes_h

#include "vtkObject.h"

#include <string> // For DescribeBlock
#include <vector> // For Block lists

class vtkMapper;
class vtkPolyData;
class vtkProp;

class vtkRefractionMeshes : public vtkObject
{
public:
  static vtkRefractionMeshes* New();
  vtkTypeMacro(vtkRefractionMeshes, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  struct Block
  {
    vtkPolyData* Mesh = nullptr;
    unsigned int FlatIndex = 0; ///< the leaf's flat index; 0 for a plain vtkPolyData
  };

  /// The mapper of an actor, or null (a volume, a 2D prop, an actor without a mapper).
  static vtkMapper* GetMapper(vtkProp* prop);

  /// Whether the prop's mapper draws a vtkCompositeDataSet.
  static bool IsComposite(vtkProp* prop);

  /// Whether the prop draws its polygons as surfaces (not an actor's wireframe or points
  /// representation): then its vertex and line cells are no part of the glass.
  static bool DrawsSurfaces(vtkProp* prop);

  /**
   * The polydata the prop's mapper draws, as it last produced them (no pipeline update).
   * Empty leaves are kept when `withEmpty` is set (the validation reports them).
   */
  static std::vector<Block> GetBlocks(vtkProp* prop, bool withEmpty = false);

  /// "block 3 of " for a leaf of composite data, "" otherwise: for messages.
  static std::string DescribeBlock(const Block& block, bool composite);

protected:
  vtkRefractionMeshes() = default;
  ~vtkRefractionMeshes() override = default;

private:
  vtkRefractionMeshes(const vtkRefractionMeshes&) = delete;
  void operator=(const vtkRefractionMeshes&) = delete;
};

#endif
