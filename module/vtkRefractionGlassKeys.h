/**
 * @class   vtkRefractionGlassKeys
 * @brief   A prop's glass settings, kept on its property keys: written and read here.
 *
 * What the pass's stages read of a glass prop (is it glass, its index of refraction, its
 * dispersion, its surface model) and the point array ISR reads, in a header of its own so
 * that the stages need not include vtkRefractionPass.h for them. vtkRefractionPass publishes
 * the same functions and forwards them here.
 */
#ifndef vtkRefractionGlassKeys_h
#define vtkRefractionGlassKeys_h

class vtkInformationDoubleKey;
class vtkInformationDoubleVectorKey;
class vtkInformationIntegerKey;
class vtkProp;

class vtkRefractionGlassKeys
{
public:
  /// The point array ISR reads d_N from (vtkISRDistanceFilter writes it).
  static const char* GetISRDistanceArrayName() { return "ISRNormalDistance"; }

  ///@{
  /// The keys on the prop's property keys (vtkRefractionPass::GLASS() and the others).
  static vtkInformationIntegerKey* GLASS();
  static vtkInformationDoubleKey* INDEX_OF_REFRACTION();
  static vtkInformationIntegerKey* SURFACE_MODEL();
  static vtkInformationDoubleVectorKey* DISPERSION();
  ///@}

  /// The values of SURFACE_MODEL (vtkRefractionPass::SurfaceModelType, which must agree).
  enum SurfaceModelType
  {
    SURFACE_AUTO = -1,
    SURFACE_SOLID = 0,
    SURFACE_THIN_SHEET = 1
  };

  /// What MakeGlass gives an actor whose property still has VTK's default specular terms.
  static constexpr double DefaultGlassSpecular = 1.0;
  static constexpr double DefaultGlassSpecularPower = 100.0;

  ///@{
  /// As vtkRefractionPass's functions of the same names, which document them.
  static bool MakeGlass(vtkProp* prop, double indexOfRefraction);
  static void ClearGlass(vtkProp* prop);
  static bool IsGlass(vtkProp* prop);
  static double GetIndexOfRefraction(vtkProp* prop);
  static void SetSurfaceModel(vtkProp* prop, int model);
  static bool SetDispersion(vtkProp* prop, double red, double green, double blue);
  static void ClearDispersion(vtkProp* prop);
  static bool GetDispersion(vtkProp* prop, double rgb[3]);
  ///@}

  vtkRefractionGlassKeys() = delete;
};

#endif
