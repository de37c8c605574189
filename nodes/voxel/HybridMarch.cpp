#include "voxel/HybridMarch.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "reference/ParallelRows.h"
#include "voxel/HybridSampling.h"
#include "voxel/StaticDynamic.h"

namespace aokit {

std::string HybridMarchConstants::defines() const {
  std::ostringstream d;
  d << "#define HAO_RAYS " << rays << "\n"
    << "#define HAO_FALLOFF " << static_cast<int>(falloff) << "\n"
    << "#define HAO_SPAN_TEST " << (segmentWalk() ? 2 : spanTest ? 1 : 0) << "\n"
    << "#define HAO_LIFT " << lift << "\n"
    << "#define HAO_STATIC " << int(staticDynamic) << "\n"
    << "#define HAO_MAX_ZONES " << kMaxDynamicZones << "\n";
  return d.str();
}

int marchSteps(const HybridSettings& s, double radius, double voxelSize) {
  if (!(s.stride > 0.0)) return s.steps;
  const double needed = std::ceil(radius / voxelSize / s.stride);
  return static_cast<int>(std::clamp(needed, static_cast<double>(s.steps), 256.0));
}

HybridMarchConstants hybridMarchShape(const HybridSettings& s, Falloff falloff) {
  HybridMarchConstants c;
  c.rays = s.rays;
  c.falloff = falloff;
  c.spanTest = s.spanTest;
  c.segmentTest = s.segmentTest;
  c.lift = static_cast<int>(s.lift);
  c.staticDynamic = s.staticBake;
  return c;
}

HybridMarchConstants makeHybridMarchConstants(const HybridSettings& s, const FrameContext& context,
                                              const VoxelFrame& frame) {
  validate(s);
  const double R = context.radius;
  if (!std::isfinite(R) || !(R > 0.0))
    throw std::invalid_argument("hybrid: radius must be positive: set it or give the scene an AO radius");
  if (!(frame.voxelSize > 0.0) || !std::isfinite(frame.voxelSize))
    throw std::invalid_argument("hybrid: the voxel frame has no positive voxel size");
  HybridMarchConstants c = hybridMarchShape(s, context.falloff);
  c.steps = marchSteps(s, R, frame.voxelSize);
  c.radius = static_cast<float>(R);
  c.cosMax = static_cast<float>(std::max(0.0, std::cos(s.spread * 1.5707963267948966)));
  if (s.spread >= 1.0) c.cosMax = 0.0f;
  c.normalOffset = static_cast<float>(s.normalOffset * frame.voxelSize);
  c.reach = static_cast<float>(s.reach);
  c.invJitterCell = static_cast<float>(1.0 / (s.jitterCell * frame.voxelSize));
  c.jitterSeed = s.jitterSeed;
  c.worldToGrid = frame.worldToGridMatrix();
  c.dims = frame.dims;
  return c;
}

namespace {
// floor(g) per axis, clamped to [-1, dims] first: outside stays outside, and no float beyond the
// int range is converted (undefined in C++ and in GLSL alike).
glm::ivec3 voxelOf(const glm::vec3& g, const glm::ivec3& dims) {
  const glm::vec3 lo(-1.0f), hi(dims);
  return glm::ivec3(glm::floor(glm::clamp(g, lo, hi)));
}
// A ray origin in a set voxel (after the normal offset: a point within a voxel of another surface,
// in a crease) moves one voxel to the face neighbour that is empty, not behind the surface
// (n_g . e > -0.25), and most along n_g + kViewerPull v_g (v_g toward the viewer). Marching from
// inside would stop every ray at once (AO near 1 where the reference has about 0.5); the neighbour
// sees the other surface from outside. The viewer's side decides between neighbours the normal
// cannot tell apart (beside a wall, both sides are along 0): the point is seen, so the other
// surface is not between it and the eye, while the neighbour behind a single-sided sheet is on its
// far side (a box's inside corner read through the wall: 0.65 for 0.93). No such neighbour: stays.
constexpr float kViewerPull = 0.5f;
glm::vec3 leaveSetVoxel(const VoxelGrid& grid, const glm::vec3& origin, const glm::vec3& nGrid, const glm::vec3& vGrid,
                        const glm::ivec3& dims) {
  const glm::ivec3 o = voxelOf(origin, dims);
  if (!grid.anyInRun(o.x, o.y, o.z, o.z)) return origin;
  glm::vec3 best(0.0f);
  float bestScore = -1e30f;
  for (int a = 0; a < 6; ++a) {
    glm::vec3 d(0.0f);
    d[a >> 1] = (a & 1) == 0 ? 1.0f : -1.0f;
    const float along = glm::dot(nGrid, d);
    const float score = along + kViewerPull * glm::dot(vGrid, d);
    const glm::ivec3 v = o + glm::ivec3(d);
    if (along > -0.25f && score > bestScore && !grid.anyInRun(v.x, v.y, v.z, v.z)) {
      bestScore = score;
      best = d;
    }
  }
  return origin + best;
}
// The segment test: the voxels of each step's segment a -> b (grid units, clamped as voxelOf) in
// each column it passes, a's, the one between where it crosses both an x and a y boundary, b's,
// each over the part of its depth in that column. The span test looks in b's column alone over the
// whole depth: a step to the diagonal column passes between two voxels of a sheet touching only at
// an edge (a dominant-axis sheet is one voxel per column), and a's column above a.z goes unseen.
// The part in b's column is tested with the next step's run of that column (one fetch a step, a
// second only where it crosses both boundaries), the last step's after the loop. A hit counts at
// the distance where its run ends (the ray leaves the column, or the step ends): past the set
// voxel, as the span test's end of the step, which offsets the voxels' fattening of surfaces.
// Exact where a step spans at most one voxel per axis (stride <= 1); longer steps test these
// columns only.
struct SegmentWalk {
  float entry = 0.0f;    // z where the segment entered its current column; below it all is tested
  bool pending = false;  // a part of the current column from `entry` on is not tested yet

  static bool run(const VoxelGrid& grid, int i, int j, float za, float zb) {
    return grid.anyInRun(i, j, static_cast<int>(std::floor(std::min(za, zb))),
                         static_cast<int>(std::floor(std::max(za, zb))));
  }
  void start(const glm::vec3& a) {
    entry = a.z;
    pending = false;
  }
  // a at distance da, b at db; a hit sets hitDist.
  bool step(const VoxelGrid& grid, const glm::vec3& a, const glm::vec3& b, float da, float db, float& hitDist) {
    const glm::ivec2 ca(glm::floor(glm::vec2(a))), cb(glm::floor(glm::vec2(b)));
    // Where the step crosses an x and a y boundary (1: it does not); within one column a's run is
    // the whole step's.
    const float tx = ca.x != cb.x ? (static_cast<float>(std::max(ca.x, cb.x)) - a.x) / (b.x - a.x) : 1.0f;
    const float ty = ca.y != cb.y ? (static_cast<float>(std::max(ca.y, cb.y)) - a.y) / (b.y - a.y) : 1.0f;
    const float t1 = std::min(tx, ty), t2 = std::max(tx, ty);
    const float z1 = a.z + t1 * (b.z - a.z), z2 = a.z + t2 * (b.z - a.z);
    hitDist = da + t1 * (db - da);
    if (run(grid, ca.x, ca.y, entry, z1)) return true;
    hitDist = da + t2 * (db - da);
    if (t2 < 1.0f && run(grid, tx < ty ? cb.x : ca.x, tx < ty ? ca.y : cb.y, z1, z2)) return true;
    entry = t2 < 1.0f ? z2 : z1;
    pending = t1 < 1.0f;
    return false;
  }
  // The last step's part in its end column b's.
  bool finish(const VoxelGrid& grid, const glm::vec3& b) const {
    return pending && run(grid, static_cast<int>(std::floor(b.x)), static_cast<int>(std::floor(b.y)), entry, b.z);
  }
};
bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

glm::vec3 towardViewer(const HybridMarchConstants& c, const glm::vec3& p) {
  if (!c.viewerKnown) return glm::vec3(0.0f);
  if (c.viewerParallel) return c.towardEye;
  const glm::vec3 d = c.eye - p;
  const float len = glm::length(d);
  return len > 0.0f ? d / len : glm::vec3(0.0f);
}

void setViewer(HybridMarchConstants& c, const Camera& camera) {
  c.viewerKnown = true;
  c.viewerParallel = camera.parallel;
  c.eye = glm::vec3(camera.position);
  const glm::dvec3 back = camera.position - camera.focalPoint;
  c.towardEye = glm::length(back) > 0.0 ? glm::vec3(glm::normalize(back)) : glm::vec3(0.0f, 0.0f, 1.0f);
}

float marchHybridAO(const VoxelGrid& grid, const HybridMarchConstants& c, const glm::vec3& p, const glm::vec3& n) {
  if (!finite(p) || !finite(n)) return 0.0f;
  const glm::vec3 jitter = hybridJitter(hybridJitterKey(p, n, c.invJitterCell, c.jitterSeed));
  glm::vec3 t, b;
  hybridBasis(n, t, b);
  // In grid space: origin and directions go through the matrix once, steps are then additions.
  const glm::mat3 m3(c.worldToGrid);
  const glm::vec3 surface(c.worldToGrid * glm::vec4(p, 1.0f));
  const glm::vec3 nGrid = m3 * n;  // grid units per world unit along the normal
  const glm::vec3 lifted(c.worldToGrid * glm::vec4(p + c.normalOffset * n, 1.0f));
  const glm::ivec3 liftedVoxel = voxelOf(lifted, c.dims);
  // Ray and Graze start on the surface, except in a crease (the lifted point's voxel set: another
  // surface within the offset, which their skipped steps would miss): there as Normal.
  const bool fromSurface = c.lift != 0 && !grid.anyInRun(liftedVoxel.x, liftedVoxel.y, liftedVoxel.z, liftedVoxel.z);
  const glm::vec3 toViewer = towardViewer(c, p);
  const glm::vec3 vGrid = c.viewerKnown ? glm::normalize(m3 * toViewer) : glm::vec3(0.0f);
  const glm::vec3 origin =
      fromSurface ? surface : leaveSetVoxel(grid, lifted, glm::normalize(nGrid), vGrid, c.dims);
  const float stepLength = c.radius / static_cast<float>(c.steps);
  const glm::vec3 lo(-1.0f), hi(c.dims);  // as voxelOf: outside stays outside
  float sum = 0.0f, weights = 0.0f;
  for (int i = 0; i < c.rays; ++i) {
    const glm::vec3 local = hybridRayLocal(i, c.rays, c.cosMax, glm::vec2(jitter.x, jitter.y));
    const glm::vec3 dir = m3 * (local.x * t + local.y * b + local.z * n);
    const float offset = hybridStepOffset(i, jitter.z);
    float k = 0.0f;
    // Ray and Graze: this ray's lift along the normal (world units), then steps below the offset skipped.
    const float lift = fromSurface && c.lift == 2 ? c.normalOffset * std::max(0.0f, 1.0f - c.reach * local.z) : 0.0f;
    const glm::vec3 rayOrigin = origin + lift * nGrid;
    // Ray and Graze: no step tested yet, and the first one tested spans its own voxel only.
    bool started = !fromSurface;
    glm::vec3 previous = glm::clamp(origin, lo, hi);
    const bool segment = c.segmentWalk();
    SegmentWalk walk;
    walk.start(previous);
    float lastDist = 0.0f, hitDist = 0.0f;
    bool hit = false;
    for (int j = 0; j < c.steps && !hit; ++j) {
      const float dist = (static_cast<float>(j) + offset) * stepLength;
      if (fromSurface && lift + dist * local.z < c.normalOffset) continue;  // within the surface's own voxels
      const glm::vec3 g = glm::clamp(rayOrigin + dist * dir, lo, hi);
      if (!started) {
        previous = g;
        lastDist = dist;
        walk.start(g);
      }
      started = true;
      const glm::ivec3 v(glm::floor(g));
      const int previousK = static_cast<int>(std::floor(previous.z));
      hit = segment      ? walk.step(grid, previous, g, lastDist, dist, hitDist)
            : c.spanTest ? grid.anyInRun(v.x, v.y, std::min(previousK, v.z), std::max(previousK, v.z))
                         : grid.get(v.x, v.y, v.z);
      if (!segment) hitDist = dist;
      lastDist = dist;
      previous = g;
    }
    if (!hit && segment) {
      hit = walk.finish(grid, previous);
      hitDist = lastDist;
    }
    if (hit) {
      // The falloff's distance is the hit's from the surface point, not from the lifted origin
      // (the reference's rays start on the surface): grid units over |dir| (1 / voxel size).
      const float hitDistance = glm::length(rayOrigin + hitDist * dir - surface) / glm::length(dir);
      k = hybridFalloff(c.falloff, hitDistance, c.radius);
    }
    sum += k * local.z;
    weights += local.z;
  }
  return weights > 0.0f ? sum / weights : 0.0f;
}

AOBuffer marchHybridAO(const VoxelGrid& grid, const HybridMarchConstants& c, const SurfaceSamples& samples,
                       int threads) {
  samples.validate();
  AOBuffer out;
  out.resize(samples.width, samples.height);
  parallelRows(samples.height, threads, [&](int y) {
    for (int x = 0; x < samples.width; ++x) {
      const std::size_t i = samples.index(x, y);
      if (!samples.covered[i]) continue;
      const glm::vec3 n = samples.normal[i];
      const float len = glm::length(n);
      if (!(len > 0.0f) || !std::isfinite(len)) continue;
      const glm::vec3 p = samples.position[i];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
      out.ao[i] = marchHybridAO(grid, c, p, n / len);
      out.covered[i] = 1;
    }
  });
  return out;
}

}  // namespace aokit
