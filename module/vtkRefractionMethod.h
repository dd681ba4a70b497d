/**
 * @class   vtkRefractionMethod
 * @brief   What one refraction method needs from vtkRefractionPass: targets, stages, shader.
 *
 * Each method (vtkRefractionMethodSIR, -DIR, -ISR, -SSP) says which render targets and which
 * stages it needs, the defines and GLSL of its part of the shading stage (the function
 * rfFindExit and the transmitted colour), and its uniforms. The pass orchestrates; it runs
 * only what the method asks for, so a method costs what it uses.
 */
#ifndef vtkRefractionMethod_h
#define vtkRefractionMethod_h

#include "vtkObject.h"
#include "vtkSmartPointer.h" // For Create

#include <ostream> // For AppendDefines
#include <string>  // For GetShaderSource
#include <vector>  // For AddTargets

class vtkRefractionPass;
class vtkShaderProgram;

class vtkRefractionMethod : public vtkObject
{
public:
  vtkTypeMacro(vtkRefractionMethod, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The method object of a vtkRefractionPass::MethodType (nullptr for an unknown one).
  static vtkSmartPointer<vtkRefractionMethod> Create(int method);

  virtual const char* GetName() const = 0;
  /// The back-surface capture (DIR pass 1).
  virtual bool NeedsBackSurface() const { return false; }
  /// The min/max back depth (DIR pass 2).
  virtual bool NeedsDepthRange() const { return false; }
  /// The opaque scene's colour and the refraction mask (SSP).
  virtual bool NeedsSceneColor() const { return false; }
  /// Whether the ray leaving the glass may be followed through the captured opaque scene.
  virtual bool SupportsSceneRefraction() const { return true; }
  /// ISR's d_N in the G-buffer.
  virtual bool NeedsNormalDistance() const { return false; }
  /// The SH method's per-vertex exit directions in the G-buffer (FRONT_SH).
  virtual bool NeedsSHTransfer() const { return false; }
  /// Depth-peeled layers of the glass, counting the front G-buffer as layer 0 (PEEL); 1: none.
  virtual int GetPeelLayers(vtkRefractionPass*) const { return 1; }

  /// Flags the render targets (vtkRefractionTargets::TargetType) the method reads.
  void AddTargets(std::vector<bool>& wanted, vtkRefractionPass* settings) const;
  /// Its defines for the shading stage.
  virtual void AppendDefines(std::ostream& defines, vtkRefractionPass* settings) const;
  /// Its GLSL for the shading stage (rfFindExit, rfFresnelWeight, rfTransmittedColour).
  virtual std::string GetShaderSource() const = 0;
  /// Its scalar uniforms (the pass binds the targets' samplers by name).
  virtual void SetUniforms(vtkShaderProgram* program, vtkRefractionPass* settings,
    const double boundsDepthRange[2]) const;

protected:
  vtkRefractionMethod() = default;
  ~vtkRefractionMethod() override = default;

private:
  vtkRefractionMethod(const vtkRefractionMethod&) = delete;
  void operator=(const vtkRefractionMethod&) = delete;
};

#endif
