#include "rfBenchSettings.h"

#include "vtkRefractionPass.h"

#include <algorithm>

namespace rfbench
{
namespace
{
std::vector<Setting> PresetSettings(const Options& o)
{
  std::vector<Setting> settings;
  // The pass's default (IsDefaultSetting): DIR, 5 steps, the exit's reflection followed.
  // {"DIR", 5} alone is the paper's two-interface model.
  Setting defaults{ "DIR", 5 };
  defaults.ExitReflection = true;
  Setting antiAliased{ "DIR", 5 };
  antiAliased.AntiAliasing = true;
  Setting bounces{ "DIR", 5 };
  bounces.Bounces = 2;
  auto exitFollowed = [](Setting setting) {
    setting.ExitReflection = true;
    return setting;
  };
  const Setting bouncesAndExit = exitFollowed(bounces);
  auto peel = [](int layers, int tirBounces) {
    Setting setting{ "PEEL", 0 };
    setting.Layers = layers;
    setting.Bounces = tirBounces;
    return setting;
  };
  auto smoothed = [](Setting setting) {
    setting.Smooth = true;
    return setting;
  };
  Setting coarse{ "DIR", 5 };
  coarse.Coarse = true;
  if (o.Quick)
  {
    // The default, what each option changes from it, and the two-interface model.
    settings.push_back(defaults);
    Setting point = defaults;
    point.PointLookups = true; // what the filtered lookups gain
    settings.push_back(point);
    settings.push_back(exitFollowed(antiAliased));
    settings.push_back(exitFollowed(coarse));
    if (o.MultiSamples > 0)
    {
      for (Setting pixelwise : { defaults, exitFollowed(antiAliased) })
      {
        pixelwise.PixelComposite = true;
        settings.push_back(pixelwise);
      }
    }
    settings.push_back({ "DIR", 5 });
    settings.push_back(bouncesAndExit);
    settings.push_back(smoothed(defaults));
    settings.push_back(smoothed(bouncesAndExit));
    settings.push_back({ "SIR", 0 });
    for (int layers : { 2, 4, 8 })
      settings.push_back(peel(layers, 0));
    settings.push_back(peel(4, 2));
    settings.push_back(smoothed(peel(4, 2)));
    // Every interface of nested glass and its internal reflections: what PEEL's closest costs.
    settings.push_back(smoothed(peel(8, 2)));
    settings.push_back({ "SH", 0 });
    return settings;
  }
  if (o.Smoke)
  {
    for (const char* method : { "SIR", "DIR", "ISR", "SSP" })
      settings.push_back({ method, 5 });
    settings.push_back(peel(4, 2));
    settings.push_back({ "SH", 0 });
    return settings;
  }
  settings.push_back({ "none", 0 });
  settings.push_back({ "SIR", 0 });
  for (int bounds = 0; bounds < 2; ++bounds)
  {
    for (int s : { 0, 1, 2, 3, 5, 8 })
    {
      settings.push_back({ "DIR", s, bounds == 1 });
    }
  }
  settings.push_back({ "DIR", 8, false, true });
  settings.push_back({ "DIR", 5, false, false, true });
  settings.push_back({ "DIR", 5, false, false, false, true });
  settings.push_back(antiAliased);
  settings.push_back(coarse);
  settings.push_back(bounces);
  settings.push_back(defaults);
  settings.push_back(bouncesAndExit);
  settings.push_back(smoothed({ "DIR", 5 }));
  settings.push_back(smoothed(bouncesAndExit));
  settings.push_back({ "ISR", 0 });
  settings.push_back({ "SSP", 0 });
  for (int layers : { 2, 4, 8 })
    for (int tirBounces : { 0, 2, 4 })
      settings.push_back(peel(layers, tirBounces));
  settings.push_back(smoothed(peel(4, 2)));
  settings.push_back({ "SH", 0 });
  return settings;
}
}

// The preset's rows, less the methods --methods leaves out.
std::vector<Setting> Settings(const Options& o)
{
  std::vector<Setting> settings;
  for (const Setting& setting : PresetSettings(o))
  {
    if (o.Methods.empty() ||
      std::find(o.Methods.begin(), o.Methods.end(), setting.Method) != o.Methods.end())
    {
      settings.push_back(setting);
    }
  }
  return settings;
}

// The scene mesh's rows: DIR 5 refracting the opaque scene (NG) and the same without it.
std::vector<Setting> SceneSettings()
{
  Setting on{ "DIR", 5 };
  Setting off = on;
  off.NoScene = true;
  return { on, off };
}

namespace
{
int MethodId(const std::string& m)
{
  return m == "SIR"   ? vtkRefractionPass::SIR
    : m == "ISR"        ? vtkRefractionPass::ISR
    : m == "SSP"        ? vtkRefractionPass::SSP
    : m == "PEEL"       ? vtkRefractionPass::PEEL
    : m == "SH"         ? vtkRefractionPass::SH
                        : vtkRefractionPass::DIR;
}
}

void Apply(vtkRefractionPass* pass, const Setting& setting)
{
  pass->SetMethod(MethodId(setting.Method));
  pass->SetSearchSteps(setting.Steps);
  pass->SetDepthRangeMode(setting.Bounds ? vtkRefractionPass::DEPTH_RANGE_BOUNDS
                                         : vtkRefractionPass::DEPTH_RANGE_REDUCTION);
  pass->SetAdaptiveSearch(setting.Adaptive);
  pass->SetBackSurface(setting.Nearest ? vtkRefractionPass::BACK_SURFACE_NEAREST
                                       : vtkRefractionPass::BACK_SURFACE_FURTHEST);
  pass->SetSecantRefinement(!setting.Paper);
  pass->SetSceneRefraction(!setting.NoScene);
  pass->SetAntiAliasing(setting.AntiAliasing);
  pass->SetMultiSampleSilhouette(!setting.PixelComposite);
  pass->SetTIRBounces(setting.Bounces);
  pass->SetExitReflection(setting.ExitReflection);
  pass->SetPeelLayers(std::max(setting.Layers, 2));
  pass->SetFilteredLookups(!setting.PointLookups);
  pass->SetSmoothInternalReflections(setting.Smooth);
  pass->SetCoarseShading(setting.Coarse);
}
}
