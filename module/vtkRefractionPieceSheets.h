/**
 * @class   vtkRefractionPieceSheets
 * @brief   The per-point thin-sheet flags of glass meshes whose pieces disagree, on the GPU.
 *
 * Part of vtkRefractionGeometryStage (issue 23: the surface model per connected piece). A
 * mesh with closed and open pieces (vtkRefractionSurfaceModel::Mesh::PointSheet) gets a
 * texture of one byte per point, uploaded once per change of the mesh; the G-buffer pass's
 * vertex shader reads it at gl_VertexID (VTK 9.1's vtkOpenGLPolyDataMapper draws a plain
 * vtkPolyData from its points in order, so the vertex index is the point id) and the fragment
 * takes the sheet pieces' material there. Props without such a mesh bind a texture of one
 * zero texel, so that the sampler always has a texture of its type.
 */
#ifndef vtkRefractionPieceSheets_h
#define vtkRefractionPieceSheets_h

#include "vtkObject.h"
#include "vtkRefractionSurfaceModel.h" // For Bind
#include "vtkSmartPointer.h" // For members

#include <map>    // For members
#include <string> // For ReplaceShaderValues
#include <vector> // For members

class vtkOpenGLRenderWindow;
class vtkPolyData;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class vtkRefractionPieceSheets : public vtkObject
{
public:
  static vtkRefractionPieceSheets* New();
  vtkTypeMacro(vtkRefractionPieceSheets, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Declares and sets rfPieceSheetVSOut in the mapper's vertex shader, and passes it through
  /// its geometry shader where there is one (edges).
  static void ReplaceShaderValues(std::string& vertexShader, std::string& geometryShader);
  /**
   * Activates the flags of `mesh` (surface: its model, whose PointSheet holds them) or, for a
   * null mesh, the texture of one zero texel, and sets the uniforms rfPieceSheets,
   * rfHavePieceSheets and rfSheetMaterial (the material, + 1, of the sheet pieces).
   */
  void Bind(vtkShaderProgram* program, vtkPolyData* mesh,
    const vtkRefractionSurfaceModel::Mesh* surface, int sheetMaterial,
    vtkOpenGLRenderWindow* renWin);
  /// Deactivates what Bind activated.
  void Unbind();
  /// Keeps the uploads of these meshes only.
  void Retain(const std::vector<vtkPolyData*>& meshes);
  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkRefractionPieceSheets() = default;
  ~vtkRefractionPieceSheets() override = default;

private:
  vtkRefractionPieceSheets(const vtkRefractionPieceSheets&) = delete;
  void operator=(const vtkRefractionPieceSheets&) = delete;

  struct Upload
  {
    vtkMTimeType Time = 0;
    vtkSmartPointer<vtkTextureObject> Texture;
  };
  vtkSmartPointer<vtkTextureObject> Upload1(
    const std::vector<unsigned char>& flags, vtkOpenGLRenderWindow* renWin);
  std::map<vtkPolyData*, Upload> Uploads;
  vtkSmartPointer<vtkTextureObject> Empty;
  std::vector<vtkTextureObject*> Active;
};

#endif
