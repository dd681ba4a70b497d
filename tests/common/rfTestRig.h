// The probe rig of the stability and bad-input tests: a renderer whose pass chain is a float
// framebuffer pass -> a probe -> the refraction pass with its debug output on. The probe
// counts the OpenGL errors the pass leaves and reads back the float colour; MessageLog
// captures VTK's messages so a test can assert what was reported.
#ifndef rfTestRig_h
#define rfTestRig_h

#include "rfTestScene.h"
#include "vtkRefractionPass.h"

#include "rf_environment.h"
#include "rf_vec3.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkFramebufferPass.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkRenderPass.h>
#include <vtkRenderState.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>
#include <vtkTextureObject.h>

#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace rftest
{
//------------------------------------------------------------------------------
// Collects VTK's errors and warnings so a test can assert what was reported (and that nothing
// else was). Installed with vtkOutputWindow::SetInstance; echoes to stderr for the log.
class MessageLog : public vtkOutputWindow
{
public:
  static MessageLog* New();
  vtkTypeMacro(MessageLog, vtkOutputWindow);

  struct Entry
  {
    std::string Kind; // "error", "warning", "text"
    std::string Text;
  };
  std::vector<Entry> Entries;

  void DisplayText(const char* text) override { this->Record("text", text); }
  void DisplayErrorText(const char* text) override { this->Record("error", text); }
  void DisplayWarningText(const char* text) override { this->Record("warning", text); }
  void DisplayGenericWarningText(const char* text) override { this->Record("warning", text); }
  void DisplayDebugText(const char* text) override { this->Record("text", text); }

  /// Number of messages of a kind ("" for all) containing every one of the given strings.
  int Count(const std::string& kind, std::initializer_list<std::string> parts = {}) const
  {
    int n = 0;
    for (const auto& e : this->Entries)
    {
      if (!kind.empty() && e.Kind != kind)
      {
        continue;
      }
      bool all = true;
      for (const auto& p : parts)
      {
        all = all && e.Text.find(p) != std::string::npos;
      }
      n += all ? 1 : 0;
    }
    return n;
  }
  void Clear() { this->Entries.clear(); }

protected:
  MessageLog() = default;
  void Record(const char* kind, const char* text)
  {
    this->Entries.push_back({ kind, text ? text : "" });
    std::fprintf(stderr, "[vtk %s] %s", kind, text ? text : "");
  }
};
// inline: a test program may include this header from more than one file (the stability
// suite does), and New() must then be defined once.
inline vtkStandardNewMacro(MessageLog);

inline MessageLog* InstallLog()
{
  vtkNew<MessageLog> log;
  vtkOutputWindow::SetInstance(log);
  return log; // the output window singleton keeps it alive
}

//------------------------------------------------------------------------------
// Wraps the refraction pass: drains GL errors before it, collects the ones it leaves, and reads
// back the float colour of the framebuffer it drew into (the enclosing vtkFramebufferPass's).
class ProbePass : public vtkRenderPass
{
public:
  static ProbePass* New();
  vtkTypeMacro(ProbePass, vtkRenderPass);

  vtkSmartPointer<vtkRenderPass> Inner;
  std::vector<unsigned int> GLErrors;
  std::vector<float> Colour; // RGBA, bottom row first
  int Size[2] = { 0, 0 };

  void Render(const vtkRenderState* s) override
  {
    // Filter across cube-map faces (for Rig::UseSmoothEnvironment); core since GL 3.2.
    glEnable(0x884F /* GL_TEXTURE_CUBE_MAP_SEAMLESS */);
    while (glGetError() != GL_NO_ERROR)
    {
    }
    this->Inner->Render(s);
    this->NumberOfRenderedProps = this->Inner->GetNumberOfRenderedProps();
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError())
    {
      this->GLErrors.push_back(e);
    }
    int origin[2];
    s->GetRenderer()->GetTiledSizeAndOrigin(this->Size, this->Size + 1, origin, origin + 1);
    this->Colour.assign(4 * static_cast<size_t>(std::max(this->Size[0], 0)) *
        static_cast<size_t>(std::max(this->Size[1], 0)),
      0.f);
    if (this->Size[0] > 0 && this->Size[1] > 0)
    {
      // The framebuffer pass renders into its own FBO with the viewport at (0, 0).
      glPixelStorei(GL_PACK_ALIGNMENT, 4);
      glReadPixels(0, 0, this->Size[0], this->Size[1], GL_RGBA, GL_FLOAT, this->Colour.data());
      while (glGetError() != GL_NO_ERROR)
      {
      }
    }
  }
  void ReleaseGraphicsResources(vtkWindow* w) override
  {
    if (this->Inner)
    {
      this->Inner->ReleaseGraphicsResources(w);
    }
  }

protected:
  ProbePass() = default;
};
inline vtkStandardNewMacro(ProbePass);

//------------------------------------------------------------------------------
// One rendered frame: the float colour and the pass's debug arrays, per pixel, bottom row first.
struct Frame
{
  int W = 0;
  int H = 0;
  std::vector<float> Colour; // RGBA
  std::vector<float> P2;     // 3 per pixel, view space
  std::vector<float> T2;     // 3 per pixel, view space
  std::vector<float> Thickness;
  std::vector<float> Flags; // 0 no glass, 1 glass, 2 TIR at the exit, 3 TIR at the entry
  int GLErrors = 0;
  bool HasDebug = false;

  bool Glass(int i) const { return this->HasDebug && this->Flags[i] > 0.5f; }
  rf_vec3 T2At(int i) const
  {
    return rf_vec3_make(this->T2[3 * i], this->T2[3 * i + 1], this->T2[3 * i + 2]);
  }
  rf_vec3 P2At(int i) const
  {
    return rf_vec3_make(this->P2[3 * i], this->P2[3 * i + 1], this->P2[3 * i + 2]);
  }
  rf_vec3 RGB(int i) const
  {
    return rf_vec3_make(this->Colour[4 * i], this->Colour[4 * i + 1], this->Colour[4 * i + 2]);
  }
  /// NaN or infinite values in the colour and the debug arrays.
  int NonFinite() const
  {
    int n = 0;
    for (const auto* v : { &this->Colour, &this->P2, &this->T2, &this->Thickness, &this->Flags })
    {
      for (float x : *v)
      {
        n += std::isfinite(x) ? 0 : 1;
      }
    }
    return n;
  }
};

//------------------------------------------------------------------------------
// A renderer whose pass chain is: float framebuffer pass -> probe -> refraction pass.
struct Rig
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRefractionPass> Glass;
  vtkNew<ProbePass> Probe;
  vtkNew<vtkFramebufferPass> Framebuffer;
  vtkSmartPointer<vtkRenderWindow> Window;

  Rig(int width, int height)
  {
    this->Glass->SetEnvironmentModeToBuiltin(); // the closed forms are of the built-in sky
    // The closed forms read the environment along each pixel's one ray; the pass's default
    // averages it over the pixel's spread of rays (FilteredLookups), which they do not model.
    this->Glass->FilteredLookupsOff();
    this->Glass->DebugOutputOn();
    this->Probe->Inner = this->Glass;
    this->Framebuffer->SetColorFormat(vtkTextureObject::Float32);
    this->Framebuffer->SetDelegatePass(this->Probe);
    this->Renderer->SetPass(this->Framebuffer);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    this->Window = MakeWindow(this->Renderer, width, height);
  }
  ~Rig()
  {
    // Release while the context and the passes are alive (vtkFramebufferPass insists).
    this->Window->Finalize();
  }

  vtkCamera* Camera() { return this->Renderer->GetActiveCamera(); }

  /**
   * A smooth environment cube map in place of the built-in pattern (whose ground tiles and
   * horizon have hard edges): colours are functions of the direction that no signed
   * permutation of its components changes, so they agree across face edges whatever the face
   * orientation convention. Used to tell the pass's continuity from the pattern's edges.
   */
  void UseSmoothEnvironment(bool on)
  {
    if (!on)
    {
      this->Renderer->SetEnvironmentTexture(nullptr);
      return;
    }
    const int n = 64;
    vtkNew<vtkTexture> cube;
    cube->CubeMapOn();
    cube->InterpolateOn();
    cube->MipmapOff();
    for (int face = 0; face < 6; ++face)
    {
      vtkNew<vtkImageData> image;
      image->SetDimensions(n, n, 1);
      image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
      for (int j = 0; j < n; ++j)
      {
        for (int i = 0; i < n; ++i)
        {
          double d[3];
          d[face / 2] = (face % 2) ? -1.0 : 1.0;
          d[(face / 2 + 1) % 3] = (i + 0.5) / n * 2.0 - 1.0;
          d[(face / 2 + 2) % 3] = (j + 0.5) / n * 2.0 - 1.0;
          const rf_vec3 u = rf_vec3_normalize(rf_vec3_make(d[0], d[1], d[2]));
          const double rgb[3] = { SmoothR(u), SmoothG(u), SmoothB(u) };
          auto* px = static_cast<unsigned char*>(image->GetScalarPointer(i, j, 0));
          for (int c = 0; c < 3; ++c)
          {
            px[c] = static_cast<unsigned char>(std::lround(255.0 * rgb[c]));
          }
        }
      }
      cube->SetInputData(face, image);
    }
    this->Renderer->SetEnvironmentTexture(cube);
  }
  static double SmoothR(rf_vec3 u)
  {
    const double s4 = u.x * u.x * u.x * u.x + u.y * u.y * u.y * u.y + u.z * u.z * u.z * u.z;
    return 1.5 * s4 - 0.5; // 0 along the diagonals, 1 along the axes
  }
  static double SmoothG(rf_vec3 u) { return 1.0 - SmoothR(u); }
  static double SmoothB(rf_vec3 u) { return 27.0 * (u.x * u.y * u.z) * (u.x * u.y * u.z); }

  void LookAt(const double eye[3], const double focal[3], const double up[3], double viewAngle,
    double nearPlane, double farPlane)
  {
    rftest::LookAt(this->Camera(), eye, focal, up, viewAngle, nearPlane, farPlane);
  }

  Frame Render()
  {
    this->Probe->GLErrors.clear();
    this->Window->Render();
    Frame f;
    f.W = this->Probe->Size[0];
    f.H = this->Probe->Size[1];
    f.Colour = this->Probe->Colour;
    f.GLErrors = static_cast<int>(this->Probe->GLErrors.size());
    for (unsigned int e : this->Probe->GLErrors)
    {
      std::fprintf(stderr, "OpenGL error 0x%x after the refraction pass (environment: %s)\n", e,
        this->Renderer->GetEnvironmentTexture() ? "cube map" : "built-in");
    }
    vtkImageData* debug = this->Glass->GetDebugImage();
    const size_t count = static_cast<size_t>(std::max(f.W, 0)) * std::max(f.H, 0);
    if (debug && static_cast<size_t>(debug->GetNumberOfPoints()) == count && count > 0 &&
      this->Glass->GetNumberOfGlassProps() > 0)
    {
      f.HasDebug = true;
      auto copy = [debug](const char* name, std::vector<float>& out, int components) {
        vtkDataArray* a = debug->GetPointData()->GetArray(name);
        out.resize(static_cast<size_t>(a->GetNumberOfTuples()) * components);
        for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
        {
          for (int c = 0; c < components; ++c)
          {
            out[i * components + c] = static_cast<float>(a->GetComponent(i, c));
          }
        }
      };
      copy("P2", f.P2, 3);
      copy("T2", f.T2, 3);
      copy("Thickness", f.Thickness, 1);
      copy("Flags", f.Flags, 1);
    }
    else
    {
      f.P2.assign(3 * count, 0.f);
      f.T2.assign(3 * count, 0.f);
      f.Thickness.assign(count, 0.f);
      f.Flags.assign(count, 0.f);
    }
    return f;
  }

  /// Unit view-space direction of the eye ray through the centre of pixel (x, y).
  rf_vec3 PixelRay(int x, int y, int w, int h)
  {
    vtkNew<vtkMatrix4x4> toView;
    toView->DeepCopy(this->Camera()->GetProjectionTransformMatrix(
      static_cast<double>(w) / h, -1.0, 1.0));
    toView->Invert();
    const double ndc[4] = { (x + 0.5) / w * 2.0 - 1.0, (y + 0.5) / h * 2.0 - 1.0, -1.0, 1.0 };
    double v[4];
    toView->MultiplyPoint(ndc, v);
    return rf_vec3_normalize(rf_vec3_make(v[0] / v[3], v[1] / v[3], v[2] / v[3]));
  }

  /// All pixel rays at once (the inverse projection computed once).
  std::vector<rf_vec3> PixelRays(int w, int h)
  {
    vtkNew<vtkMatrix4x4> toView;
    toView->DeepCopy(this->Camera()->GetProjectionTransformMatrix(
      static_cast<double>(w) / h, -1.0, 1.0));
    toView->Invert();
    std::vector<rf_vec3> rays(static_cast<size_t>(w) * h);
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        const double ndc[4] = { (x + 0.5) / w * 2.0 - 1.0, (y + 0.5) / h * 2.0 - 1.0, -1.0,
          1.0 };
        double v[4];
        toView->MultiplyPoint(ndc, v);
        rays[static_cast<size_t>(y) * w + x] =
          rf_vec3_normalize(rf_vec3_make(v[0] / v[3], v[1] / v[3], v[2] / v[3]));
      }
    }
    return rays;
  }

  /// World point to view space.
  rf_vec3 ToView(const double p[3])
  {
    double in[4] = { p[0], p[1], p[2], 1.0 };
    double out[4];
    this->Camera()->GetViewTransformMatrix()->MultiplyPoint(in, out);
    return rf_vec3_make(out[0], out[1], out[2]);
  }
  /// World direction to view space.
  rf_vec3 DirToView(const double d[3])
  {
    vtkMatrix4x4* m = this->Camera()->GetViewTransformMatrix();
    double r[3];
    for (int i = 0; i < 3; ++i)
    {
      r[i] = m->GetElement(i, 0) * d[0] + m->GetElement(i, 1) * d[1] + m->GetElement(i, 2) * d[2];
    }
    return rf_vec3_make(r[0], r[1], r[2]);
  }
  /// The built-in environment's colour seen along a view-space direction (what the shader does).
  rf_vec3 Environment(rf_vec3 directionVC)
  {
    vtkMatrix4x4* m = this->Camera()->GetViewTransformMatrix();
    double world[3];
    for (int i = 0; i < 3; ++i)
    {
      // The view rotation is orthonormal: its transpose maps view to world.
      world[i] = m->GetElement(0, i) * directionVC.x + m->GetElement(1, i) * directionVC.y +
        m->GetElement(2, i) * directionVC.z;
    }
    double rgb[3];
    rf_builtin_environment(world, rgb);
    return rf_vec3_make(rgb[0], rgb[1], rgb[2]);
  }
};

}

#endif
