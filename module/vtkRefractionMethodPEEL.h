/**
 * @class   vtkRefractionMethodPEEL
 * @brief   Chi, Wang & Hu: the ray followed through K depth-peeled layers of all the glass.
 *
 * The front G-buffer is layer 0; the geometry stage peels layers 1 .. K-1 (both faces, each
 * the nearest surface behind the previous one), and the shading stage follows the refracted
 * ray through every interface they hold, with the medium of nested and overlapping glass kept
 * on a stack and total internal reflection followed (shaders/rfMethodPEEL.glsl, the kernel's
 * rf_kernel_peel.h). Settings: PeelLayers (K) and TIRBounces (B) of vtkRefractionPass.
 */
#ifndef vtkRefractionMethodPEEL_h
#define vtkRefractionMethodPEEL_h

#include "vtkRefractionMethod.h"

class vtkRefractionMethodPEEL : public vtkRefractionMethod
{
public:
  static vtkRefractionMethodPEEL* New();
  vtkTypeMacro(vtkRefractionMethodPEEL, vtkRefractionMethod);

  const char* GetName() const override { return "PEEL"; }
  int GetPeelLayers(vtkRefractionPass* settings) const override;
  void AppendDefines(std::ostream& defines, vtkRefractionPass* settings) const override;
  std::string GetShaderSource() const override;
  void SetUniforms(vtkShaderProgram* program, vtkRefractionPass* settings,
    const double boundsDepthRange[2]) const override;

protected:
  vtkRefractionMethodPEEL() = default;
  ~vtkRefractionMethodPEEL() override = default;

private:
  vtkRefractionMethodPEEL(const vtkRefractionMethodPEEL&) = delete;
  void operator=(const vtkRefractionMethodPEEL&) = delete;
};

#endif
