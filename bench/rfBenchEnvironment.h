// The renderer's environment for --environment: none (the pass's built-in one), the studio
// made in code, or an HDR file, as a cube map.
#ifndef rfBenchEnvironment_h
#define rfBenchEnvironment_h

#include <vtkSmartPointer.h>
#include <vtkTexture.h>

#include <string>

namespace rfbench
{
// The cube map for `name` (builtin, studio or a .hdr path; nullptr for builtin or on error,
// its message printed), and a sentence describing it for the report.
vtkSmartPointer<vtkTexture> MakeEnvironment(
  const std::string& name, bool smoke, std::string& description);
}

#endif
