#include "io/SceneFile.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "fields/ContentHash.h"
#include "fields/FieldAttachment.h"
#include "fields/FieldFile.h"
#include "io/InputFiles.h"
#include "io/JsonField.h"
#include "io/MeshIO.h"
#include "reference/Falloff.h"
#include "scenes/BuiltinScenes.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"

namespace aokit {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

// Parses JSON, rejecting duplicate keys (nlohmann would silently keep the last one).
json parseStrict(const std::string& text, const std::string& file) {
  std::vector<std::set<std::string>> keys;
  auto callback = [&](int, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) keys.emplace_back();
    if (event == json::parse_event_t::object_end) keys.pop_back();
    if (event == json::parse_event_t::key && !keys.back().insert(parsed.get<std::string>()).second)
      throw std::runtime_error(file + ": invalid JSON: duplicate key '" + parsed.get<std::string>() + "'");
    return true;
  };
  try {
    return json::parse(text, callback, true, false);
  } catch (const json::exception& e) {
    std::string what = e.what();
    if (const auto close = what.find("] "); what.rfind("[json.exception", 0) == 0 && close != std::string::npos)
      what = what.substr(close + 2);
    throw std::runtime_error(file + ": invalid JSON: " + oneLine(what));
  }
}

Falloff parseFalloff(const JsonField& f) {
  const std::string s = f.string();
  std::string names;
  for (Falloff k : kAllFalloffs) {
    if (s == falloffName(k)) return k;
    names += (names.empty() ? "" : ", ") + falloffName(k);
  }
  f.fail("expected one of " + names);
}

// Fields present in `f` override `cam`; `complete` requires position and focal point. The camera
// as a whole is checked as the CLI checks it (io/SceneLimits.h).
void parseCamera(const JsonField& f, Camera& cam, bool complete) {
  f.allowOnly({"position", "focalPoint", "viewUp", "viewAngle"});
  if (complete || f.has("position")) cam.position = f["position"].vec3();
  if (complete || f.has("focalPoint")) cam.focalPoint = f["focalPoint"].vec3();
  if (f.has("viewUp")) cam.viewUp = f["viewUp"].vec3();
  if (f.has("viewAngle")) cam.viewAngleDeg = f["viewAngle"].number(limits::kViewAngle);
  if (const auto problem = cameraProblem(cam)) {
    static const char* const keys[] = {"position", "focalPoint", "viewUp", "viewAngle"};
    f.fail(std::string(keys[problem->field]) + " " + problem->what);
  }
}

// A positive number or `n` positive numbers.
std::vector<double> sizes(const JsonField& f, std::size_t n) {
  if (f.json().is_number()) return std::vector<double>(n, f.positive());
  return f.numbers(n, 1e-300, limits::kLength.max,
                   "a positive number or " + std::to_string(n) + " positive numbers (at most 1e+15)");
}

glm::vec3 parseAlbedo(const JsonField& f) {
  if (f.json().is_number()) return glm::vec3(static_cast<float>(f.number(limits::kAlbedo)));
  const auto v = f.numbers(3, limits::kAlbedo.min, limits::kAlbedo.max, "a number or 3 numbers in [0, 1]");
  return glm::vec3(v[0], v[1], v[2]);
}

glm::dmat4 parsePlacement(const JsonField& o) {
  glm::dmat4 m(1.0);
  if (o.has("translate")) m = m * translation(o["translate"].vec3());
  if (o.has("rotate")) {
    const JsonField r = o["rotate"];
    const auto v = r.numbers(4, -1e300, 1e300, "4 numbers [angleDeg, axisX, axisY, axisZ]");
    const glm::dvec3 axis(v[1], v[2], v[3]);
    if (glm::length(axis) == 0.0) r.fail("rotation axis must not be zero");
    m = m * rotation(v[0], axis);
  }
  if (o.has("scale")) {
    const auto s = sizes(o["scale"], 3);
    m = m * scaling({s[0], s[1], s[2]});
  }
  return m;
}

std::shared_ptr<const TriangleMesh> parseShape(const JsonField& o) {
  const JsonField shape = o["shape"];
  const std::string kind = shape.string();
  auto optionalInt = [&](const char* key, int def, const NumberRange& r) {
    return o.has(key) ? o[key].integer(int(r.min), int(r.max)) : def;
  };
  auto optionalPositive = [&](const char* key, double def) { return o.has(key) ? o[key].positive() : def; };
  if (kind == "sphere") {
    o.allowOnly({"name", "shape", "radius", "slices", "stacks", "translate", "rotate", "scale", "albedo", "field"});
    return makeUVSphere(optionalPositive("radius", 1.0), optionalInt("slices", 64, limits::kSegments),
                        optionalInt("stacks", 32, limits::kStacks));
  }
  if (kind == "box") {
    o.allowOnly({"name", "shape", "size", "translate", "rotate", "scale", "albedo", "field"});
    const auto s = o.has("size") ? sizes(o["size"], 3) : std::vector<double>(3, 1.0);
    return makeBox({s[0], s[1], s[2]});
  }
  if (kind == "cylinder") {
    o.allowOnly({"name", "shape", "radius", "height", "segments", "translate", "rotate", "scale", "albedo", "field"});
    return makeCylinder(optionalPositive("radius", 0.5), optionalPositive("height", 1.0), optionalInt("segments", 48, limits::kSegments));
  }
  if (kind == "plane") {
    o.allowOnly({"name", "shape", "size", "cells", "translate", "rotate", "scale", "albedo", "field"});
    const auto s = o.has("size") ? sizes(o["size"], 2) : std::vector<double>(2, 10.0);
    int nx = 1, ny = 1;
    if (o.has("cells")) {
      const JsonField c = o["cells"];
      if (c.json().is_array()) {
        if (c.size() != 2) c.fail("expected an integer or 2 integers");
        nx = c[std::size_t(0)].integer(int(limits::kCells.min), int(limits::kCells.max));
        ny = c[std::size_t(1)].integer(int(limits::kCells.min), int(limits::kCells.max));
      } else {
        nx = ny = c.integer(int(limits::kCells.min), int(limits::kCells.max));
      }
    }
    return makeGridPlane(s[0], s[1], nx, ny);
  }
  shape.fail("unknown shape '" + kind + "' (known: sphere, box, cylinder, plane)");
}

class ObjectReader {
 public:
  explicit ObjectReader(fs::path baseDir) : baseDir_(std::move(baseDir)) {}

  void add(const JsonField& o, Group& parent) {
    if (!o.json().is_object()) o.fail("expected an object");
    const bool hasMesh = o.has("mesh"), hasShape = o.has("shape");
    if (hasMesh == hasShape) o.fail(hasMesh ? "has both 'mesh' and 'shape'" : "needs a 'mesh' or a 'shape'");
    std::shared_ptr<const TriangleMesh> mesh;
    if (hasMesh) {
      o.allowOnly({"name", "mesh", "featureAngle", "translate", "rotate", "scale", "albedo", "field"});
      const double featureAngle =
          o.has("featureAngle") ? o["featureAngle"].number(limits::kFeatureAngle) : kDefaultFeatureAngle;
      mesh = loadCached(o["mesh"], featureAngle);
    } else {
      mesh = parseShape(o);
    }
    const glm::vec3 albedo = o.has("albedo") ? parseAlbedo(o["albedo"]) : glm::vec3(0.8f);
    const TransformPtr placed =
        addPlaced(parent, mesh, parsePlacement(o), albedo, o.has("name") ? o["name"].string() : std::string());
    if (o.has("field")) attachField(o["field"], *mesh, *placed->child(0));
  }

 private:
  // The same file named twice (with one feature angle) is loaded once and shared.
  std::shared_ptr<const TriangleMesh> loadCached(const JsonField& f, double featureAngle) {
    fs::path p = f.string();
    if (p.empty()) f.fail("expected a file name");
    if (p.is_relative()) p = baseDir_ / p;
    const std::string key = p.lexically_normal().string();
    auto& slot = cache_[{key, featureAngle}];
    if (!slot) {
      try {
        slot = std::make_shared<TriangleMesh>(loadMesh(key, featureAngle));
      } catch (const std::exception& e) {
        f.fail(e.what());
      }
    }
    return slot;
  }

  // "field": a baked field file for this object (fields/FieldAttachment.h); its header and mesh
  // are checked now, its R and falloff when the field method prepares.
  void attachField(const JsonField& f, const TriangleMesh& mesh, const Node& geometry) {
    fs::path p = f.string();
    if (p.empty()) f.fail("expected a field file name");
    if (p.is_relative()) p = baseDir_ / p;
    const std::string path = p.lexically_normal().string();
    std::uint64_t baked = 0;
    try {
      baked = readFieldFileInfo(path).meshHash;
    } catch (const std::runtime_error& e) {
      f.fail(e.what());
    }
    if (baked != meshContentHash(mesh)) f.fail(path + ": field was baked for another mesh");
    setFieldFile(geometry, path);
  }

  fs::path baseDir_;
  std::map<std::pair<std::string, double>, std::shared_ptr<const TriangleMesh>> cache_;
};

Scene parseScene(const JsonField& top, const fs::path& file) {
  if (!top.json().is_object()) top.fail("expected a JSON object");
  top.allowOnly({"name", "builtin", "options", "aoRadius", "falloff", "camera", "objects"});
  const bool builtin = top.has("builtin");
  Scene scene;
  if (builtin) {
    BuiltinOptions opts;
    if (top.has("options")) {
      const JsonField o = top["options"];
      o.allowOnly({"cubeCount", "seed"});
      if (o.has("cubeCount")) opts.cubeCount = static_cast<int>(o["cubeCount"].whole(limits::kCubeCount));
      if (o.has("seed")) opts.seed = static_cast<std::uint32_t>(o["seed"].whole(limits::kSeed32));
    }
    try {
      scene = makeBuiltinScene(top["builtin"].string(), opts);
    } catch (const std::exception& e) {
      top["builtin"].fail(e.what());
    }
  } else {
    if (top.has("options")) top["options"].fail("only allowed with 'builtin'");
    scene.name = file.stem().string();
    scene.root->setAORadius(top["aoRadius"].number(limits::kAORadius));
    parseCamera(top["camera"], scene.camera, true);
    if (top["objects"].size() == 0) top["objects"].fail("expected at least one object");
  }
  if (top.has("name")) scene.name = top["name"].string();
  if (builtin && top.has("aoRadius")) scene.root->setAORadius(top["aoRadius"].number(limits::kAORadius));
  if (builtin && top.has("camera")) parseCamera(top["camera"], scene.camera, false);
  if (top.has("falloff")) scene.root->setFalloff(parseFalloff(top["falloff"]));
  if (top.has("objects")) {
    const JsonField objects = top["objects"];
    ObjectReader reader(file.parent_path());
    for (std::size_t i = 0; i < objects.size(); ++i) reader.add(objects[i], *scene.root);
  }
  return scene;
}

}  // namespace

Scene loadSceneFile(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw std::runtime_error(path + ": no such file");
  if (!fs::is_regular_file(path, ec)) throw std::runtime_error(path + ": not a regular file");
  noteInputFile(path);
  if (const auto size = fs::file_size(path, ec); !ec && size > (std::uintmax_t(64) << 20))
    throw std::runtime_error(path + ": larger than 64 MiB, too large for a scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  const json doc = parseStrict(text.str(), path);
  return parseScene(JsonField(doc, path), fs::path(path));
}

}  // namespace aokit
