/**
 * @class   vtkMetaballsSource
 * @brief   Time-varying metaball field sampled on a regular grid.
 *
 * Produces a vtkImageData of SampleDimensions^3 points covering [-1,1]^3 with
 * one float point scalar array, "field", holding
 *
 *   f(x) = sum_i r^2 / |x - c_i(t)|^2
 *
 * for NumberOfBalls balls of radius BallRadius. Contouring the field at
 * IsoValue (1.0, where an isolated ball's surface is exactly its radius)
 * gives smooth blobs that merge and split as the balls move; with the
 * default settings the surface stays inside [-0.8,0.8]^3 and is therefore
 * closed. Many or large balls can reach the edge of the box, where the
 * surface is cut open.
 *
 * The motion is periodic with period TimePeriod and is exposed through the
 * pipeline: the source advertises NumberOfTimeSteps time steps
 * k * TimePeriod / NumberOfTimeSteps (k = 0 .. NumberOfTimeSteps-1, so that a
 * looping animation does not show the t = 0 state twice) and the time range
 * [0, TimePeriod]. Any time may be requested, not only the advertised steps.
 * Typical use:
 *
 * @code
 * vtkNew<vtkMetaballsSource> blobs;
 * vtkNew<vtkFlyingEdges3D> surface;
 * surface->SetInputConnection(blobs->GetOutputPort());
 * surface->SetValue(0, blobs->GetIsoValue());
 * surface->ComputeNormalsOn();
 * mapper->SetInputConnection(surface->GetOutputPort());
 * // Request the time on the algorithm the mapper pulls from (here the contour filter): a
 * // request on an algorithm further up leaves the filters below it at their old time step.
 * mapper->GetInputAlgorithm()->UpdateTimeStep(0.25);
 * renderWindow->Render();
 * @endcode
 */

#ifndef vtkMetaballsSource_h
#define vtkMetaballsSource_h

#include "vtkImageAlgorithm.h"
#include "vtkRefractionDataModule.h" // For export macro

class VTKREFRACTIONDATA_EXPORT vtkMetaballsSource : public vtkImageAlgorithm
{
public:
  static vtkMetaballsSource* New();
  vtkTypeMacro(vtkMetaballsSource, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of grid points along each axis (default 48). The upper bound keeps
   * a mistyped value from asking for many gigabytes.
   */
  vtkSetClampMacro(SampleDimensions, int, 2, 1024);
  vtkGetMacro(SampleDimensions, int);
  ///@}

  ///@{
  /**
   * Number of balls (1 to 16, default 4). Up to 4 balls the surface stays
   * inside [-0.8,0.8]^3; more balls make a bigger merged blob, which from
   * about 9 balls is cut open by the edge of the sampled box.
   */
  vtkSetClampMacro(NumberOfBalls, int, 1, 16);
  vtkGetMacro(NumberOfBalls, int);
  ///@}

  ///@{
  /**
   * Number of time steps advertised over one period (default 60).
   */
  vtkSetClampMacro(NumberOfTimeSteps, int, 1, VTK_INT_MAX);
  vtkGetMacro(NumberOfTimeSteps, int);
  ///@}

  ///@{
  /**
   * Duration of one period of the motion (default 1.0, must be positive).
   */
  vtkSetClampMacro(TimePeriod, double, 1.0e-9, VTK_DOUBLE_MAX);
  vtkGetMacro(TimePeriod, double);
  ///@}

  ///@{
  /**
   * Radius of every ball (default 0.30): the distance at which an isolated
   * ball's field equals 1. The paths are tuned for the default; with the
   * long inverse-square tails, balls much larger than 0.3 never separate
   * inside the box (already at 0.35 they stay one blob, or reach the edge
   * if the paths are widened to split them).
   */
  vtkSetClampMacro(BallRadius, double, 1.0e-3, 1.0);
  vtkGetMacro(BallRadius, double);
  ///@}

  ///@{
  /**
   * The contour value the field is designed for (default 1.0). The source
   * does not use it; it is here so that a pipeline can ask the source which
   * value to contour at.
   */
  vtkSetMacro(IsoValue, double);
  vtkGetMacro(IsoValue, double);
  ///@}

  /**
   * Centre of ball @a ball (0 .. NumberOfBalls-1) at time @a time, e.g. to
   * place glyphs or lights that follow the blobs.
   */
  void ComputeBallCenter(int ball, double time, double center[3]) const;

protected:
  vtkMetaballsSource();
  ~vtkMetaballsSource() override = default;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int SampleDimensions;
  int NumberOfBalls;
  int NumberOfTimeSteps;
  double TimePeriod;
  double BallRadius;
  double IsoValue;

private:
  vtkMetaballsSource(const vtkMetaballsSource&) = delete;
  void operator=(const vtkMetaballsSource&) = delete;
};

#endif
