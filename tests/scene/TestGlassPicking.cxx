// Picking through the pass: VTK 9.1 draws a hardware selection's ids only where the renderer
// has no render pass, so with the pass set (any pass, vtkRenderStepsPass included) vtkPropPicker
// and vtkHardwareSelector found nothing, the opaque props included. A glass sphere, an opaque
// cone beside it and an opaque ball behind both, in VTK's default window:
//  - vtkPropPicker at the sphere's centre finds the sphere (glass is picked as its surface),
//    at the cone's the cone;
//  - vtkHardwareSelector over the whole window finds the same props and the same cells as
//    without the pass;
//  - the frame rendered after the selections equals the one before.
#include "vtkRefractionPass.h"

#include "rfTestScene.h"
#include "rf_require.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkHardwareSelector.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkNew.h>
#include <vtkPropPicker.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSelection.h>
#include <vtkSelectionNode.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <string>

namespace
{
const int kWidth = 200;
const int kHeight = 150;

struct Scene
{
  vtkSmartPointer<vtkActor> Glass;
  vtkSmartPointer<vtkActor> Cone;
  vtkSmartPointer<vtkActor> Ball;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRefractionPass> Pass;
  vtkSmartPointer<vtkRenderWindow> Window;

  explicit Scene(bool withPass)
  {
    const double left[3] = { -1.0, 0.0, 0.0 };
    this->Glass = rftest::ActorFor(rftest::SpherePoly(left, 0.8, 32));
    vtkRefractionPass::MakeGlass(this->Glass, 1.5);
    const double right[3] = { 1.0, 0.0, 0.0 };
    this->Cone = rftest::ActorFor(rftest::ConePoly(right, 1.0, 0.5, 24));
    this->Cone->GetProperty()->SetColor(1.0, 0.5, 0.0);
    const double behind[3] = { 0.0, 0.0, -3.0 };
    this->Ball = rftest::ActorFor(rftest::SpherePoly(behind, 2.5, 24));
    this->Ball->GetProperty()->SetColor(0.2, 0.6, 0.3);
    this->Renderer->AddActor(this->Glass);
    this->Renderer->AddActor(this->Cone);
    this->Renderer->AddActor(this->Ball);
    if (withPass)
    {
      this->Renderer->SetPass(this->Pass);
    }
    this->Window = rftest::MakeWindow(this->Renderer, kWidth, kHeight);
    const double eye[3] = { 0.0, 0.0, 7.0 };
    const double focal[3] = { 0.0, 0.0, 0.0 };
    const double up[3] = { 0.0, 1.0, 0.0 };
    rftest::LookAt(this->Renderer->GetActiveCamera(), eye, focal, up, 40.0, 1.0, 20.0);
    this->Window->Render();
  }

  // The display pixel of a world point.
  void Pixel(const double world[3], int pixel[2])
  {
    this->Renderer->SetWorldPoint(world[0], world[1], world[2], 1.0);
    this->Renderer->WorldToDisplay();
    double display[3];
    this->Renderer->GetDisplayPoint(display);
    pixel[0] = static_cast<int>(display[0]);
    pixel[1] = static_cast<int>(display[1]);
  }

  std::string Name(vtkObjectBase* prop) const
  {
    return prop == this->Glass.Get() ? "glass"
      : prop == this->Cone.Get()     ? "cone"
      : prop == this->Ball.Get()     ? "ball"
      : prop                          ? "other"
                                      : "none";
  }

  std::string PickAt(const double world[3])
  {
    int pixel[2];
    this->Pixel(world, pixel);
    vtkNew<vtkPropPicker> picker;
    picker->Pick(pixel[0], pixel[1], 0.0, this->Renderer);
    return this->Name(picker->GetViewProp());
  }

  // Per prop picked over the whole window, its cells.
  std::map<std::string, std::set<vtkIdType>> SelectCells()
  {
    vtkNew<vtkHardwareSelector> selector;
    selector->SetRenderer(this->Renderer);
    selector->SetArea(0, 0, kWidth - 1, kHeight - 1);
    selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
    vtkSmartPointer<vtkSelection> selection;
    selection.TakeReference(selector->Select());
    std::map<std::string, std::set<vtkIdType>> cells;
    for (unsigned int i = 0; selection && i < selection->GetNumberOfNodes(); ++i)
    {
      vtkSelectionNode* node = selection->GetNode(i);
      auto* ids = vtkIdTypeArray::SafeDownCast(node->GetSelectionList());
      std::set<vtkIdType>& set = cells[this->Name(node->GetProperties()->Get(vtkSelectionNode::PROP()))];
      for (vtkIdType j = 0; ids && j < ids->GetNumberOfTuples(); ++j)
      {
        set.insert(ids->GetValue(j));
      }
    }
    return cells;
  }
};
}

int main()
{
  Scene glass(true);
  auto before = rftest::Grab(glass.Window);
  const double sphereCentre[3] = { -1.0, 0.0, 0.0 };
  const double coneCentre[3] = { 1.0, 0.0, 0.0 };
  const std::string atSphere = glass.PickAt(sphereCentre);
  const std::string atCone = glass.PickAt(coneCentre);
  std::printf("vtkPropPicker: %s at the glass sphere's centre, %s at the cone's\n",
    atSphere.c_str(), atCone.c_str());
  RF_REQUIRE(atSphere == "glass", "the glass sphere is not picked");
  RF_REQUIRE(atCone == "cone", "the opaque cone is not picked");

  auto withPass = glass.SelectCells();
  Scene plain(false);
  auto withoutPass = plain.SelectCells();
  for (const auto& entry : withoutPass)
  {
    std::printf("vtkHardwareSelector: %s: %zu cells without the pass, %zu with it\n",
      entry.first.c_str(), entry.second.size(), withPass[entry.first].size());
  }
  RF_REQUIRE(withoutPass.size() == 3, "the scene without the pass does not show three props");
  RF_REQUIRE(withPass == withoutPass, "the selection differs from VTK's without the pass");

  glass.Window->Render();
  auto after = rftest::Grab(glass.Window);
  const int changed = rftest::DifferingPixels(before, after, 0);
  std::printf("pixels changed by the selections: %d\n", changed);
  RF_REQUIRE(changed == 0, "the frame after the selections differs from the one before");
  return EXIT_SUCCESS;
}
