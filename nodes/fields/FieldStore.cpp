#include "fields/FieldStore.h"

#include "fields/FieldBaker.h"
#include "fields/FieldCache.h"
#include "fields/FieldFile.h"
#include "fields/HorizonLimit.h"

namespace aokit {

std::shared_ptr<const BakedField> FieldStore::one(const PlannedField& f, const FieldSettings& settings, Falloff falloff,
                                                  FieldPrepareReport& report,
                                                  const std::function<void(double)>& progress) {
  const Key key{f.mesh.get(), f.radius, f.kind, falloff, f.file};
  if (auto it = kept_.find(key); it != kept_.end()) return it->second.second;
  FieldBakeSettings bakeSettings = settings.bake;
  bakeSettings.kind = f.kind;
  const BakeMesh mesh(*f.mesh);  // validated and hashed once, one Embree scene for all its bakes
  std::shared_ptr<BakedField> field;
  if (!f.file.empty()) {
    field = std::make_shared<BakedField>(readFieldFile(f.file));
    checkFieldMatches(field->info, mesh.hash(), f.radius, falloff, f.file);
    ++report.fromFile;
  } else if (settings.cache) {
    CachedField c = FieldCache(settings.cacheDirectory).getOrBake(mesh, bakeSettings, f.radius, falloff, progress);
    if (!c.warning.empty()) report.warnings.push_back(c.warning);
    if (c.hit) {
      ++report.fromCache;
    } else {
      ++report.baked;
      report.bakeSeconds += c.field.info.bakeSeconds;
    }
    field = std::make_shared<BakedField>(std::move(c.field));
  } else {
    field = std::make_shared<BakedField>(bakeField(mesh, bakeSettings, f.radius, falloff, progress));
    ++report.baked;
    report.bakeSeconds += field->info.bakeSeconds;
  }
  if (field->info.kind == FieldKind::Cube) updateHullBox(field->radial, *f.mesh);
  kept_[key] = {f.mesh, field};
  return field;
}

std::vector<std::shared_ptr<const BakedField>> FieldStore::obtain(const FieldPlan& plan, const FieldSettings& settings,
                                                                  Falloff falloff, FieldPrepareReport& report,
                                                                  const std::function<void(double)>& progress) {
  report = {};
  report.fields = static_cast<int>(plan.fields.size());
  report.occluders = static_cast<int>(plan.occluders.size());
  std::vector<std::shared_ptr<const BakedField>> out;
  const double count = static_cast<double>(plan.fields.size());
  for (std::size_t i = 0; i < plan.fields.size(); ++i) {
    auto part = [&progress, i, count](double f) {
      if (progress) progress((static_cast<double>(i) + f) / count);
    };
    out.push_back(one(plan.fields[i], settings, falloff, report, part));
  }
  if (progress) progress(1.0);
  return out;
}

}  // namespace aokit
