// Error against the reference: the Embree reference's pictures of a mesh at a size (traced
// through vtkRefractionReference), and a row's errors against them (rf_metrics).
#ifndef rfBenchReference_h
#define rfBenchReference_h

#include "rfBenchRow.h"

#include <string>
#include <vector>

class vtkImageData;
class vtkRefractionPass;
class vtkRenderer;

namespace rfbench
{
struct Reference
{
  std::vector<float> Colour, P2, T2;
  std::vector<unsigned char> Hit, Tir;
  double Seconds = 0;
  double Diagonal = 1;
};

// The four references of one mesh at one size.
struct Truth
{
  Reference Two, Full, TwoSS, FullSS;
};

// Traces the renderer's scene as the pass sees it (mode: vtkRefractionReference's, samples
// per pixel side), its progress on one line under `label`; false when it cannot.
bool Trace(vtkRenderer* renderer, vtkRefractionPass* pass, int size, int mode, int samples,
  const std::string& label, Reference& out);

// Fills the row's errors of `colour` (with the pass's debug image) against the references.
void Measure(Row& row, const std::vector<float>& colour, vtkImageData* debug, const Truth& truth,
  int size);
}

#endif
