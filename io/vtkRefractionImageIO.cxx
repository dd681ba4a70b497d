#include "vtkRefractionImageIO.h"

#include "vtkDataArray.h"
#include "vtkEquirectangularToCubeMapTexture.h"
#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLTexture.h"
#include "vtkPointData.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <vector>

vtkStandardNewMacro(vtkRefractionImageIO);

namespace
{
// Routes a failure to the caller's string when there is one, so the API stays
// usable from code that prefers to decide itself how to report errors.
void ReportError(std::string* error, const std::string& message)
{
  if (error)
  {
    *error = message;
  }
  else
  {
    vtkGenericWarningMacro(<< message);
  }
}

std::string LowerExtension(const std::string& path)
{
  const std::size_t slash = path.find_last_of("/\\");
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return std::string();
  }
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Formats whose writers keep 32-bit floats; everything else is treated as an
// 8-bit display format, which is where clamping to [0,1] makes sense.
bool IsFloatFormat(const std::string& ext)
{
  return ext == "exr" || ext == "hdr" || ext == "tif" || ext == "tiff";
}

// OIIO keeps a per-thread error when a factory call fails before there is an
// object to ask; fall back to a generic reason so the message is never empty.
std::string OiioReason(const std::string& reason)
{
  return reason.empty() ? std::string("unknown OpenImageIO error") : reason;
}
}

//------------------------------------------------------------------------------
void vtkRefractionImageIO::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> vtkRefractionImageIO::ReadImage(
  const std::string& path, std::string* error)
{
  const std::string prefix = "vtkRefractionImageIO: cannot read '" + path + "': ";

  // Ask for alpha as stored: OIIO would otherwise premultiply PNG colours by
  // alpha, so an RGBA file would not read back the RGB values that were written.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto input = OIIO::ImageInput::open(path, &config);
  if (!input)
  {
    ReportError(error, prefix + OiioReason(OIIO::geterror()));
    return nullptr;
  }

  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
  {
    ReportError(error, prefix + "image has zero size");
    return nullptr;
  }
  if (spec.depth > 1 || spec.deep)
  {
    ReportError(error, prefix + "volume and deep images are not supported");
    return nullptr;
  }

  const int width = spec.width;
  const int height = spec.height;
  const int nchannels = spec.nchannels;
  const std::size_t numPixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);

  // Converting to float inside OIIO normalises integer data (0..255 -> 0..1)
  // and leaves float/half data as stored.
  std::vector<float> pixels(numPixels * static_cast<std::size_t>(nchannels));
  if (!input->read_image(0, 0, 0, nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
  {
    ReportError(error, prefix + OiioReason(input->geterror()));
    return nullptr;
  }
  input->close();

  vtkNew<vtkFloatArray> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(static_cast<vtkIdType>(numPixels));
  float* out = rgb->GetPointer(0);
  // Grey (and grey+alpha) images have fewer than 3 colour channels.
  const bool grey = nchannels < 3;
  for (int row = 0; row < height; ++row)
  {
    // File row 0 is the top of the picture, VTK row 0 is the bottom.
    const float* src = pixels.data() + static_cast<std::size_t>(row) * width * nchannels;
    float* dst = out + static_cast<std::size_t>(height - 1 - row) * width * 3;
    for (int x = 0; x < width; ++x, src += nchannels, dst += 3)
    {
      dst[0] = src[0];
      dst[1] = grey ? src[0] : src[1];
      dst[2] = grey ? src[0] : src[2];
    }
  }

  vtkSmartPointer<vtkImageData> image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->SetOrigin(0.0, 0.0, 0.0);
  image->SetSpacing(1.0, 1.0, 1.0);
  image->GetPointData()->SetScalars(rgb);
  return image;
}

//------------------------------------------------------------------------------
bool vtkRefractionImageIO::WriteImage(
  vtkImageData* image, const char* arrayName, const std::string& path, std::string* error)
{
  const std::string prefix = "vtkRefractionImageIO: cannot write '" + path + "': ";
  if (!image)
  {
    ReportError(error, prefix + "no image given");
    return false;
  }

  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] <= 0 || dims[1] <= 0 || dims[2] <= 0)
  {
    ReportError(error, prefix + "image is empty");
    return false;
  }
  if (dims[2] != 1)
  {
    ReportError(error,
      prefix + "image is 3D (" + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" +
        std::to_string(dims[2]) + "), only 2D images (depth 1) can be written");
    return false;
  }

  vtkDataArray* array = arrayName ? image->GetPointData()->GetArray(arrayName)
                                  : image->GetPointData()->GetScalars();
  if (!array)
  {
    ReportError(error,
      prefix +
        (arrayName ? "no point-data array named '" + std::string(arrayName) + "'"
                   : std::string("image has no active point scalars")));
    return false;
  }
  const int ncomp = array->GetNumberOfComponents();
  if (ncomp < 1 || ncomp > 4)
  {
    ReportError(error,
      prefix + "array '" + (array->GetName() ? array->GetName() : "") + "' has " +
        std::to_string(ncomp) + " components, 1 to 4 are supported");
    return false;
  }
  const int width = dims[0];
  const int height = dims[1];
  const vtkIdType numPixels = static_cast<vtkIdType>(width) * height;
  if (array->GetNumberOfTuples() != numPixels)
  {
    ReportError(error, prefix + "array size does not match the image dimensions");
    return false;
  }

  const std::string ext = LowerExtension(path);
  const bool asFloat = IsFloatFormat(ext);

  // Pixels are converted to the file's type here rather than left to OIIO so
  // the rules (no rounding of floats, clamping for 8-bit) are ours and stable.
  std::vector<float> floatPixels;
  std::vector<unsigned char> bytePixels;
  const std::size_t numValues = static_cast<std::size_t>(numPixels) * ncomp;
  if (asFloat)
  {
    floatPixels.resize(numValues);
  }
  else
  {
    bytePixels.resize(numValues);
  }
  const bool bytesVerbatim = array->GetDataType() == VTK_UNSIGNED_CHAR;
  for (int row = 0; row < height; ++row)
  {
    // VTK row 0 is the bottom of the picture, file row 0 the top.
    const vtkIdType srcRow = static_cast<vtkIdType>(height - 1 - row) * width;
    const std::size_t dstRow = static_cast<std::size_t>(row) * width * ncomp;
    for (int x = 0; x < width; ++x)
    {
      for (int c = 0; c < ncomp; ++c)
      {
        const double value = array->GetComponent(srcRow + x, c);
        const std::size_t dst = dstRow + static_cast<std::size_t>(x) * ncomp + c;
        if (asFloat)
        {
          floatPixels[dst] = static_cast<float>(value);
        }
        else if (bytesVerbatim)
        {
          bytePixels[dst] = static_cast<unsigned char>(value);
        }
        else
        {
          // NaN compares false everywhere, so test it first to map it to 0.
          const double clamped = std::isnan(value) ? 0.0 : std::min(1.0, std::max(0.0, value));
          bytePixels[dst] = static_cast<unsigned char>(std::lround(clamped * 255.0));
        }
      }
    }
  }

  auto output = OIIO::ImageOutput::create(path);
  if (!output)
  {
    ReportError(error, prefix + OiioReason(OIIO::geterror()));
    return false;
  }

  const OIIO::TypeDesc format = asFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  OIIO::ImageSpec spec(width, height, ncomp, format);
  if (ncomp == 2 || ncomp == 4)
  {
    spec.alpha_channel = ncomp - 1;
  }
  // Our data is not premultiplied; without this OIIO would divide PNG colours
  // by alpha on output and the values written would differ from the array.
  spec.attribute("oiio:UnassociatedAlpha", 1);

  if (!output->open(path, spec))
  {
    ReportError(error, prefix + OiioReason(output->geterror()));
    return false;
  }
  const void* data = asFloat ? static_cast<const void*>(floatPixels.data())
                             : static_cast<const void*>(bytePixels.data());
  if (!output->write_image(format, data))
  {
    ReportError(error, prefix + OiioReason(output->geterror()));
    output->close();
    return false;
  }
  if (!output->close())
  {
    ReportError(error, prefix + OiioReason(output->geterror()));
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkTexture> vtkRefractionImageIO::ReadEnvironment(
  const std::string& path, std::string* error, int cubeMapSize)
{
  if (cubeMapSize < 16 || cubeMapSize > 8192)
  {
    ReportError(error,
      "vtkRefractionImageIO: cube map size " + std::to_string(cubeMapSize) +
        " is out of range (16 to 8192)");
    return nullptr;
  }
  vtkSmartPointer<vtkImageData> image = ReadImage(path, error);
  if (!image)
  {
    return nullptr;
  }
  vtkNew<vtkOpenGLTexture> latLong;
  latLong->SetInputData(image);
  latLong->SetColorModeToDirectScalars();
  latLong->UseSRGBColorSpaceOff();
  latLong->InterpolateOn();
  // No mipmaps on the lat-long image: the conversion's longitude jumps from 1 to 0 at the
  // seam, and the derivative there would pick the coarsest level, a grey line in the sky.
  latLong->MipmapOff();
  // Repeat would blend the north pole's row with the south pole's.
  latLong->SetWrap(vtkTexture::ClampToEdge);
  auto cubeMap = vtkSmartPointer<vtkEquirectangularToCubeMapTexture>::New();
  cubeMap->SetInputTexture(latLong);
  cubeMap->SetCubeMapSize(static_cast<unsigned int>(cubeMapSize));
  // VTK's image-based lighting prefilters the environment and asks for both.
  cubeMap->InterpolateOn();
  cubeMap->MipmapOn();
  return cubeMap;
}
