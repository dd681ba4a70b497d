// Round trips through vtkRefractionImageIO, and an orientation cross-check
// against VTK's own PNG reader/writer: a round trip alone cannot see a reader
// and a writer that are both wrong in the same way (e.g. neither flips rows).

#include "vtkRefractionImageIO.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
int Failures = 0;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "FAIL: " << what << "\n";
    ++Failures;
  }
}

const int Width = 7;  // non-square, so a transposition would be caught too
const int Height = 5;

// A marker value in the top-left pixel as displayed (VTK row Height-1): a
// vertical flip moves it to the bottom-left. The values are not
// representable as half floats, so an EXR stored as HALF would fail the
// exact comparison.
const float Marker[3] = { 100.0f, -7.0f, 0.123456789f };

float Gradient(int x, int y, int c)
{
  if (x == 0 && y == Height - 1)
  {
    return Marker[c];
  }
  // Ranges below 0 and above 1 so clamping and float storage both matter.
  return -0.5f + 2.0f * static_cast<float>(x) / (Width - 1) +
    0.3f * static_cast<float>(y) / (Height - 1) + 0.01f * static_cast<float>(c) + 1.0e-4f / 3.0f;
}

vtkSmartPointer<vtkImageData> MakeImage(int ncomp)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(Width, Height, 1);
  vtkNew<vtkFloatArray> array;
  array->SetName("colour");
  array->SetNumberOfComponents(ncomp);
  array->SetNumberOfTuples(Width * Height);
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      for (int c = 0; c < ncomp; ++c)
      {
        // The 4th component is an alpha well away from 1, so a writer that
        // premultiplied or a reader that unpremultiplied would be caught.
        array->SetComponent(y * Width + x, c, c == 3 ? 0.5f : Gradient(x, y, c));
      }
    }
  }
  image->GetPointData()->AddArray(array);
  return image;
}

bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

float Clamp01(float v)
{
  return std::min(1.0f, std::max(0.0f, v));
}

// Checks the basic shape of what ReadImage returns.
bool CheckReadShape(vtkImageData* image, const std::string& what)
{
  Check(image != nullptr, what + ": ReadImage returned nullptr");
  if (!image)
  {
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  Check(dims[0] == Width && dims[1] == Height && dims[2] == 1,
    what + ": dimensions " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" +
      std::to_string(dims[2]));
  vtkDataArray* rgb = image->GetPointData()->GetArray("RGB");
  Check(rgb != nullptr, what + ": no array named RGB");
  Check(image->GetPointData()->GetScalars() == rgb, what + ": RGB is not the active scalars");
  if (!rgb || dims[0] != Width || dims[1] != Height)
  {
    return false;
  }
  Check(rgb->GetDataType() == VTK_FLOAT, what + ": RGB is not float");
  Check(rgb->GetNumberOfComponents() == 3, what + ": RGB does not have 3 components");
  return rgb->GetDataType() == VTK_FLOAT && rgb->GetNumberOfComponents() == 3;
}

void TestExrRoundTrip(const std::string& dir)
{
  const std::string path = dir + "/TestImageIO_gradient.exr";
  std::string error;
  auto source = MakeImage(3);
  Check(vtkRefractionImageIO::WriteImage(source, "colour", path, &error),
    "write EXR: " + error);
  auto image = vtkRefractionImageIO::ReadImage(path, &error);
  if (!CheckReadShape(image, "EXR read (" + error + ")"))
  {
    return;
  }
  vtkDataArray* rgb = image->GetPointData()->GetArray("RGB");
  int mismatches = 0;
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        const float got = static_cast<float>(rgb->GetComponent(y * Width + x, c));
        if (got != Gradient(x, y, c))
        {
          if (mismatches++ < 5)
          {
            std::cerr << "  EXR (" << x << "," << y << "," << c << "): got " << got
                      << " expected " << Gradient(x, y, c) << "\n";
          }
        }
      }
    }
  }
  Check(mismatches == 0, "EXR float round trip is not exact (" + std::to_string(mismatches) +
      " values differ)");
  Check(rgb->GetComponent((Height - 1) * Width, 0) == Marker[0], "EXR: marker not top-left");

  // One-component data is written as a single channel and read back as grey.
  auto grey = MakeImage(1);
  const std::string greyPath = dir + "/TestImageIO_grey.exr";
  Check(vtkRefractionImageIO::WriteImage(grey, nullptr, greyPath, &error) == false,
    "write with nullptr arrayName and no active scalars should fail");
  Check(Contains(error, "scalars"), "missing active scalars message: " + error);
  grey->GetPointData()->SetActiveScalars("colour");
  Check(vtkRefractionImageIO::WriteImage(grey, nullptr, greyPath, &error),
    "write 1-component EXR: " + error);
  auto greyRead = vtkRefractionImageIO::ReadImage(greyPath, &error);
  if (CheckReadShape(greyRead, "grey EXR read (" + error + ")"))
  {
    vtkDataArray* g = greyRead->GetPointData()->GetArray("RGB");
    bool same = true;
    for (int i = 0; i < Width * Height; ++i)
    {
      const float expected = Gradient(i % Width, i / Width, 0);
      for (int c = 0; c < 3; ++c)
      {
        same = same && static_cast<float>(g->GetComponent(i, c)) == expected;
      }
    }
    Check(same, "grey EXR is not read back as replicated exact grey");
  }
}

void TestPngRoundTrip(const std::string& dir)
{
  std::string error;
  const double tolerance = 1.0 / 255.0;
  for (int ncomp : { 3, 4 })
  {
    const std::string what = "PNG " + std::to_string(ncomp) + " components";
    const std::string path = dir + "/TestImageIO_gradient" + std::to_string(ncomp) + ".png";
    auto source = MakeImage(ncomp);
    Check(vtkRefractionImageIO::WriteImage(source, "colour", path, &error),
      "write " + what + ": " + error);
    auto image = vtkRefractionImageIO::ReadImage(path, &error);
    if (!CheckReadShape(image, what + " read (" + error + ")"))
    {
      continue;
    }
    vtkDataArray* rgb = image->GetPointData()->GetArray("RGB");
    double worst = 0.0;
    for (int y = 0; y < Height; ++y)
    {
      for (int x = 0; x < Width; ++x)
      {
        for (int c = 0; c < 3; ++c)
        {
          const double diff =
            std::abs(rgb->GetComponent(y * Width + x, c) - Clamp01(Gradient(x, y, c)));
          worst = std::max(worst, diff);
        }
      }
    }
    Check(worst <= tolerance,
      what + ": round trip error " + std::to_string(worst) + " exceeds 1/255");
    // The marker's red (100) clamps to 1 and its green (-7) to 0.
    Check(rgb->GetComponent((Height - 1) * Width, 0) == 1.0 &&
        rgb->GetComponent((Height - 1) * Width, 1) == 0.0,
      what + ": clamped marker not in the top-left pixel");
  }

  // Unsigned char arrays go to 8-bit files unscaled.
  auto bytes = vtkSmartPointer<vtkImageData>::New();
  bytes->SetDimensions(Width, Height, 1);
  vtkNew<vtkUnsignedCharArray> byteArray;
  byteArray->SetName("bytes");
  byteArray->SetNumberOfComponents(3);
  byteArray->SetNumberOfTuples(Width * Height);
  for (int i = 0; i < Width * Height; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      byteArray->SetComponent(i, c, (i * 7 + c * 50) % 256);
    }
  }
  bytes->GetPointData()->SetScalars(byteArray);
  const std::string bytePath = dir + "/TestImageIO_bytes.png";
  Check(vtkRefractionImageIO::WriteImage(bytes, nullptr, bytePath, &error),
    "write uchar PNG: " + error);
  auto byteRead = vtkRefractionImageIO::ReadImage(bytePath, &error);
  if (CheckReadShape(byteRead, "uchar PNG read (" + error + ")"))
  {
    vtkDataArray* rgb = byteRead->GetPointData()->GetArray("RGB");
    double worst = 0.0;
    for (int i = 0; i < Width * Height; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst,
          std::abs(rgb->GetComponent(i, c) * 255.0 - byteArray->GetComponent(i, c)));
      }
    }
    Check(worst < 1.0e-3, "uchar PNG not written verbatim (worst error " +
        std::to_string(worst) + " levels)");
  }
}

// Our files must agree with VTK's own convention (row 0 = bottom) as
// implemented by vtkPNGReader/vtkPNGWriter.
void TestOrientationAgainstVTK(const std::string& dir)
{
  std::string error;
  const int markerIndex = (Height - 1) * Width; // top-left as displayed

  // Written by us, read by VTK.
  const std::string ours = dir + "/TestImageIO_gradient3.png";
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(ours.c_str());
  reader->Update();
  vtkImageData* vtkRead = reader->GetOutput();
  int dims[3];
  vtkRead->GetDimensions(dims);
  Check(dims[0] == Width && dims[1] == Height, "vtkPNGReader: unexpected dimensions");
  vtkDataArray* scalars = vtkRead->GetPointData()->GetScalars();
  Check(scalars && dims[0] == Width && dims[1] == Height &&
      scalars->GetComponent(markerIndex, 0) == 255.0 &&
      scalars->GetComponent(markerIndex, 1) == 0.0,
    "our PNG read by vtkPNGReader does not have the marker top-left");

  // Written by VTK, read by us.
  auto bytes = vtkSmartPointer<vtkImageData>::New();
  bytes->SetDimensions(Width, Height, 1);
  bytes->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* p = static_cast<unsigned char*>(bytes->GetScalarPointer());
  std::fill(p, p + Width * Height * 3, static_cast<unsigned char>(10));
  p[markerIndex * 3 + 0] = 200;
  const std::string theirs = dir + "/TestImageIO_vtkwritten.png";
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(theirs.c_str());
  writer->SetInputData(bytes);
  writer->Write();
  auto image = vtkRefractionImageIO::ReadImage(theirs, &error);
  if (CheckReadShape(image, "vtkPNGWriter file read (" + error + ")"))
  {
    vtkDataArray* rgb = image->GetPointData()->GetArray("RGB");
    Check(std::abs(rgb->GetComponent(markerIndex, 0) - 200.0 / 255.0) < 1.0e-6 &&
        std::abs(rgb->GetComponent(0, 0) - 10.0 / 255.0) < 1.0e-6,
      "PNG written by vtkPNGWriter is not read upright");
  }
}

void TestErrors(const std::string& dir)
{
  std::string error;

  const std::string missing = dir + "/TestImageIO_does_not_exist.exr";
  auto image = vtkRefractionImageIO::ReadImage(missing, &error);
  Check(image == nullptr, "reading a missing file should return nullptr");
  Check(Contains(error, missing), "missing-file message lacks the path: '" + error + "'");

  // A file that exists but is not an image.
  const std::string garbage = dir + "/TestImageIO_garbage.png";
  if (FILE* f = std::fopen(garbage.c_str(), "wb"))
  {
    std::fputs("this is not a PNG file", f);
    std::fclose(f);
  }
  error.clear();
  image = vtkRefractionImageIO::ReadImage(garbage, &error);
  Check(image == nullptr, "reading a non-image should return nullptr");
  Check(Contains(error, garbage), "non-image message lacks the path: '" + error + "'");

  vtkNew<vtkImageData> volume;
  volume->SetDimensions(4, 3, 2);
  volume->AllocateScalars(VTK_FLOAT, 1);
  error.clear();
  Check(!vtkRefractionImageIO::WriteImage(volume, nullptr, dir + "/TestImageIO_3d.exr", &error),
    "writing a 3D image should fail");
  Check(Contains(error, "3D"), "3D image message unclear: '" + error + "'");

  auto flat = MakeImage(3);
  error.clear();
  Check(!vtkRefractionImageIO::WriteImage(flat, "nope", dir + "/TestImageIO_nope.exr", &error),
    "writing a missing array should fail");
  Check(Contains(error, "nope"), "missing array message lacks its name: '" + error + "'");

  const std::string unwritable = dir + "/no_such_directory/TestImageIO.png";
  error.clear();
  Check(!vtkRefractionImageIO::WriteImage(flat, "colour", unwritable, &error),
    "writing into a missing directory should fail");
  Check(Contains(error, unwritable), "unwritable path message lacks the path: '" + error + "'");
}
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " <scratch directory>\n";
    return EXIT_FAILURE;
  }
  const std::string dir = argv[1];

  TestExrRoundTrip(dir);
  TestPngRoundTrip(dir);
  TestOrientationAgainstVTK(dir);
  TestErrors(dir);

  if (Failures)
  {
    std::cerr << Failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  std::cout << "all image I/O checks passed\n";
  return EXIT_SUCCESS;
}
