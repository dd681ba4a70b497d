// Pictures a test leaves for a person to look at (tests say where in their output).
#ifndef rfTestPNG_h
#define rfTestPNG_h

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>

#include <cstdio>
#include <string>

namespace rftest
{
inline void WritePNG(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
  std::printf("wrote %s\n", path.c_str());
}
}

#endif
