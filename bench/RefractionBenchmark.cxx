// Error against run time: every method and setting on every mesh and resolution, timed
// against a plain VTK render of the same mesh in the same run, and compared with the Embree
// reference (two-interface: the image-space approximation's own error; full: what a user
// sees as wrong). Writes results.csv, results.md and pareto.png into --out.
//
//   RefractionBenchmark [--out DIR] [--sizes 256,512,1024] [--meshes sphere,torus,isosurface,bunny]
//                       [--frames N] [--smoke] [--x11] [--bunny PATH]
//
// Rendering goes through EGL (no X server) unless --x11 is given or EGL is not available.
#include "rf_metrics.h"
#include "vtkISRDistanceFilter.h"
#include "vtkMetaballsSource.h"
#include "vtkRefractionEGL.h"
#include "vtkRefractionPass.h"
#include "vtkRefractionReference.h"

#include <vtkActor.h>
#include <vtkAxis.h>
#include <vtkCamera.h>
#include <vtkChartLegend.h>
#include <vtkChartMatrix.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDataArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkOpenGLRenderTimer.h>
#include <vtkParametricFunctionSource.h>
#include <vtkParametricTorus.h>
#include <vtkPNGWriter.h>
#include <vtkPlot.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkRenderWindow.h>
#include <vtkRendererCollection.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTable.h>
#include <vtkTimerLog.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVector.h>
#include <vtkWindowToImageFilter.h>
#include <vtk_glew.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace
{
struct Options
{
  std::string Out;
  std::vector<int> Sizes{ 256, 512, 1024 };
  std::vector<std::string> Meshes{ "sphere", "torus", "isosurface", "bunny" };
  int Frames = 30;
  bool Smoke = false;
  bool X11 = false;
  bool Dump = false;
  std::string FromCsv;
  std::string Bunny = "/usr/share/glmark2/models/bunny.obj";
};

struct Setting
{
  std::string Method; // SIR, DIR, ISR, SSP
  int Steps = 5;
  bool Bounds = false;
  bool Adaptive = false;
  bool Nearest = false;
  bool Paper = false; // the paper's search exactly: no secant refinement
  std::string Label() const
  {
    std::ostringstream s;
    s << Method;
    if (Method == "DIR")
    {
      s << (Adaptive ? " adaptive<=" : " ") << Steps << (Bounds ? " bbox" : "")
        << (Nearest ? " nearest" : "") << (Paper ? " paper" : "");
    }
    return s.str();
  }
};

struct Row
{
  std::string Mesh;
  vtkIdType Triangles = 0;
  int Size = 0;
  Setting Config;
  double CpuMs = 0, GpuFrameMs = -1, GpuBackMs = -1, GpuRangeMs = -1, GpuFrontMs = -1;
  double PlainCpuMs = 0, PlainGpuMs = -1, PrecomputeMs = 0;
  double RefTwoMs = 0, RefFullMs = 0, BytesPerPixel = 0;
  double Psnr2 = 0, Rmse2 = 0, Ssim2 = 0, PsnrF = 0, RmseF = 0, SsimF = 0;
  double AngMean = 0, AngP95 = 0, AngMax = 0, P2Mean = 0, P2Max = 0, TirShare = 0,
         RefTirShare = 0;
  long Pixels = 0;
};

std::vector<std::string> Split(const std::string& text)
{
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, ','))
  {
    if (!part.empty())
    {
      parts.push_back(part);
    }
  }
  return parts;
}

bool Parse(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool v = i + 1 < argc;
    if (a == "--out" && v)
      o.Out = argv[++i];
    else if (a == "--sizes" && v)
    {
      o.Sizes.clear();
      for (const auto& s : Split(argv[++i]))
        o.Sizes.push_back(std::atoi(s.c_str()));
    }
    else if (a == "--meshes" && v)
      o.Meshes = Split(argv[++i]);
    else if (a == "--frames" && v)
      o.Frames = std::atoi(argv[++i]);
    else if (a == "--bunny" && v)
      o.Bunny = argv[++i];
    else if (a == "--smoke")
      o.Smoke = true;
    else if (a == "--x11")
      o.X11 = true;
    else if (a == "--dump")
      o.Dump = true;
    else if (a == "--from-csv" && v)
      o.FromCsv = argv[++i];
    else
    {
      std::fprintf(stderr, "unknown or incomplete option %s\n", a.c_str());
      return false;
    }
  }
  if (o.Smoke)
  {
    o.Sizes = { 64 };
    o.Meshes = { "sphere", "torus" };
    o.Frames = 5;
  }
  for (int s : o.Sizes)
  {
    if (s < 8 || s > 4096)
    {
      std::fprintf(stderr, "sizes must be 8..4096\n");
      return false;
    }
  }
  return o.Frames >= 1;
}

void MakeDirectories(const std::string& path)
{
  for (size_t i = 1; i <= path.size(); ++i)
  {
    if (i == path.size() || path[i] == '/')
    {
      mkdir(path.substr(0, i).c_str(), 0755);
    }
  }
}

std::string HostKind(const std::string& renderer)
{
  if (renderer.find("llvmpipe") != std::string::npos)
  {
    return "cpu-llvmpipe";
  }
  std::string kind;
  for (char c : renderer)
  {
    if (std::isalnum(static_cast<unsigned char>(c)))
      kind += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else if (!kind.empty() && kind.back() != '-')
      kind += '-';
    if (kind.size() > 40)
      break;
  }
  return kind.empty() ? "unknown" : kind;
}

// The mesh, with d_N for ISR added by the filter (which other methods ignore).
vtkSmartPointer<vtkAlgorithm> MakeMesh(const std::string& name, const Options& o)
{
  vtkSmartPointer<vtkAlgorithm> source;
  if (name == "sphere")
  {
    auto sphere = vtkSmartPointer<vtkSphereSource>::New();
    sphere->SetThetaResolution(o.Smoke ? 48 : 160);
    sphere->SetPhiResolution(o.Smoke ? 48 : 160);
    source = sphere;
  }
  else if (name == "torus")
  {
    vtkNew<vtkParametricTorus> torus;
    torus->SetRingRadius(0.7);
    torus->SetCrossSectionRadius(0.3);
    auto fn = vtkSmartPointer<vtkParametricFunctionSource>::New();
    fn->SetParametricFunction(torus);
    fn->SetUResolution(o.Smoke ? 64 : 192);
    fn->SetVResolution(o.Smoke ? 32 : 96);
    auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
    normals->SetInputConnection(fn->GetOutputPort());
    source = normals;
  }
  else if (name == "isosurface")
  {
    auto blobs = vtkSmartPointer<vtkMetaballsSource>::New();
    blobs->SetSampleDimensions(o.Smoke ? 32 : 80);
    auto surface = vtkSmartPointer<vtkFlyingEdges3D>::New();
    surface->SetInputConnection(blobs->GetOutputPort());
    surface->SetValue(0, blobs->GetIsoValue());
    surface->ComputeNormalsOn();
    surface->UpdateTimeStep(0.3 * blobs->GetTimePeriod());
    source = surface;
  }
  else if (name == "bunny")
  {
    std::ifstream probe(o.Bunny);
    if (!probe)
    {
      std::fprintf(stderr, "bunny: %s not found (Debian package glmark2-data); skipped\n",
        o.Bunny.c_str());
      return nullptr;
    }
    auto reader = vtkSmartPointer<vtkOBJReader>::New();
    reader->SetFileName(o.Bunny.c_str());
    auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
    normals->SetInputConnection(reader->GetOutputPort());
    normals->SplittingOff();
    source = normals;
  }
  else
  {
    std::fprintf(stderr, "unknown mesh %s; skipped\n", name.c_str());
    return nullptr;
  }
  auto distances = vtkSmartPointer<vtkISRDistanceFilter>::New();
  distances->SetInputConnection(source->GetOutputPort());
  distances->Update();
  return distances;
}

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return -1.0;
  }
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

struct Timing
{
  double Cpu = 0, GpuFrame = -1, Back = -1, Range = -1, Front = -1;
};

Timing TimeFrames(vtkRenderWindow* window, vtkRefractionPass* pass, int frames)
{
  vtkNew<vtkTimerLog> clock;
  vtkOpenGLRenderTimer frameTimer;
  std::vector<double> cpu, gpu, back, range, front;
  const bool gpuTimers = vtkOpenGLRenderTimer::IsSupported();
  for (int i = 0; i < 5 + frames; ++i)
  {
    clock->StartTimer();
    if (gpuTimers)
    {
      frameTimer.Reset();
      frameTimer.Start();
    }
    window->Render();
    if (gpuTimers)
    {
      frameTimer.Stop();
    }
    glFinish();
    clock->StopTimer();
    if (i < 5)
    {
      continue;
    }
    cpu.push_back(clock->GetElapsedTime() * 1e3);
    if (gpuTimers && frameTimer.Ready())
    {
      gpu.push_back(frameTimer.GetElapsedMilliseconds());
    }
    if (pass && pass->GetGPUTiming())
    {
      back.push_back(pass->GetStageMilliseconds(vtkRefractionPass::TIMED_BACK_CAPTURE));
      range.push_back(pass->GetStageMilliseconds(vtkRefractionPass::TIMED_DEPTH_RANGE));
      front.push_back(pass->GetStageMilliseconds(vtkRefractionPass::TIMED_FRONT));
    }
  }
  frameTimer.ReleaseGraphicsResources();
  return { Median(cpu), Median(gpu), Median(back), Median(range), Median(front) };
}

// The window's colour as floats in [0,1], bottom row first (as the reference).
std::vector<float> GrabColour(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  vtkDataArray* rgb = grab->GetOutput()->GetPointData()->GetScalars();
  std::vector<float> colour(3 * rgb->GetNumberOfTuples());
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      colour[3 * i + c] = static_cast<float>(rgb->GetComponent(i, c) / 255.0);
    }
  }
  return colour;
}

std::vector<float> Floats(vtkImageData* image, const char* name, int components)
{
  vtkDataArray* a = image->GetPointData()->GetArray(name);
  std::vector<float> values(a ? components * a->GetNumberOfTuples() : 0);
  for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < components; ++c)
    {
      values[components * i + c] = static_cast<float>(a->GetComponent(i, c));
    }
  }
  return values;
}

struct Reference
{
  std::vector<float> Colour, P2, T2;
  std::vector<unsigned char> Hit, Tir;
  double Seconds = 0;
  double Diagonal = 1;
};

bool Trace(vtkRenderer* renderer, int size, int mode, Reference& out)
{
  vtkNew<vtkRefractionReference> reference;
  reference->SetMode(mode);
  reference->SetThreads(2);
  if (!reference->Trace(renderer, size, size))
  {
    return false;
  }
  vtkImageData* image = reference->GetOutput();
  out.Colour = Floats(image, "Colour", 3);
  for (float& c : out.Colour)
  {
    c = std::min(std::max(c, 0.0f), 1.0f);
  }
  out.P2 = Floats(image, "P2", 3);
  out.T2 = Floats(image, "T2", 3);
  const auto hit = Floats(image, "Hit", 1);
  const auto tir = Floats(image, "TIR", 1);
  out.Hit.resize(hit.size());
  out.Tir.resize(tir.size());
  for (size_t i = 0; i < hit.size(); ++i)
  {
    out.Hit[i] = hit[i] > 0.5f ? 1 : 0;
    out.Tir[i] = i < tir.size() && tir[i] > 0.5f ? 1 : 0;
  }
  out.Seconds = reference->GetTraceSeconds();
  out.Diagonal = reference->GetGlassDiagonal();
  return true;
}

void Measure(Row& row, const std::vector<float>& colour, vtkImageData* debug,
  const Reference& two, const Reference& full, int size)
{
  const size_t n = static_cast<size_t>(size) * size;
  const auto flags = Floats(debug, "Flags", 1);
  const auto t2 = Floats(debug, "T2", 3);
  const auto p2 = Floats(debug, "P2", 3);
  std::vector<unsigned char> mask(n, 0);
  std::vector<unsigned char> tir(n, 0);
  long count = 0;
  for (size_t i = 0; i < n; ++i)
  {
    const bool glass = i < flags.size() && flags[i] > 0.5f;
    mask[i] = glass && two.Hit[i] ? 1 : 0;
    tir[i] = glass && flags[i] > 1.5f ? 1 : 0;
    count += mask[i];
  }
  row.Pixels = count;
  if (count == 0)
  {
    return;
  }
  rf_psnr(colour.data(), two.Colour.data(), n, 3, mask.data(), &row.Psnr2);
  rf_rmse(colour.data(), two.Colour.data(), n, 3, mask.data(), &row.Rmse2);
  rf_ssim(colour.data(), two.Colour.data(), size, size, 3, mask.data(), &row.Ssim2);
  rf_psnr(colour.data(), full.Colour.data(), n, 3, mask.data(), &row.PsnrF);
  rf_rmse(colour.data(), full.Colour.data(), n, 3, mask.data(), &row.RmseF);
  rf_ssim(colour.data(), full.Colour.data(), size, size, 3, mask.data(), &row.SsimF);
  rf_error_stats angle{};
  if (rf_angular_error(t2.data(), two.T2.data(), n, mask.data(), &angle) == RF_OK)
  {
    row.AngMean = angle.mean;
    row.AngP95 = angle.p95;
    row.AngMax = angle.max;
  }
  rf_error_stats position{};
  if (rf_position_error(p2.data(), two.P2.data(), n, mask.data(), two.Diagonal, &position) ==
    RF_OK)
  {
    row.P2Mean = position.mean;
    row.P2Max = position.max;
  }
  rf_flag_share(tir.data(), n, mask.data(), &row.TirShare);
  rf_flag_share(two.Tir.data(), n, mask.data(), &row.RefTirShare);
}

// An RGB float image (bottom row first) as an 8-bit PNG, for a person to compare.
void WritePng(const std::string& path, const std::vector<float>& rgb, int size)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(size, size, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  for (size_t i = 0; i < rgb.size(); ++i)
  {
    out[i] = static_cast<unsigned char>(std::min(std::max(rgb[i], 0.0f), 1.0f) * 255.0f + 0.5f);
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
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
  auto fields = [](const std::string& text) {
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
  };
  const auto header = fields(line);
  while (std::getline(in, line))
  {
    const auto f = fields(line);
    if (f.size() != header.size())
      continue;
    std::map<std::string, std::string> v;
    for (size_t i = 0; i < f.size(); ++i)
      v[header[i]] = f[i];
    auto d = [&](const char* k) { return std::atof(v[k].c_str()); };
    Row r;
    renderer = v["renderer"];
    r.Mesh = v["mesh"];
    r.Triangles = static_cast<vtkIdType>(d("triangles"));
    r.Size = static_cast<int>(d("size"));
    r.Config.Method = v["method"];
    r.Config.Steps = static_cast<int>(d("steps"));
    r.Config.Bounds = v["depth_range"] == "bbox";
    r.Config.Adaptive = v["adaptive"] == "1";
    r.Config.Nearest = v["back_surface"] == "nearest";
    r.Config.Paper = v["secant"] == "0";
    r.CpuMs = d("cpu_ms");
    r.GpuFrameMs = d("gpu_frame_ms");
    r.GpuBackMs = d("gpu_back_ms");
    r.GpuRangeMs = d("gpu_range_ms");
    r.GpuFrontMs = d("gpu_front_ms");
    r.PlainCpuMs = d("plain_cpu_ms");
    r.PlainGpuMs = d("plain_gpu_ms");
    r.PrecomputeMs = d("precompute_ms");
    r.RefTwoMs = d("ref_two_ms");
    r.RefFullMs = d("ref_full_ms");
    r.BytesPerPixel = d("bytes_per_pixel");
    r.Psnr2 = d("psnr_two");
    r.Rmse2 = d("rmse_two");
    r.Ssim2 = d("ssim_two");
    r.PsnrF = d("psnr_full");
    r.RmseF = d("rmse_full");
    r.SsimF = d("ssim_full");
    r.AngMean = d("t2_deg_mean");
    r.AngP95 = d("t2_deg_p95");
    r.AngMax = d("t2_deg_max");
    r.P2Mean = d("p2_rel_mean");
    r.P2Max = d("p2_rel_max");
    r.TirShare = d("tir_share");
    r.RefTirShare = d("ref_tir_share");
    r.Pixels = static_cast<long>(d("pixels"));
    rows.push_back(r);
  }
  return !rows.empty();
}

std::vector<Setting> Settings(bool smoke)
{
  std::vector<Setting> settings;
  settings.push_back({ "SIR", 0, false, false });
  const std::vector<int> steps = smoke ? std::vector<int>{ 0, 5 } : std::vector<int>{ 0, 1, 2, 3, 5, 8 };
  for (int bounds = 0; bounds < 2; ++bounds)
  {
    for (int s : steps)
    {
      settings.push_back({ "DIR", s, bounds == 1, false });
    }
  }
  settings.push_back({ "DIR", 8, false, true });
  settings.push_back({ "DIR", 5, false, false, true });
  settings.push_back({ "DIR", 5, false, false, false, true });
  settings.push_back({ "ISR", 0, false, false });
  settings.push_back({ "SSP", 0, false, false });
  return settings;
}

int MethodId(const std::string& m)
{
  return m == "SIR" ? vtkRefractionPass::SIR
                    : m == "ISR" ? vtkRefractionPass::ISR
                                 : m == "SSP" ? vtkRefractionPass::SSP : vtkRefractionPass::DIR;
}

void WriteCsv(const std::string& path, const std::vector<Row>& rows, const std::string& renderer)
{
  std::ofstream f(path);
  f << "renderer,mesh,triangles,size,method,steps,depth_range,adaptive,cpu_ms,gpu_frame_ms,"
       "back_surface,secant,gpu_back_ms,gpu_range_ms,gpu_front_ms,plain_cpu_ms,plain_gpu_ms,cpu_ratio,"
       "precompute_ms,ref_two_ms,ref_full_ms,bytes_per_pixel,psnr_two,rmse_two,ssim_two,"
       "psnr_full,rmse_full,ssim_full,t2_deg_mean,t2_deg_p95,t2_deg_max,p2_rel_mean,"
       "p2_rel_max,tir_share,ref_tir_share,pixels\n";
  for (const Row& r : rows)
  {
    f << '"' << renderer << "\"," << r.Mesh << ',' << r.Triangles << ',' << r.Size << ','
      << r.Config.Method << ',' << r.Config.Steps << ','
      << (r.Config.Bounds ? "bbox" : "reduction") << ',' << (r.Config.Adaptive ? 1 : 0) << ','
      << r.CpuMs << ',' << r.GpuFrameMs << ',' << (r.Config.Nearest ? "nearest" : "furthest")
      << ',' << (r.Config.Paper ? 0 : 1) << ',' << r.GpuBackMs << ',' << r.GpuRangeMs << ','
      << r.GpuFrontMs << ',' << r.PlainCpuMs << ',' << r.PlainGpuMs << ','
      << r.CpuMs / r.PlainCpuMs << ',' << r.PrecomputeMs << ',' << r.RefTwoMs << ','
      << r.RefFullMs << ',' << r.BytesPerPixel << ',' << r.Psnr2 << ',' << r.Rmse2 << ','
      << r.Ssim2 << ',' << r.PsnrF << ',' << r.RmseF << ',' << r.SsimF << ',' << r.AngMean
      << ',' << r.AngP95 << ',' << r.AngMax << ',' << r.P2Mean << ',' << r.P2Max << ','
      << r.TirShare << ',' << r.RefTirShare << ',' << r.Pixels << '\n';
  }
}

void WriteMarkdown(const std::string& path, const std::vector<Row>& rows,
  const std::string& renderer, const std::string& windowPath, int frames)
{
  std::ofstream f(path);
  char line[512];
  f << "# Error against run time\n\nRenderer: " << renderer << " (" << windowPath
    << "). Times are medians over " << frames
    << " frames after 5 warm-up frames; `ratio` is the glass frame time over a plain VTK "
       "render of the same mesh in the same run. Errors on glass pixels only, against the "
       "Embree reference: `two` is the two-interface reference (the approximation's own "
       "error), `full` the Whitted reference (depth 8, Fresnel splits, TIR). ISR's `pre` is "
       "the per-vertex d_N ray casting (recomputed whenever the points change). Rows marked "
       "`paper` run the paper's search without the secant step, `nearest` capture the nearest "
       "back surface instead of the furthest. Stage times are GL timer queries (on llvmpipe "
       "they include work queued before the stage); -1 marks a stage the method does not run.\n\n";
  // Table 1 of the paper: fps per model at 512x512 (or the size nearest it).
  std::map<std::string, std::map<std::string, const Row*>> table;
  int tableSize = 0;
  for (const Row& r : rows)
  {
    if (tableSize == 0 || std::abs(r.Size - 512) < std::abs(tableSize - 512))
      tableSize = r.Size;
  }
  f << "## Table 1 analogue (" << tableSize << "x" << tableSize << ", fps from CPU frame time; RT in seconds)\n\n"
    << "| model | triangles | pixels | DIR | ISR | SIR | SSP | plain VTK | RT (two-interface) | RT (full) |\n"
    << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows)
  {
    if (r.Size != tableSize)
      continue;
    std::string key = r.Config.Method;
    if (r.Config.Method == "DIR" && (r.Config.Steps != 5 || r.Config.Bounds || r.Config.Adaptive ||
                                      r.Config.Nearest || r.Config.Paper))
      continue;
    table[r.Mesh][key] = &r;
  }
  for (auto& entry : table)
  {
    auto fps = [&](const char* m) {
      auto it = entry.second.find(m);
      return it == entry.second.end() ? std::string("-")
                                      : std::to_string(static_cast<int>(1000.0 / it->second->CpuMs + 0.5));
    };
    const Row* any = entry.second.begin()->second;
    std::snprintf(line, sizeof(line), "| %s | %lld | %ld | %s | %s | %s | %s | %d | %.2f s | %.2f s |\n",
      entry.first.c_str(), static_cast<long long>(any->Triangles), any->Pixels, fps("DIR").c_str(),
      fps("ISR").c_str(), fps("SIR").c_str(), fps("SSP").c_str(),
      static_cast<int>(1000.0 / any->PlainCpuMs + 0.5), any->RefTwoMs / 1000.0, any->RefFullMs / 1000.0);
    f << line;
  }
  f << "\n## All runs\n\n| mesh | size | method | cpu ms | ratio | gpu ms (back/range/front) | pre ms | B/px | PSNR two | SSIM two | PSNR full | T2 deg mean/p95 | P2 rel mean | TIR |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows)
  {
    std::snprintf(line, sizeof(line),
      "| %s | %d | %s | %.2f | %.2f | %.2f (%.2f/%.2f/%.2f) | %.1f | %.0f | %.1f | %.3f | %.1f | %.2f/%.2f | %.4f | %.3f |\n",
      r.Mesh.c_str(), r.Size, r.Config.Label().c_str(), r.CpuMs, r.CpuMs / r.PlainCpuMs,
      r.GpuFrameMs, r.GpuBackMs, r.GpuRangeMs, r.GpuFrontMs, r.PrecomputeMs, r.BytesPerPixel,
      r.Psnr2, r.Ssim2, r.PsnrF, r.AngMean, r.AngP95, r.P2Mean, r.TirShare);
    f << line;
  }
}

void WritePareto(vtkRenderWindow* window, const std::string& path, const std::vector<Row>& rows)
{
  std::vector<std::string> meshes;
  int plotSize = 0;
  for (const Row& r : rows)
  {
    if (std::find(meshes.begin(), meshes.end(), r.Mesh) == meshes.end())
      meshes.push_back(r.Mesh);
    if (plotSize == 0 || std::abs(r.Size - 512) < std::abs(plotSize - 512))
      plotSize = r.Size;
  }
  if (meshes.empty())
    return;
  vtkNew<vtkContextView> view;
  while (window->GetRenderers()->GetFirstRenderer())
  {
    window->RemoveRenderer(window->GetRenderers()->GetFirstRenderer());
  }
  view->SetRenderWindow(window);
  window->SetSize(1200, 900);
  const int columns = meshes.size() > 1 ? 2 : 1;
  const int rowsCount = static_cast<int>((meshes.size() + columns - 1) / columns);
  vtkNew<vtkChartMatrix> matrix;
  view->GetScene()->AddItem(matrix);
  matrix->SetSize(vtkVector2i(columns, rowsCount));
  const char* families[] = { "SIR", "DIR reduction", "DIR bbox", "DIR adaptive", "ISR", "SSP",
    "DIR paper (no secant)", "DIR nearest back" };
  const unsigned char colours[][3] = { { 120, 120, 120 }, { 31, 119, 180 }, { 255, 127, 14 },
    { 44, 160, 44 }, { 214, 39, 40 }, { 148, 103, 189 }, { 140, 86, 75 }, { 23, 190, 207 } };
  for (size_t m = 0; m < meshes.size(); ++m)
  {
    vtkChart* chart = matrix->GetChart(vtkVector2i(static_cast<int>(m % columns),
      rowsCount - 1 - static_cast<int>(m / columns)));
    chart->SetTitle(meshes[m] + " " + std::to_string(plotSize) + "x" + std::to_string(plotSize));
    chart->GetAxis(vtkAxis::BOTTOM)->SetTitle("frame time / plain VTK");
    chart->GetAxis(vtkAxis::LEFT)->SetTitle("RMSE against the full reference");
    chart->SetShowLegend(m == 0);
    for (int family = 0; family < 8; ++family)
    {
      vtkNew<vtkTable> table;
      vtkNew<vtkFloatArray> x;
      vtkNew<vtkFloatArray> y;
      x->SetName("ratio");
      y->SetName(families[family]);
      table->AddColumn(x);
      table->AddColumn(y);
      std::vector<std::pair<double, double>> points;
      for (const Row& r : rows)
      {
        if (r.Mesh != meshes[m] || r.Size != plotSize || r.Config.Method == "none")
          continue;
        const std::string& method = r.Config.Method;
        const int f = method == "SIR" ? 0
          : method == "ISR" ? 4
          : method == "SSP" ? 5
          : r.Config.Paper ? 6 : r.Config.Nearest ? 7 : r.Config.Adaptive ? 3 : r.Config.Bounds ? 2 : 1;
        if (f == family)
          points.emplace_back(r.CpuMs / r.PlainCpuMs, r.RmseF);
      }
      if (points.empty())
        continue;
      std::sort(points.begin(), points.end());
      table->SetNumberOfRows(static_cast<vtkIdType>(points.size()));
      for (size_t i = 0; i < points.size(); ++i)
      {
        table->SetValue(static_cast<vtkIdType>(i), 0, points[i].first);
        table->SetValue(static_cast<vtkIdType>(i), 1, points[i].second);
      }
      vtkPlot* plot = chart->AddPlot(points.size() > 1 ? vtkChart::LINE : vtkChart::POINTS);
      plot->SetInputData(table, 0, 1);
      plot->SetColor(colours[family][0], colours[family][1], colours[family][2], 255);
      plot->SetWidth(2.0);
    }
  }
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(path.c_str());
  writer->Write();
}
}

int main(int argc, char* argv[])
{
  Options options;
  if (!Parse(argc, argv, options))
  {
    return 2;
  }
  const int maxSize = *std::max_element(options.Sizes.begin(), options.Sizes.end());
  vtkSmartPointer<vtkRenderWindow> window;
  std::string windowPath = "GLX window";
  if (!options.X11)
  {
    std::string error;
    window = vtkRefractionCreateEGLWindow(std::max(maxSize, 1200), std::max(maxSize, 900), &error, &windowPath);
    if (!window)
    {
      std::fprintf(stderr, "EGL unavailable (%s); using an X window\n", error.c_str());
    }
  }
  if (!window)
  {
    window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(0);
    windowPath = "GLX window";
  }
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->SetSize(options.Sizes.front(), options.Sizes.front());
  window->Render();
  std::string rendererName = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (!options.FromCsv.empty())
  {
    // Remake the report of an earlier run (same folder unless --out says otherwise).
    std::vector<Row> rows;
    std::string recorded;
    if (!ReadCsv(options.FromCsv, rows, recorded))
    {
      std::fprintf(stderr, "cannot read rows from %s\n", options.FromCsv.c_str());
      return 1;
    }
    if (options.Out.empty())
    {
      const size_t slash = options.FromCsv.find_last_of('/');
      options.Out = slash == std::string::npos ? "." : options.FromCsv.substr(0, slash);
    }
    WriteMarkdown(options.Out + "/results.md", rows, recorded, "recorded run", options.Frames);
    WritePareto(window, options.Out + "/pareto.png", rows);
    std::printf("remade %s/results.md and pareto.png from %zu rows\n", options.Out.c_str(), rows.size());
    return 0;
  }
  if (options.Out.empty())
  {
    options.Out = "bench/results/" + HostKind(rendererName);
  }
  MakeDirectories(options.Out);
  std::printf("renderer %s (%s); results in %s\n", rendererName.c_str(), windowPath.c_str(),
    options.Out.c_str());

  std::vector<Row> rows;
  vtkNew<vtkRefractionPass> pass;
  pass->SetGPUTiming(true);
  renderer->SetPass(pass);
  for (const std::string& meshName : options.Meshes)
  {
    auto mesh = MakeMesh(meshName, options);
    if (!mesh)
    {
      continue;
    }
    auto* distances = vtkISRDistanceFilter::SafeDownCast(mesh);
    vtkPolyData* poly = vtkPolyData::SafeDownCast(mesh->GetOutputDataObject(0));
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(mesh->GetOutputPort());
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->RemoveAllViewProps();
    renderer->AddActor(actor);
    renderer->ResetCamera();
    renderer->GetActiveCamera()->SetViewAngle(30.0);
    renderer->ResetCamera();
    renderer->GetActiveCamera()->Elevation(15.0);
    renderer->GetActiveCamera()->OrthogonalizeViewUp();
    renderer->GetActiveCamera()->Dolly(1.25);
    renderer->ResetCameraClippingRange();
    const vtkIdType triangles = poly->GetNumberOfPolys() + poly->GetNumberOfStrips();

    for (int size : options.Sizes)
    {
      window->SetSize(size, size);
      // Plain VTK, and the pass with no glass in the scene (what it costs when unused).
      vtkRefractionPass::ClearGlass(actor);
      renderer->SetPass(nullptr);
      const Timing plain = TimeFrames(window, nullptr, options.Frames);
      renderer->SetPass(pass);
      const Timing idle = TimeFrames(window, nullptr, options.Frames);
      vtkRefractionPass::MakeGlass(actor, 1.5);
      window->Render();
      Reference two;
      Reference full;
      if (!Trace(renderer, size, vtkRefractionReference::TWO_INTERFACE, two) ||
        !Trace(renderer, size, vtkRefractionReference::FULL, full))
      {
        std::fprintf(stderr, "%s: the reference could not trace the scene; skipped\n", meshName.c_str());
        continue;
      }
      {
        Row row;
        row.Mesh = meshName;
        row.Triangles = triangles;
        row.Size = size;
        row.Config.Method = "none";
        row.CpuMs = idle.Cpu;
        row.GpuFrameMs = idle.GpuFrame;
        row.PlainCpuMs = plain.Cpu;
        row.PlainGpuMs = plain.GpuFrame;
        rows.push_back(row);
      }
      for (const Setting& setting : Settings(options.Smoke))
      {
        pass->SetMethod(MethodId(setting.Method));
        pass->SetSearchSteps(setting.Steps);
        pass->SetDepthRangeMode(setting.Bounds ? vtkRefractionPass::DEPTH_RANGE_BOUNDS
                                               : vtkRefractionPass::DEPTH_RANGE_REDUCTION);
        pass->SetAdaptiveSearch(setting.Adaptive);
        pass->SetBackSurface(setting.Nearest ? vtkRefractionPass::BACK_SURFACE_NEAREST
                                             : vtkRefractionPass::BACK_SURFACE_FURTHEST);
        pass->SetSecantRefinement(!setting.Paper);
        const Timing t = TimeFrames(window, pass, options.Frames);
        pass->DebugOutputOn();
        window->Render();
        pass->DebugOutputOff();
        vtkNew<vtkImageData> debug;
        debug->DeepCopy(pass->GetDebugImage());
        window->Render();
        const std::vector<float> colour = GrabColour(window);
        Row row;
        row.Mesh = meshName;
        row.Triangles = triangles;
        row.Size = size;
        row.Config = setting;
        row.CpuMs = t.Cpu;
        row.GpuFrameMs = t.GpuFrame;
        row.GpuBackMs = t.Back;
        row.GpuRangeMs = t.Range;
        row.GpuFrontMs = t.Front;
        row.PlainCpuMs = plain.Cpu;
        row.PlainGpuMs = plain.GpuFrame;
        row.PrecomputeMs = setting.Method == "ISR" && distances ? distances->GetLastComputeSeconds() * 1e3 : 0.0;
        row.RefTwoMs = two.Seconds * 1e3;
        row.RefFullMs = full.Seconds * 1e3;
        row.BytesPerPixel = static_cast<double>(pass->GetTextureBytes()) / (static_cast<double>(size) * size);
        Measure(row, colour, debug, two, full, size);
        if (options.Dump)
        {
          std::string label = setting.Label();
          std::replace(label.begin(), label.end(), ' ', '_');
          std::replace(label.begin(), label.end(), '<', '_');
          std::replace(label.begin(), label.end(), '=', '_');
          const std::string stem = options.Out + "/" + meshName + "_" + std::to_string(size) + "_";
          WritePng(stem + label + ".png", colour, size);
          WritePng(stem + "reference_two.png", two.Colour, size);
          WritePng(stem + "reference_full.png", full.Colour, size);
        }
        std::printf("%-10s %4d %-18s %7.2f ms (%.2fx plain %.2f ms)  PSNR two %5.1f full %5.1f  T2 %.2f deg\n",
          meshName.c_str(), size, setting.Label().c_str(), row.CpuMs, row.CpuMs / row.PlainCpuMs,
          row.PlainCpuMs, row.Psnr2, row.PsnrF, row.AngMean);
        std::fflush(stdout);
        rows.push_back(row);
      }
    }
  }
  renderer->RemoveAllViewProps();
  WriteCsv(options.Out + "/results.csv", rows, rendererName);
  WriteMarkdown(options.Out + "/results.md", rows, rendererName, windowPath, options.Frames);
  renderer->SetPass(nullptr);
  WritePareto(window, options.Out + "/pareto.png", rows);
  std::printf("wrote %s/results.csv, results.md, pareto.png\n", options.Out.c_str());
  return 0;
}
