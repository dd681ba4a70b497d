#include "vtkRefractionSHTransfer.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRefractionGlassKeys.h"
#include "vtkRefractionMeshes.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "rf_sh.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkRefractionSHTransfer);

namespace
{
// Texels per row of the coefficient texture.
const int kWidth = 4096;

vtkPolyData* MeshOf(vtkProp* prop, vtkMapper** mapperOut = nullptr)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  if (mapperOut)
  {
    *mapperOut = mapper;
  }
  return mapper ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
}

// The order L of a transfer of `components` = 4 (L + 1)^2 per point; -1 when none fits.
int OrderOf(int components)
{
  for (int order = 0; order <= 8; ++order)
  {
    if (components == 4 * (order + 1) * (order + 1))
    {
      return order;
    }
  }
  return -1;
}
}

//------------------------------------------------------------------------------
vtkRefractionSHTransfer::vtkRefractionSHTransfer() = default;
vtkRefractionSHTransfer::~vtkRefractionSHTransfer() = default;

//------------------------------------------------------------------------------
void vtkRefractionSHTransfer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Uploaded meshes: " << this->Uploads.size() << " (" << this->GetBytes()
     << " bytes)\n";
}

//------------------------------------------------------------------------------
bool vtkRefractionSHTransfer::Check(const std::vector<vtkProp*>& glass, std::string& reason)
{
  for (vtkProp* prop : glass)
  {
    std::ostringstream why;
    vtkPolyData* poly = MeshOf(prop);
    vtkDataArray* transfer = poly ? poly->GetPointData()->GetArray(GetTransferArrayName()) : nullptr;
    vtkDataArray* ids = poly ? poly->GetPointData()->GetArray(GetVertexIdArrayName()) : nullptr;
    vtkDataArray* settings =
      poly ? poly->GetFieldData()->GetArray(GetSettingsArrayName()) : nullptr;
    if (vtkRefractionMeshes::IsComposite(prop))
    {
      why << "glass prop " << prop
          << " draws composite data: VTK's (9.1, 9.2) vtkCompositePolyDataMapper2 uploads no extra "
             "vertex attributes, which the SH method needs (give it a vtkPolyData)";
    }
    else if (!transfer || !ids || !settings || settings->GetNumberOfTuples() < 4 ||
      OrderOf(transfer->GetNumberOfComponents()) < 0 ||
      transfer->GetNumberOfTuples() != poly->GetNumberOfPoints())
    {
      why << "glass prop " << prop << " has no SH transfer (put a vtkSHTransferFilter before its "
          << "mapper)";
    }
    else if (poly->GetPoints() && poly->GetPoints()->GetMTime() > transfer->GetMTime())
    {
      why << "the SH transfer of glass prop " << prop
          << " is stale: its points changed after it was computed (the SH method is for "
             "static meshes)";
    }
    else if (std::abs(settings->GetComponent(3, 0) -
               vtkRefractionGlassKeys::GetIndexOfRefraction(prop)) > 1e-6)
    {
      why << "the SH transfer of glass prop " << prop << " was computed for index of refraction "
          << settings->GetComponent(3, 0) << ", the prop has "
          << vtkRefractionGlassKeys::GetIndexOfRefraction(prop);
    }
    if (!why.str().empty())
    {
      reason = why.str();
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkRefractionSHTransfer::MapVertexIds(vtkProp* prop)
{
  vtkMapper* mapper = nullptr;
  MeshOf(prop, &mapper);
  auto* glMapper = vtkOpenGLPolyDataMapper::SafeDownCast(mapper);
  if (glMapper)
  {
    // Mapping again replaces the same entry: nothing is rebuilt while it stays the same.
    glMapper->MapDataArrayToVertexAttribute(
      "rfSHVertex", GetVertexIdArrayName(), vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  }
}

//------------------------------------------------------------------------------
bool vtkRefractionSHTransfer::Bind(
  vtkShaderProgram* program, vtkProp* prop, vtkRenderer* ren, vtkOpenGLRenderWindow* renWin)
{
  vtkPolyData* poly = MeshOf(prop);
  vtkDataArray* transfer = poly ? poly->GetPointData()->GetArray(GetTransferArrayName()) : nullptr;
  const int order = transfer ? OrderOf(transfer->GetNumberOfComponents()) : -1;
  if (order < 0 || !program->IsUniformUsed("rfSHCoefficients"))
  {
    return false;
  }
  const int count = (order + 1) * (order + 1);
  Upload& upload = this->Uploads[poly];
  if (!upload.Texture || upload.Time != transfer->GetMTime() || upload.Count != count ||
    upload.Smoothing != this->Smoothing)
  {
    // Point-major texels of (x, y, z, length): the point's coefficient c at point * count + c.
    const vtkIdType points = transfer->GetNumberOfTuples();
    const long long texels = static_cast<long long>(points) * count;
    const int height = static_cast<int>((texels + kWidth - 1) / kWidth);
    std::vector<float> data(4 * static_cast<size_t>(kWidth) * std::max(height, 1), 0.f);
    std::vector<double> weights(count);
    for (vtkIdType p = 0; p < points; ++p)
    {
      for (int f = 0; f < 4; ++f)
      {
        for (int c = 0; c < count; ++c)
        {
          weights[c] = transfer->GetComponent(p, f * count + c);
        }
        rf_sh_smooth(order, this->Smoothing, weights.data());
        for (int c = 0; c < count; ++c)
        {
          data[4 * (static_cast<size_t>(p) * count + c) + f] = static_cast<float>(weights[c]);
        }
      }
    }
    upload.Texture = vtkSmartPointer<vtkTextureObject>::New();
    upload.Texture->SetContext(renWin);
    upload.Texture->SetInternalFormat(GL_RGBA32F);
    upload.Texture->SetFormat(GL_RGBA);
    upload.Texture->SetDataType(GL_FLOAT);
    upload.Texture->SetMinificationFilter(vtkTextureObject::Nearest);
    upload.Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    upload.Texture->Create2DFromRaw(kWidth, std::max(height, 1), 4, VTK_FLOAT, data.data());
    upload.Time = transfer->GetMTime();
    upload.Count = count;
    upload.Smoothing = this->Smoothing;
    upload.Bytes = 16ULL * kWidth * std::max(height, 1);
  }
  upload.Texture->Activate();
  this->Active.push_back(upload.Texture);
  program->SetUniformi("rfSHCoefficients", upload.Texture->GetTextureUnit());
  program->SetUniformi("rfSHCount", count);
  program->SetUniformi("rfSHOrder", order);

  // The camera in the mesh's model coordinates, and the model-to-view linear map.
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  vtkCamera* camera = ren->GetActiveCamera();
  vtkNew<vtkMatrix4x4> model;
  if (actor)
  {
    model->DeepCopy(actor->GetMatrix());
  }
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(model, inverse);
  double eye[4] = { 0.0, 0.0, 0.0, 1.0 };
  camera->GetPosition(eye);
  double eyeMC[4];
  inverse->MultiplyPoint(eye, eyeMC);
  double projection[4] = { 0.0, 0.0, 0.0, 0.0 };
  camera->GetDirectionOfProjection(projection);
  double directionMC[4];
  inverse->MultiplyPoint(projection, directionMC);
  vtkMath::Normalize(directionMC);
  const float eyeValues[3] = { static_cast<float>(eyeMC[0] / eyeMC[3]),
    static_cast<float>(eyeMC[1] / eyeMC[3]), static_cast<float>(eyeMC[2] / eyeMC[3]) };
  const float directionValues[3] = { static_cast<float>(directionMC[0]),
    static_cast<float>(directionMC[1]), static_cast<float>(directionMC[2]) };
  program->SetUniform3f("rfSHEyeMC", eyeValues);
  program->SetUniform3f("rfSHDirectionMC", directionValues);
  program->SetUniformi("rfSHParallel", camera->GetParallelProjection() ? 1 : 0);
  vtkNew<vtkMatrix4x4> modelToView;
  vtkMatrix4x4::Multiply4x4(camera->GetViewTransformMatrix(), model, modelToView);
  float linear[9];
  double m[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      m[r][c] = model->GetElement(r, c);
      linear[c * 3 + r] = static_cast<float>(modelToView->GetElement(r, c)); // column-major
    }
  }
  program->SetUniformMatrix3x3("rfSHModelToView", linear);
  program->SetUniformf(
    "rfSHLengthScale", static_cast<float>(std::cbrt(std::abs(vtkMath::Determinant3x3(m)))));
  return true;
}

//------------------------------------------------------------------------------
void vtkRefractionSHTransfer::Retain(const std::vector<vtkProp*>& glass)
{
  std::vector<vtkPolyData*> meshes;
  for (vtkProp* prop : glass)
  {
    meshes.push_back(MeshOf(prop));
  }
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
void vtkRefractionSHTransfer::Unbind()
{
  for (vtkTextureObject* texture : this->Active)
  {
    texture->Deactivate();
  }
  this->Active.clear();
}

//------------------------------------------------------------------------------
unsigned long long vtkRefractionSHTransfer::GetBytes() const
{
  unsigned long long bytes = 0;
  for (const auto& upload : this->Uploads)
  {
    bytes += upload.second.Bytes;
  }
  return bytes;
}

//------------------------------------------------------------------------------
void vtkRefractionSHTransfer::ReleaseGraphicsResources(vtkWindow* w)
{
  for (auto& upload : this->Uploads)
  {
    if (upload.second.Texture)
    {
      upload.second.Texture->ReleaseGraphicsResources(w);
    }
  }
  this->Uploads.clear();
  this->Active.clear();
}
