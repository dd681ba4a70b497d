/**
 * @class   vtkRefractionLights
 * @brief   The renderer's lights in view space, for the glass's highlights.
 *
 * The refraction is shaded in a full-screen stage, where VTK's light uniforms are not set:
 * this class reads the renderer's switched-on lights (headlight, camera lights, scene lights,
 * a vtkLightKit's) each frame, as VTK's own shaders see them (the light's transformed position
 * and focal point, colour = diffuse colour times intensity), and keeps them in view
 * coordinates: xyz and w = 0 for a direction towards a directional light, w = 1 for a
 * positional light's position. Spot cones and attenuation are not applied.
 */
#ifndef vtkRefractionLights_h
#define vtkRefractionLights_h

#include "vtkObject.h"

#include <vector> // For members

class vtkRenderer;

class vtkRefractionLights : public vtkObject
{
public:
  static vtkRefractionLights* New();
  vtkTypeMacro(vtkRefractionLights, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The most lights the highlights follow (the first ones switched on).
  static constexpr int MaximumLights = 8;

  /// Reads the renderer's lights; call after VTK has placed its camera lights for the frame.
  void Update(vtkRenderer* ren);

  int GetNumberOfLights() const { return static_cast<int>(this->Colours.size() / 3); }
  /// 4 floats per light: view-space direction to the light (w = 0) or position (w = 1).
  const std::vector<float>& GetPositions() const { return this->Positions; }
  /// 3 floats per light: colour times intensity.
  const std::vector<float>& GetColours() const { return this->Colours; }

protected:
  vtkRefractionLights() = default;
  ~vtkRefractionLights() override = default;

private:
  vtkRefractionLights(const vtkRefractionLights&) = delete;
  void operator=(const vtkRefractionLights&) = delete;

  std::vector<float> Positions;
  std::vector<float> Colours;
};

#endif
