#include "voxel/VertexAOBake.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "reference/AOReference.h"
#include "reference/HemisphereSampler.h"
#include "reference/ParallelRows.h"
#include "reference/SurfaceRay.h"
#include "voxel/VertexAOFit.h"

namespace aokit {

namespace {

// Points laid out in rows of 256, so that the reference's row-parallel loop spreads them over threads.
SurfaceSamples pointRows(std::size_t n) {
  const int width = static_cast<int>(std::max<std::size_t>(1, std::min<std::size_t>(n, 256)));
  SurfaceSamples s;
  s.resize(width, static_cast<int>((n + width - 1) / width));
  return s;
}

ReferenceOptions referenceOptions(const VertexBakeOptions& o) {
  ReferenceOptions r;
  r.samples = o.samples;
  r.radius = o.radius;
  r.falloff = o.falloff;
  r.seed = o.seed;
  r.threads = o.threads;
  r.hemisphere = Hemisphere::Shading;  // a vertex has no one facet: its own normal's hemisphere
  return r;
}

// A surface point of a triangle: its corners and barycentric weights, world position and normal.
struct FitPoint {
  std::size_t triangle;
  glm::vec3 bary;
  float weight;
};

// Centres of the k^2 equal sub-triangles of a triangle split k times per edge (barycentrics).
void subTriangleCentres(int k, std::vector<glm::vec3>& out) {
  out.clear();
  const float inv = 1.0f / k;
  for (int i = 0; i < k; ++i)
    for (int j = 0; i + j < k; ++j) {
      const float u = (i + 1.0f / 3.0f) * inv, v = (j + 1.0f / 3.0f) * inv;
      out.emplace_back(1.0f - u - v, u, v);
      if (i + j + 1 < k) {
        const float u2 = (i + 2.0f / 3.0f) * inv, v2 = (j + 2.0f / 3.0f) * inv;
        out.emplace_back(1.0f - u2 - v2, u2, v2);
      }
    }
}

std::vector<float> fitOverSurface(const EmbreeScene& occluders, const TriangleMesh& mesh,
                                  const std::vector<glm::vec3>& position, const std::vector<glm::vec3>& normal,
                                  const VertexBakeOptions& o) {
  const double spacing = o.spacing > 0.0 ? o.spacing : o.radius / 8.0;
  if (!std::isfinite(spacing)) throw std::invalid_argument("vertex bake: spacing must be positive and finite");
  std::vector<FitPoint> points;
  std::vector<glm::vec3> pattern;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const glm::uvec3& tri = mesh.triangles[t];
    const glm::dvec3 a(position[tri.x]), b(position[tri.y]), c(position[tri.z]);
    const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
    if (!(area > 0.0)) continue;
    const int k = static_cast<int>(std::clamp(std::ceil(longest / spacing), 1.0, 16.0));
    subTriangleCentres(k, pattern);
    for (const glm::vec3& w : pattern) points.push_back({t, w, static_cast<float>(area / (k * k))});
  }
  std::vector<float> out(position.size(), 0.0f);
  if (points.empty()) return out;

  SurfaceSamples s = pointRows(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::uvec3& tri = mesh.triangles[points[i].triangle];
    const glm::vec3& w = points[i].bary;
    s.position[i] = w.x * position[tri.x] + w.y * position[tri.y] + w.z * position[tri.z];
    const glm::vec3 n = w.x * normal[tri.x] + w.y * normal[tri.y] + w.z * normal[tri.z];
    const float len = glm::length(n);
    s.normal[i] = len > 0.0f ? n / len : glm::vec3(0.0f);
    s.covered[i] = len > 0.0f ? 1 : 0;
  }
  auto report = [&](double from, double span) {
    return [&o, from, span](double f) {
      if (o.progress) o.progress(from + span * f);
    };
  };
  ReferenceOptions r = referenceOptions(o);
  r.progress = report(0.0, 0.9);
  const AOBuffer ao = computeReferenceAO(occluders, s, r);

  // Points inside another caster, row by row (results depend on the point only).
  std::vector<std::uint8_t> inside(points.size(), 0);
  const int width = s.width;
  parallelRows(
      s.height, o.threads,
      [&](int row) {
        for (int x = 0; x < width; ++x) {
          const std::size_t i = static_cast<std::size_t>(row) * width + x;
          if (i < points.size() && s.covered[i])
            inside[i] = insideOccluder(occluders, s.position[i], s.normal[i], 16, o.seed ^ (i * 0x9e3779b97f4a7c15ull)) ? 1 : 0;
        }
      },
      report(0.9, 0.1));

  std::vector<VertexFitSample> fit;
  fit.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!ao.covered[i] || inside[i]) continue;
    fit.push_back({mesh.triangles[points[i].triangle], points[i].bary, ao.ao[i], points[i].weight});
  }
  const VertexFitResult values = fitVertexValues(position.size(), mesh.triangles, fit);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = std::clamp(values.values[i], 0.0f, 1.0f);
  return out;
}

}  // namespace

bool insideOccluder(const EmbreeScene& occluders, const glm::vec3& p, const glm::vec3& n, int rays, std::uint64_t key) {
  const SurfaceRay sr = makeSurfaceRay(occluders, p, n, 0.0f, Hemisphere::Shading);
  if (!sr.valid || rays < 1) return false;
  const HemisphereSampler sampler(rays);
  const PixelShift shift = HemisphereSampler::pixelShift(key, 0x5eedu);
  RTCIntersectContext ctx;
  int behind = 0;
  for (int j = 0; j < rays; ++j) {
    const glm::vec3 d = sr.toWorld(sampler.localDirection(j, shift));
    RTCRayHit rh = makeRayHit(sr.origin, d, 0.0f, std::numeric_limits<float>::infinity());
    rtcInitIntersectContext(&ctx);
    rtcIntersect1(occluders.scene(), &ctx, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
    const EmbreeScene::Instance& inst = occluders.instances()[rh.hit.geomID];
    const glm::uvec3& t = inst.mesh->triangles[rh.hit.primID];
    const glm::dvec3 a = glm::dvec3(inst.world * glm::dvec4(glm::dvec3(inst.mesh->positions[t.x]), 1.0));
    const glm::dvec3 b = glm::dvec3(inst.world * glm::dvec4(glm::dvec3(inst.mesh->positions[t.y]), 1.0));
    const glm::dvec3 c = glm::dvec3(inst.world * glm::dvec4(glm::dvec3(inst.mesh->positions[t.z]), 1.0));
    // A mirroring placement turns the winding: the outward side with it.
    const double handed = glm::determinant(glm::dmat3(inst.world)) < 0.0 ? -1.0 : 1.0;
    if (handed * glm::dot(glm::cross(b - a, c - a), glm::dvec3(d)) > 0.0) ++behind;
  }
  return 2 * behind > rays;
}

std::vector<float> bakeVertexAO(const EmbreeScene& occluders, const TriangleMesh& mesh, const glm::dmat4& world,
                                const VertexBakeOptions& o) {
  mesh.validate();
  std::vector<glm::vec3> normals = mesh.normals;
  if (normals.size() != mesh.positions.size()) {
    TriangleMesh copy = mesh;
    copy.computeNormals();
    normals = copy.normals;
  }
  const std::size_t n = mesh.positions.size();
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
  std::vector<glm::vec3> position(n), normal(n);
  for (std::size_t i = 0; i < n; ++i) {
    position[i] = glm::vec3(world * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0));
    const glm::dvec3 wn = normalMatrix * glm::dvec3(normals[i]);
    const double len = glm::length(wn);
    normal[i] = len > 0.0 && std::isfinite(len) ? glm::vec3(wn / len) : glm::vec3(0.0f);
  }
  if (o.mode == VertexBakeMode::SurfaceFit) {
    if (o.samples < 1) throw std::invalid_argument("vertex bake: samples must be at least 1");
    if (!(o.radius > 0.0) || !std::isfinite(o.radius)) throw std::invalid_argument("vertex bake: radius must be positive");
    return fitOverSurface(occluders, mesh, position, normal, o);
  }
  SurfaceSamples s = pointRows(n);
  for (std::size_t i = 0; i < n; ++i) {
    s.position[i] = position[i];
    s.normal[i] = normal[i];
    s.covered[i] = 1;
  }
  ReferenceOptions r = referenceOptions(o);
  r.progress = o.progress;
  const AOBuffer ao = computeReferenceAO(occluders, s, r);
  std::vector<float> out(n, 0.0f);
  for (std::size_t i = 0; i < n; ++i) out[i] = ao.covered[i] ? ao.ao[i] : 0.0f;
  return out;
}

float interpolateVertexAO(const TriangleMesh& mesh, const std::vector<float>& ao, std::size_t triangle, float u,
                          float v) {
  if (triangle >= mesh.triangles.size() || ao.size() != mesh.positions.size())
    throw std::invalid_argument("interpolateVertexAO: triangle or AO array out of range");
  const glm::uvec3& t = mesh.triangles[triangle];
  return (1.0f - u - v) * ao[t.x] + u * ao[t.y] + v * ao[t.z];
}

}  // namespace aokit
