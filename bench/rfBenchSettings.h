// The rows a run measures: one setting of the pass each (method, search, anti-aliasing, TIR,
// PEEL's layers), the presets' lists of them, and how a setting is applied to the pass.
#ifndef rfBenchSettings_h
#define rfBenchSettings_h

#include "rfBenchOptions.h"

#include <sstream>
#include <string>
#include <vector>

class vtkRefractionPass;

namespace rfbench
{
struct Setting
{
  std::string Method; // none (the pass without glass), SIR, DIR, ISR, SSP, PEEL, SH
  int Steps = 5;
  bool Bounds = false;
  bool Adaptive = false;
  bool Nearest = false;
  bool Paper = false; // the paper's search exactly: no secant refinement
  bool NoScene = false; // SetSceneRefraction(false): the opaque scene is not refracted (NG off)
  bool AntiAliasing = false; // SetAntiAliasing(true): four rays per pixel
  bool PixelComposite = false; // SetMultiSampleSilhouette(false): composited pixel by pixel
  int Bounces = 0;           // SetTIRBounces: total internal reflections followed
  bool ExitReflection = false; // SetExitReflection: the exit's reflected share followed
  int Layers = 0;            // PEEL: SetPeelLayers (K)
  bool PointLookups = false; // SetFilteredLookups(false): one direction per ray
  bool Smooth = false;       // SetSmoothInternalReflections(true)
  bool Coarse = false;       // SetCoarseShading(true): one ray per 2x2 block where smooth
  std::string Label() const
  {
    std::ostringstream s;
    s << Method;
    if (Method == "PEEL")
    {
      s << " " << Layers;
    }
    if (Method == "DIR")
    {
      s << (Adaptive ? " adaptive<=" : " ") << Steps << (Bounds ? " bbox" : "")
        << (Nearest ? " nearest" : "") << (Paper ? " paper" : "");
    }
    s << (NoScene ? " NG off" : "") << (AntiAliasing ? " AA" : "")
      << (PixelComposite ? " px" : "") << (PointLookups ? " point" : "");
    if (Bounces > 0)
    {
      s << " TIR " << Bounces;
    }
    s << (ExitReflection ? " exit" : "") << (Smooth ? " smooth" : "")
      << (Coarse ? " coarse" : "");
    return s.str();
  }
};

// The preset's rows, less the methods --methods leaves out.
std::vector<Setting> Settings(const Options& o);

// The scene mesh's rows: DIR 5 refracting the opaque scene (NG) and the same without it.
std::vector<Setting> SceneSettings();

// Sets every property of the pass a setting names.
void Apply(vtkRefractionPass* pass, const Setting& setting);
}

#endif
