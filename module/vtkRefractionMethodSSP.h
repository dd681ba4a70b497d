/**
 * @class   vtkRefractionMethodSSP
 * @brief   Sousa (GPU Gems 2, ch. 19): the opaque scene behind the glass, perturbed on screen.
 *
 * Needs the opaque scene's colour with the chapter's refraction mask in alpha (so objects in
 * front of the glass do not leak in); no back surface (shaders/rfMethodSSP.glsl). Settings:
 * SSPStrength, SSPFresnelBias, SSPFresnelPower, ChromaticAberration, SSPRefractionMask.
 */
#ifndef vtkRefractionMethodSSP_h
#define vtkRefractionMethodSSP_h

#include "vtkRefractionMethod.h"

class vtkRefractionMethodSSP : public vtkRefractionMethod
{
public:
  static vtkRefractionMethodSSP* New();
  vtkTypeMacro(vtkRefractionMethodSSP, vtkRefractionMethod);

  const char* GetName() const override { return "SSP"; }
  bool NeedsSceneColor() const override { return true; }
  bool SupportsSceneRefraction() const override { return false; }
  std::string GetShaderSource() const override;
  void SetUniforms(vtkShaderProgram* program, vtkRefractionPass* settings,
    const double boundsDepthRange[2]) const override;

protected:
  vtkRefractionMethodSSP() = default;
  ~vtkRefractionMethodSSP() override = default;

private:
  vtkRefractionMethodSSP(const vtkRefractionMethodSSP&) = delete;
  void operator=(const vtkRefractionMethodSSP&) = delete;
};

#endif
