// The arrays the reference library's C functions take of a glass mesh (rf_normal_distances,
// rf_sh_transfer): float positions and point normals, three point indices per triangle.
// Private to the library's filters (vtkISRDistanceFilter, vtkSHTransferFilter).
#ifndef rfGlassMeshArrays_h
#define rfGlassMeshArrays_h

#include <vector>

class vtkDataArray;
class vtkPolyData;

struct rfGlassMeshArrays
{
  std::vector<float> Positions; // xyz per point
  std::vector<float> Normals;   // xyz per point
  std::vector<unsigned> Triangles;
};

// The input's point normals; without them, normals computed without splitting (point ids
// kept), consistently wound and, with orientOutward, turned outward, and added to output.
vtkDataArray* rfGlassMeshNormals(vtkPolyData* input, vtkPolyData* output, bool orientOutward);

// The input triangulated (polygons and strips; lines and vertices left out) with the given
// point normals, as arrays.
rfGlassMeshArrays rfGetGlassMeshArrays(vtkPolyData* input, vtkDataArray* normals);

#endif
