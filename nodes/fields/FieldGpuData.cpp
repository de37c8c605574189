#include "fields/FieldGpuData.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace aokit {

namespace {

std::uint32_t kindCode(FieldKind k) { return k == FieldKind::Cube ? 0u : k == FieldKind::Grid6 ? 1u : 2u; }

void append(std::vector<float>& to, const std::vector<float>& from) { to.insert(to.end(), from.begin(), from.end()); }

double occluderScale(const glm::dmat4& o) { return std::cbrt(std::abs(glm::determinant(glm::dmat3(o)))); }

}  // namespace

FieldGpuData packFields(const std::vector<std::shared_ptr<const BakedField>>& fields) {
  FieldGpuData d;
  d.fieldCount = static_cast<int>(fields.size());
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (!fields[i]) throw std::invalid_argument("field pass: field " + std::to_string(i) + " is missing");
    const BakedField& f = *fields[i];
    if (f.info.kind == FieldKind::Cube) {
      d.hasCube = true;
    } else {
      if (d.hasGrid && f.info.kind != d.gridKind)
        throw std::invalid_argument("field pass: grid fields of kinds " + fieldKindName(d.gridKind) + " and " +
                                    fieldKindName(f.info.kind) + " in one scene (use one grid kind)");
      d.hasGrid = true;
      d.gridKind = f.info.kind;
    }
    const std::uint32_t base4 = static_cast<std::uint32_t>(d.texels4.size() / 4);
    const std::uint32_t base3 = static_cast<std::uint32_t>(d.texels3.size() / 3);
    float floats[kFieldFloatsPerField] = {};
    int n = 0;
    if (f.info.kind == FieldKind::Cube) {
      const RadialField& r = f.radial;
      n = r.resolution;
      if (n < 1 || r.occlusion.size() != r.texelCount() * 4 || r.centroid.size() != r.texelCount() * 3)
        throw std::invalid_argument("field pass: cube field " + std::to_string(i) + " holds no texels of its size");
      append(d.texels4, r.occlusion);
      append(d.texels3, r.centroid);
      floats[0] = static_cast<float>(r.rMax);
      floats[1] = static_cast<float>(r.fadeStart);
      floats[2] = static_cast<float>(r.fadeEnd);
      const bool box = r.hullBoxHalf.x >= 0.0;
      for (int a = 0; a < 3; ++a) {
        floats[4 + a] = box ? static_cast<float>(r.hullBoxCentre[a]) : 0.0f;
        floats[8 + a] = box ? static_cast<float>(r.hullBoxHalf[a]) : 1e30f;
      }
      d.fieldBytes += r.memoryBytes();
    } else {
      const GridField& g = f.grid;
      n = g.resolution;
      if (n < 1 || g.texels.size() != g.pointCount() * g.terms())
        throw std::invalid_argument("field pass: grid field " + std::to_string(i) + " holds no texels of its size");
      append(g.kind == FieldKind::Grid4 ? d.texels4 : d.texels3, g.texels);
      for (int a = 0; a < 3; ++a) {
        floats[a] = static_cast<float>(g.origin[a]);
        floats[4 + a] = static_cast<float>(g.size[a]);
      }
      d.fieldBytes += g.memoryBytes();
    }
    d.fieldInts.insert(d.fieldInts.end(), {kindCode(f.info.kind), static_cast<std::uint32_t>(n), base4, base3});
    d.fieldFloats.insert(d.fieldFloats.end(), floats, floats + kFieldFloatsPerField);
  }
  // A buffer texture cannot be empty.
  if (d.texels4.empty()) d.texels4.assign(4, 0.0f);
  if (d.texels3.empty()) d.texels3.assign(3, 0.0f);
  if (d.fieldInts.empty()) d.fieldInts.assign(4, 0u);
  if (d.fieldFloats.empty()) d.fieldFloats.assign(kFieldFloatsPerField, 0.0f);
  return d;
}

glm::dmat4 worldToFieldCoordinates(const BakedField& field, const glm::dmat4& occluderToWorld) {
  glm::dmat4 m = glm::inverse(occluderToWorld);
  if (field.info.kind == FieldKind::Cube) m[3] -= glm::dvec4(field.radial.centre, 0.0);
  return m;
}

InfluenceSphere influenceSphere(const BakedField& field, const glm::dmat4& o, double gridBias) {
  const double s = occluderScale(o);
  InfluenceSphere out;
  if (field.info.kind == FieldKind::Cube) {
    out.centre = glm::dvec3(o * glm::dvec4(field.radial.centre, 1.0));
    out.radius = s * field.radial.rMax;
  } else {
    const GridField& g = field.grid;
    out.centre = glm::dvec3(o * glm::dvec4(g.origin + 0.5 * g.size, 1.0));
    // The normal offset moves a sample by up to bias / N of the box along each axis.
    out.radius = s * glm::length(g.size) * (0.5 + gridBias / std::max(1, g.resolution));
  }
  return out;
}

OccluderGpuData packOccluders(const std::vector<std::shared_ptr<const BakedField>>& fields,
                              const std::vector<FieldOccluder>& occluders, double gridBias) {
  OccluderGpuData d;
  d.occluderCount = static_cast<int>(occluders.size());
  for (const FieldOccluder& o : occluders)
    if (o.field < 0 || o.field >= static_cast<int>(fields.size()) || !fields[o.field])
      throw std::invalid_argument("field pass: an occluder names field " + std::to_string(o.field) + " of " +
                                  std::to_string(fields.size()));
  for (int pass = 0; pass < 2; ++pass)  // cube fields first
    for (std::size_t i = 0; i < occluders.size(); ++i)
      if ((fields[occluders[i].field]->info.kind == FieldKind::Cube) == (pass == 0))
        d.order.push_back(static_cast<int>(i));
  for (int i : d.order) {
    const FieldOccluder& o = occluders[i];
    const BakedField& f = *fields[o.field];
    if (f.info.kind == FieldKind::Cube) ++d.cubeCount;
    const glm::dmat4 m = worldToFieldCoordinates(f, o.occluderToWorld);
    for (int row = 0; row < 3; ++row)
      for (int col = 0; col < 4; ++col) d.floats.push_back(static_cast<float>(m[col][row]));
    const InfluenceSphere s = influenceSphere(f, o.occluderToWorld, gridBias);
    d.floats.insert(d.floats.end(), {static_cast<float>(s.centre.x), static_cast<float>(s.centre.y),
                                     static_cast<float>(s.centre.z), static_cast<float>(s.radius)});
    d.ints.insert(d.ints.end(), {o.instanceId, static_cast<std::uint32_t>(o.field), o.ownBox.valid() ? 1u : 0u, 0u});
    const float big = std::numeric_limits<float>::max();
    if (o.ownBox.valid())
      for (const glm::dvec3& c : {o.ownBox.min, o.ownBox.max})
        d.ownBoxes.insert(d.ownBoxes.end(), {static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z)});
    else
      d.ownBoxes.insert(d.ownBoxes.end(), {-big, -big, -big, big, big, big});
  }
  d.cubeWords = (d.cubeCount + 31) / 32;
  d.words = std::max(1, d.cubeWords + (d.occluderCount - d.cubeCount + 31) / 32);
  if (d.floats.empty()) d.floats.assign(kOccluderFloatsPerOccluder, 0.0f);
  if (d.ints.empty()) d.ints.assign(kOccluderIntsPerOccluder, 0u);
  return d;
}

OccluderRecord occluderRecord(const OccluderGpuData& d, int slot) {
  const std::size_t k = static_cast<std::size_t>(slot);
  OccluderRecord r;
  r.worldToField = &d.floats[k * kOccluderFloatsPerOccluder];
  r.sphere = r.worldToField + 12;
  r.instanceId = d.ints[k * kOccluderIntsPerOccluder];
  r.field = d.ints[k * kOccluderIntsPerOccluder + 1];
  r.sharedId = d.ints[k * kOccluderIntsPerOccluder + 2] != 0;
  r.ownBox = d.ownBoxes.empty() ? nullptr : &d.ownBoxes[k * 6];
  return r;
}

FieldRecord fieldRecord(const FieldGpuData& d, std::uint32_t field) {
  FieldRecord r;
  for (int i = 0; i < 4; ++i) r.info[i] = static_cast<int>(d.fieldInts[field * 4 + i]);
  r.floats = &d.fieldFloats[field * kFieldFloatsPerField];
  return r;
}

}  // namespace aokit
