#include "vtkRefractionEGL.h"

#include <vtkCommand.h>
#include <vtkNew.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glew.h>
#include <dlfcn.h>

#include <sstream>

// VTK calls glewInit after the context is current: answer with the context part alone.
extern "C" GLenum glewInit(void)
{
  using InitFunction = GLenum (*)(void);
  static InitFunction real = reinterpret_cast<InitFunction>(dlsym(RTLD_NEXT, "glewInit"));
  const GLenum result = real ? real() : GLEW_ERROR_NO_GL_VERSION;
  return result == GLEW_ERROR_NO_GLX_DISPLAY ? GLEW_OK : result;
}

namespace
{
EGLDisplay OpenDisplay(std::string& which)
{
  auto queryDevices =
    reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto platformDisplay =
    reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (queryDevices && platformDisplay)
  {
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (queryDevices(8, devices, &count))
    {
      for (EGLint i = 0; i < count; ++i)
      {
        EGLDisplay display = platformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        EGLint major = 0;
        EGLint minor = 0;
        if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor))
        {
          std::ostringstream s;
          s << "EGL device " << i << " of " << count << ", EGL " << major << "." << minor;
          which = s.str();
          return display;
        }
      }
    }
  }
  EGLDisplay display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  EGLint major = 0;
  EGLint minor = 0;
  if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor))
  {
    std::ostringstream s;
    s << "EGL default display, EGL " << major << "." << minor;
    which = s.str();
    return display;
  }
  return EGL_NO_DISPLAY;
}

// vtkGenericOpenGLRenderWindow asks its observers to make its context current and to say
// whether it is: with two windows in one process each must switch back to its own context.
// The window owns this observer and deletes it after its own destructor has released its
// OpenGL resources, so the context outlives them.
class EGLContextKeeper : public vtkCommand
{
public:
  static EGLContextKeeper* New() { return new EGLContextKeeper; }

  EGLDisplay Display = EGL_NO_DISPLAY;
  EGLSurface Surface = EGL_NO_SURFACE;
  EGLContext Context = EGL_NO_CONTEXT;

  void Execute(vtkObject*, unsigned long event, void* callData) override
  {
    if (event == vtkCommand::WindowMakeCurrentEvent)
    {
      if (eglGetCurrentContext() != this->Context)
      {
        eglMakeCurrent(this->Display, this->Surface, this->Surface, this->Context);
      }
    }
    else if (event == vtkCommand::WindowIsCurrentEvent && callData)
    {
      *static_cast<bool*>(callData) = eglGetCurrentContext() == this->Context;
    }
  }

protected:
  EGLContextKeeper() = default;
  ~EGLContextKeeper() override
  {
    if (eglGetCurrentContext() == this->Context)
    {
      eglMakeCurrent(this->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    eglDestroyContext(this->Display, this->Context);
    eglDestroySurface(this->Display, this->Surface);
  }
};
}

vtkSmartPointer<vtkGenericOpenGLRenderWindow> vtkRefractionCreateEGLWindow(
  int width, int height, std::string* error, std::string* description)
{
  auto fail = [error](const char* message) {
    if (error)
    {
      *error = message;
    }
    return vtkSmartPointer<vtkGenericOpenGLRenderWindow>();
  };
  if (width < 1 || height < 1)
  {
    return fail("EGL window size must be at least 1x1");
  }
  std::string which;
  EGLDisplay display = OpenDisplay(which);
  if (display == EGL_NO_DISPLAY)
  {
    return fail("no EGL display (no GPU device and no default display)");
  }
  const EGLint configAttributes[] = { EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 8,
    EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 24,
    EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE };
  EGLConfig config;
  EGLint configCount = 0;
  if (!eglChooseConfig(display, configAttributes, &config, 1, &configCount) || configCount < 1)
  {
    return fail("no EGL configuration with an OpenGL pbuffer");
  }
  const EGLint surfaceAttributes[] = { EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE };
  EGLSurface surface = eglCreatePbufferSurface(display, config, surfaceAttributes);
  if (surface == EGL_NO_SURFACE || !eglBindAPI(EGL_OPENGL_API))
  {
    return fail("cannot create an EGL pbuffer surface for OpenGL");
  }
  const EGLint contextAttributes[] = { EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
    EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
  if (context == EGL_NO_CONTEXT || !eglMakeCurrent(display, surface, surface, context))
  {
    if (context != EGL_NO_CONTEXT)
    {
      eglDestroyContext(display, context);
    }
    eglDestroySurface(display, surface);
    return fail("cannot create or make current an OpenGL 4.5 core EGL context");
  }
  auto window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  vtkNew<EGLContextKeeper> keeper;
  keeper->Display = display;
  keeper->Surface = surface;
  keeper->Context = context;
  window->AddObserver(vtkCommand::WindowMakeCurrentEvent, keeper);
  window->AddObserver(vtkCommand::WindowIsCurrentEvent, keeper);
  window->SetSize(width, height);
  window->SetReadyForRendering(true);
  window->SetIsCurrent(true);
  // VTK's own windows start their context with VTK's default state (depth function
  // GL_LEQUAL); a vtkGenericOpenGLRenderWindow adopts the context's state instead, GL_LESS
  // on a new context. This context is new and the window's alone, so give it VTK's default:
  // code that relies on it (the refraction pass's SSP front stage, measured) then behaves
  // as in VTK's own windows.
  glDepthFunc(GL_LEQUAL);
  window->InitializeFromCurrentContext();
  if (description)
  {
    const GLubyte* renderer = glGetString(GL_RENDERER);
    *description = which + ", " + (renderer ? reinterpret_cast<const char*>(renderer) : "?");
  }
  return window;
}
