#include "vtkRefractionProgramGuard.h"

#include "vtkActor.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLShaderProperty.h"
#include "vtkShaderProgram.h"

namespace
{
// Drawn in place of a program that does not build: every vertex outside the clip volume and
// every fragment discarded. The tags are the shader cache's (version, outputs), so this
// builds wherever VTK's own shaders do.
const char* const kEmptyVertexShader = "//VTK::System::Dec\n"
                                       "void main()\n"
                                       "{\n"
                                       "  gl_Position = vec4(0.0, 0.0, 2.0, 1.0);\n"
                                       "}\n";
const char* const kEmptyFragmentShader = "//VTK::System::Dec\n"
                                         "//VTK::Output::Dec\n"
                                         "void main()\n"
                                         "{\n"
                                         "  discard;\n"
                                         "}\n";

std::string Key(const std::string& vertexShader, const std::string& geometryShader,
  const std::string& fragmentShader)
{
  // Lengths first, so that no two different triples join into the same key.
  return std::to_string(vertexShader.size()) + ":" + std::to_string(geometryShader.size()) + ":" +
    vertexShader + geometryShader + fragmentShader;
}
}

vtkStandardNewMacro(vtkRefractionProgramGuard);

//------------------------------------------------------------------------------
vtkRefractionProgramGuard::vtkRefractionProgramGuard() = default;
vtkRefractionProgramGuard::~vtkRefractionProgramGuard() = default;

//------------------------------------------------------------------------------
void vtkRefractionProgramGuard::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Failed sources: " << this->Failed.size() << "\n";
}

//------------------------------------------------------------------------------
bool vtkRefractionProgramGuard::Check(vtkOpenGLRenderWindow* renWin, vtkProp* prop,
  std::string& vertexShader, std::string& geometryShader, std::string& fragmentShader)
{
  if (!renWin)
  {
    return true;
  }
  // The sources as the mapper will hand them to the cache: after the actor's own shader
  // replacements that VTK applies after every render pass's (vtkOpenGLPolyDataMapper::
  // BuildShaders).
  std::string sources[3] = { vertexShader, geometryShader, fragmentShader };
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  vtkOpenGLShaderProperty* property =
    actor ? vtkOpenGLShaderProperty::SafeDownCast(actor->GetShaderProperty()) : nullptr;
  if (property)
  {
    for (const auto& replacement : property->GetAllShaderReplacements())
    {
      const int index = replacement.first.ShaderType == vtkShader::Vertex ? 0
        : replacement.first.ShaderType == vtkShader::Geometry             ? 1
        : replacement.first.ShaderType == vtkShader::Fragment             ? 2
                                                                          : -1;
      if (!replacement.first.ReplaceFirst && index >= 0)
      {
        vtkShaderProgram::Substitute(sources[index], replacement.first.OriginalValue,
          replacement.second.Replacement, replacement.second.ReplaceAll);
      }
    }
  }
  std::string key = Key(sources[0], sources[1], sources[2]);
  bool builds = this->Failed.count(key) == 0;
  if (builds)
  {
    // The mapper asks the same cache with the same sources and no transform feedback
    // (vtkOpenGLPolyDataMapper::UpdateShaders), so it is handed this program, built once.
    builds = renWin->GetShaderCache()->ReadyShaderProgram(
               sources[0].c_str(), sources[2].c_str(), sources[1].c_str()) != nullptr;
    if (!builds)
    {
      this->Failed.insert(std::move(key));
    }
  }
  if (!builds)
  {
    vertexShader = kEmptyVertexShader;
    geometryShader.clear();
    fragmentShader = kEmptyFragmentShader;
  }
  return builds;
}
