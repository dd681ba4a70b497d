/**
 * Headless rendering without an X server: an EGL pbuffer context (the GPU's device platform
 * first, then the default display, e.g. Mesa's llvmpipe) made current, and a
 * vtkGenericOpenGLRenderWindow that renders into it. Debian's VTK 9.1 has no EGL window
 * class; this is the path measured in ../shared/gpu/README.md.
 *
 * Debian's GLEW is built for GLX: its glewInit loads every entry point and then fails with
 * GLEW_ERROR_NO_GLX_DISPLAY, which VTK treats as fatal. This library defines glewInit to map
 * that one code to GLEW_OK; executables that link it export the symbol (the link option comes
 * with the target) so that VTK's call resolves to it.
 */
#ifndef vtkRefractionEGL_h
#define vtkRefractionEGL_h

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkSmartPointer.h>

#include <string>

/**
 * Create a window of width x height rendering into a new EGL pbuffer context. Returns
 * nullptr and a message in *error when no EGL display or context can be had.
 * *description receives the EGL display used and GL_RENDERER. Each window has its own
 * context, made current whenever VTK makes the window current (several windows may live in
 * one process), and destroyed with the window.
 */
vtkSmartPointer<vtkGenericOpenGLRenderWindow> vtkRefractionCreateEGLWindow(
  int width, int height, std::string* error, std::string* description = nullptr);

#endif
