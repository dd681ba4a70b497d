/**
 * @class   vtkRefractionSHTransfer
 * @brief   The SH method's per-vertex transfer functions on the GPU.
 *
 * Part of vtkRefractionGeometryStage for the SH method (Genevaux et al., seed 003): checks
 * that each glass mesh carries a transfer that fits it (the point arrays "SHTransfer" and
 * "SHVertexId" of vtkSHTransferFilter, computed after its points last changed, for its index
 * of refraction), uploads each mesh's coefficients into a texture once per change, maps the
 * vertex index to the mappers' vertex attribute rfSHVertex, and binds the texture and the
 * camera in model coordinates for shaders/rfSHTransferVS.glsl.
 */
#ifndef vtkRefractionSHTransfer_h
#define vtkRefractionSHTransfer_h

#include "vtkObject.h"
#include "vtkSmartPointer.h" // For members

#include <map>    // For members
#include <string> // For Check
#include <vector> // For members

class vtkPolyData;
class vtkProp;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;
class vtkOpenGLRenderWindow;
class vtkWindow;

class vtkRefractionSHTransfer : public vtkObject
{
public:
  static vtkRefractionSHTransfer* New();
  vtkTypeMacro(vtkRefractionSHTransfer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The point arrays vtkSHTransferFilter adds (the names the pass reads).
  static const char* GetTransferArrayName() { return "SHTransfer"; }
  static const char* GetVertexIdArrayName() { return "SHVertexId"; }
  static const char* GetSettingsArrayName() { return "SHTransferSettings"; }

  /// Whether every prop fits (see the class); else why the first that does not.
  static bool Check(const std::vector<vtkProp*>& glass, std::string& reason);
  /// Maps the vertex index array to the prop's mapper's rfSHVertex attribute.
  void MapVertexIds(vtkProp* prop);
  /// Uploads the prop's coefficients if they changed, activates them and sets the uniforms.
  bool Bind(vtkShaderProgram* program, vtkProp* prop, vtkRenderer* ren,
    vtkOpenGLRenderWindow* renWin);
  /// The semi-Gaussian filter's width on the weights (rf_sh_smooth); <= 0: none.
  void SetSmoothing(double width) { this->Smoothing = width; }
  /// Keeps the uploads of these props' meshes only (all are released for an empty list): a
  /// method other than SH, or glass that went away, holds no coefficient texture.
  void Retain(const std::vector<vtkProp*>& glass);
  /// Deactivates what Bind activated.
  void Unbind();
  /// Bytes of the coefficient textures.
  unsigned long long GetBytes() const;

  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkRefractionSHTransfer();
  ~vtkRefractionSHTransfer() override;

private:
  vtkRefractionSHTransfer(const vtkRefractionSHTransfer&) = delete;
  void operator=(const vtkRefractionSHTransfer&) = delete;

  struct Upload
  {
    vtkMTimeType Time = 0;
    int Count = 0;
    double Smoothing = 0.0;
    vtkSmartPointer<vtkTextureObject> Texture;
    unsigned long long Bytes = 0;
  };
  std::map<vtkPolyData*, Upload> Uploads;
  std::vector<vtkTextureObject*> Active;
  double Smoothing = 0.0;
};

#endif
