#include "fields/FieldInstances.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <stdexcept>
#include <tuple>

#include "core/Geometry.h"
#include "fields/FieldAttachment.h"

namespace aokit {

bool isSimilarity(const glm::dmat4& m, double* scale) {
  const glm::dmat3 l(m);
  const glm::dmat3 g = glm::transpose(l) * l;
  const double s2 = (g[0][0] + g[1][1] + g[2][2]) / 3.0;
  if (!(s2 > 0.0) || !std::isfinite(s2)) return false;
  double worst = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) worst = std::max(worst, std::abs(g[i][j] - (i == j ? s2 : 0.0)));
  if (worst > 1e-6 * s2) return false;
  // Rounded to 9 digits, so that rotations (whose s differs from 1 in the last bits) share fields
  // and cache entries.
  if (scale) {
    char digits[32];
    std::snprintf(digits, sizeof digits, "%.9g", std::sqrt(s2));
    *scale = std::strtod(digits, nullptr);
  }
  return true;
}

glm::dvec3 principalExtents(const TriangleMesh& mesh) {
  if (mesh.positions.empty()) return glm::dvec3(0.0);
  glm::dvec3 mean(0.0);
  for (const glm::vec3& p : mesh.positions) mean += glm::dvec3(p);
  mean /= static_cast<double>(mesh.positions.size());
  glm::dmat3 c(0.0);
  for (const glm::vec3& p : mesh.positions) {
    const glm::dvec3 d = glm::dvec3(p) - mean;
    c += glm::outerProduct(d, d);
  }
  // Cyclic Jacobi rotations: v accumulates the eigenvectors (columns).
  glm::dmat3 v(1.0);
  for (int sweep = 0; sweep < 32; ++sweep) {
    const double off = c[1][0] * c[1][0] + c[2][0] * c[2][0] + c[2][1] * c[2][1];
    if (off <= 1e-30 * (c[0][0] * c[0][0] + c[1][1] * c[1][1] + c[2][2] * c[2][2]) || off == 0.0) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (c[q][p] == 0.0) continue;
        const double theta = 0.5 * std::atan2(2.0 * c[q][p], c[q][q] - c[p][p]);
        const double cs = std::cos(theta), sn = std::sin(theta);
        glm::dmat3 r(1.0);
        r[p][p] = cs;
        r[q][q] = cs;
        r[q][p] = sn;   // column q, row p
        r[p][q] = -sn;  // column p, row q
        c = glm::transpose(r) * c * r;
        v = v * r;
      }
  }
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::vec3& p : mesh.positions) {
    const glm::dvec3 d = glm::dvec3(p) - mean;
    for (int a = 0; a < 3; ++a) {
      const double t = glm::dot(d, v[a]);
      lo[a] = std::min(lo[a], t);
      hi[a] = std::max(hi[a], t);
    }
  }
  glm::dvec3 e = hi - lo;
  if (e.x > e.y) std::swap(e.x, e.y);
  if (e.y > e.z) std::swap(e.y, e.z);
  if (e.x > e.y) std::swap(e.x, e.y);
  return e;
}

bool isFlat(const TriangleMesh& mesh) {
  const glm::dvec3 e = principalExtents(mesh);
  return e.x < 0.1 * e.y;
}

namespace {

std::string nameOf(const Geometry& g, std::size_t index) {
  return g.name().empty() ? "mesh " + std::to_string(index) : "'" + g.name() + "'";
}

std::shared_ptr<const TriangleMesh> withLinear(const TriangleMesh& mesh, const glm::dmat3& l) {
  auto out = std::make_shared<TriangleMesh>();
  out->triangles = mesh.triangles;
  out->positions.reserve(mesh.positions.size());
  for (const glm::vec3& p : mesh.positions) out->positions.push_back(glm::vec3(l * glm::dvec3(p)));
  if (!mesh.normals.empty()) out->computeNormals();
  return out;
}

}  // namespace

FieldPlan planFields(const std::vector<GeometryInstance>& instances, double radius, std::optional<FieldKind> kind) {
  auto kindOf = [&](const TriangleMesh& m) { return kind ? *kind : isFlat(m) ? FieldKind::Grid6 : FieldKind::Cube; };
  FieldPlan plan;
  // (mesh, scale, file) -> field, for the shared fields of similarity instances.
  std::map<std::tuple<const TriangleMesh*, double, std::string>, int> shared;
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const GeometryInstance& inst = instances[i];
    const Geometry* g = inst.geometry;
    if (!g || !g->mesh() || g->mesh()->empty()) continue;
    const glm::dmat3 l(inst.world);
    const double det = glm::determinant(l);
    if (!(std::abs(det) > 0.0) || !std::isfinite(det))
      throw std::invalid_argument("field: " + nameOf(*g, i) + " is placed by a degenerate transform");
    const std::string file = fieldFileOf(*g);
    PlannedOccluder o;
    o.instanceId = inst.id;
    double s = 1.0;
    if (isSimilarity(inst.world, &s)) {
      const auto key = std::make_tuple(g->mesh().get(), s, file);
      auto it = shared.find(key);
      if (it == shared.end()) {
        it = shared.emplace(key, static_cast<int>(plan.fields.size())).first;
        plan.fields.push_back({kindOf(*g->mesh()), g->mesh(), radius / s, file, nameOf(*g, i)});
      }
      o.field = it->second;
    } else {
      if (!file.empty())
        throw std::invalid_argument("field: " + nameOf(*g, i) + " names field file " + file +
                                    " but is scaled non-uniformly (a field file serves rotated, moved and "
                                    "uniformly scaled instances only)");
      o.field = static_cast<int>(plan.fields.size());
      auto mesh = withLinear(*g->mesh(), l);
      plan.fields.push_back({kindOf(*mesh), mesh, radius, {}, nameOf(*g, i)});
      o.correction = glm::dmat4(glm::inverse(l));
    }
    plan.occluders.push_back(o);
  }
  return plan;
}

}  // namespace aokit
