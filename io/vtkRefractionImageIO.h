/**
 * @class   vtkRefractionImageIO
 * @brief   Reads and writes 2D images (EXR, HDR, PNG, TIFF, JPEG) through OpenImageIO.
 *
 * VTK's own readers do not handle OpenEXR/Radiance HDR environment maps, which
 * the refraction pass needs as linear float data; this thin wrapper over
 * OpenImageIO fills that gap and is also used to write float render results
 * without losing range.
 *
 * Orientation: VTK's image origin is the bottom-left pixel while image files
 * store the top row first, so rows are flipped on both read and write; an
 * image read here displays upright in VTK, and a VTK image written here
 * appears upright in an image viewer.
 *
 * Both functions report failure through their return value and a message in
 * @a error (naming the path and OpenImageIO's reason). When @a error is
 * nullptr the message goes to VTK's generic warning output instead, so that
 * failures are never silent.
 */

#ifndef vtkRefractionImageIO_h
#define vtkRefractionImageIO_h

#include "refractionio_export.h"

#include "vtkImageData.h" // For vtkSmartPointer<vtkImageData> return values
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For return values
#include "vtkTexture.h"      // For vtkSmartPointer<vtkTexture> return values

#include <string> // For paths and error messages

class REFRACTIONIO_EXPORT vtkRefractionImageIO : public vtkObject
{
public:
  static vtkRefractionImageIO* New();
  vtkTypeMacro(vtkRefractionImageIO, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Read the first subimage of @a path into a vtkImageData of dimensions
   * (width, height, 1), with one 3-component float point-data array named
   * "RGB" set as the active scalars. Float files keep their stored linear
   * values; integer files are normalised (8-bit 0..255 becomes 0..1).
   * One-channel (and grey+alpha) images are replicated to grey RGB; extra
   * channels such as alpha are dropped. Returns nullptr on failure.
   */
  static vtkSmartPointer<vtkImageData> ReadImage(const std::string& path, std::string* error);

  /**
   * Write the point-data array @a arrayName (nullptr: the active scalars) of
   * a 2D image to @a path, the format following the extension. The array may
   * have 1 to 4 components of any numeric type. Float-capable formats (.exr,
   * .hdr, .tif, .tiff) are written as 32-bit float with the values
   * converted unchanged (no normalisation); other formats (.png, .jpg, ...)
   * are written as 8 bits, unsigned char arrays verbatim and other types
   * clamped to [0,1] then scaled by 255. Radiance .hdr takes 3 components
   * only and stores shared-exponent RGBE, so it is not an exact round trip.
   * Returns false on failure.
   */
  static bool WriteImage(
    vtkImageData* image, const char* arrayName, const std::string& path, std::string* error);

  /**
   * Read a lat-long (equirectangular) environment image, EXR, HDR or PNG, and return the
   * cube map to give vtkRenderer::SetEnvironmentTexture (the refraction pass, VTK's
   * image-based lighting and vtkSkybox all take it). The image becomes a linear float
   * texture whose values reach the shaders unchanged (direct scalars: without that, VTK
   * maps float scalars through a lookup table and the world turns red), interpolated and
   * clamped at the edges, converted by a vtkEquirectangularToCubeMapTexture of
   * @a cubeMapSize pixels a face (16 to 8192) with interpolation and mipmaps on, as VTK's
   * image-based lighting expects. The top row of the file is the sky (+y, the renderer's
   * EnvironmentUp by default). PNG and other 8-bit files are taken as linear too (no sRGB
   * decoding), so that a colour written to the file is the colour the glass shows. Returns nullptr and a message on
   * failure (a missing or unreadable file, a size out of range).
   */
  static vtkSmartPointer<vtkTexture> ReadEnvironment(
    const std::string& path, std::string* error, int cubeMapSize = 512);

protected:
  vtkRefractionImageIO() = default;
  ~vtkRefractionImageIO() override = default;

private:
  vtkRefractionImageIO(const vtkRefractionImageIO&) = delete;
  void operator=(const vtkRefractionImageIO&) = delete;
};

#endif
