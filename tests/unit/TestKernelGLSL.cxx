// The kernel's single source on the GPU path: rfKernelSource (the GLSL prelude and the kernel
// headers, as the pass embeds them) compiled into a full-screen fragment shader on the GL the
// machine has (llvmpipe through EGL here, X as a fallback), the cases of rf_kernel_cases.h
// evaluated per pixel into an RGBA32F target, read back, and compared with the C kernel on
// the same inputs (kernel_glsl_reference.c). Each case must agree within float tolerance on
// every pixel except those the C side shows to lie within rounding of a discontinuity, and
// those must stay few (so they cannot hide a broken formula).
// Usage: TestKernelGLSL CASES_HEADER [--break-glsl CASE]. The second form alters one case's
// result by 0.1% on the GLSL side only (as a formula edited in one place would) and passes
// only when exactly that case is found to differ: the comparison can fail.
#include "kernel_glsl_reference.h"
#include "rfShaders.h"
#include "vtkRefractionEGL.h"

#include <vtkNew.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLQuadHelper.h>
#include <vtkOpenGLRenderUtilities.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkRenderWindow.h>
#include <vtkShaderProgram.h>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
const int kSize = 64;

// The kernel dialect's GLSL side has no #include: the test cases come after rfKernelSource.
bool ReadCases(const char* path, std::string& text)
{
  std::ifstream in(path);
  if (!in)
  {
    return false;
  }
  std::string line;
  std::ostringstream out;
  while (std::getline(in, line))
  {
    if (line.compare(0, 8, "#include") != 0)
    {
      out << line << "\n";
    }
  }
  text = out.str();
  return true;
}

std::string FragmentShader(const std::string& cases, int brokenCase)
{
  std::ostringstream fs;
  fs << "//VTK::System::Dec\n"
     << "in vec2 texCoord;\n"
     << "uniform int rftCase;\n"
     << "uniform sampler2D rftDepth;\n"
     << "uniform mat4 rftProjection;\n"
     << "uniform vec2 rftSize;\n"
     << "uniform vec2 rftFocal;\n"
     << "uniform vec2 rftDepthRange;\n"
     << "//VTK::Output::Dec\n"
     << rfKernelSource << "\n"
     << cases << "\n"
     << "void main()\n"
     << "{\n"
     << "  rfk_camera camera = rfk_make_camera(rftProjection, rftSize, false);\n"
     << "  vec2 pixel = floor(texCoord * rftSize) + 0.5; // the pixel's centre, as in C\n"
     << "  vec4 value = rft_evaluate(rftCase, pixel, rftSize, rftFocal, camera,\n"
     << "    rftDepthRange, rftDepth);\n";
  if (brokenCase >= 0)
  {
    // A deliberate slip on one side, as a formula edited in one place only would be.
    fs << "  if (rftCase == " << brokenCase << ") value.x *= 1.001;\n";
  }
  fs << "  gl_FragData[0] = value;\n"
     << "}\n";
  return fs.str();
}

vtkSmartPointer<vtkRenderWindow> MakeWindow(std::string& description)
{
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window =
    vtkRefractionCreateEGLWindow(kSize, kSize, &error, &description);
  if (window)
  {
    description = "EGL: " + description;
    return window;
  }
  std::cout << "No EGL context (" << error << "); trying an off-screen X window.\n";
  window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetSize(kSize, kSize);
  window->SetOffScreenRendering(1);
  window->Render(); // creates and initializes the context
  description = "X";
  return window;
}
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: TestKernelGLSL rf_kernel_cases.h [--break-glsl CASE]\n";
    return 2;
  }
  int brokenCase = -1;
  if (argc >= 4 && std::string(argv[2]) == "--break-glsl")
  {
    brokenCase = std::atoi(argv[3]);
  }
  std::string cases;
  if (!ReadCases(argv[1], cases))
  {
    std::cerr << "Cannot read the test cases " << argv[1] << "\n";
    return 1;
  }

  std::vector<float> depth(kSize * kSize);
  rft_scene scene;
  const int covered = rft_make_scene(kSize, kSize, depth.data(), &scene);
  if (covered < kSize * kSize / 4)
  {
    std::cerr << "The test sphere covers only " << covered << " texels\n";
    return 1;
  }

  std::string description;
  vtkSmartPointer<vtkRenderWindow> window = MakeWindow(description);
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!renWin)
  {
    std::cerr << "No OpenGL render window\n";
    return 1;
  }
  renWin->MakeCurrent();
  std::cout << "GL: " << description << "\n";

  int failures = 0;
  std::vector<int> differing; // per case
  {
    const std::string fs = FragmentShader(cases, brokenCase);
    vtkOpenGLQuadHelper quad(renWin,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), "");
    vtkShaderProgram* program = quad.Program;
    if (!program || !program->GetCompiled())
    {
      std::cerr << "The kernel did not compile as GLSL:\n"
                << (program ? program->GetError() : "no program") << "\n";
      return 1;
    }

    vtkNew<vtkTextureObject> depthTexture;
    depthTexture->SetContext(renWin);
    depthTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    depthTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    depthTexture->Create2DFromRaw(kSize, kSize, 1, VTK_FLOAT, depth.data());

    vtkNew<vtkTextureObject> target;
    target->SetContext(renWin);
    target->SetInternalFormat(GL_RGBA32F);
    target->SetFormat(GL_RGBA);
    target->SetDataType(GL_FLOAT);
    target->Allocate2D(kSize, kSize, 4, VTK_FLOAT);

    vtkNew<vtkOpenGLFramebufferObject> framebuffer;
    framebuffer->SetContext(renWin);
    framebuffer->SaveCurrentBindingsAndBuffers();
    framebuffer->Bind();
    framebuffer->AddColorAttachment(0, target);
    framebuffer->ActivateDrawBuffers(1);
    framebuffer->ActivateReadBuffer(0);
    vtkOpenGLState* state = renWin->GetState();
    state->vtkglViewport(0, 0, kSize, kSize);
    state->vtkglScissor(0, 0, kSize, kSize);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_DEPTH_TEST);

    // GLSL mat4 uniforms are column-major.
    float projection[16];
    for (int row = 0; row < 4; ++row)
    {
      for (int col = 0; col < 4; ++col)
      {
        projection[col * 4 + row] = static_cast<float>(scene.projection[row * 4 + col]);
      }
    }
    const float size[2] = { static_cast<float>(kSize), static_cast<float>(kSize) };
    const float focal[2] = { static_cast<float>(scene.focal[0]),
      static_cast<float>(scene.focal[1]) };
    const float range[2] = { static_cast<float>(scene.depth_range[0]),
      static_cast<float>(scene.depth_range[1]) };
    depthTexture->Activate();
    program->SetUniformi("rftDepth", depthTexture->GetTextureUnit());
    program->SetUniformMatrix4x4("rftProjection", projection);
    program->SetUniform2f("rftSize", size);
    program->SetUniform2f("rftFocal", focal);
    program->SetUniform2f("rftDepthRange", range);

    std::vector<float> pixels(4 * kSize * kSize);
    const int pixelCount = kSize * kSize;
    for (int testCase = 0; testCase < rft_case_count(); ++testCase)
    {
      program->SetUniformi("rftCase", testCase);
      quad.Render();
      glPixelStorei(GL_PACK_ALIGNMENT, 1);
      glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_FLOAT, pixels.data());

      const double tolerance = rft_tolerance(testCase);
      int disagreeing = 0;
      int ambiguous = 0;
      int flagged = 0; // refraction: TIR; search: the exit estimate left the entry point
      double largest = 0.0;
      for (int j = 0; j < kSize; ++j)
      {
        for (int i = 0; i < kSize; ++i)
        {
          double expected[4];
          rft_evaluate_pixel(&scene, testCase, i, j, expected);
          const float* got = &pixels[4 * (j * kSize + i)];
          flagged += expected[3] > 0.0 ? 1 : 0;
          bool agrees = true;
          for (int k = 0; k < 4; ++k)
          {
            const double difference = std::fabs(static_cast<double>(got[k]) - expected[k]);
            const double allowed = tolerance * (1.0 + std::fabs(expected[k]));
            if (!(difference <= allowed))
            {
              agrees = false;
            }
            else
            {
              largest = std::max(largest, difference / (1.0 + std::fabs(expected[k])));
            }
          }
          if (agrees)
          {
            continue;
          }
          if (rft_is_ambiguous(&scene, testCase, i, j))
          {
            ++ambiguous;
            continue;
          }
          if (++disagreeing <= 3)
          {
            std::cerr << "  " << rft_case_name(testCase) << " at pixel (" << i << ", " << j
                      << "): GLSL (" << got[0] << ", " << got[1] << ", " << got[2] << ", "
                      << got[3] << "), C (" << expected[0] << ", " << expected[1] << ", "
                      << expected[2] << ", " << expected[3] << ")\n";
          }
        }
      }
      // Rounding may flip a result only next to a discontinuity: a few pixels in 4096.
      const int ambiguousAllowed = pixelCount / 50;
      const bool ok = disagreeing == 0 && ambiguous <= ambiguousAllowed;
      // The cases must reach the branches they are about: TIR and refraction alike, searches
      // that move off the entry point on a good share of the sphere.
      const bool branchCase = testCase == RFT_TEST_REFRACT_REFLECT ||
        testCase == RFT_TEST_REFRACT_CLAMP ||
        (testCase >= RFT_TEST_SEARCH_FIRST && testCase <= RFT_TEST_SEARCH_LAST);
      if (branchCase && !(flagged > pixelCount / 20 && flagged < pixelCount))
      {
        std::cerr << "  " << rft_case_name(testCase) << ": only " << flagged
                  << " pixels reach the branch under test\n";
        ++failures;
      }
      std::printf("%-44s %s: largest relative difference %.3g (tolerance %.0e), %d pixels "
                  "disagree, %d at a discontinuity (<= %d allowed), %d flagged\n",
        rft_case_name(testCase), ok ? "agrees" : "DIFFERS", largest, tolerance, disagreeing,
        ambiguous, ambiguousAllowed, flagged);
      failures += ok ? 0 : 1;
      differing.push_back(ok ? 0 : 1);
    }
    depthTexture->Deactivate();
    framebuffer->UnBind();
    framebuffer->RestorePreviousBindingsAndBuffers();
  }
  window->Finalize();
  if (brokenCase >= 0)
  {
    int others = 0;
    for (int testCase = 0; testCase < static_cast<int>(differing.size()); ++testCase)
    {
      others += testCase != brokenCase ? differing[testCase] : 0;
    }
    const bool caught = brokenCase < static_cast<int>(differing.size()) &&
      differing[brokenCase] == 1 && others == 0;
    std::cout << (caught ? "The slip in case " : "The slip was NOT caught in case ")
              << brokenCase << (caught ? " was caught\n" : "\n");
    return caught ? 0 : 1;
  }
  if (failures > 0)
  {
    std::cerr << failures << " of " << rft_case_count() << " cases differ between GLSL and C\n";
    return 1;
  }
  std::cout << "All " << rft_case_count() << " cases agree between GLSL and C\n";
  return 0;
}
