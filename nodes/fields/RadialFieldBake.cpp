#include "fields/RadialFieldBake.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "fields/CubeMapLayout.h"
#include "fields/HorizonLimit.h"
#include "fields/HullRadius.h"
#include "fields/OcclusionProbe.h"
#include "fields/RadialFieldEval.h"
#include "fields/RadialFit.h"
#include "fields/SphereDirections.h"
#include "fields/SphericalCaps.h"
#include "reference/EmbreeScene.h"
#include "reference/HemisphereSampler.h"
#include "reference/ParallelRows.h"

namespace aokit {

namespace {

// The supersampled directions of one face: hi-res texel k of `side` sits at face coordinate
// -1 + (k - margin + 0.5) * spacing; `margin` texels reach beyond each face edge.
struct HiResGrid {
  int factor, margin, side;
  double spacing;
  HiResGrid(int n, int supersampling)
      : factor(supersampling), margin(supersampling == 2 ? 3 : 1), side(supersampling * n + 2 * margin),
        spacing(2.0 / (supersampling * n)) {}
  double coordinate(int k) const { return -1.0 + (k - margin + 0.5) * spacing; }
};

struct HiResSamples {
  std::vector<float> r0;          // per direction
  std::vector<glm::dvec3> dir;    // per direction (unit)
  std::vector<float> r, omega;    // per direction x radius
  std::vector<glm::vec3> upsilon;
};

// Taps of a stored texel along one axis: hi-res indices and Gaussian weights (sigma = half a texel).
struct Taps {
  int index[4];
  double weight[4];
  int count;
};
Taps texelTaps(int i, const HiResGrid& g) {
  Taps t{};
  if (g.factor == 1) {
    t.count = 1;
    t.index[0] = i - 1 + g.margin;
    t.weight[0] = 1.0;
    return t;
  }
  t.count = 4;
  for (int k = 0; k < 4; ++k) {
    t.index[k] = 2 * i - 3 + k + g.margin;     // hi-res centres at -1.5 .. 1.5 hi-res texels from the texel's
    const double offset = k - 1.5;             // sigma = 1 hi-res texel = half a stored texel
    t.weight[k] = std::exp(-0.5 * offset * offset);
  }
  return t;
}

// (dA/dOmega)^2 of a cap facing the normal, A = sin^2(alpha): proportional to cos^2(alpha) with
// cos(alpha) = 1 - Omega / 2 pi. Near Omega = 2 pi (next to a flat face) the occlusion hardly depends
// on Omega, so those many near-hull samples should not dictate the fit. Floored at 0.1 so that
// every sample still counts.
double occlusionSensitivity(double omega) {
  const double c = 1.0 - omega / (2.0 * kPi);
  return std::max(0.1, c * c);
}


// Far-fade candidates (fractions of R beyond the hull): a window ending about R past the hull
// suits compact occluders (a box's shadow ends R below its face), one ending at the cull radius
// suits flat or elongated ones (a plane's shadow reaches R / sin(elevation) along a direction).
constexpr double kFadeCandidates[][2] = {{0.5, 1.5}, {0.7, 1.2}, {1.5, 2.5}, {3.75, 4.0}};

struct TexelFit {
  SolidAngleModel model;
  glm::dvec3 c0{0.0};
  double r0 = 0.0;
  double residual = 0.0;  // the solid-angle fit's weighted squared residual
};

// Fits one stored texel (row = face * (N + 2) + j, column i) to the pooled samples of its taps.
struct TexelFitter {
  const RadialField& field;
  const HiResGrid& grid;
  const HiResSamples& hi;
  int radii;

  TexelFit fit(int row, int i, bool withDirection) const {
    const int side = field.layerSide(), face = row / side, j = row % side;
    const Taps tx = texelTaps(i, grid), ty = texelTaps(j, grid);
    auto tapIndex = [&](int a, int b) {
      return (static_cast<std::size_t>(face) * grid.side + ty.index[b]) * grid.side + tx.index[a];
    };
    TexelFit out;
    double sumW = 0.0, minR0 = field.rMax;
    for (int b = 0; b < ty.count; ++b)
      for (int a = 0; a < tx.count; ++a) {
        const double g = tx.weight[a] * ty.weight[b];
        sumW += g;
        out.r0 += g * hi.r0[tapIndex(a, b)];
        minR0 = std::min(minR0, static_cast<double>(hi.r0[tapIndex(a, b)]));
      }
    out.r0 /= sumW;
    std::vector<SolidAngleSample> omegaSamples;
    std::vector<DirectionSample> dirSamples;
    for (int b = 0; b < ty.count; ++b)
      for (int a = 0; a < tx.count; ++a) {
        const double g = tx.weight[a] * ty.weight[b];
        const std::size_t d = tapIndex(a, b);
        for (int q = 0; q < radii; ++q) {
          const std::size_t at = d * radii + q;
          const double r = hi.r[at], omega = hi.omega[at];
          omegaSamples.push_back({r, omega, field.fade(r, out.r0), g * occlusionSensitivity(omega)});
          if (withDirection && omega > 0.0) dirSamples.push_back({r * hi.dir[d], glm::dvec3(hi.upsilon[at]), g * omega});
        }
      }
    // Feasible (Omega <= 4 pi) from the smallest r0 around. Where the shader's interpolated r0 is
    // lower still, Omega may reach 4 pi, but continuously: the evaluator clamps 1/D to 4 pi and
    // counts D <= 0 as 4 pi. Demanding more (down to 0.8 r0) doubled the sphere's error.
    out.model = fitSolidAngle(omegaSamples, minR0, field.rMax);
    for (const auto& x : omegaSamples) {
      const double e = x.omega - x.fade / out.model.denominator(x.r);
      out.residual += x.weight * e * e;
    }
    if (withDirection) {
      const glm::dvec3 w = glm::normalize(
          faceDirection(face, borderedTexelCentre(i, field.resolution), borderedTexelCentre(j, field.resolution)));
      out.c0 = fitDirectionCentre(dirSamples, glm::dvec3(0.0));
      const double along = glm::dot(out.c0, w), limit = 0.9 * out.r0;
      if (along > limit) out.c0 -= (along - limit) * w;
    }
    return out;
  }
};

}  // namespace

RadialField bakeRadialField(const BakeMesh& input, const FieldBakeSettings& s, double radius, Falloff falloff,
                            const std::function<void(double)>& progress) {
  const TriangleMesh& mesh = input.mesh();
  validate(s);
  if (s.resolution < 1) throw std::invalid_argument("radial field bake: resolution must be resolved (> 0)");
  if (!(radius > 0.0) || !std::isfinite(radius)) throw std::invalid_argument("radial field bake: radius must be positive");
  const int n = s.resolution;
  RadialField field;
  field.resolution = n;
  field.centre = surfaceCentroid(mesh);
  const HullRadius hull(mesh, field.centre, 4096, s.threads);
  field.boundingRadius = hull.boundingRadius();
  field.rMax = field.boundingRadius + radius;

  // Measure Omega and Upsilon along every supersampled direction.
  const EmbreeScene& scene = input.scene();
  const HiResGrid grid(n, s.supersampling);
  const int k = s.radialSamples;
  const std::size_t dirs = 6u * grid.side * grid.side;
  HiResSamples hi{std::vector<float>(dirs), std::vector<glm::dvec3>(dirs), std::vector<float>(dirs * k),
                  std::vector<float>(dirs * k), std::vector<glm::vec3>(dirs * k)};
  const std::vector<glm::dvec3> sphere = fibonacciSphere(s.raysPerSample);
  const double deltaMin = 0.01 * radius;
  const auto rayProgress = [&](double f) {
    if (progress) progress(0.9 * f);
  };
  parallelRows(
      6 * grid.side, s.threads,
      [&](int row) {
        OcclusionProbe probe(scene, radius, falloff, sphere);
        const int face = row / grid.side, l = row % grid.side;
        for (int kx = 0; kx < grid.side; ++kx) {
          const std::size_t d = (static_cast<std::size_t>(face) * grid.side + l) * grid.side + kx;
          const glm::dvec3 w = glm::normalize(faceDirection(face, grid.coordinate(kx), grid.coordinate(l)));
          const double r0 = hull(w);
          hi.dir[d] = w;
          hi.r0[d] = static_cast<float>(r0);
          const double deltaMax = std::max(field.rMax - r0, 2.0 * deltaMin);
          for (int j = 0; j < k; ++j) {
            const double r = r0 + deltaMin * std::pow(deltaMax / deltaMin, static_cast<double>(j) / (k - 1));
            probe.trace(field.centre + r * w, randomRotation(mix64(s.seed) ^ (d * 64 + j) * 0x9e3779b97f4a7c15ull));
            double sum = 0.0;
            glm::dvec3 moment(0.0);
            for (int q = 0; q < probe.size(); ++q) {
              sum += probe.weight(q);
              moment += probe.weight(q) * probe.direction(q);
            }
            const std::size_t at = d * k + j;
            hi.r[at] = static_cast<float>(r);
            hi.omega[at] = static_cast<float>(kFourPi / probe.size() * sum);
            const double len = glm::length(moment);
            hi.upsilon[at] = len > 0.0 ? glm::vec3(moment / len) : glm::vec3(0.0f);
          }
        }
      },
      rayProgress);
  scene.throwIfError("radial field bake");

  // Fit every stored texel to the Gaussian-weighted samples around it, with the far fade given or,
  // by default, the candidate whose fits leave the smallest residual on a third of the texels.
  const TexelFitter fitter{field, grid, hi, k};
  if (s.farDistance > 0.0) {
    field.fadeStart = s.nearDistance * radius;
    field.fadeEnd = s.farDistance * radius;
  } else {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& c : kFadeCandidates) {
      RadialField trial = field;
      trial.fadeStart = c[0] * radius;
      trial.fadeEnd = c[1] * radius;
      const TexelFitter f{trial, grid, hi, k};
      std::vector<double> rowResidual(6 * field.layerSide(), 0.0);
      parallelRows(6 * field.layerSide(), s.threads, [&](int row) {
        for (int i = row % 3; i < field.layerSide(); i += 3) rowResidual[row] += f.fit(row, i, false).residual;
      });
      double total = 0.0;
      for (double r : rowResidual) total += r;
      if (total < best) {
        best = total;
        field.fadeStart = trial.fadeStart;
        field.fadeEnd = trial.fadeEnd;
      }
    }
  }
  const int side = field.layerSide();
  field.occlusion.assign(field.texelCount() * 4, 0.0f);
  field.centroid.assign(field.texelCount() * 3, 0.0f);
  parallelRows(
      6 * side, s.threads,
      [&](int row) {
        for (int i = 0; i < side; ++i) {
          const TexelFit t = fitter.fit(row, i, true);
          const std::size_t at = static_cast<std::size_t>(row) * side + i;  // row = face * side + j
          field.occlusion[at * 4 + 0] = static_cast<float>(t.model.a);
          field.occlusion[at * 4 + 1] = static_cast<float>(t.model.b);
          field.occlusion[at * 4 + 2] = static_cast<float>(t.model.c);
          field.occlusion[at * 4 + 3] = static_cast<float>(t.r0);
          for (int c = 0; c < 3; ++c) field.centroid[at * 3 + c] = static_cast<float>(t.c0[c]);
        }
      },
      [&](double f) {
        if (progress) progress(0.9 + 0.1 * f);
      });
  updateHullBox(field, mesh);
  return field;
}

}  // namespace aokit
