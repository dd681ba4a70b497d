/**
 * @class   vtkSHTransferFilter
 * @brief   Adds the SH method's per-vertex transfer functions to a static glass mesh.
 *
 * The SH method (Genevaux et al., seed 003) precomputes, per vertex, the direction in which
 * light leaves the glass and the length it travels inside, for every view direction, and
 * stores them as spherical-harmonic coefficients (rf_sh_transfer, Embree on the CPU, on
 * Threads threads). This filter adds them as the point array "SHTransfer": 4 (L + 1)^2
 * components per point, the exit direction's x, y, z and the length, each (L + 1)^2
 * coefficients, in the input's model coordinates, and "SHVertexId", each point's index; the
 * field array "SHTransferSettings" holds the order, the directions, the bounces and the index
 * of refraction used.
 *
 * The result is cached on disk (CacheDirectory; default $XDG_CACHE_HOME/refraction-glass or
 * ~/.cache/refraction-glass; empty after SetCacheDirectory("") disables it), keyed by a hash
 * of the points, normals and triangles and of the settings: a second run on the same mesh
 * loads it (GetLastCacheHit). The precomputation reports ProgressEvent as vertices finish.
 */
#ifndef vtkSHTransferFilter_h
#define vtkSHTransferFilter_h

#include "rf_reference_export.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // For members

class RF_REFERENCE_EXPORT vtkSHTransferFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkSHTransferFilter* New();
  vtkTypeMacro(vtkSHTransferFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The point array the filter adds and the pass reads.
  static const char* GetArrayName() { return "SHTransfer"; }
  /// The field array of the settings: order, directions, bounces, index of refraction.
  static const char* GetSettingsArrayName() { return "SHTransferSettings"; }
  /// The point array of each point's own index (a float), by which the pass's vertex shader
  /// finds the point's coefficients (the mapper may reorder or repeat the points).
  static const char* GetVertexIdArrayName() { return "SHVertexId"; }

  ///@{
  /// SH order L, 0..8 (default 8, as the paper).
  vtkSetClampMacro(Order, int, 0, 8);
  vtkGetMacro(Order, int);
  /// View directions sampled per vertex over the hemisphere, >= 16 (default 1024; the
  /// paper: about 2,000).
  vtkSetClampMacro(Directions, int, 16, 1 << 20);
  vtkGetMacro(Directions, int);
  /// Total internal reflections followed inside (default 8).
  vtkSetClampMacro(MaxBounces, int, 0, 64);
  vtkGetMacro(MaxBounces, int);
  /// The glass's index of refraction (default 1.5); the functions hold for this index only.
  vtkSetClampMacro(IndexOfRefraction, double, 1e-3, 1e3);
  vtkGetMacro(IndexOfRefraction, double);
  /// Worker threads (default 2).
  vtkSetClampMacro(Threads, int, 1, 256);
  vtkGetMacro(Threads, int);
  /// Where results are cached; "" disables the cache.
  void SetCacheDirectory(const std::string& directory);
  const std::string& GetCacheDirectory() const { return this->CacheDirectory; }
  ///@}

  /// Wall-clock seconds of the last update (the precomputation, or loading the cache).
  vtkGetMacro(LastComputeSeconds, double);
  /// Whether the last update was loaded from the cache.
  vtkGetMacro(LastCacheHit, bool);
  /// The cache file of the last update ("" without a cache).
  const std::string& GetLastCacheFile() const { return this->LastCacheFile; }

protected:
  vtkSHTransferFilter();
  ~vtkSHTransferFilter() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Order = 8;
  int Directions = 1024;
  int MaxBounces = 8;
  double IndexOfRefraction = 1.5;
  int Threads = 2;
  std::string CacheDirectory;
  double LastComputeSeconds = 0.0;
  bool LastCacheHit = false;
  std::string LastCacheFile;

private:
  vtkSHTransferFilter(const vtkSHTransferFilter&) = delete;
  void operator=(const vtkSHTransferFilter&) = delete;
};

#endif
