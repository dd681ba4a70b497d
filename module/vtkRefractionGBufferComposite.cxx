#include "vtkRefractionGBufferComposite.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRefractionRankExchange.h"
#include "vtkRefractionTargets.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"

#include "rf_composite.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

vtkStandardNewMacro(vtkRefractionGBufferComposite);

vtkRefractionGBufferComposite::vtkRefractionGBufferComposite() = default;
vtkRefractionGBufferComposite::~vtkRefractionGBufferComposite() = default;

//------------------------------------------------------------------------------
void vtkRefractionGBufferComposite::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Planes: " << this->Planes.size() << "\n";
  os << indent << "BufferBytes: " << this->BufferBytes << "\n";
  os << indent << "Milliseconds: " << this->Milliseconds << "\n";
  os << indent << "WaitMilliseconds: " << this->WaitMilliseconds << "\n";
}

//------------------------------------------------------------------------------
int vtkRefractionGBufferComposite::Find(int target) const
{
  for (size_t i = 0; i < this->Planes.size(); ++i)
  {
    if (this->Planes[i].Target == target)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
bool vtkRefractionGBufferComposite::Describe(vtkRefractionTargets* targets, const Request& request)
{
  // The front surface's followers first, then FRONT_SURFACE and PEEL's layers in one run (the
  // layer merge reads them as consecutive planes), then the back surface and the scene.
  std::vector<int> wanted{ vtkRefractionTargets::FRONT_DEPTH };
  if (request.FrontColour)
  {
    wanted.push_back(vtkRefractionTargets::FRONT_COLOR);
  }
  if (request.FrontAux)
  {
    wanted.push_back(vtkRefractionTargets::FRONT_AUX);
  }
  if (request.FrontSH)
  {
    wanted.push_back(vtkRefractionTargets::FRONT_SH);
  }
  wanted.push_back(vtkRefractionTargets::FRONT_SURFACE);
  for (int layer = 1; layer < request.PeelLayers; ++layer)
  {
    wanted.push_back(vtkRefractionTargets::PEEL_1 + layer - 1);
  }
  if (request.Back)
  {
    wanted.push_back(vtkRefractionTargets::BACK_SURFACE);
    wanted.push_back(vtkRefractionTargets::BACK_Z);
  }
  if (request.Scene)
  {
    wanted.push_back(vtkRefractionTargets::SCENE_DEPTH);
    wanted.push_back(vtkRefractionTargets::SCENE_COLOR);
  }
  this->Planes.clear();
  unsigned long long offset = 0;
  size_t pixels = 0;
  for (int target : wanted)
  {
    vtkTextureObject* texture = targets->Get(target);
    if (!texture)
    {
      vtkErrorMacro("Compositing across ranks: the target "
        << vtkRefractionTargets::GetTargetName(target) << " is not allocated.");
      return false;
    }
    const size_t count = static_cast<size_t>(texture->GetWidth()) * texture->GetHeight();
    if (pixels != 0 && count != pixels)
    {
      vtkErrorMacro("Compositing across ranks: targets of different sizes.");
      return false;
    }
    pixels = count;
    this->Width = static_cast<size_t>(texture->GetWidth());
    Plane plane;
    plane.Target = target;
    texture->Activate();
    GLint internal = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
    texture->Deactivate();
    switch (internal)
    {
      case GL_RGBA32F:
        plane.Format = GL_RGBA;
        plane.Type = GL_FLOAT;
        plane.PixelBytes = 16;
        break;
      case GL_R32F:
        plane.Format = GL_RED;
        plane.Type = GL_FLOAT;
        plane.PixelBytes = 4;
        break;
      case GL_RGBA8:
        plane.Format = GL_RGBA;
        plane.Type = GL_UNSIGNED_BYTE;
        plane.PixelBytes = 4;
        break;
      case GL_DEPTH24_STENCIL8:
        // Written back with its stencil, as it was read; the key is the upper 24 bits.
        plane.Format = GL_DEPTH_STENCIL;
        plane.Type = GL_UNSIGNED_INT_24_8;
        plane.PixelBytes = 4;
        plane.PackedDepthStencil = true;
        break;
      case GL_DEPTH_COMPONENT16:
      case GL_DEPTH_COMPONENT24:
      case GL_DEPTH_COMPONENT32:
      case GL_DEPTH_COMPONENT32F:
      case GL_DEPTH_COMPONENT:
        plane.Format = GL_DEPTH_COMPONENT;
        plane.Type = GL_FLOAT;
        plane.PixelBytes = 4;
        break;
      default:
      {
        // vtkErrorMacro's stream takes no manipulators (std::hex would print as "1").
        char hex[16];
        std::snprintf(hex, sizeof(hex), "0x%04X", static_cast<unsigned>(internal));
        vtkErrorMacro("Compositing across ranks: the target "
          << vtkRefractionTargets::GetTargetName(target) << " has the internal format " << hex
          << ", which this class cannot transfer.");
        return false;
      }
    }
    plane.Offset = offset;
    offset += static_cast<unsigned long long>(plane.PixelBytes) * count;
    this->Planes.push_back(plane);
  }
  this->PixelCount = pixels;
  this->BufferBytes = offset;
  return true;
}

//------------------------------------------------------------------------------
void vtkRefractionGBufferComposite::DepthKeys(
  const Plane& plane, const unsigned char* buffer, std::vector<float>& keys) const
{
  keys.resize(this->PixelCount);
  const unsigned char* pixels = buffer + plane.Offset;
  if (!plane.PackedDepthStencil)
  {
    std::memcpy(keys.data(), pixels, this->PixelCount * sizeof(float));
    return;
  }
  for (size_t i = 0; i < this->PixelCount; ++i)
  {
    unsigned int packed;
    std::memcpy(&packed, pixels + 4 * i, 4);
    keys[i] = static_cast<float>(packed >> 8) / 16777215.0f;
  }
}

//------------------------------------------------------------------------------
void vtkRefractionGBufferComposite::Merge(
  unsigned char* kept, const unsigned char* incoming, const Request& request)
{
  const size_t n = this->PixelCount;
  this->Take.resize(n);
  unsigned char* take = this->Take.data();
  auto planeOf = [&](int target) -> const Plane& { return this->Planes[this->Find(target)]; };
  auto follow = [&](int target) {
    const Plane& p = planeOf(target);
    rf_composite_copy(n, p.PixelBytes, take, incoming + p.Offset, kept + p.Offset);
  };

  // The front surface: the nearest depth; its normal and material come with it, or with PEEL
  // the K nearest layers of both.
  const Plane& frontDepth = planeOf(vtkRefractionTargets::FRONT_DEPTH);
  rf_composite_select(n, RF_COMPOSITE_NEAREST, reinterpret_cast<float*>(kept + frontDepth.Offset),
    reinterpret_cast<const float*>(incoming + frontDepth.Offset), 1, take);
  for (int target : { vtkRefractionTargets::FRONT_COLOR, vtkRefractionTargets::FRONT_AUX,
         vtkRefractionTargets::FRONT_SH })
  {
    if (this->Find(target) >= 0)
    {
      follow(target);
    }
  }
  const Plane& layers = planeOf(vtkRefractionTargets::FRONT_SURFACE);
  if (request.PeelLayers > 1)
  {
    rf_composite_layers(n, request.PeelLayers, reinterpret_cast<float*>(kept + layers.Offset),
      reinterpret_cast<const float*>(incoming + layers.Offset));
  }
  else
  {
    follow(vtkRefractionTargets::FRONT_SURFACE);
  }

  // The back surface: the furthest (or nearest) by its -z_view, which is BACK_SURFACE's alpha.
  if (request.Back)
  {
    const Plane& back = planeOf(vtkRefractionTargets::BACK_SURFACE);
    std::vector<float> keyKept(n);
    rf_composite_select(n,
      request.BackNearest ? RF_COMPOSITE_NEAREST_PRESENT : RF_COMPOSITE_FURTHEST_PRESENT,
      reinterpret_cast<float*>(kept + back.Offset) + 3,
      reinterpret_cast<const float*>(incoming + back.Offset) + 3, 4, take);
    follow(vtkRefractionTargets::BACK_SURFACE);
    follow(vtkRefractionTargets::BACK_Z);
  }

  // The opaque scene: the nearest depth, in whatever format the window's depth has.
  if (request.Scene)
  {
    const Plane& sceneDepth = planeOf(vtkRefractionTargets::SCENE_DEPTH);
    this->DepthKeys(sceneDepth, kept, this->KeptKeys);
    this->DepthKeys(sceneDepth, incoming, this->IncomingKeys);
    rf_composite_select(
      n, RF_COMPOSITE_NEAREST, this->KeptKeys.data(), this->IncomingKeys.data(), 1, take);
    follow(vtkRefractionTargets::SCENE_DEPTH);
    follow(vtkRefractionTargets::SCENE_COLOR);
  }
}

//------------------------------------------------------------------------------
void vtkRefractionGBufferComposite::FillBackground(const Request& request)
{
  const Plane& sceneDepth = this->Planes[this->Find(vtkRefractionTargets::SCENE_DEPTH)];
  const Plane& sceneColour = this->Planes[this->Find(vtkRefractionTargets::SCENE_COLOR)];
  this->DepthKeys(sceneDepth, this->Kept.data(), this->KeptKeys);
  unsigned char* colour = this->Kept.data() + sceneColour.Offset;
  const size_t width = this->Width;
  const size_t height = width ? this->PixelCount / width : 0;
  for (size_t y = 0; y < height; ++y)
  {
    // vtkOpenGLRenderer's gradient: Background at the bottom row, Background2 at the top.
    const double f = (static_cast<double>(y) + 0.5) / static_cast<double>(height);
    unsigned char rgb[3];
    for (int c = 0; c < 3; ++c)
    {
      const double v = (1.0 - f) * request.Background[c] + f * request.Background2[c];
      rgb[c] = static_cast<unsigned char>(std::min(1.0, std::max(0.0, v)) * 255.0 + 0.5);
    }
    for (size_t x = 0; x < width; ++x)
    {
      const size_t i = y * width + x;
      if (this->KeptKeys[i] >= 1.0f)
      {
        std::memcpy(colour + 4 * i, rgb, 3);
      }
    }
  }
}

//------------------------------------------------------------------------------
bool vtkRefractionGBufferComposite::Composite(vtkOpenGLRenderWindow* renWin,
  vtkRefractionTargets* targets, const Request& request, vtkRefractionRankExchange* exchange)
{
  renWin->MakeCurrent();
  // The G-buffers' drawing finished first, so that the time below is the compositing's (a
  // read-back would wait for it anyway: llvmpipe rasterizes when results are needed).
  glFinish();
  const double start = vtkTimerLog::GetUniversalTime();
  this->WaitMilliseconds = 0.0;
  const int rank = exchange->GetRank();
  const int ranks = exchange->GetNumberOfRanks();
  // Every rank describes the same planes (the same request and sizes), so a failure here is
  // everyone's, and nobody waits for a message that will not come.
  int failed = this->Describe(targets, request) ? 0 : 1;
  exchange->AllReduceMax(&failed, 1);
  if (failed)
  {
    return false;
  }
  this->Kept.resize(this->BufferBytes);
  for (const Plane& plane : this->Planes)
  {
    vtkTextureObject* texture = targets->Get(plane.Target);
    texture->Activate();
    glGetTexImage(GL_TEXTURE_2D, 0, plane.Format, plane.Type, this->Kept.data() + plane.Offset);
    texture->Deactivate();
  }

  bool ok = true;
  for (int step = 1; step < ranks; step *= 2)
  {
    if (rank % (2 * step) == step)
    {
      ok = exchange->Send(this->Kept.data(), this->BufferBytes, rank - step);
      break;
    }
    if (rank % (2 * step) == 0 && rank + step < ranks)
    {
      this->Incoming.resize(this->BufferBytes);
      const double waitStart = vtkTimerLog::GetUniversalTime();
      const bool received =
        exchange->Receive(this->Incoming.data(), this->BufferBytes, rank + step);
      this->WaitMilliseconds += 1000.0 * (vtkTimerLog::GetUniversalTime() - waitStart);
      if (!received)
      {
        ok = false;
        break;
      }
      this->Merge(this->Kept.data(), this->Incoming.data(), request);
    }
  }

  if (rank == 0 && ok)
  {
    if (request.FillBackground && request.Scene)
    {
      this->FillBackground(request);
    }
    if (request.SSPMask && request.Scene)
    {
      const Plane& frontDepth = this->Planes[this->Find(vtkRefractionTargets::FRONT_DEPTH)];
      const Plane& sceneDepth = this->Planes[this->Find(vtkRefractionTargets::SCENE_DEPTH)];
      const Plane& sceneColour = this->Planes[this->Find(vtkRefractionTargets::SCENE_COLOR)];
      this->DepthKeys(sceneDepth, this->Kept.data(), this->KeptKeys);
      rf_composite_ssp_mask(this->PixelCount,
        reinterpret_cast<const float*>(this->Kept.data() + frontDepth.Offset),
        this->KeptKeys.data(), this->Kept.data() + sceneColour.Offset);
    }
    if (request.PeelLayers > 1)
    {
      // The front layer's material without the sign that ordered the layers (the shading
      // stage reads the front G-buffer's material as material + 1).
      float* front = reinterpret_cast<float*>(
        this->Kept.data() + this->Planes[this->Find(vtkRefractionTargets::FRONT_SURFACE)].Offset);
      for (size_t i = 0; i < this->PixelCount; ++i)
      {
        front[4 * i + 3] = std::fabs(front[4 * i + 3]);
      }
    }
    for (const Plane& plane : this->Planes)
    {
      vtkTextureObject* texture = targets->Get(plane.Target);
      texture->Activate();
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, static_cast<GLsizei>(texture->GetWidth()),
        static_cast<GLsizei>(texture->GetHeight()), plane.Format, plane.Type,
        this->Kept.data() + plane.Offset);
      texture->Deactivate();
    }
  }
  if (!ok)
  {
    vtkErrorMacro("Compositing the glass across " << ranks << " ranks failed on rank " << rank
                                                  << ": a transfer did not complete.");
  }
  this->Milliseconds = 1000.0 * (vtkTimerLog::GetUniversalTime() - start);
  return ok;
}
