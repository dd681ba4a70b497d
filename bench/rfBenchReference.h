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
  std::vector<float> Coverage; // share of a pixel's sub-samples that see glass
  std::vector<unsigned char> Hit, Tir;
  double Seconds = 0;
  double Diagonal = 1;
};

// The four references of one mesh at one size.
struct Truth
{
  Reference Two, Full, TwoSS, FullSS;
  Reference FullDoubleSS; // traced with --convergence only: twice FullSS's samples per side
  // Half FullSS's samples per side (traced where that is 2 or more): what a method that follows
  // every path exactly at a few samples a pixel, as a multisampled window's, would read.
  Reference FullHalfSS;
  // The renderer's background is one colour: the supersampled references' sub-samples that
  // miss the glass take it (rf_trace_options.background), so a picture's whole silhouette can
  // be held against them (Errors::PsnrEdge).
  bool SolidBackground = true;
};

// Traces the renderer's scene as the pass sees it (mode: vtkRefractionReference's, samples
// per pixel side), its progress on one line under `label`; false when it cannot.
bool Trace(vtkRenderer* renderer, vtkRefractionPass* pass, int size, int mode, int samples,
  const std::string& label, Reference& out);

// Fills the row's errors (with the pass's debug image) against the references: of `colour`
// against the supersampled ones, of `pointColour` (the same with one lookup direction per
// ray) against the one-ray ones.
void Measure(Row& row, const std::vector<float>& colour, const std::vector<float>& pointColour,
  vtkImageData* debug, const Truth& truth, int size);
}

#endif
