#include "vtkRefractionDepthRange.h"

#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRefractionQuad.h"
#include "vtkRefractionTargetDraw.h"
#include "vtkRefractionTargets.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "rfShaders.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkRefractionDepthRange);

//------------------------------------------------------------------------------
vtkRefractionDepthRange::vtkRefractionDepthRange() = default;
vtkRefractionDepthRange::~vtkRefractionDepthRange() = default;

//------------------------------------------------------------------------------
void vtkRefractionDepthRange::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Reduction shaders: " << (this->FirstQuad && this->LaterQuad ? "built" : "not built")
     << "\n";
}

//------------------------------------------------------------------------------
bool vtkRefractionDepthRange::Reduce(
  vtkOpenGLRenderWindow* renWin, vtkRefractionTargets* targets, const int rectangle[4])
{
  vtkShaderProgram* first = this->ReadyProgram(renWin, this->FirstQuad, true);
  vtkShaderProgram* later = this->ReadyProgram(renWin, this->LaterQuad, false);
  if (!first || !later)
  {
    vtkErrorMacro("Could not build the depth-range reduction shader.");
    return false;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  {
    vtkRefractionTargetDraw draw(renWin, targets, {}, nullptr);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    vtkTextureObject* source = targets->Get(vtkRefractionTargets::BACK_SURFACE);
    const auto& levels = targets->GetReductionLevels();
    // The source's texels that hold data: [x0, x1) x [y0, y1). Outside them a level keeps what
    // an earlier frame left; the reads are clamped into them (a repeated texel leaves a min or
    // a max as it is), so that stays unread.
    int valid[4] = { std::max(rectangle[0], 0), std::max(rectangle[1], 0),
      std::min(rectangle[0] + rectangle[2], static_cast<int>(source->GetWidth())),
      std::min(rectangle[1] + rectangle[3], static_cast<int>(source->GetHeight())) };
    if (valid[2] <= valid[0] || valid[3] <= valid[1])
    {
      // No glass on screen: nothing is shaded, so nothing reads the range.
      valid[0] = valid[1] = 0;
      valid[2] = valid[3] = 0;
    }
    for (size_t level = 0; level < levels.size(); ++level)
    {
      vtkOpenGLQuadHelper* quad = level == 0 ? this->FirstQuad.get() : this->LaterQuad.get();
      vtkShaderProgram* program = level == 0 ? first : later;
      renWin->GetShaderCache()->ReadyShaderProgram(program);
      vtkTextureObject* target = levels[level];
      draw.Attach({ target }, nullptr);
      const int w = draw.GetWidth();
      const int h = draw.GetHeight();
      // The target's texels whose blocks hold valid source texels.
      const int block = vtkRefractionTargets::ReductionBlock;
      const int written[4] = { valid[0] / block, valid[1] / block,
        std::min((valid[2] + block - 1) / block, w), std::min((valid[3] + block - 1) / block, h) };
      if (written[2] <= written[0] || written[3] <= written[1])
      {
        break;
      }
      ostate->vtkglScissor(written[0], written[1], written[2] - written[0], written[3] - written[1]);
      source->Activate();
      program->SetUniformi("rfSource", source->GetTextureUnit());
      const int targetSize[2] = { w, h };
      program->SetUniform2i("rfTargetSize", targetSize);
      program->SetUniform2i("rfSourceValidFirst", valid);
      program->SetUniform2i("rfSourceValidEnd", valid + 2);
      quad->Render();
      source->Deactivate();
      source = target;
      std::copy(written, written + 4, valid);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkRefractionDepthRange::ReadyProgram(
  vtkOpenGLRenderWindow* renWin, std::unique_ptr<vtkOpenGLQuadHelper>& quad, bool firstLevel)
{
  std::string source;
  if (!quad) // the source only when the program is made
  {
    source = rfReductionFSSource;
    std::ostringstream defines;
    defines << "//VTK::System::Dec\n#define RF_REDUCTION_BLOCK "
            << vtkRefractionTargets::ReductionBlock << "\n"
            << (firstLevel ? "#define RF_REDUCTION_FIRST\n" : "");
    vtkShaderProgram::Substitute(source, "//VTK::System::Dec", defines.str());
  }
  return vtkRefractionQuad::Ready(renWin, quad,
    vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), source.c_str());
}

//------------------------------------------------------------------------------
void vtkRefractionDepthRange::ComputeBounds(
  vtkRenderer* ren, const std::vector<vtkProp*>& props, double range[2])
{
  vtkCamera* camera = ren->GetActiveCamera();
  vtkMatrix4x4* view = camera->GetViewTransformMatrix();
  double nearest = VTK_DOUBLE_MAX;
  double furthest = 0.0;
  for (vtkProp* prop : props)
  {
    const double* b = prop->GetBounds();
    if (!b || !(b[0] <= b[1]))
    {
      continue;
    }
    const vtkBoundingBox box(b);
    for (int corner = 0; corner < 8; ++corner)
    {
      double p[4] = { 0.0, 0.0, 0.0, 1.0 };
      box.GetCorner(corner, p);
      double q[4];
      view->MultiplyPoint(p, q);
      nearest = std::min(nearest, -q[2]);
      furthest = std::max(furthest, -q[2]);
    }
  }
  double clipping[2];
  camera->GetClippingRange(clipping);
  range[0] = std::max(nearest, clipping[0]);
  range[1] = furthest;
}

//------------------------------------------------------------------------------
void vtkRefractionDepthRange::ReleaseGraphicsResources(vtkWindow* w)
{
  for (auto* quad : { &this->FirstQuad, &this->LaterQuad })
  {
    if (*quad)
    {
      (*quad)->ReleaseGraphicsResources(w);
      quad->reset();
    }
  }
}

//------------------------------------------------------------------------------
void vtkRefractionDepthRange::ComputeScreenRectangle(vtkRenderer* ren,
  const std::vector<vtkProp*>& props, int width, int height, int margin, int rectangle[4])
{
  rectangle[0] = 0;
  rectangle[1] = 0;
  rectangle[2] = width;
  rectangle[3] = height;
  vtkOpenGLCamera* camera = vtkOpenGLCamera::SafeDownCast(ren->GetActiveCamera());
  if (!camera || width < 1 || height < 1)
  {
    return;
  }
  vtkMatrix4x4* wcvc = nullptr;
  vtkMatrix3x3* normalMatrix = nullptr;
  vtkMatrix4x4* vcdc = nullptr;
  vtkMatrix4x4* wcdc = nullptr;
  camera->GetKeyMatrices(ren, wcvc, normalMatrix, vcdc, wcdc);
  double lower[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double upper[2] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (vtkProp* prop : props)
  {
    const double* b = prop->GetBounds();
    if (!b)
    {
      return; // a prop that can draw anywhere
    }
    if (!(b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5]))
    {
      continue; // nothing to draw
    }
    const vtkBoundingBox box(b);
    for (int corner = 0; corner < 8; ++corner)
    {
      double p[4] = { 0.0, 0.0, 0.0, 1.0 };
      box.GetCorner(corner, p);
      // VTK's key matrices are laid out for OpenGL (transposed): clip = p^T wcdc.
      double clip[4];
      for (int j = 0; j < 4; ++j)
      {
        clip[j] = p[0] * wcdc->GetElement(0, j) + p[1] * wcdc->GetElement(1, j) +
          p[2] * wcdc->GetElement(2, j) + p[3] * wcdc->GetElement(3, j);
      }
      // A corner at or behind the eye plane projects without bound (or mirrored).
      if (!(clip[3] > 1e-9 * (std::abs(clip[0]) + std::abs(clip[1]))) || !std::isfinite(clip[0]) ||
        !std::isfinite(clip[1]) || !std::isfinite(clip[3]))
      {
        return;
      }
      for (int a = 0; a < 2; ++a)
      {
        const double ndc = clip[a] / clip[3];
        lower[a] = std::min(lower[a], ndc);
        upper[a] = std::max(upper[a], ndc);
      }
    }
  }
  if (!(lower[0] <= upper[0]) || !(lower[1] <= upper[1]))
  {
    return; // no prop with bounds: the whole viewport, as before anything was known
  }
  const int size[2] = { width, height };
  int from[2];
  int to[2];
  for (int a = 0; a < 2; ++a)
  {
    // Normalized device coordinates to pixels, clamped before the conversion to int.
    const double low = std::floor((0.5 * std::max(lower[a], -2.0) + 0.5) * size[a]) - margin;
    const double high = std::ceil((0.5 * std::min(upper[a], 2.0) + 0.5) * size[a]) + margin;
    from[a] = static_cast<int>(std::min(std::max(low, 0.0), static_cast<double>(size[a])));
    to[a] = static_cast<int>(std::min(std::max(high, 0.0), static_cast<double>(size[a])));
    to[a] = std::max(to[a], from[a]);
  }
  rectangle[0] = from[0];
  rectangle[1] = from[1];
  rectangle[2] = to[0] - from[0];
  rectangle[3] = to[1] - from[1];
}
