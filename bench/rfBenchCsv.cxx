#include "rfBenchCsv.h"

#include "vtkRefractionPass.h"

#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <utility>

namespace rfbench
{
namespace
{
// One CSV column: its name, how a row writes it and how a row reads it back.
struct Column
{
  std::string Name;
  std::function<std::string(const Row&)> Get;
  std::function<void(Row&, const std::string&)> Set;
};

std::string Number(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

std::vector<Column> Columns(int stageCount)
{
  std::vector<Column> c;
  auto text = [&c](const char* name, std::function<std::string(const Row&)> get,
                std::function<void(Row&, const std::string&)> set) {
    c.push_back({ name, std::move(get), std::move(set) });
  };
  auto number = [&c](const std::string& name, std::function<double&(Row&)> field) {
    c.push_back({ name,
      [field](const Row& r) { return Number(field(const_cast<Row&>(r))); },
      [field](Row& r, const std::string& v) { field(r) = std::atof(v.c_str()); } });
  };
  text("mesh", [](const Row& r) { return r.Mesh; }, [](Row& r, const std::string& v) { r.Mesh = v; });
  c.push_back({ "triangles", [](const Row& r) { return std::to_string(r.Triangles); },
    [](Row& r, const std::string& v) { r.Triangles = std::atoll(v.c_str()); } });
  c.push_back({ "size", [](const Row& r) { return std::to_string(r.Size); },
    [](Row& r, const std::string& v) { r.Size = std::atoi(v.c_str()); } });
  text("method", [](const Row& r) { return r.Config.Method; },
    [](Row& r, const std::string& v) { r.Config.Method = v; });
  c.push_back({ "steps", [](const Row& r) { return std::to_string(r.Config.Steps); },
    [](Row& r, const std::string& v) { r.Config.Steps = std::atoi(v.c_str()); } });
  text("depth_range", [](const Row& r) { return std::string(r.Config.Bounds ? "bbox" : "reduction"); },
    [](Row& r, const std::string& v) { r.Config.Bounds = v == "bbox"; });
  c.push_back({ "adaptive", [](const Row& r) { return std::string(r.Config.Adaptive ? "1" : "0"); },
    [](Row& r, const std::string& v) { r.Config.Adaptive = v == "1"; } });
  text("back_surface", [](const Row& r) { return std::string(r.Config.Nearest ? "nearest" : "furthest"); },
    [](Row& r, const std::string& v) { r.Config.Nearest = v == "nearest"; });
  c.push_back({ "secant", [](const Row& r) { return std::string(r.Config.Paper ? "0" : "1"); },
    [](Row& r, const std::string& v) { r.Config.Paper = v == "0"; } });
  c.push_back({ "scene_refraction",
    [](const Row& r) { return std::string(r.Config.NoScene ? "0" : "1"); },
    [](Row& r, const std::string& v) { r.Config.NoScene = v == "0"; } });
  c.push_back({ "tir_bounces", [](const Row& r) { return std::to_string(r.Config.Bounces); },
    [](Row& r, const std::string& v) { r.Config.Bounces = std::atoi(v.c_str()); } });
  c.push_back({ "exit_reflection",
    [](const Row& r) { return std::string(r.Config.ExitReflection ? "1" : "0"); },
    [](Row& r, const std::string& v) { r.Config.ExitReflection = v == "1"; } });
  c.push_back({ "peel_layers", [](const Row& r) { return std::to_string(r.Config.Layers); },
    [](Row& r, const std::string& v) { r.Config.Layers = std::atoi(v.c_str()); } });
  c.push_back({ "anti_aliasing",
    [](const Row& r) { return std::string(r.Config.AntiAliasing ? "1" : "0"); },
    [](Row& r, const std::string& v) { r.Config.AntiAliasing = v == "1"; } });
  c.push_back({ "multisample_silhouette",
    [](const Row& r) { return std::string(r.Config.PixelComposite ? "0" : "1"); },
    [](Row& r, const std::string& v) { r.Config.PixelComposite = v == "0"; } });
  c.push_back({ "filtered_lookups",
    [](const Row& r) { return std::string(r.Config.PointLookups ? "0" : "1"); },
    [](Row& r, const std::string& v) { r.Config.PointLookups = v == "0"; } });
  c.push_back({ "smooth_internal_reflections",
    [](const Row& r) { return std::string(r.Config.Smooth ? "1" : "0"); },
    [](Row& r, const std::string& v) { r.Config.Smooth = v == "1"; } });
  c.push_back({ "coarse_shading",
    [](const Row& r) { return std::string(r.Config.Coarse ? "1" : "0"); },
    [](Row& r, const std::string& v) { r.Config.Coarse = v == "1"; } });
  c.push_back({ "repeats", [](const Row& r) { return std::to_string(r.Repeats); },
    [](Row& r, const std::string& v) { r.Repeats = std::atoi(v.c_str()); } });
  number("cpu_ms", [](Row& r) -> double& { return r.CpuMs.Median; });
  number("cpu_ms_min", [](Row& r) -> double& { return r.CpuMs.Min; });
  number("cpu_ms_max", [](Row& r) -> double& { return r.CpuMs.Max; });
  number("plain_cpu_ms", [](Row& r) -> double& { return r.PlainCpuMs.Median; });
  number("plain_cpu_ms_min", [](Row& r) -> double& { return r.PlainCpuMs.Min; });
  number("plain_cpu_ms_max", [](Row& r) -> double& { return r.PlainCpuMs.Max; });
  number("cpu_ratio", [](Row& r) -> double& { return r.Ratio.Median; });
  number("cpu_ratio_min", [](Row& r) -> double& { return r.Ratio.Min; });
  number("cpu_ratio_max", [](Row& r) -> double& { return r.Ratio.Max; });
  number("gpu_frame_ms", [](Row& r) -> double& { return r.GpuFrameMs; });
  number("plain_gpu_ms", [](Row& r) -> double& { return r.PlainGpuMs; });
  for (int s = 0; s < stageCount; ++s)
  {
    number("gpu_stage" + std::to_string(s) + "_ms", [s](Row& r) -> double& {
      if (static_cast<int>(r.StageMs.size()) <= s)
        r.StageMs.resize(s + 1, -1.0);
      return r.StageMs[s];
    });
  }
  number("precompute_ms", [](Row& r) -> double& { return r.PrecomputeMs; });
  number("ref_two_ms", [](Row& r) -> double& { return r.RefTwoMs; });
  number("ref_full_ms", [](Row& r) -> double& { return r.RefFullMs; });
  number("ref_full_ss_ms", [](Row& r) -> double& { return r.RefFullSSMs; });
  number("bytes_per_pixel", [](Row& r) -> double& { return r.BytesPerPixel; });
  const std::pair<const char*, Errors Row::*> references[] = { { "two", &Row::Two },
    { "full", &Row::Full }, { "two_ss", &Row::TwoSS }, { "full_ss", &Row::FullSS },
    { "one_ray_full_ss", &Row::OneRay }, { "few_rays_full_ss", &Row::FewRays } };
  for (const auto& ref : references)
  {
    const std::string suffix = ref.first;
    Errors Row::*member = ref.second;
    number("psnr_" + suffix, [member](Row& r) -> double& { return (r.*member).Psnr; });
    number("rmse_" + suffix, [member](Row& r) -> double& { return (r.*member).Rmse; });
    number("ssim_" + suffix, [member](Row& r) -> double& { return (r.*member).Ssim; });
    number("psnr_" + suffix + "_tir", [member](Row& r) -> double& { return (r.*member).PsnrTir; });
    number("psnr_" + suffix + "_rest", [member](Row& r) -> double& { return (r.*member).PsnrRest; });
    number("psnr_" + suffix + "_rim", [member](Row& r) -> double& { return (r.*member).PsnrRim; });
    number("psnr_" + suffix + "_edge", [member](Row& r) -> double& { return (r.*member).PsnrEdge; });
  }
  number("psnr_model_full_ss", [](Row& r) -> double& { return r.PsnrModelFullSS; });
  number("brightness_full_ss", [](Row& r) -> double& { return r.BrightnessFullSS; });
  c.push_back({ "few_rays_side", [](const Row& r) { return std::to_string(r.FewRaysSide); },
    [](Row& r, const std::string& v) { r.FewRaysSide = std::atoi(v.c_str()); } });
  number("ref_ss_convergence_psnr", [](Row& r) -> double& { return r.PsnrSSConvergence; });
  number("ref_ss_convergence_psnr_rim", [](Row& r) -> double& { return r.PsnrSSConvergenceRim; });
  number("ref_ss_convergence_psnr_tir", [](Row& r) -> double& { return r.PsnrSSConvergenceTir; });
  number("t2_deg_mean", [](Row& r) -> double& { return r.AngMean; });
  number("t2_deg_p95", [](Row& r) -> double& { return r.AngP95; });
  number("t2_deg_max", [](Row& r) -> double& { return r.AngMax; });
  number("p2_rel_mean", [](Row& r) -> double& { return r.P2Mean; });
  number("p2_rel_max", [](Row& r) -> double& { return r.P2Max; });
  number("tir_share", [](Row& r) -> double& { return r.TirShare; });
  number("ref_tir_share", [](Row& r) -> double& { return r.RefTirShare; });
  c.push_back({ "pixels", [](const Row& r) { return std::to_string(r.Pixels); },
    [](Row& r, const std::string& v) { r.Pixels = std::atol(v.c_str()); } });
  c.push_back({ "tir_pixels", [](const Row& r) { return std::to_string(r.TirPixels); },
    [](Row& r, const std::string& v) { r.TirPixels = std::atol(v.c_str()); } });
  c.push_back({ "peel_layers_found",
    [](const Row& r) { return std::to_string(r.PeelLayersFound); },
    [](Row& r, const std::string& v) { r.PeelLayersFound = std::atoi(v.c_str()); } });
  c.push_back({ "peel_draws", [](const Row& r) { return std::to_string(r.PeelDraws); },
    [](Row& r, const std::string& v) { r.PeelDraws = std::atoi(v.c_str()); } });
  return c;
}
}

bool WriteCsv(const std::string& path, const std::vector<Row>& rows, const std::string& renderer)
{
  std::ofstream f(path);
  const auto columns = Columns(vtkRefractionPass::TIMED_STAGE_COUNT);
  f << "renderer";
  for (const auto& column : columns)
    f << ',' << column.Name;
  f << '\n';
  for (const Row& r : rows)
  {
    f << '"' << renderer << '"';
    for (const auto& column : columns)
      f << ',' << column.Get(r);
    f << '\n';
  }
  f.flush();
  return static_cast<bool>(f);
}

namespace
{
std::vector<std::string> CsvFields(const std::string& text)
{
  std::vector<std::string> out(1);
  bool quoted = false;
  for (char c : text)
  {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}
}

// Rows back from a results.csv written by WriteCsv, to remake results.md and pareto.png.
bool ReadCsv(const std::string& path, std::vector<Row>& rows, std::string& renderer)
{
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line))
  {
    return false;
  }
  const auto header = CsvFields(line);
  int stageCount = 0;
  for (const auto& name : header)
    stageCount += name.rfind("gpu_stage", 0) == 0 ? 1 : 0;
  const auto columns = Columns(stageCount);
  while (std::getline(in, line))
  {
    const auto f = CsvFields(line);
    if (f.size() != header.size())
      continue;
    Row r;
    for (size_t i = 0; i < f.size(); ++i)
    {
      if (header[i] == "renderer")
        renderer = f[i];
      for (const auto& column : columns)
        if (column.Name == header[i])
          column.Set(r, f[i]);
    }
    rows.push_back(r);
  }
  return !rows.empty();
}
}
