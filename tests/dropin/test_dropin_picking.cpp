// Picking: vtkPropPicker, vtkCellPicker and hardware selection (vtkHardwareSelector over an area)
// return with the pass on the renderer what they return without it.
#include <set>

#include <vtkCellPicker.h>
#include <vtkHardwareSelector.h>
#include <vtkInformation.h>
#include <vtkPropPicker.h>
#include <vtkSelection.h>
#include <vtkSelectionNode.h>

#include "DropinRig.h"

using namespace aokit;
using namespace aokit::dropin;

namespace {

struct Picks {
  vtkProp* propPicked = nullptr;
  vtkProp* cellPickedProp = nullptr;
  vtkIdType cell = -1;
  std::set<vtkProp*> areaProps;
  std::size_t areaNodes = 0;
};

Picks pickAll(vtkRenderWindow* window, vtkRenderer* renderer) {
  Picks p;
  renderer->SetWorldPoint(0.0, 0.0, 1.2, 1.0);  // the sphere's centre
  renderer->WorldToDisplay();
  const double* d = renderer->GetDisplayPoint();
  vtkNew<vtkPropPicker> propPicker;
  if (propPicker->Pick(d[0], d[1], 0.0, renderer)) p.propPicked = propPicker->GetViewProp();
  vtkNew<vtkCellPicker> cellPicker;
  if (cellPicker->Pick(d[0], d[1], 0.0, renderer)) {
    p.cellPickedProp = cellPicker->GetViewProp();
    p.cell = cellPicker->GetCellId();
  }
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(renderer);
  const int* size = window->GetSize();
  selector->SetArea(0, 0, size[0] - 1, size[1] - 1);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  vtkSmartPointer<vtkSelection> selection = vtkSmartPointer<vtkSelection>::Take(selector->Select());
  if (selection) {
    p.areaNodes = selection->GetNumberOfNodes();
    for (unsigned i = 0; i < selection->GetNumberOfNodes(); ++i)
      p.areaProps.insert(vtkProp::SafeDownCast(selection->GetNode(i)->GetProperties()->Get(vtkSelectionNode::PROP())));
  }
  return p;
}

}  // namespace

TEST(DropinPicking, PickersSeeWhatTheySeeWithoutThePass) {
  AOKIT_REQUIRE_DISPLAY();
  for (Family family : families()) {
    vtkNew<vtkRenderWindow> window;
    window->SetSize(400, 300);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    SphereFloor scene(renderer);
    window->Render();
    const Picks plain = pickAll(window, renderer);
    ASSERT_EQ(plain.propPicked, scene.sphere.Get());
    ASSERT_EQ(plain.cellPickedProp, scene.sphere.Get());
    ASSERT_EQ(plain.areaProps.size(), 2u);
    auto pass = makePass(family);
    renderer->SetPass(pass);
    window->Render();
    const Picks withAO = pickAll(window, renderer);
    EXPECT_EQ(withAO.propPicked, plain.propPicked) << familyName(family);
    EXPECT_EQ(withAO.cellPickedProp, plain.cellPickedProp) << familyName(family);
    EXPECT_EQ(withAO.cell, plain.cell) << familyName(family);
    EXPECT_EQ(withAO.areaProps, plain.areaProps) << familyName(family);
    EXPECT_EQ(withAO.areaNodes, plain.areaNodes) << familyName(family);
    // And the frame after picking is the AO frame again.
    const double contact = brightness(window, renderer, kContact);
    window->Render();
    EXPECT_NEAR(brightness(window, renderer, kContact), contact, 1.0) << familyName(family);
    renderer->SetPass(nullptr);
  }
}
