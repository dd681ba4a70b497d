/**
 * @class   vtkRefractionMethodDIR
 * @brief   Oliveira & Brauwers 2007: the exit found by searching the captured back surface.
 *
 * Back capture (pass 1), min/max back depth by GPU reduction or from the glass's bounding
 * boxes (pass 2), and in the shading stage the perspective-correct conservative binary search
 * (eq. 3-10, algorithm 2) with the secant refinement and the adaptive step bound
 * (shaders/rfMethodDIR.glsl). Settings: SearchSteps, AdaptiveSearch, SecantRefinement,
 * DepthRangeMode, BackSurface of vtkRefractionPass.
 */
#ifndef vtkRefractionMethodDIR_h
#define vtkRefractionMethodDIR_h

#include "vtkRefractionMethod.h"

class vtkRefractionMethodDIR : public vtkRefractionMethod
{
public:
  static vtkRefractionMethodDIR* New();
  vtkTypeMacro(vtkRefractionMethodDIR, vtkRefractionMethod);

  const char* GetName() const override { return "DIR"; }
  bool NeedsBackSurface() const override { return true; }
  bool NeedsDepthRange() const override { return true; }
  void AppendDefines(std::ostream& defines, vtkRefractionPass* settings) const override;
  std::string GetShaderSource() const override;
  void SetUniforms(vtkShaderProgram* program, vtkRefractionPass* settings,
    const double boundsDepthRange[2]) const override;

protected:
  vtkRefractionMethodDIR() = default;
  ~vtkRefractionMethodDIR() override = default;

private:
  vtkRefractionMethodDIR(const vtkRefractionMethodDIR&) = delete;
  void operator=(const vtkRefractionMethodDIR&) = delete;
};

#endif
