// FieldPass as a drop-in: `vtkNew<FieldPass> ao; ao->SetSceneRadius(R); renderer->SetPass(ao);`
// finds the casting actors itself, bakes each distinct polydata once (two actors of one polydata:
// one field; a second pass: read from the bake cache), follows actor matrices without baking (the
// floor's dark spot moves with the sphere), bakes again a polydata whose data changed, and reports
// its bakes as VTK start, progress and end events. Without a radius, R comes from the first
// frame's visible bounds and is held, so moving a prop does not bake again.
#include <cstdio>
#include <filesystem>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>

#include "DropinRig.h"

using namespace aokit;
using namespace aokit::dropin;

namespace {

// Counts the pass's bake events and checks the progress values.
struct BakeEvents {
  int starts = 0, ends = 0, progress = 0;
  double last = -1.0;
  bool monotonic = true, inRange = true;
  vtkNew<vtkCallbackCommand> command;
  explicit BakeEvents(vtkObject* pass) {
    command->SetClientData(this);
    command->SetCallback([](vtkObject*, unsigned long event, void* self, void* data) {
      auto* e = static_cast<BakeEvents*>(self);
      if (event == vtkCommand::StartEvent) {
        ++e->starts;
        e->last = -1.0;
      } else if (event == vtkCommand::EndEvent) {
        ++e->ends;
      } else if (event == vtkCommand::ProgressEvent) {
        const double f = *static_cast<double*>(data);
        ++e->progress;
        e->monotonic = e->monotonic && f >= e->last;
        e->inRange = e->inRange && f >= 0.0 && f <= 1.0;
        e->last = f;
      }
    });
    pass->AddObserver(vtkCommand::StartEvent, command);
    pass->AddObserver(vtkCommand::EndEvent, command);
    pass->AddObserver(vtkCommand::ProgressEvent, command);
  }
};

std::string freshCache(const char* name) {
  const auto dir = std::filesystem::temp_directory_path() / ("aokit-dropin-field-" + std::to_string(getpid()) + name);
  std::filesystem::remove_all(dir);
  return dir.string();
}

vtkSmartPointer<FieldPass> fieldPass(const std::string& cache, double radius) {
  auto pass = vtkSmartPointer<FieldPass>::New();
  FieldSettings s = pass->GetSettings();
  s.cacheDirectory = cache;
  pass->SetSettings(s);
  if (radius > 0) pass->SetSceneRadius(radius);
  return pass;
}

}  // namespace

TEST(DropinField, BakesEachPolyDataOnceFollowsMatricesRebakesChangedData) {
  AOKIT_REQUIRE_DISPLAY();
  const std::string cache = freshCache("a");
  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 300);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  SphereFloor scene(renderer);
  // A second actor of the sphere's polydata, far off on the floor.
  vtkNew<vtkPolyDataMapper> shared;
  shared->SetInputConnection(scene.sphere->GetMapper()->GetInputConnection(0, 0));
  vtkNew<vtkActor> twin;
  twin->SetMapper(shared);
  twin->SetPosition(-2.6, 2.6, 0.0);
  renderer->AddActor(twin);

  auto pass = fieldPass(cache, 1.5);
  BakeEvents events(pass);
  renderer->SetPass(pass);
  window->Render();
  const FieldPrepareReport first = pass->GetFoundReport();
  std::printf("first frame: %d fields for %d occluders, %d baked (%.2f s), %d from the cache; %d progress events\n",
              first.fields, first.occluders, first.baked, first.bakeSeconds, first.fromCache, events.progress);
  EXPECT_EQ(first.occluders, 3);
  EXPECT_EQ(first.fields, 2);  // the sphere's polydata once, the floor's
  EXPECT_EQ(first.baked, 2);
  EXPECT_EQ(events.starts, 1);
  EXPECT_EQ(events.ends, 1);
  EXPECT_GE(events.progress, 2);
  EXPECT_TRUE(events.monotonic && events.inRange);
  EXPECT_DOUBLE_EQ(events.last, 1.0);
  const double contact = brightness(window, renderer, kContact), open = brightness(window, renderer, kOpen);
  EXPECT_LT(contact, open - 20) << "no AO under the sphere";

  // Moved: the matrices follow, nothing is baked; the dark spot moves with the sphere.
  scene.sphere->SetPosition(kOpen[0], kOpen[1], 0.0);
  window->Render();
  EXPECT_EQ(events.starts, 1) << "moving an actor re-planned its fields";
  const double openNow = brightness(window, renderer, kOpen);
  std::printf("sphere moved over the open floor point: %.1f -> %.1f; %d bake events in all\n", open, openNow,
              events.starts);
  const double underMoved[3] = {kOpen[0], kOpen[1] - 1.0, 0.0};
  EXPECT_LT(brightness(window, renderer, underMoved), open - 20) << "the AO did not follow the sphere";

  // Changed data: the sphere's source made bigger is a new mesh, baked again (the twin too: it
  // shares the data); the floor's field is kept.
  auto* source = vtkSphereSource::SafeDownCast(scene.sphere->GetMapper()->GetInputAlgorithm());
  ASSERT_NE(source, nullptr);
  source->SetRadius(1.1);
  window->Render();
  const FieldPrepareReport changed = pass->GetFoundReport();
  std::printf("sphere data changed: %d fields, %d baked, %d from the cache\n", changed.fields, changed.baked,
              changed.fromCache);
  EXPECT_EQ(events.starts, 2);
  EXPECT_EQ(changed.fields, 2);
  EXPECT_EQ(changed.baked, 1);
  renderer->SetPass(nullptr);

  // A second pass: every field from the cache, keyed by content.
  auto again = fieldPass(cache, 1.5);
  renderer->SetPass(again);
  window->Render();
  EXPECT_EQ(again->GetFoundReport().baked, 0);
  EXPECT_EQ(again->GetFoundReport().fromCache, 2);
  renderer->SetPass(nullptr);
  std::filesystem::remove_all(cache);
}

TEST(DropinField, WithoutARadiusTheFirstFramesIsHeld) {
  AOKIT_REQUIRE_DISPLAY();
  const std::string cache = freshCache("b");
  vtkNew<vtkRenderWindow> window;
  window->SetSize(300, 200);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  SphereFloor scene(renderer);
  auto pass = fieldPass(cache, 0.0);
  BakeEvents events(pass);
  renderer->SetPass(pass);
  window->Render();
  const double before = brightness(window, renderer, kContact);
  scene.floor->SetScale(1.5, 1.5, 1.0);  // the visible bounds grow: a tenth of them would be a new R
  scene.floor->SetScale(1.0, 1.0, 1.0);
  scene.sphere->AddPosition(0.3, 0.0, 0.0);
  window->Render();
  EXPECT_EQ(events.starts, 1) << "the held R changed";
  EXPECT_LT(before, brightness(window, renderer, kOpen) - 10);
  renderer->SetPass(nullptr);
  std::filesystem::remove_all(cache);
}

TEST(DropinField, TheManualAPIEndsTheSearch) {
  AOKIT_REQUIRE_DISPLAY();
  vtkNew<vtkRenderWindow> window;
  window->SetSize(300, 200);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  SphereFloor scene(renderer);
  auto pass = fieldPass(freshCache("c"), 1.5);
  EXPECT_TRUE(pass->GetFindOccluders());
  pass->SetFields({});
  pass->SetOccluders({});
  EXPECT_FALSE(pass->GetFindOccluders());
  BakeEvents events(pass);
  renderer->SetPass(pass);
  window->Render();
  EXPECT_EQ(events.starts, 0);
  // No occluders given: no AO anywhere.
  const ReadBack ao = readAO(pass, window, renderer);
  float most = 0.0f;
  for (std::size_t i = 0; i < ao.ao.size(); ++i)
    if (ao.covered[i]) most = std::max(most, ao.ao[i]);
  EXPECT_EQ(most, 0.0f);
  renderer->SetPass(nullptr);
}
