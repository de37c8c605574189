#pragma once
// The Hybrid AO estimator on the CPU, step for step as the GPU march shader: the oracle for
// GPU-vs-CPU tests and the tool that charts convergence to the reference (HybridSampling.h has the
// formulas). Step j of a ray reaches g_j = M (origin + t_j dir) (M the float world-to-grid
// matrix, g_-1 = M origin; each g clamped to [-1, dims] before floor, so the int conversion is
// defined) and tests column (floor g_j.x, floor g_j.y): with the span test every voxel k in
// [min, max] of (floor g_{j-1}.z, floor g_j.z), clamped to the grid, else only k = floor g_j.z.
// The segment test has no steps: the ray M (origin + t dir), t in [0, R], column by column
// (ColumnWalk.h), its hit half a voxel past the first set voxel's face (README.md, March).
// Outside the grid reads as empty. An origin in a set voxel (a crease) first steps to an empty face
// neighbour along the normal (README.md, March). A non-finite point or normal gives 0.
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "core/AOScene.h"
#include "core/Camera.h"
#include "reference/SurfaceSamples.h"
#include "render/FrameContext.h"
#include "voxel/HybridSettings.h"
#include "voxel/VoxelFrame.h"
#include "voxel/VoxelGrid.h"

namespace aokit {

// What the march shader gets: shape as #defines, values as uniforms.
// Made by makeHybridMarchConstants (the settings hold the defaults).
struct HybridMarchConstants {
  int rays = 0;                       // #define HAO_RAYS
  int steps = 0;                      // uniform haoSteps (marchSteps: the grid can raise it)
  int walkColumns = 0;                // uniform haoWalkColumns: the segment test's iteration bound
  Falloff falloff = Falloff::Binary;  // #define HAO_FALLOFF (0 binary, 1 wendland, 2 sqrt, 3 exponential)
  bool spanTest = true;               // #define HAO_SPAN_TEST 1
  bool segmentTest = false;           // with spanTest: #define HAO_SPAN_TEST 2
  int lift = 0;                       // #define HAO_LIFT (RayLift: 0 normal, 1 ray, 2 graze)
  bool staticDynamic = false;         // #define HAO_STATIC (GPU: a second, static grid; StaticDynamic.h)
  float radius = 1.0f;                // world units
  float cosMax = 0.0f;                // cos of the cone half-angle: cos(spread * 90 deg), >= 0
  float normalOffset = 0.0f;          // world units
  float reach = 1.0f;                 // uniform haoReach (RayLift::Graze)
  float invJitterCell = 1.0f;         // 1 / world units
  std::uint32_t jitterSeed = 0;
  glm::mat4 worldToGrid{1.0f};
  glm::ivec3 dims{1};
  // The camera, for a crease's way out (leaveSetVoxel): the shader has it from the G-buffer.
  // viewerKnown false (constants made without a camera): ties between neighbours go by axis order.
  bool viewerKnown = false;
  bool viewerParallel = false;
  glm::vec3 eye{0.0f};            // perspective: world position of the eye
  glm::vec3 towardEye{0.0f};      // parallel: unit world direction toward the viewer

  // The segment test runs only with the span test (HAO_SPAN_TEST 2).
  bool segmentWalk() const { return spanTest && segmentTest; }
  std::string defines() const;
};

// Steps per ray: the setting's, or more where one step would cross more than `stride` voxels.
int marchSteps(const HybridSettings& s, double radius, double voxelSize);

// The fields that are #defines (the shader's shape), from the settings alone: the pass compiles
// its shader from them before the frame's grid exists.
HybridMarchConstants hybridMarchShape(const HybridSettings& s, Falloff falloff);

// Validates the settings, then resolves them against the frame's context (radius, falloff:
// render/FrameContext.h) and the grid's frame (offset and jitter cell are in voxels). Throws
// std::invalid_argument on bad settings or a radius that is not positive.
HybridMarchConstants makeHybridMarchConstants(const HybridSettings& s, const FrameContext& context,
                                              const VoxelFrame& frame);

// The camera's side of the surface point p (unit world vector; 0 without viewerKnown).
glm::vec3 towardViewer(const HybridMarchConstants& c, const glm::vec3& p);
void setViewer(HybridMarchConstants& c, const Camera& camera);

// A(p, n) of one surface point (n unit length), in [0, 1].
float marchHybridAO(const VoxelGrid& grid, const HybridMarchConstants& c, const glm::vec3& p, const glm::vec3& n);

// Every covered pixel (uncovered ones, and zero or non-finite normals, come back uncovered). Rows
// run on `threads` workers (0 = all cores); results do not depend on the thread count.
AOBuffer marchHybridAO(const VoxelGrid& grid, const HybridMarchConstants& c, const SurfaceSamples& samples,
                       int threads = 0);

}  // namespace aokit
