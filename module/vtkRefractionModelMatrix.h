/**
 * @class   vtkRefractionModelMatrix
 * @brief   What the geometry stage reads of a glass actor's model matrix.
 *
 * Whether the matrix mirrors (its determinant's sign flips the winding of the faces on
 * screen) and how much it scales (d_N is measured in model coordinates). Props that are not
 * actors have no matrix: determinant and scale 1.
 */
#ifndef vtkRefractionModelMatrix_h
#define vtkRefractionModelMatrix_h

class vtkProp;

class vtkRefractionModelMatrix
{
public:
  /// The determinant of the upper 3x3 of the actor's matrix (1 for a prop that is no actor).
  static double GetDeterminant(vtkProp* prop);
  /// The geometric mean of the lengths of the matrix's three axes (1 for no actor).
  static double GetScale(vtkProp* prop);

  vtkRefractionModelMatrix() = delete;
};

#endif
