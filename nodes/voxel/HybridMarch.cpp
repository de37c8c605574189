#include "voxel/HybridMarch.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/Finite.h"
#include "reference/ParallelRows.h"
#include "voxel/ColumnWalk.h"
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
  c.walkColumns = columnWalkBound(R / frame.voxelSize);
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
  if (!allFinite(p) || !allFinite(n)) return 0.0f;
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
    float hitDist = 0.0f;
    bool hit = false;
    if (c.segmentWalk()) {
      // Ray and Graze: from the first of the ray's step distances where it is the offset above the
      // tangent plane (as the steps: from exactly there, the surface's own voxels in the next
      // column stop the ray).
      const float below = fromSurface ? c.normalOffset - lift : 0.0f;
      const float above = below <= 0.0f ? 0.0f : local.z > 0.0f ? below / local.z : 2.0f * c.radius;
      const float t0 = above <= 0.0f ? 0.0f : (std::ceil(above / stepLength - offset) + offset) * stepLength;
      float tHit = 0.0f;
      hit = t0 <= c.radius && columnWalk(grid, rayOrigin, dir, t0, c.radius, c.walkColumns, tHit);
      // Half a voxel past the set voxel's face: a dominant-axis voxel stands for a surface
      // through its middle, on average.
      hitDist = tHit + 0.5f / glm::length(dir);
    } else {
      // The first step tested spans its own voxel only: a span from the origin's height in the
      // step's column meets the surface's own voxels beside the origin (false occlusion on open
      // surfaces: isosurface 0.0129 -> 0.0113 against a 1024-ray reference, res 256).
      bool started = false;
      glm::vec3 previous(0.0f);
      for (int j = 0; j < c.steps && !hit; ++j) {
        const float dist = (static_cast<float>(j) + offset) * stepLength;
        if (fromSurface && lift + dist * local.z < c.normalOffset) continue;  // within the surface's own voxels
        const glm::vec3 g = glm::clamp(rayOrigin + dist * dir, lo, hi);
        if (!started) previous = g;
        started = true;
        const glm::ivec3 v(glm::floor(g));
        const int previousK = static_cast<int>(std::floor(previous.z));
        hit = c.spanTest ? grid.anyInRun(v.x, v.y, std::min(previousK, v.z), std::max(previousK, v.z))
                         : grid.get(v.x, v.y, v.z);
        hitDist = dist;
        previous = g;
      }
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
