#include "vtkRefractionPieceSheets.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPolyData.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>

vtkStandardNewMacro(vtkRefractionPieceSheets);

namespace
{
// Texels per row (the vertex shader divides the vertex index by the texture's width).
const int kWidth = 4096;
}

//------------------------------------------------------------------------------
void vtkRefractionPieceSheets::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Uploaded meshes: " << this->Uploads.size() << "\n";
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkTextureObject> vtkRefractionPieceSheets::Upload1(
  const std::vector<unsigned char>& flags, vtkOpenGLRenderWindow* renWin)
{
  const size_t count = std::max<size_t>(flags.size(), 1);
  const int width = static_cast<int>(std::min<size_t>(count, kWidth));
  const int height = static_cast<int>((count + kWidth - 1) / kWidth);
  std::vector<unsigned char> data(static_cast<size_t>(width) * height, 0);
  std::transform(flags.begin(), flags.end(), data.begin(),
    [](unsigned char f) { return static_cast<unsigned char>(f ? 255 : 0); });
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(renWin);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->Create2DFromRaw(width, height, 1, VTK_UNSIGNED_CHAR, data.data());
  return texture;
}

//------------------------------------------------------------------------------
void vtkRefractionPieceSheets::ReplaceShaderValues(
  std::string& vertexShader, std::string& geometryShader)
{
  // The thin-sheet flag of the vertex's connected piece (this class), constant
  // over each polygon: the fragment takes the sheet pieces' material where it is set.
  vtkShaderProgram::Substitute(vertexShader, "//VTK::Normal::Dec",
    "//VTK::Normal::Dec\nuniform sampler2D rfPieceSheets;\nuniform int rfHavePieceSheets;\n"
    "out float rfPieceSheetVSOut;\n",
    false);
  vtkShaderProgram::Substitute(vertexShader, "//VTK::Normal::Impl",
    "//VTK::Normal::Impl\n  {\n    int rfWidth = textureSize(rfPieceSheets, 0).x;\n"
    "    rfPieceSheetVSOut = rfHavePieceSheets == 1\n"
    "      ? texelFetch(rfPieceSheets, ivec2(gl_VertexID % rfWidth, gl_VertexID / rfWidth), 0).r\n"
    "      : 0.0;\n  }\n",
    false);
  // Through VTK's geometry shader where there is one (edges): VTK's shader cache then reads
  // the fragment shader's ...VSOut inputs as ...GSOut.
  vtkShaderProgram::Substitute(geometryShader, "//VTK::Normal::Dec",
    "//VTK::Normal::Dec\nin float rfPieceSheetVSOut[];\nout float rfPieceSheetGSOut;\n", false);
  vtkShaderProgram::Substitute(geometryShader, "//VTK::Normal::Impl",
    "//VTK::Normal::Impl\n    rfPieceSheetGSOut = rfPieceSheetVSOut[i];\n", false);
}

//------------------------------------------------------------------------------
void vtkRefractionPieceSheets::Bind(vtkShaderProgram* program, vtkPolyData* mesh,
  const vtkRefractionSurfaceModel::Mesh* surface, int sheetMaterial, vtkOpenGLRenderWindow* renWin)
{
  if (program->IsUniformUsed("rfSheetMaterial"))
  {
    program->SetUniformf("rfSheetMaterial", static_cast<float>(sheetMaterial));
  }
  if (!program->IsUniformUsed("rfPieceSheets"))
  {
    return;
  }
  const bool flags = mesh && surface && surface->PointSheet.size() == static_cast<size_t>(
    mesh->GetNumberOfPoints());
  vtkTextureObject* texture = nullptr;
  if (flags)
  {
    Upload& upload = this->Uploads[mesh];
    if (!upload.Texture || upload.Time != surface->Time)
    {
      upload.Texture = this->Upload1(surface->PointSheet, renWin);
      upload.Time = surface->Time;
    }
    texture = upload.Texture;
  }
  else
  {
    if (!this->Empty)
    {
      this->Empty = this->Upload1(std::vector<unsigned char>(), renWin);
    }
    texture = this->Empty;
  }
  texture->Activate();
  this->Active.push_back(texture);
  program->SetUniformi("rfPieceSheets", texture->GetTextureUnit());
  program->SetUniformi("rfHavePieceSheets", flags ? 1 : 0);
}

//------------------------------------------------------------------------------
void vtkRefractionPieceSheets::Unbind()
{
  for (vtkTextureObject* texture : this->Active)
  {
    texture->Deactivate();
  }
  this->Active.clear();
}

//------------------------------------------------------------------------------
void vtkRefractionPieceSheets::Retain(const std::vector<vtkPolyData*>& meshes)
{
  for (auto upload = this->Uploads.begin(); upload != this->Uploads.end();)
  {
    if (std::find(meshes.begin(), meshes.end(), upload->first) == meshes.end())
    {
      upload = this->Uploads.erase(upload);
    }
    else
    {
      ++upload;
    }
  }
}

//------------------------------------------------------------------------------
void vtkRefractionPieceSheets::ReleaseGraphicsResources(vtkWindow* w)
{
  for (auto& upload : this->Uploads)
  {
    upload.second.Texture->ReleaseGraphicsResources(w);
  }
  this->Uploads.clear();
  if (this->Empty)
  {
    this->Empty->ReleaseGraphicsResources(w);
    this->Empty = nullptr;
  }
  this->Active.clear();
}
