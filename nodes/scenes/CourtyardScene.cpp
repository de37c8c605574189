// "courtyard": static plus dynamic (issue 9 item 5). A static courtyard (floor, three walls,
// pillars, a bench, a planter; one group whose node mask lacks kDynamic) with the moving objects of
// "animated" passing close to it, and the same orbiting camera. The static meshes are subdivided
// into cells of R/4 so that AO baked per vertex resolves the static corners and contacts.
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "scenes/SceneBuilders.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"

namespace aokit {
namespace {

// Axis-aligned box centred at the origin, each face a grid of cells no larger than `cell`, with
// flat normals (vertices not shared across faces; edges meet exactly, so it stays watertight).
std::shared_ptr<TriangleMesh> makeCellBox(const glm::dvec3& size, double cell) {
  auto m = std::make_shared<TriangleMesh>();
  const glm::dvec3 h = 0.5 * size;
  const glm::ivec3 cells(glm::max(glm::dvec3(1.0), glm::ceil(size / cell)));
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {-1.0, 1.0}) {
      const int ua = (axis + 1) % 3, va = (axis + 2) % 3;
      glm::dvec3 n(0.0), u(0.0), v(0.0);
      n[axis] = sign;
      u[ua] = 1.0;
      v[va] = sign;  // u x v = n: counter-clockwise seen from outside
      const int nu = cells[ua], nv = cells[va];
      const unsigned first = static_cast<unsigned>(m->positions.size());
      for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i) {
          const glm::dvec3 p = n * h + u * (h[ua] * (2.0 * i / nu - 1.0)) + v * (h[va] * (2.0 * j / nv - 1.0));
          m->positions.emplace_back(p);
          m->normals.emplace_back(n);
        }
      for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
          const unsigned a = first + static_cast<unsigned>(j * (nu + 1) + i), b = a + 1,
                         c = a + static_cast<unsigned>(nu + 1) + 1, d = a + static_cast<unsigned>(nu + 1);
          m->triangles.emplace_back(a, b, c);
          m->triangles.emplace_back(a, c, d);
        }
    }
  return m;
}

struct Movers {
  TransformPtr orbiter, bouncer, slider, spinner;
};

// As "animated": a pure function of the frame.
void pose(Scene& scene, const Movers& m, int frame) {
  const double t = static_cast<double>(frame) / scene.frameCount;
  const double a = glm::two_pi<double>() * t;
  m.orbiter->setMatrix(translation({2.5 * std::cos(a), 2.5 * std::sin(a), 0.65}));
  m.bouncer->setMatrix(translation({-0.8, 0.8, 0.4 + 1.5 * std::abs(std::sin(2.0 * a))}));
  m.slider->setMatrix(translation({2.0 * std::sin(a), -3.5, 0.5}) * rotation(90.0 * std::sin(a), {0, 0, 1}));
  m.spinner->setMatrix(translation({-4.2, 0.0, 0.9}) * rotation(360.0 * t, {0, 0, 1}));
  const double yaw = glm::radians(-90.0 + 25.0 * std::sin(a));
  scene.camera.position = {13.0 * std::cos(yaw), 13.0 * std::sin(yaw), 6.0};
  scene.camera.focalPoint = {0.0, 0.5, 0.5};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 34.0;
}

}  // namespace

Scene makeCourtyardScene() {
  Scene scene;
  const glm::vec3 grey(kDefaultAlbedo);
  const double R = 1.0, cell = 0.25 * R;
  auto statics = std::make_shared<Group>();
  statics->setName("static");
  statics->setDynamic(false);  // everything below is static
  Group& s = *statics;
  auto box = [&](const glm::dvec3& lo, const glm::dvec3& hi, const std::string& name) {
    addPlaced(s, makeCellBox(hi - lo, cell), translation(0.5 * (lo + hi)), grey, name);
  };
  addPlaced(s, makeGridPlane(14.0, 14.0, 56, 56), glm::dmat4(1.0), grey, "floor");
  box({-6.0, 4.35, 0.0}, {6.0, 4.65, 2.5}, "back wall");
  box({-6.3, -2.0, 0.0}, {-6.0, 4.65, 2.5}, "left wall");
  box({6.0, -2.0, 0.0}, {6.3, 4.65, 2.5}, "right wall");
  for (double x : {-3.2, 3.2})
    for (double y : {-1.5, 2.0}) box({x - 0.25, y - 0.25, 0.0}, {x + 0.25, y + 0.25, 2.5}, "pillar");
  box({-1.0, 3.45, 0.0}, {1.0, 3.95, 0.45}, "bench");
  box({-1.5, -5.4, 0.0}, {1.5, -4.6, 0.6}, "planter");
  scene.root->addChild(statics);

  Movers m;
  Group& root = *scene.root;
  m.orbiter = addPlaced(root, makeUVSphere(0.6, 64, 32), glm::dmat4(1.0), grey, "orbiting sphere");
  m.bouncer = addPlaced(root, makeUVSphere(0.4, 48, 24), glm::dmat4(1.0), grey, "bouncing sphere");
  m.slider = addPlaced(root, makeBox(glm::dvec3(1.0)), glm::dmat4(1.0), grey, "sliding box");
  m.spinner = addPlaced(root, makeBox({0.6, 1.6, 1.8}), glm::dmat4(1.0), grey, "spinning box");

  scene.frameCount = 60;
  scene.root->setAORadius(R);
  scene.animate = [m](Scene& sc, int frame) { pose(sc, m, frame); };
  scene.animate(scene, 0);
  return scene;
}

}  // namespace aokit
