/**
 * @class   vtkISRDistanceFilter
 * @brief   Adds ISR's per-vertex distance d_N to a vtkPolyData (Embree, on the CPU).
 *
 * Wyman's image-space refraction (ISR) interpolates the exit distance between d_V (along the
 * view ray, read from the back-face depth) and d_N, the distance from each vertex along its
 * inward normal to the far side of the mesh. d_N needs a ray cast per vertex, repeated
 * whenever the points change: put this filter between a deforming or re-contoured source
 * and the mapper, and vtkRefractionPass (method ISR) reads the point array it adds,
 * "ISRNormalDistance". GetLastComputeSeconds() is the cost of the last update — the cost DIR
 * avoids.
 *
 * Point normals are taken from the input when present, else computed (without splitting,
 * so point ids are kept) and added to the output. The filter reports ProgressEvent at the
 * start, after each preparation stage and at the end (the ray casts are one step). The rays
 * are cast in Embree's packets of 8 on Threads threads.
 */
#ifndef vtkISRDistanceFilter_h
#define vtkISRDistanceFilter_h

#include "vtkPolyDataAlgorithm.h"
#include "rf_reference_export.h"  // For export macro

class RF_REFERENCE_EXPORT vtkISRDistanceFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkISRDistanceFilter* New();
  vtkTypeMacro(vtkISRDistanceFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The name of the point array the filter adds and the pass reads.
  static const char* GetArrayName() { return "ISRNormalDistance"; }

  /// Wall-clock seconds of the last update (normals, triangulation and ray casts).
  vtkGetMacro(LastComputeSeconds, double);

  /// Threads the ray casts run on (default: vtkMultiThreader's global default, the machine's
  /// cores unless VTK_MAX_THREADS says otherwise).
  vtkSetClampMacro(Threads, int, 1, 256);
  vtkGetMacro(Threads, int);

protected:
  vtkISRDistanceFilter();
  ~vtkISRDistanceFilter() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double LastComputeSeconds = 0.0;
  int Threads = 1;

private:
  vtkISRDistanceFilter(const vtkISRDistanceFilter&) = delete;
  void operator=(const vtkISRDistanceFilter&) = delete;
};

#endif
