#include "vtkRefractionTargets.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

vtkStandardNewMacro(vtkRefractionTargets);

namespace
{
struct TargetFormat
{
  const char* Name;
  int Components; // 0: a depth texture
  int InternalFormat;
  int Format;
  int Filter;
};

const TargetFormat kFormats[vtkRefractionTargets::TARGET_COUNT] = {
  { "front surface", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Nearest },
  { "front depth", 0, 0, 0, vtkTextureObject::Nearest },
  { "front d_N", 1, GL_R32F, GL_RED, vtkTextureObject::Nearest },
  { "front colour", 4, GL_RGBA8, GL_RGBA, vtkTextureObject::Nearest },
  // Back normals are filtered (the paper: filtering reduces noise; empty texels are zero
  // vectors, which only shorten a filtered normal); the depth beside them in alpha is read
  // unfiltered (texelFetch). One target instead of two: the back capture writes one output.
  // 32-bit floats: on the 256 px sphere DIR (5 steps) gave 37.9 dB against the two-interface
  // reference with half floats, 38.1 dB with floats.
  { "back surface", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Linear },
  { "back z-buffer", 0, 0, 0, vtkTextureObject::Nearest },
  { "scene colour", 4, GL_RGBA8, GL_RGBA, vtkTextureObject::Nearest },
  { "scene depth", 0, 0, 0, vtkTextureObject::Nearest },
  { "glass colour", 4, GL_RGBA16F, GL_RGBA, vtkTextureObject::Nearest },
  { "shaded glass colour", 4, GL_RGBA16F, GL_RGBA, vtkTextureObject::Nearest },
  { "corner z-buffer", 0, 0, 0, vtkTextureObject::Nearest },
  { "peeled layer 1", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Nearest },
  { "peeled layer 2", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Nearest },
  { "peeled layer 3", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Nearest },
  { "peeled layer 4", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Nearest },
  { "peeled layer 5", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Nearest },
  { "peeled layer 6", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Nearest },
  { "peeled layer 7", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Nearest },
  { "peel z-buffer", 0, 0, 0, vtkTextureObject::Nearest },
  { "peeled depths 0-3", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Nearest },
  { "peeled depths 4-7", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Nearest },
  { "peel slots", 1, GL_R32UI, GL_RED_INTEGER, vtkTextureObject::Nearest },
  { "peeled layers stacked", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Nearest },
  { "front SH exit", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Nearest },
  { "debug P2", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Nearest },
  { "debug T2", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Nearest },
  // Filtered: a pixel between the traced ones reads their mean in one lookup.
  { "coarse colour", 4, GL_RGBA16F, GL_RGBA, vtkTextureObject::Linear },
  // 32-bit: the mean of the blocks' exit directions is compared with unit length to 5e-4,
  // which half floats' rounding of each component (up to 5e-4) made fail at random pixels.
  { "coarse ray", 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Linear },
  { "coarse z-buffer", 0, 0, 0, vtkTextureObject::Nearest },
  { "trace z-buffer", 0, 0, 0, vtkTextureObject::Nearest },
};

vtkSmartPointer<vtkTextureObject> MakeColorTexture(vtkOpenGLRenderWindow* renWin, int width,
  int height, int components, int internalFormat, int format, int filter)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(renWin);
  texture->SetInternalFormat(internalFormat);
  texture->SetFormat(format);
  const bool bytes = internalFormat == GL_RGBA8;
  const bool integers = internalFormat == GL_R32UI;
  texture->SetDataType(bytes ? GL_UNSIGNED_BYTE : integers ? GL_UNSIGNED_INT : GL_FLOAT);
  texture->SetMinificationFilter(filter);
  texture->SetMagnificationFilter(filter);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->Allocate2D(
    width, height, components, bytes ? VTK_UNSIGNED_CHAR : integers ? VTK_UNSIGNED_INT : VTK_FLOAT);
  return texture;
}

// What the driver allocated for a 2D texture, from its reported channel sizes: level 0 and
// every mipmap level it has (the levels stop at the first of width 0).
unsigned long long MeasureBytes(vtkTextureObject* texture)
{
  texture->Activate();
  GLint bits = 0;
  for (GLenum channel : { GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE,
         GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_STENCIL_SIZE })
  {
    GLint size = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, channel, &size);
    bits += size;
  }
  unsigned long long bytes = 0;
  for (GLint level = 0; level < 15; ++level)
  {
    GLint width = 0;
    GLint height = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_WIDTH, &width);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_HEIGHT, &height);
    if (width <= 0 || height <= 0)
    {
      break;
    }
    bytes += static_cast<unsigned long long>(width) * height * ((bits + 7) / 8);
  }
  texture->Deactivate();
  return bytes;
}
}

//------------------------------------------------------------------------------
vtkRefractionTargets::vtkRefractionTargets() = default;
vtkRefractionTargets::~vtkRefractionTargets() = default;

//------------------------------------------------------------------------------
const char* vtkRefractionTargets::GetTargetName(int target)
{
  return target >= 0 && target < TARGET_COUNT ? kFormats[target].Name : "(none)";
}

//------------------------------------------------------------------------------
void vtkRefractionTargets::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Size: " << this->Width << " x " << this->Height << "\n";
  for (int i = 0; i < TARGET_COUNT; ++i)
  {
    if (this->Targets[i])
    {
      os << indent << kFormats[i].Name << ": " << this->TargetBytes[i] << " bytes\n";
    }
  }
  os << indent << "Reduction levels: " << this->ReductionLevels.size() << " ("
     << this->ReductionBytes << " bytes)\n";
}

//------------------------------------------------------------------------------
void vtkRefractionTargets::Allocate(vtkOpenGLRenderWindow* renWin, int target)
{
  const TargetFormat& f = kFormats[target];
  if (f.Components == 0)
  {
    auto depth = vtkSmartPointer<vtkTextureObject>::New();
    depth->SetContext(renWin);
    if ((target == SCENE_DEPTH && this->SceneDepthFormat < 0) || target == PEEL_Z)
    {
      // PEEL_Z's stencil counts the fragments a peeling draw keeps (vtkRefractionPeelCount).
      depth->AllocateDepthStencil(this->Width, this->Height);
    }
    else if (target == COARSE_Z)
    {
      depth->AllocateDepth(
        (this->Width + 1) / 2, (this->Height + 1) / 2, vtkTextureObject::Float32);
    }
    else
    {
      depth->AllocateDepth(this->Width, this->Height,
        target == SCENE_DEPTH ? this->SceneDepthFormat : vtkTextureObject::Float32);
    }
    this->Targets[target] = depth;
  }
  else
  {
    // PEEL's slots, and one row more for the count of layers found (its first texel); the
    // coarse shading's targets, a texel per 2x2 block of pixels.
    const bool coarse = target == COARSE_COLOR || target == COARSE_RAY;
    int columns = coarse ? (this->Width + 1) / 2 : this->Width;
    int rows = target == PEEL_SLOTS ? this->Height * this->PeelSlots + 1
      : coarse                      ? (this->Height + 1) / 2
                                    : this->Height;
    if (target == PEEL_STACK)
    {
      // As many layers to a row as the largest texture is wide: a stack of K layers one above
      // the other is too tall at 3840x2160 with 8 layers (17,280 rows against llvmpipe's
      // 16,384).
      GLint largest = 0;
      glGetIntegerv(GL_MAX_TEXTURE_SIZE, &largest);
      const int layers = this->PeelSlots + 1;
      int stackColumns = this->Width > 0 ? static_cast<int>(largest) / this->Width : 1;
      stackColumns = stackColumns < 1 ? 1 : stackColumns > layers ? layers : stackColumns;
      columns = this->Width * stackColumns;
      rows = this->Height * ((layers + stackColumns - 1) / stackColumns);
      if (rows > static_cast<int>(largest))
      {
        // Left unallocated: vtkRefractionLayerPack reports it and PEEL does not refract.
        vtkErrorMacro("PEEL's " << layers << " layers of " << this->Width << " x "
                                << this->Height << " do not fit the largest texture ("
                                << largest << " texels a side)");
        this->TargetBytes[target] = 0;
        return;
      }
    }
    this->Targets[target] = MakeColorTexture(
      renWin, columns, rows, f.Components, f.InternalFormat, f.Format, f.Filter);
  }
  this->TargetBytes[target] = MeasureBytes(this->Targets[target]);
  this->MipmapsCounted[target] = false;
}

//------------------------------------------------------------------------------
void vtkRefractionTargets::CountMipmaps(int target)
{
  if (target >= 0 && target < TARGET_COUNT && this->Targets[target] &&
    !this->MipmapsCounted[target])
  {
    this->TargetBytes[target] = MeasureBytes(this->Targets[target]);
    this->MipmapsCounted[target] = true;
  }
}

//------------------------------------------------------------------------------
vtkRefractionTargets::ScopedMipmaps::ScopedMipmaps(vtkRefractionTargets* targets, int target,
  int minification, int magnification, int maxLevel)
  : Targets(targets)
  , Target(target)
  , Texture(targets->Get(target))
{
  if (!this->Texture)
  {
    return;
  }
  this->Minification = this->Texture->GetMinificationFilter();
  this->Magnification = this->Texture->GetMagnificationFilter();
  this->MaxLevel = this->Texture->GetMaxLevel();
  this->Texture->SetMinificationFilter(minification);
  this->Texture->SetMagnificationFilter(magnification);
  this->Texture->SetMaxLevel(maxLevel);
  this->Texture->Activate();
  glGenerateMipmap(GL_TEXTURE_2D);
}

//------------------------------------------------------------------------------
vtkRefractionTargets::ScopedMipmaps::~ScopedMipmaps()
{
  if (!this->Texture)
  {
    return;
  }
  this->Texture->SetMinificationFilter(this->Minification);
  this->Texture->SetMagnificationFilter(this->Magnification);
  this->Texture->SetMaxLevel(this->MaxLevel);
  this->Texture->Activate(); // sends the changed parameters to the texture again
  this->Texture->Deactivate();
  this->Targets->CountMipmaps(this->Target);
}

//------------------------------------------------------------------------------
void vtkRefractionTargets::SetPeelSlots(int slots)
{
  slots = slots < 1 ? 1 : slots;
  if (slots != this->PeelSlots)
  {
    for (int target : { PEEL_SLOTS, PEEL_STACK })
    {
      this->Targets[target] = nullptr; // released with its context by its destructor
      this->TargetBytes[target] = 0;
    }
  }
  this->PeelSlots = slots;
}

//------------------------------------------------------------------------------
void vtkRefractionTargets::Update(vtkOpenGLRenderWindow* renWin, int width, int height,
  const std::vector<bool>& wanted, bool reduction)
{
  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Framebuffer->SetContext(renWin);
  }
  const bool resized = width != this->Width || height != this->Height;
  this->Width = width;
  this->Height = height;
  for (int i = 0; i < TARGET_COUNT; ++i)
  {
    const bool want = i < static_cast<int>(wanted.size()) && wanted[i];
    if (this->Targets[i] && (!want || resized))
    {
      this->Targets[i]->ReleaseGraphicsResources(renWin);
      this->Targets[i] = nullptr;
      this->TargetBytes[i] = 0;
    }
    if (want && !this->Targets[i])
    {
      this->Allocate(renWin, i);
    }
  }
  if (!this->ReductionLevels.empty() && (!reduction || resized))
  {
    for (auto& level : this->ReductionLevels)
    {
      level->ReleaseGraphicsResources(renWin);
    }
    this->ReductionLevels.clear();
    this->ReductionBytes = 0;
  }
  if (reduction && this->ReductionLevels.empty())
  {
    int w = width;
    int h = height;
    do
    {
      w = (w + ReductionBlock - 1) / ReductionBlock;
      h = (h + ReductionBlock - 1) / ReductionBlock;
      this->ReductionLevels.push_back(
        MakeColorTexture(renWin, w, h, 2, GL_RG32F, GL_RG, vtkTextureObject::Nearest));
      this->ReductionBytes += MeasureBytes(this->ReductionLevels.back());
    } while (w > 1 || h > 1);
  }
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkRefractionTargets::Get(int target) const
{
  return target >= 0 && target < TARGET_COUNT ? this->Targets[target].Get() : nullptr;
}

//------------------------------------------------------------------------------
vtkOpenGLFramebufferObject* vtkRefractionTargets::GetFramebuffer() const
{
  return this->Framebuffer;
}

//------------------------------------------------------------------------------
bool vtkRefractionTargets::MatchSceneDepth(std::string& error)
{
  GLint binding = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &binding);
  // The default framebuffer names its depth GL_DEPTH, an object GL_DEPTH_ATTACHMENT.
  const GLenum attachment = binding == 0 ? GL_DEPTH : GL_DEPTH_ATTACHMENT;
  GLint type = GL_NONE;
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  if (type == GL_NONE)
  {
    error = "the framebuffer the scene is drawn into has no depth buffer";
    return false;
  }
  GLint depthBits = 0;
  GLint stencilBits = 0;
  GLint component = GL_NONE;
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depthBits);
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &stencilBits);
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &component);
  int format = -2;
  if (stencilBits == 8 && depthBits == 24)
  {
    format = -1;
  }
  else if (stencilBits == 0 && component == GL_FLOAT && depthBits == 32)
  {
    format = vtkTextureObject::Float32;
  }
  else if (stencilBits == 0 && component == GL_UNSIGNED_NORMALIZED)
  {
    format = depthBits == 16 ? vtkTextureObject::Fixed16
      : depthBits == 24      ? vtkTextureObject::Fixed24
      : depthBits == 32      ? vtkTextureObject::Fixed32
                             : -2;
  }
  if (format == -2)
  {
    error = "the scene's depth buffer has a format the capture cannot match (" +
      std::to_string(depthBits) + " depth bits, " + std::to_string(stencilBits) +
      " stencil bits, " + (component == GL_FLOAT ? "float" : "fixed point") + ")";
    return false;
  }
  if (format != this->SceneDepthFormat && this->Targets[SCENE_DEPTH])
  {
    this->Targets[SCENE_DEPTH] = nullptr; // released with its context by its destructor
    this->TargetBytes[SCENE_DEPTH] = 0;
  }
  this->SceneDepthFormat = format;
  return true;
}

//------------------------------------------------------------------------------
unsigned long long vtkRefractionTargets::GetBytes() const
{
  unsigned long long total = this->ReductionBytes;
  for (unsigned long long bytes : this->TargetBytes)
  {
    total += bytes;
  }
  return total;
}

//------------------------------------------------------------------------------
void vtkRefractionTargets::ReleaseGraphicsResources(vtkWindow* w)
{
  for (int i = 0; i < TARGET_COUNT; ++i)
  {
    if (this->Targets[i])
    {
      this->Targets[i]->ReleaseGraphicsResources(w);
      this->Targets[i] = nullptr;
    }
    this->TargetBytes[i] = 0;
  }
  for (auto& level : this->ReductionLevels)
  {
    level->ReleaseGraphicsResources(w);
  }
  this->ReductionLevels.clear();
  this->ReductionBytes = 0;
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(w);
    this->Framebuffer = nullptr;
  }
  this->Width = 0;
  this->Height = 0;
}
