#include "vtkSHTransferFilter.h"

#include "rfGlassMeshArrays.h"
#include "rf_sh.h"
#include "rf_sh_transfer.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRefractionGlassChecker.h"
#include "vtkTimerLog.h"

#include <vtksys/SystemTools.hxx>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSHTransferFilter);

namespace
{
const char kMagic[8] = { 'R', 'F', 'S', 'H', 'v', '1', '\0', '\0' };

// FNV-1a over bytes: the cache key of the mesh and the settings.
struct Hash
{
  std::uint64_t Value = 1469598103934665603ULL;
  void Add(const void* data, size_t bytes)
  {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < bytes; ++i)
    {
      this->Value = (this->Value ^ p[i]) * 1099511628211ULL;
    }
  }
};

// The progress of the C core, as the filter's ProgressEvent (from 0.3 to 1).
void ReportProgress(double fraction, void* user)
{
  static_cast<vtkSHTransferFilter*>(user)->UpdateProgress(0.3 + 0.7 * fraction);
}

bool ReadCache(const std::string& path, std::uint64_t key, size_t values, float* out)
{
  std::ifstream in(path, std::ios::binary);
  char magic[8];
  std::uint64_t storedKey = 0;
  std::uint64_t storedValues = 0;
  if (!in.read(magic, sizeof(magic)) || std::memcmp(magic, kMagic, sizeof(magic)) != 0 ||
    !in.read(reinterpret_cast<char*>(&storedKey), sizeof(storedKey)) ||
    !in.read(reinterpret_cast<char*>(&storedValues), sizeof(storedValues)) || storedKey != key ||
    storedValues != values)
  {
    return false;
  }
  return static_cast<bool>(in.read(reinterpret_cast<char*>(out), values * sizeof(float)));
}

bool WriteCache(const std::string& path, std::uint64_t key, size_t values, const float* data)
{
  // Written beside and renamed: a reader never sees half a file.
  const std::string partial = path + ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    const std::uint64_t count = values;
    if (!out.write(kMagic, sizeof(kMagic)) ||
      !out.write(reinterpret_cast<const char*>(&key), sizeof(key)) ||
      !out.write(reinterpret_cast<const char*>(&count), sizeof(count)) ||
      !out.write(reinterpret_cast<const char*>(data), values * sizeof(float)))
    {
      return false;
    }
  }
  return std::rename(partial.c_str(), path.c_str()) == 0;
}
}

//------------------------------------------------------------------------------
vtkSHTransferFilter::vtkSHTransferFilter()
{
  std::string base;
  if (vtksys::SystemTools::GetEnv("XDG_CACHE_HOME", base) && !base.empty())
  {
    this->CacheDirectory = base + "/refraction-glass";
  }
  else if (vtksys::SystemTools::GetEnv("HOME", base) && !base.empty())
  {
    this->CacheDirectory = base + "/.cache/refraction-glass";
  }
}

//------------------------------------------------------------------------------
void vtkSHTransferFilter::SetCacheDirectory(const std::string& directory)
{
  if (directory != this->CacheDirectory)
  {
    this->CacheDirectory = directory;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkSHTransferFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Order: " << this->Order << "\n";
  os << indent << "Directions: " << this->Directions << "\n";
  os << indent << "MaxBounces: " << this->MaxBounces << "\n";
  os << indent << "IndexOfRefraction: " << this->IndexOfRefraction << "\n";
  os << indent << "Threads: " << this->Threads << "\n";
  os << indent << "CacheDirectory: " << this->CacheDirectory << "\n";
  os << indent << "LastComputeSeconds: " << this->LastComputeSeconds << "\n";
  os << indent << "LastCacheHit: " << this->LastCacheHit << "\n";
}

//------------------------------------------------------------------------------
int vtkSHTransferFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  this->LastCacheHit = false;
  this->LastCacheFile.clear();
  this->UpdateProgress(0.0);
  output->ShallowCopy(input);
  const vtkIdType pointCount = input->GetNumberOfPoints();
  const int count = rf_sh_coefficient_count(this->Order);
  const size_t perPoint = static_cast<size_t>(RF_SH_TRANSFER_FUNCTIONS) * count;
  vtkNew<vtkFloatArray> transfer;
  transfer->SetName(GetArrayName());
  transfer->SetNumberOfComponents(static_cast<int>(perPoint));
  transfer->SetNumberOfTuples(pointCount);
  transfer->Fill(0.0);
  vtkNew<vtkDoubleArray> settings;
  settings->SetName(GetSettingsArrayName());
  settings->SetNumberOfValues(4);
  settings->SetValue(0, this->Order);
  settings->SetValue(1, this->Directions);
  settings->SetValue(2, this->MaxBounces);
  settings->SetValue(3, this->IndexOfRefraction);
  output->GetFieldData()->AddArray(settings);
  output->GetPointData()->AddArray(transfer);
  vtkNew<vtkFloatArray> vertexIds;
  vertexIds->SetName(GetVertexIdArrayName());
  vertexIds->SetNumberOfTuples(pointCount);
  for (vtkIdType i = 0; i < pointCount; ++i)
  {
    vertexIds->SetValue(i, static_cast<float>(i));
  }
  output->GetPointData()->AddArray(vertexIds);
  std::string malformed;
  if (!vtkRefractionGlassChecker::CheckMesh(input, malformed))
  {
    // The pass refuses such glass too; reading its cells would go beyond its points.
    vtkErrorMacro(
      "Cannot compute the SH transfer: the input " << malformed << "; the output keeps zeros.");
    this->LastComputeSeconds = 0.0;
    this->UpdateProgress(1.0);
    return 1;
  }
  if (pointCount == 0 || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    this->LastComputeSeconds = 0.0;
    this->UpdateProgress(1.0);
    return 1;
  }

  // Outward: the functions start with a refraction in.
  vtkDataArray* normals = rfGlassMeshNormals(input, output, true);
  const rfGlassMeshArrays mesh = rfGetGlassMeshArrays(input, normals);
  const std::vector<float>& positions = mesh.Positions;
  const std::vector<float>& normalValues = mesh.Normals;
  const std::vector<unsigned>& indices = mesh.Triangles;
  this->UpdateProgress(0.3);

  Hash hash;
  hash.Add(positions.data(), positions.size() * sizeof(float));
  hash.Add(normalValues.data(), normalValues.size() * sizeof(float));
  hash.Add(indices.data(), indices.size() * sizeof(unsigned));
  const double key[4] = { static_cast<double>(this->Order),
    static_cast<double>(this->Directions), static_cast<double>(this->MaxBounces),
    this->IndexOfRefraction };
  hash.Add(key, sizeof(key));
  float* values = static_cast<float*>(transfer->GetVoidPointer(0));
  const size_t valueCount = perPoint * static_cast<size_t>(pointCount);
  if (!this->CacheDirectory.empty())
  {
    char name[64];
    std::snprintf(name, sizeof(name), "/sh-%016llx.bin",
      static_cast<unsigned long long>(hash.Value));
    this->LastCacheFile = this->CacheDirectory + name;
    if (ReadCache(this->LastCacheFile, hash.Value, valueCount, values))
    {
      this->LastCacheHit = true;
      timer->StopTimer();
      this->LastComputeSeconds = timer->GetElapsedTime();
      this->UpdateProgress(1.0);
      return 1;
    }
  }

  rf_sh_transfer_options options;
  options.order = this->Order;
  options.directions = this->Directions;
  options.max_bounces = this->MaxBounces;
  options.threads = this->Threads;
  options.progress = ReportProgress;
  options.progress_user = this;
  const rf_status status = rf_sh_transfer(positions.data(), normalValues.data(),
    static_cast<size_t>(pointCount), indices.data(), indices.size() / 3, this->IndexOfRefraction,
    &options, values);
  timer->StopTimer();
  this->LastComputeSeconds = timer->GetElapsedTime();
  if (status != RF_OK)
  {
    vtkErrorMacro("Cannot precompute the SH transfer: " << rf_reference_status_message(status));
    transfer->Fill(0.0);
    this->LastCacheFile.clear();
  }
  else if (!this->CacheDirectory.empty())
  {
    if (!vtksys::SystemTools::MakeDirectory(this->CacheDirectory) ||
      !WriteCache(this->LastCacheFile, hash.Value, valueCount, values))
    {
      vtkWarningMacro("Cannot write the SH cache " << this->LastCacheFile
                                                  << "; the next run computes it again.");
      this->LastCacheFile.clear();
    }
  }
  this->UpdateProgress(1.0);
  return 1;
}
