/**
 * @class   vtkRefractionProgramGuard
 * @brief   Keeps a glass mapper's program that does not build from reaching VTK's mapper.
 *
 * VTK 9.1's vtkOpenGLPolyDataMapper::UpdateShaders dereferences the program its shader cache
 * failed to build, so a glass shader that does not compile or link (a driver that rejects
 * our code, a user's shader replacement that does not compile with it) would crash the
 * application. The geometry stage hands each glass mapper's finished sources to Check in its
 * PostReplaceShaderValues, the last change before the mapper asks the cache for them: Check
 * builds them in that same cache (the mapper's request then finds the built program, nothing
 * is compiled twice), and where they fail it puts a program in their place that draws
 * nothing, and remembers them so that they are not compiled again.
 */
#ifndef vtkRefractionProgramGuard_h
#define vtkRefractionProgramGuard_h

#include "vtkObject.h"

#include <set>    // For members
#include <string> // For the sources

class vtkOpenGLRenderWindow;
class vtkProp;

class vtkRefractionProgramGuard : public vtkObject
{
public:
  static vtkRefractionProgramGuard* New();
  vtkTypeMacro(vtkRefractionProgramGuard, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Whether the program of these sources, with the prop's own shader replacements that VTK
  /// applies after the render passes' (vtkOpenGLShaderProperty, ReplaceFirst false), builds
  /// in renWin's shader cache. When it does not (vtkShaderProgram has reported the compiler's
  /// log), the three sources are replaced by a program that draws nothing, and false is
  /// returned.
  bool Check(vtkOpenGLRenderWindow* renWin, vtkProp* prop, std::string& vertexShader,
    std::string& geometryShader, std::string& fragmentShader);

protected:
  vtkRefractionProgramGuard();
  ~vtkRefractionProgramGuard() override;

private:
  vtkRefractionProgramGuard(const vtkRefractionProgramGuard&) = delete;
  void operator=(const vtkRefractionProgramGuard&) = delete;

  std::set<std::string> Failed; ///< the sources that did not build, vertex + geometry + fragment
};

#endif
