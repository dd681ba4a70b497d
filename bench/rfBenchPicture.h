// Pictures as RGB floats in [0,1], bottom row first (as the reference writes them): the
// window's colour read back, and such a picture written as a PNG.
#ifndef rfBenchPicture_h
#define rfBenchPicture_h

#include <string>
#include <vector>

class vtkRenderWindow;

namespace rfbench
{
// The window's colour as floats in [0,1], bottom row first (as the reference).
std::vector<float> GrabColour(vtkRenderWindow* window);

// An RGB float image (bottom row first) as an 8-bit PNG, for a person to compare.
void WritePng(const std::string& path, const std::vector<float>& rgb, int size);
}

#endif
