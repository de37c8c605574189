// aokit bake: an occluder's AO field (cube map, 6- or 4-term grid) and its self-occlusion -> field file.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "Commands.h"
#include "core/Progress.h"
#include "fields/FieldBaker.h"
#include "fields/FieldFile.h"
#include "fields/FieldResolution.h"
#include "io/MeshIO.h"
#include "reference/Falloff.h"

namespace aokit::cli {

namespace {
struct BakeArgs {
  std::string mesh;
  std::string kind = "cube";
  std::string resolution = "auto";
  double radius = 0.0;
  std::string falloff = "binary";
  std::string output;
  int threads = 0;
  bool noSelfOcclusion = false;
};

int parseResolution(const std::string& text, FieldKind kind) {
  const int maxRes = maxFieldResolution(kind);
  const std::string rule = "--resolution must be auto or an integer in 2.." + std::to_string(maxRes);
  if (text == "auto") return 0;
  std::size_t used = 0;
  int n = 0;
  try {
    n = std::stoi(text, &used);
  } catch (const std::exception&) {
    throw std::invalid_argument(rule + ", got '" + text + "'");
  }
  if (used != text.size() || n < 2 || n > maxRes) throw std::invalid_argument(rule + ", got '" + text + "'");
  return n;
}

// Fails before a long bake rather than after it.
void checkWritable(const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path parent = fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path();
  if (!fs::is_directory(parent)) throw std::runtime_error(path + ": folder " + parent.string() + " does not exist");
  if (access(parent.c_str(), W_OK) != 0) throw std::runtime_error(path + ": folder " + parent.string() + " is not writable");
  if (fs::is_directory(path)) throw std::runtime_error(path + ": is a folder");
}

void runBake(const BakeArgs& a) {
  FieldBakeSettings s;
  s.kind = parseFieldKind(a.kind);
  s.resolution = parseResolution(a.resolution, s.kind);
  s.threads = a.threads;
  s.selfOcclusion = !a.noSelfOcclusion;
  const Falloff falloff = parseFalloff(a.falloff);
  if (!std::isfinite(a.radius) || a.radius < 0.0)
    throw std::invalid_argument("--radius must be positive (or left out for a tenth of the mesh's diagonal)");
  validate(s);
  checkWritable(a.output);

  const TriangleMesh mesh = loadMesh(a.mesh);
  // Default R as for a lone mesh given to `aokit render`: a tenth of its bounding-box diagonal.
  const double radius = a.radius > 0.0 ? a.radius : 0.1 * mesh.bounds().diagonal();
  if (!(radius > 0.0)) throw std::invalid_argument(a.mesh + ": the mesh has no extent, give --radius");
  const int resolution = resolveFieldResolution(s, mesh, radius);
  Progress progress("bake " + fieldKindName(s.kind) + " " + std::to_string(resolution));
  const BakedField field = bakeField(mesh, s, radius, falloff, progress.reporter());
  progress.done();
  throwIfInterrupted();
  writeFieldFile(a.output, field);
  std::printf("%s: %s field, resolution %d%s, of %s (%zu triangles), R %g %s: %zu bytes of field%s, baked in %.2f s\n",
              a.output.c_str(), fieldKindName(s.kind).c_str(), resolution, s.resolution == 0 ? " (auto)" : "",
              a.mesh.c_str(), mesh.triangles.size(), radius, falloffName(falloff).c_str(),
              fieldMemoryBytes(s.kind, resolution),
              field.vertexOcclusion.empty()
                  ? ""
                  : (" + " + std::to_string(field.vertexOcclusion.size() * sizeof(float)) + " of self-occlusion").c_str(),
              field.info.bakeSeconds);
}
}  // namespace

void addBakeCommand(CLI::App& app) {
  auto args = std::make_shared<BakeArgs>();
  CLI::App* cmd = app.add_subcommand("bake", "bake an occluder's AO field (seed 000 cube map or seed 002 grid) to a file");
  cmd->add_option("--mesh", args->mesh, "occluder mesh (OFF, OBJ, PLY, STL, VTP, VTU, VTK)")->required();
  cmd->add_option("--kind", args->kind, "cube (radial cube map), grid6 or grid4 (3D grids)")->capture_default_str();
  cmd->add_option("--resolution", args->resolution, "texels per cube face or grid points per axis (2..128), or auto")
      ->capture_default_str();
  cmd->add_option("--radius", args->radius, "AO radius R in mesh units (default: a tenth of the mesh's diagonal)");
  cmd->add_option("--falloff", args->falloff, "binary, wendland, sqrt, exponential")->capture_default_str();
  cmd->add_option("--threads", args->threads, "bake threads (0 = all cores)")->check(CLI::Range(0, 1024));
  cmd->add_flag("--no-self-occlusion", args->noSelfOcclusion, "skip the per-vertex self-occlusion");
  cmd->add_option("--output,-o", args->output, "field file to write")->required();
  cmd->callback([args] { runBake(*args); });
}

}  // namespace aokit::cli
