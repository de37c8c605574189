// "animated": objects moving over a floor and an orbiting camera, for temporal stability tests and
// for methods that must re-bake, re-voxelize or re-project every frame.
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "scenes/SceneBuilders.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"

namespace aokit {
namespace {

struct Movers {
  TransformPtr orbiter, bouncer, slider, spinner;
};

// Paths keep clear of each other (orbit radius 2.5, the others 1.4+ away from it).
// The whole animation as a pure function of the frame: no state carried between frames, so any
// frame can be rendered alone and frame 0 is the state right after construction.
void pose(Scene& scene, const Movers& m, int frame) {
  const double t = static_cast<double>(frame) / scene.frameCount;  // one loop over frameCount frames
  const double tau = glm::two_pi<double>();

  const double a = tau * t;
  m.orbiter->setMatrix(translation({2.5 * std::cos(a), 2.5 * std::sin(a), 0.65}));
  m.bouncer->setMatrix(translation({-0.8, 0.8, 0.4 + 1.5 * std::abs(std::sin(2 * tau * t))}));
  m.slider->setMatrix(translation({2.0 * std::sin(a), -4.0, 0.5}) * rotation(90.0 * std::sin(a), {0, 0, 1}));
  m.spinner->setMatrix(translation({-4.2, 0.0, 0.9}) * rotation(360.0 * t, {0, 0, 1}));

  // Camera swings +-25 degrees around the -y view, 13 units out, 6 up.
  const double yaw = glm::radians(-90.0 + 25.0 * std::sin(a));
  scene.camera.position = {13.0 * std::cos(yaw), 13.0 * std::sin(yaw), 6.0};
  scene.camera.focalPoint = {0.0, 0.0, 0.5};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 30.0;
}

}  // namespace

Scene makeAnimatedScene() {
  Scene scene;
  const glm::vec3 grey(kDefaultAlbedo);
  Group& root = *scene.root;
  addPlaced(root, makeGridPlane(12.0, 12.0, 24, 24), glm::dmat4(1.0), grey, "floor");

  Movers m;
  m.orbiter = addPlaced(root, makeUVSphere(0.6, 64, 32), glm::dmat4(1.0), grey, "orbiting sphere");
  m.bouncer = addPlaced(root, makeUVSphere(0.4, 48, 24), glm::dmat4(1.0), grey, "bouncing sphere");
  m.slider = addPlaced(root, makeBox(glm::dvec3(1.0)), glm::dmat4(1.0), grey, "sliding box");
  m.spinner = addPlaced(root, makeBox({0.6, 1.6, 1.8}), glm::dmat4(1.0), grey, "spinning box");

  scene.frameCount = 60;
  scene.root->setAORadius(1.0);
  scene.animate = [m](Scene& s, int frame) { pose(s, m, frame); };
  scene.animate(scene, 0);
  return scene;
}

}  // namespace aokit
