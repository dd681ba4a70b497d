// The benchmark's command line: the options with their defaults, and the parser that checks
// them and prints --help (vtksys::CommandLineArguments).
#ifndef rfBenchOptions_h
#define rfBenchOptions_h

#include <string>
#include <vector>

namespace rfbench
{
struct Options
{
  std::string Out;
  std::vector<int> Sizes{ 256, 512, 1024 };
  std::vector<std::string> Meshes{ "sphere", "torus", "isosurface", "bunny" };
  std::vector<std::string> Methods; // empty: every row of the preset
  int Frames = 30;
  int Repeats = 3;
  int Seed = 1;
  int Supersample = 4;
  int MultiSamples = 0; // the window's (--multisamples)
  int PeelCapture = 0;  // vtkRefractionPass::SetPeelCapture (--peel-capture)
  bool Smoke = false;
  bool Quick = false;
  bool X11 = false;
  bool Dump = false;
  bool Convergence = false; // also the full reference at twice the samples per side
  bool Scaling = false;     // the scaling sweep instead of the rows (rfBenchScaling)
  std::string FromCsv;
  std::string Environment = "builtin";
  std::string Bunny = "/usr/share/glmark2/models/bunny.obj";
};

// Fills `o` from argv, presets (--quick, --smoke) first; false after printing what is wrong.
// --help prints the options and exits 0.
bool Parse(int argc, char* argv[], Options& o);
}

#endif
