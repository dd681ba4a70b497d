// Writes the files the viewer tests read, into the folder given:
//   sphere.vtp                 a sphere (normals, no point scalars)
//   cone.stl, cone.ply,        a cone as STL, PLY, legacy VTK and an unstructured grid
//   cone.vtk, cone.vtu
//   torus.obj                  a torus, Wavefront OBJ
//   blobs.pvd, blobs_00k.vti   4 time steps of the metaball field (volumes, contoured by the
//                              viewer), referenced by a ParaView collection
//   wave_000k.vtp              4 contoured time steps of the wave equation, a numbered series
//   broken.vtp                 not XML at all
//   missing_point.obj          a face naming vertex 99 of 3 (f 1 2 99)
//   empty_polygon.vtk,         a polygon of no points after a triangle (legacy VTK, PLY): VTK
//   empty_polygon.ply          reads it, and vtkPolyDataNormals crashed on it
//   short_tetra.vtk            an unstructured grid's tetrahedron of 2 points
//   points_prefix.vtk          "POINTS4 400000000 float": VTK reads the keyword by its first
//                              letters and would allocate for the count
//   notes.xyz                  an unknown type
#include "vtkMetaballsSource.h"
#include "vtkWaveEquationSource.h"

#include <vtkAppendFilter.h>
#include <vtkConeSource.h>
#include "rfTestIsosurface.h"
#include <vtkPLYWriter.h>
#include <vtkPolyDataWriter.h>
#include <vtkSTLWriter.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <vtkNew.h>
#include <vtkOBJWriter.h>
#include <vtkParametricFunctionSource.h>
#include <vtkParametricTorus.h>
#include <vtkPolyDataNormals.h>
#include <vtkSphereSource.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace
{
bool WriteText(const std::string& path, const std::string& text)
{
  std::ofstream out(path);
  out << text;
  return static_cast<bool>(out);
}
}

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: MakeViewerData FOLDER\n");
    return EXIT_FAILURE;
  }
  const std::string folder = argv[1];

  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  vtkNew<vtkXMLPolyDataWriter> polyWriter;
  polyWriter->SetInputConnection(sphere->GetOutputPort());
  polyWriter->SetFileName((folder + "/sphere.vtp").c_str());
  if (!polyWriter->Write())
  {
    return EXIT_FAILURE;
  }

  // A closed cone: the other mesh formats.
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(40);
  cone->SetHeight(1.6);
  cone->SetRadius(0.7);
  cone->CappingOn();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cone->GetOutputPort());
  vtkNew<vtkSTLWriter> stlWriter;
  stlWriter->SetInputConnection(triangles->GetOutputPort());
  stlWriter->SetFileName((folder + "/cone.stl").c_str());
  vtkNew<vtkPLYWriter> plyWriter;
  plyWriter->SetInputConnection(triangles->GetOutputPort());
  plyWriter->SetFileName((folder + "/cone.ply").c_str());
  vtkNew<vtkPolyDataWriter> legacyWriter;
  legacyWriter->SetInputConnection(triangles->GetOutputPort());
  legacyWriter->SetFileName((folder + "/cone.vtk").c_str());
  vtkNew<vtkAppendFilter> unstructured;
  unstructured->SetInputConnection(triangles->GetOutputPort());
  vtkNew<vtkXMLUnstructuredGridWriter> gridWriter;
  gridWriter->SetInputConnection(unstructured->GetOutputPort());
  gridWriter->SetFileName((folder + "/cone.vtu").c_str());
  if (!stlWriter->Write() || !plyWriter->Write() || !legacyWriter->Write() || !gridWriter->Write())
  {
    return EXIT_FAILURE;
  }

  vtkNew<vtkParametricTorus> torus;
  torus->SetRingRadius(0.7);
  torus->SetCrossSectionRadius(0.3);
  vtkNew<vtkParametricFunctionSource> torusSource;
  torusSource->SetParametricFunction(torus);
  torusSource->SetUResolution(64);
  torusSource->SetVResolution(32);
  vtkNew<vtkOBJWriter> objWriter;
  objWriter->SetInputConnection(torusSource->GetOutputPort());
  objWriter->SetFileName((folder + "/torus.obj").c_str());
  if (!objWriter->Write())
  {
    return EXIT_FAILURE;
  }

  vtkNew<vtkMetaballsSource> blobs;
  blobs->SetSampleDimensions(40);
  vtkNew<vtkXMLImageDataWriter> imageWriter;
  imageWriter->SetInputConnection(blobs->GetOutputPort());
  std::string collection = "<?xml version=\"1.0\"?>\n"
                           "<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (int k = 0; k < 4; ++k)
  {
    const double time = 0.1 * k;
    blobs->UpdateTimeStep(time);
    char name[32];
    std::snprintf(name, sizeof(name), "blobs_%02d.vti", k);
    imageWriter->SetFileName((folder + "/" + name).c_str());
    if (!imageWriter->Write())
    {
      return EXIT_FAILURE;
    }
    collection += "    <DataSet timestep=\"" + std::to_string(time) + "\" part=\"0\" file=\"" +
      name + "\"/>\n";
  }
  collection += "  </Collection>\n</VTKFile>\n";

  vtkNew<vtkWaveEquationSource> waves;
  auto surface = rftest::IsosurfaceOf(waves.Get());
  polyWriter->SetInputConnection(surface->GetOutputPort());
  for (int k = 0; k < 4; ++k)
  {
    surface->UpdateTimeStep(0.1 * k);
    char name[32];
    std::snprintf(name, sizeof(name), "/wave_%04d.vtp", k);
    polyWriter->SetFileName((folder + name).c_str());
    if (!polyWriter->Write())
    {
      return EXIT_FAILURE;
    }
  }

  if (!WriteText(folder + "/blobs.pvd", collection) ||
    !WriteText(folder + "/broken.vtp", "this is not a VTK file\n") ||
    !WriteText(folder + "/notes.xyz", "1 2 3\n") ||
    !WriteText(folder + "/missing_point.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n") ||
    !WriteText(folder + "/empty_polygon.vtk",
      "# vtk DataFile Version 4.2\nempty polygon\nASCII\nDATASET POLYDATA\n"
      "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 2 5\n3 0 1 2\n0\n") ||
    !WriteText(folder + "/empty_polygon.ply",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n0\n") ||
    !WriteText(folder + "/short_tetra.vtk",
      "# vtk DataFile Version 4.2\nshort tetrahedron\nASCII\nDATASET UNSTRUCTURED_GRID\n"
      "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 3\n2 0 1\nCELL_TYPES 1\n10\n") ||
    !WriteText(folder + "/points_prefix.vtk",
      "# vtk DataFile Version 3.0\nprefix\nASCII\nDATASET POLYDATA\n"
      "POINTS4 400000000 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 2\n"))
  {
    return EXIT_FAILURE;
  }
  std::printf("wrote the viewer's test data to %s\n", folder.c_str());
  return EXIT_SUCCESS;
}
