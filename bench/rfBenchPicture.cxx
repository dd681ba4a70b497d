#include "rfBenchPicture.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>

namespace rfbench
{
// The window's colour as floats in [0,1], bottom row first (as the reference).
std::vector<float> GrabColour(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  vtkDataArray* rgb = grab->GetOutput()->GetPointData()->GetScalars();
  std::vector<float> colour(3 * rgb->GetNumberOfTuples());
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      colour[3 * i + c] = static_cast<float>(rgb->GetComponent(i, c) / 255.0);
    }
  }
  return colour;
}

// An RGB float image (bottom row first) as an 8-bit PNG, for a person to compare.
void WritePng(const std::string& path, const std::vector<float>& rgb, int size)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(size, size, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  for (size_t i = 0; i < rgb.size(); ++i)
  {
    out[i] = static_cast<unsigned char>(std::min(std::max(rgb[i], 0.0f), 1.0f) * 255.0f + 0.5f);
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
}
}
