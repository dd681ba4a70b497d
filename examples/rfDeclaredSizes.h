// What a mesh file declares before its data, checked against the file's size before VTK's
// readers trust it: a count of points or cells (legacy .vtk, .ply headers, a binary STL's
// triangles, the XML formats' attributes) that the file cannot hold would have the reader allocate gigabytes and read for
// minutes, and a PLY header whose properties belong to no element crashes vtkPLYReader (VTK
// 9.1). Found by fuzzing the viewer's inputs (tests/fuzz/fuzz_files.cxx).
#ifndef rfDeclaredSizes_h
#define rfDeclaredSizes_h

#include <string>

// True when what `path` declares fits in it (and, for .ply, the header is well formed);
// otherwise false and why in `error`. Formats without declared sizes (.obj, ASCII .stl) pass.
bool rfCheckDeclaredSizes(const std::string& path, std::string& error);

#endif
