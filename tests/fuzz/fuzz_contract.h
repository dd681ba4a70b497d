// What the fuzz targets over users' meshes and files (fuzz_mesh.cxx, fuzz_files.cxx) check
// alike: the messages VTK gives, counted instead of printed; a mesh as the pass may draw it;
// a contract that aborts when violated (a finding).
#ifndef fuzz_contract_h
#define fuzz_contract_h

#include <vtkOutputWindow.h>

class vtkPolyData;

// Counts every message instead of printing it: a refused input must have been told of.
class rfCountingOutputWindow : public vtkOutputWindow
{
public:
  static rfCountingOutputWindow* New();
  vtkTypeMacro(rfCountingOutputWindow, vtkOutputWindow);
  void DisplayText(const char*) override { ++this->Messages; }
  long Messages = 0;
};

// Installed as VTK's output window once (vtkLogger's copy of each message silenced too).
rfCountingOutputWindow* rfFuzzMessages();

// What vtkRefractionGlassChecker::CheckMesh promises of glass it keeps, checked independently:
// cells name existing points, polygons and strips have 3 points or more, coordinates are
// within float range.
bool rfFuzzWellFormed(vtkPolyData* mesh);

// Aborts with "TARGET: contract violated: WHAT" unless `condition`.
void rfFuzzRequire(bool condition, const char* target, const char* what);

#endif
