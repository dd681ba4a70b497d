// libFuzzer target over files, as the viewer (RefractionViewer, RefractionDemo) reads them: the
// first byte picks a kind (a mesh or volume: .vtp .vtu .vti .vts .vtr .vtk .stl .ply .obj,
// a .pvd series index; an environment image through OpenImageIO: .hdr .exr .png .jpg .tif),
// the second whether the input is contoured (--contour), the rest is the file. A mesh goes
// through the viewer's own scene building (rfviewer::BuildScene: vtkRefractionSeriesReader,
// the surface or the contour, normals, ISR's distances) and its glass actor through the
// pass's glass checker; an image through vtkRefractionImageIO::ReadEnvironment.
// Contracts (a violation aborts; a crash is a finding): a file the viewer refuses gets a
// message; a scene the viewer accepts updates, and its glass, when the checker keeps it, has
// finite points and cells naming points that exist; an environment is a texture or an error.
// Built with -fsanitize=fuzzer in an instrumented clang build (tests/fuzz/CMakeLists.txt);
// without libFuzzer, fuzz_replay.c replays the kept corpus (corpus-files/).
#include "fuzz_contract.h"
#include "rfViewer.h"
#include "rfViewerOptions.h"
#include "rfViewerScene.h"
#include "vtkRefractionGlassChecker.h"
#ifdef REFRACTION_HAVE_IO
#include "vtkRefractionImageIO.h"
#endif

#include <vtkActor.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkProp.h>
#include <vtkRenderState.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>
#include <vtksys/SystemTools.hxx>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
void Require(bool condition, const char* what)
{
  rfFuzzRequire(condition, "fuzz_files", what);
}

// One folder per process for the files under test (removed at exit). A char array: it is
// never destroyed, so the exit handler may still read it.
char FolderPattern[] = "/tmp/rf_fuzz_files_XXXXXX";

const char* Folder()
{
  static const char* folder = [] {
    const char* made = mkdtemp(FolderPattern);
    Require(made != nullptr, "a temporary folder");
    std::atexit([] { vtksys::SystemTools::RemoveADirectory(FolderPattern); });
    return made;
  }();
  return folder;
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  rfCountingOutputWindow* messages = rfFuzzMessages();
  static const char* const kinds[] = { ".vtp", ".vtu", ".vti", ".vts", ".vtr", ".vtk", ".stl",
    ".ply", ".obj", ".pvd", ".hdr", ".exr", ".png", ".jpg", ".tif" };
  const int kindCount = static_cast<int>(sizeof(kinds) / sizeof(kinds[0]));
  if (size < 2)
  {
    return 0;
  }
  const std::string extension = kinds[data[0] % kindCount];
  const bool contour = data[1] & 1;
  const std::string path = std::string(Folder()) + "/input" + extension;
  FILE* file = std::fopen(path.c_str(), "wb");
  Require(file != nullptr, "the input file can be written");
  if (size > 2)
  {
    Require(std::fwrite(data + 2, 1, size - 2, file) == size - 2, "the input file is written");
  }
  std::fclose(file);

  const long before = messages->Messages;
  const bool image = data[0] % kindCount >= 10;
  if (image)
  {
#ifdef REFRACTION_HAVE_IO
    std::string error;
    vtkSmartPointer<vtkTexture> environment =
      vtkRefractionImageIO::ReadEnvironment(path, &error, 16);
    Require(environment != nullptr || !error.empty(), "an environment or an error");
#endif
    return 0;
  }

  rfViewerOptions options;
  options.Inputs = { path };
  if (contour)
  {
    options.Contour = std::to_string(static_cast<double>(data[1] >> 1) / 8.0);
  }
  rfViewerSettings settings;
  // The viewer checks the options into settings; only the contour values matter here.
  if (contour)
  {
    settings.ContourValues = { static_cast<double>(data[1] >> 1) / 8.0 };
  }
  // The viewer's refusals go to stderr, as a user sees them (the libFuzzer run closes it).
  rfviewer::Scene scene;
  const int status = rfviewer::BuildScene(options, settings, scene);
  if (status == RF_VIEWER_OK)
  {
    scene.Surface->Update();
  }
  Require(status == RF_VIEWER_OK || status == RF_VIEWER_BAD_INPUT,
    "the scene is built or the input refused as bad input");
  if (status != RF_VIEWER_OK)
  {
    return 0;
  }
  vtkNew<vtkRefractionGlassChecker> checker;
  vtkProp* props[1] = { scene.Glass };
  vtkRenderState state(scene.Renderer);
  state.SetPropArrayAndCount(props, 1);
  std::vector<vtkProp*> glass;
  std::vector<vtkProp*> others;
  checker->SplitProps(&state, glass, &others);
  vtkPolyData* mesh =
    vtkPolyData::SafeDownCast(scene.Glass->GetMapper()->GetInputDataObject(0, 0));
  if (!glass.empty() && mesh)
  {
    Require(rfFuzzWellFormed(mesh), "glass the checker keeps has ids in range and finite points");
  }
  if (glass.empty())
  {
    Require(messages->Messages > before, "glass that is not drawn as glass gets a message");
  }
  return 0;
}
