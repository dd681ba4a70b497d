// The viewer's command line: the options as given, their checked values, and the parser
// (vtksys::CommandLineArguments) with the --help text.
#ifndef rfViewerOptions_h
#define rfViewerOptions_h

#include "vtkRefractionPass.h"

#include <string>
#include <vector>

// The options as typed (text, checked by rfViewerParseOptions).
struct rfViewerOptions
{
  std::vector<std::string> Inputs;
  bool Series = false;
  std::string Demo;
  std::string Contour;
  std::string Array;
  std::string Environment;
  std::string Background = "0.12,0.12,0.14,0.35,0.45,0.6";
  std::string Method = "dir";
  std::string IOR = "1.5";
  std::string Dispersion;
  std::string Steps = "5";
  std::string Layers = "4";
  std::string PeelCapture = "auto";
  std::string Size = "512";
  std::string Frames;
  std::string Time;
  std::string OutDir;
  std::string Screenshot;
  std::string ContactSheet;
  std::string SheetColumns = "4";
  std::string SheetFrames = "8";
  std::string Orbit = "0";
  std::string Azimuth = "0";
  std::string Elevation = "20";
  std::string Zoom = "1.1";
  std::string Timing = "0";
  std::string TimingRepeats = "3";
  bool Interactive = false;
  bool NoText = false;
  bool AntiAliasing = false;
  bool CoarseShading = false;
  bool ExitReflection = false; // accepted for older scripts: on by default
  bool NoExitReflection = false;
  bool SmoothInternalReflections = false;
  bool Masks = false;
  bool Help = false;
  bool EGL = false; // accepted for older scripts: headless rendering always tries EGL first
};

// The checked values.
struct rfViewerSettings
{
  int Method = vtkRefractionPass::DIR;
  double IOR = 1.5;
  std::vector<double> Dispersion; // red, green, blue indices; empty: none
  int Steps = 5;
  int Layers = 4;
  int PeelCapture = vtkRefractionPass::PEEL_CAPTURE_AUTO;
  int Width = 512;
  int Height = 512;
  int Frames = -1; // -1: every time step (or one frame of a static mesh)
  bool HaveTime = false;
  double Time = 0.0;
  std::vector<double> ContourValues;
  double Background[6] = { 0, 0, 0, 0, 0, 0 };
  bool Gradient = false;
  int SheetColumns = 4;
  int SheetFrames = 8;
  double Orbit = 0.0;
  double Azimuth = 0.0;
  double Elevation = 20.0;
  double Zoom = 1.1;
  int Timing = 0;
  int TimingRepeats = 3; // rounds of --timing, each timing every method and the plain render
};

// Parses argv after @a preset; returns RF_VIEWER_OK, the exit code of a usage error (its
// message printed), or -1 after printing --help.
int rfViewerParseOptions(int argc, char* argv[], const std::vector<std::string>& preset,
  rfViewerOptions& options, rfViewerSettings& settings);

// The program's name for messages: RefractionViewer, or RefractionDemo for the preset.
const char* rfViewerProgram();

// Print "<program>: message (see --help)" and return RF_VIEWER_USAGE.
int rfViewerUsage(const std::string& message);

// Print "<program>: message" and return RF_VIEWER_BAD_INPUT.
int rfViewerBadInput(const std::string& message);

// 'text', as messages quote values and paths.
std::string rfViewerQuote(const std::string& text);

#endif
