/**
 * @class   vtkRefractionMethodISR
 * @brief   Wyman 2005 image-space refraction: the exit at an estimated distance (eq. 1-2).
 *
 * Back capture and d_N per vertex (point array ISRNormalDistance) in the G-buffer (shaders/rfMethodISR.glsl).
 */
#ifndef vtkRefractionMethodISR_h
#define vtkRefractionMethodISR_h

#include "vtkRefractionMethod.h"

class vtkRefractionMethodISR : public vtkRefractionMethod
{
public:
  static vtkRefractionMethodISR* New();
  vtkTypeMacro(vtkRefractionMethodISR, vtkRefractionMethod);

  const char* GetName() const override { return "ISR"; }
  bool NeedsBackSurface() const override { return true; }
  bool NeedsNormalDistance() const override { return true; }
  std::string GetShaderSource() const override;

protected:
  vtkRefractionMethodISR() = default;
  ~vtkRefractionMethodISR() override = default;

private:
  vtkRefractionMethodISR(const vtkRefractionMethodISR&) = delete;
  void operator=(const vtkRefractionMethodISR&) = delete;
};

#endif
