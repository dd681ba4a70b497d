/**
 * @class   vtkRefractionMethodSIR
 * @brief   Single-interface refraction: the front's refracted ray goes to the environment.
 *
 * Front G-buffer only; the cheapest baseline (shaders/rfMethodSIR.glsl).
 */
#ifndef vtkRefractionMethodSIR_h
#define vtkRefractionMethodSIR_h

#include "vtkRefractionMethod.h"

class vtkRefractionMethodSIR : public vtkRefractionMethod
{
public:
  static vtkRefractionMethodSIR* New();
  vtkTypeMacro(vtkRefractionMethodSIR, vtkRefractionMethod);

  const char* GetName() const override { return "SIR"; }

  std::string GetShaderSource() const override;

protected:
  vtkRefractionMethodSIR() = default;
  ~vtkRefractionMethodSIR() override = default;

private:
  vtkRefractionMethodSIR(const vtkRefractionMethodSIR&) = delete;
  void operator=(const vtkRefractionMethodSIR&) = delete;
};

#endif
