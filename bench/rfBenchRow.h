// One row of the results: a setting on a mesh at a size, with its times over the repeats and
// its errors against the references; what results.csv and results.md are made of.
#ifndef rfBenchRow_h
#define rfBenchRow_h

#include "rfBenchSettings.h"
#include "rfSpread.h"

#include <vtkType.h>

#include <string>
#include <vector>

namespace rfbench
{
// Error of one picture against one reference, on glass pixels, split by TIR; on the
// silhouette's glass pixels (Rim: those the supersampled full reference covers only in part);
// and on the whole silhouette (Edge: every pixel that reference covers in part, whatever the
// picture's or the reference's pixel centre sees, so that what a picture does to the
// background side of its rim counts too; -1 over a gradient background, which the truth's
// sub-samples that miss the glass do not follow).
struct Errors
{
  double Psnr = -1, Rmse = -1, Ssim = -1, PsnrTir = -1, PsnrRest = -1, PsnrRim = -1,
         PsnrEdge = -1;
};

// Medians and extremes over the repeats of one row.
using Spread = rftiming::Spread;

struct Row
{
  std::string Mesh;
  vtkIdType Triangles = 0;
  int Size = 0;
  Setting Config;
  int Repeats = 0;
  Spread CpuMs, PlainCpuMs, Ratio;
  double GpuFrameMs = -1, PlainGpuMs = -1;
  std::vector<double> StageMs; // medians, one per vtkRefractionPass timed stage
  double PrecomputeMs = 0, RefTwoMs = 0, RefFullMs = 0, RefFullSSMs = 0, BytesPerPixel = 0;
  Errors Two, Full, TwoSS, FullSS;
  // The two-interface model's own error: its supersampled reference against the supersampled
  // full one, on the row's glass pixels (the floor a method of that model can reach).
  double PsnrModelFullSS = -1;
  // The exact trace at one ray per pixel centre (the full reference) against the supersampled
  // full one, on the row's glass pixels and their parts: what one sample a pixel costs,
  // whatever the refraction does (a method that filters may read better; one that samples a
  // pixel once and follows the path exactly reads this).
  Errors OneRay;
  // The same at half `full SS`'s rays per pixel side (FewRaysSide, 2 or more; -1 and 0 where
  // the truth has fewer than 4 x 4).
  Errors FewRays;
  int FewRaysSide = 0;
  // Mean colour of the picture over the supersampled full reference's, on the glass pixels:
  // light lost or gained (1 is as bright as the truth).
  double BrightnessFullSS = -1;
  // The supersampled full reference against the same traced at twice the samples per side, on
  // the glass the reference sees (--convergence; -1 without): how converged the truth is; and
  // on its parts: the rim (the pixels the truth's sub-samples cover in part) and the pixels
  // whose two-interface ray is totally reflected at the exit (-1: none).
  double PsnrSSConvergence = -1, PsnrSSConvergenceRim = -1, PsnrSSConvergenceTir = -1;
  double AngMean = 0, AngP95 = 0, AngMax = 0, P2Mean = 0, P2Max = 0, TirShare = 0,
         RefTirShare = 0;
  long Pixels = 0, TirPixels = 0;
  // PEEL: the layers found holding glass and the draws that captured them, in the frame scored
  // (vtkRefractionPass::GetPeelLayersFound, GetPeelLayersDrawn; 0 for the other methods). The
  // shading follows only the layers found, so two runs that score a row differently can say
  // whether they found different layers.
  int PeelLayersFound = 0, PeelDraws = 0;
};
}

#endif
