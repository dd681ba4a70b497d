/**
 * @class   vtkRefractionMethodSH
 * @brief   Genevaux et al.: exit directions precomputed per vertex as spherical harmonics.
 *
 * For static glass meshes that carry vtkSHTransferFilter's point arrays: the geometry stage
 * evaluates each vertex's functions for the view (shaders/rfSHTransferVS.glsl) into the front
 * G-buffer (FRONT_SH), and the shading stage refracts at the front and leaves along the
 * stored direction (shaders/rfMethodSH.glsl). Where a glass mesh has no fitting transfer the
 * pass warns and draws DIR instead (vtkRefractionSHTransfer::Check).
 */
#ifndef vtkRefractionMethodSH_h
#define vtkRefractionMethodSH_h

#include "vtkRefractionMethod.h"

class vtkRefractionMethodSH : public vtkRefractionMethod
{
public:
  static vtkRefractionMethodSH* New();
  vtkTypeMacro(vtkRefractionMethodSH, vtkRefractionMethod);

  const char* GetName() const override { return "SH"; }
  bool NeedsSHTransfer() const override { return true; }
  std::string GetShaderSource() const override;

protected:
  vtkRefractionMethodSH() = default;
  ~vtkRefractionMethodSH() override = default;

private:
  vtkRefractionMethodSH(const vtkRefractionMethodSH&) = delete;
  void operator=(const vtkRefractionMethodSH&) = delete;
};

#endif
