/**
 * @class   vtkWaveEquationSource
 * @brief   The scalar wave equation u_tt = c^2 laplace(u) solved on a regular grid, in time.
 *
 * Produces a vtkImageData of SampleDimensions^3 points covering the box [-1,1]^3 with one
 * float point scalar array, "u": the displacement at the requested time. At t = 0 the field
 * is a sum of NumberOfPulses Gaussian bumps of amplitude 1 and width PulseWidth at rest; the
 * walls hold u = 0 (a closed drum), so the pulses spread as shells, reflect from the walls
 * and interfere, and the energy stays in the box. Contouring u at IsoValue gives closed
 * surfaces that split, grow and merge: a deforming isosurface a physicist recognises.
 *
 * The scheme is the standard second-order leapfrog with the 7-point Laplacian, its time step
 * chosen at half the CFL limit (c dt / h <= 1/sqrt(3)) and shortened so that every
 * advertised time step is hit exactly. The source advertises NumberOfTimeSteps time steps
 * k * EndTime / (NumberOfTimeSteps - 1) and the range [0, EndTime]; any time in the range
 * may be requested. It keeps the last state: a request later than it continues from there,
 * an earlier one starts again from t = 0. Long integrations report ProgressEvent.
 *
 * @code
 * vtkNew<vtkWaveEquationSource> waves;
 * vtkNew<vtkFlyingEdges3D> surface;
 * surface->SetInputConnection(waves->GetOutputPort());
 * surface->SetValue(0, waves->GetIsoValue());
 * @endcode
 */

#ifndef vtkWaveEquationSource_h
#define vtkWaveEquationSource_h

#include "vtkImageAlgorithm.h"
#include "vtkRefractionDataModule.h" // For export macro

#include <vector> // For the kept state

class VTKREFRACTIONDATA_EXPORT vtkWaveEquationSource : public vtkImageAlgorithm
{
public:
  static vtkWaveEquationSource* New();
  vtkTypeMacro(vtkWaveEquationSource, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Grid points along each axis (default 48, 8 to 512; the upper bound keeps a mistyped
   * value from asking for gigabytes).
   */
  vtkSetClampMacro(SampleDimensions, int, 8, 512);
  vtkGetMacro(SampleDimensions, int);
  ///@}

  ///@{
  /** Wave speed c (default 1: a wave crosses the box in 2 time units). */
  vtkSetClampMacro(WaveSpeed, double, 1.0e-3, 1.0e3);
  vtkGetMacro(WaveSpeed, double);
  ///@}

  ///@{
  /** Number of initial Gaussian pulses (1 to 4, default 3), at fixed places off the centre. */
  vtkSetClampMacro(NumberOfPulses, int, 1, 4);
  vtkGetMacro(NumberOfPulses, int);
  ///@}

  ///@{
  /** Width sigma of the pulses, exp(-r^2 / (2 sigma^2)) (default 0.15). */
  vtkSetClampMacro(PulseWidth, double, 0.02, 1.0);
  vtkGetMacro(PulseWidth, double);
  ///@}

  ///@{
  /** Number of advertised time steps (at least 2, default 60). */
  vtkSetClampMacro(NumberOfTimeSteps, int, 2, 100000);
  vtkGetMacro(NumberOfTimeSteps, int);
  ///@}

  ///@{
  /** The last advertised time (default 2.0, positive). */
  vtkSetClampMacro(EndTime, double, 1.0e-6, 1.0e6);
  vtkGetMacro(EndTime, double);
  ///@}

  ///@{
  /**
   * The contour value the field is designed for (default 0.08: low enough that the shells
   * leaving the pulses stay visible until their reflections gather again); the source does
   * not use it, a pipeline can ask for it.
   */
  vtkSetMacro(IsoValue, double);
  vtkGetMacro(IsoValue, double);
  ///@}

  /** Leapfrog steps taken from t = 0 for the last output (for tests and reports). */
  vtkGetMacro(StepsFromStart, int);

protected:
  vtkWaveEquationSource();
  ~vtkWaveEquationSource() override = default;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int SampleDimensions;
  double WaveSpeed;
  int NumberOfPulses;
  double PulseWidth;
  int NumberOfTimeSteps;
  double EndTime;
  double IsoValue;
  int StepsFromStart;

private:
  vtkWaveEquationSource(const vtkWaveEquationSource&) = delete;
  void operator=(const vtkWaveEquationSource&) = delete;

  void Restart(double dt);
  void Step(double courantSquared);
  double StepLength() const;

  // The kept state: u at the last two steps, and which step that is.
  std::vector<float> Previous;
  std::vector<float> Current;
  vtkMTimeType StateTime = 0;
};

#endif
