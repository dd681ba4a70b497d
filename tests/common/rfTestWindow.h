// The render window every GL test draws into: an EGL pbuffer context on the default EGL
// device (Mesa's llvmpipe here and on CI, a GPU where there is one), so that no test needs an
// X server. Under Xvfb a test could be refused its X connection while the server reset after
// the previous test's client left, and VTK aborts on that; EGL has no such server.
#ifndef rfTestWindow_h
#define rfTestWindow_h

#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>

namespace rftest
{
/**
 * An off-screen window of width x height with VTK's default multisampling (8 samples asked;
 * RF_TEST_MULTISAMPLES=N in the environment asks for N, 0 for a single-sampled window).
 * Without EGL it prints why and exits the test with EXIT_FAILURE (a test that cannot render
 * must not pass). RF_TEST_WINDOW=x11 in the environment gives VTK's X window instead (needs a
 * display), to compare the paths. After every frame a pending OpenGL error fails the test.
 */
vtkSmartPointer<vtkRenderWindow> NewRenderWindow(int width, int height);
}

#endif
