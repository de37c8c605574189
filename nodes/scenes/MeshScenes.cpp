// "bunny" and "fandisk": real meshes (fetched by models/fetch-meshes.sh) stood on a floor. Both come
// normalized to about a unit box; they are turned to z-up and scaled to a few units.
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "io/MeshIO.h"
#include "scenes/SceneBuilders.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"

namespace aokit {
namespace {

struct PackagedMesh {
  const char* name;
  const char* file;     // under <models>/packaged/
  glm::dmat4 toZUp;     // the file's up axis onto +z
  double height;        // world height after scaling
  double aoRadius;
  double azimuthDeg;    // camera direction, seen from above
};

const PackagedMesh& packaged(const std::string& name) {
  static const PackagedMesh bunny{"bunny", "bunny00.off", rotation(90.0, {1, 0, 0}), 3.0, 1.0, -120.0};
  static const PackagedMesh fandisk{"fandisk", "fandisk.off", glm::dmat4(1.0), 3.0, 1.0, -60.0};
  if (name == "bunny") return bunny;
  if (name == "fandisk") return fandisk;
  throw std::invalid_argument("no packaged mesh called '" + name + "'");
}

}  // namespace

Scene makePackagedMeshScene(const std::string& name, const std::string& modelsDir) {
  const PackagedMesh& spec = packaged(name);
  const std::filesystem::path dir = modelsDir.empty() ? defaultModelsDir() : modelsDir;
  const std::string path = (dir / "packaged" / spec.file).string();
  if (!std::filesystem::exists(path))
    throw std::runtime_error(name + " needs " + path + ": run models/fetch-meshes.sh");
  auto mesh = std::make_shared<TriangleMesh>(loadMesh(path));

  // Turn, scale to the target height, centre over the origin, and stand on z = 0.
  const Bounds b = mesh->bounds().transformed(spec.toZUp);
  const double scale = spec.height / (b.max.z - b.min.z);
  const glm::dvec3 shift(-b.center().x, -b.center().y, -b.min.z);
  const glm::dmat4 place = scaling(glm::dvec3(scale)) * translation(shift) * spec.toZUp;

  Scene scene;
  addPlaced(*scene.root, makeGridPlane(8 * spec.height, 8 * spec.height, 16, 16), glm::dmat4(1.0),
            glm::vec3(kDefaultAlbedo), "floor");
  addPlaced(*scene.root, mesh, place, glm::vec3(kDefaultAlbedo), name);

  const double az = glm::radians(spec.azimuthDeg), el = glm::radians(25.0), dist = 3.6 * spec.height;
  scene.camera.focalPoint = {0.0, 0.0, 0.45 * spec.height};
  scene.camera.position = scene.camera.focalPoint +
                          dist * glm::dvec3(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 30.0;
  scene.root->setAORadius(spec.aoRadius);
  return scene;
}

}  // namespace aokit
