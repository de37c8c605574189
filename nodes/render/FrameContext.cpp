#include "render/FrameContext.h"

#include <vector>

#include "parallel/RankBounds.h"
#include "parallel/RankExchange.h"

#include <cmath>

#include <vtkActor.h>
#include <vtkMapper.h>
#include <vtkPolyData.h>
#include <vtkPropCollection.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include "render/ActorKeys.h"

#include "render/DeferredSettings.h"

namespace aokit {

namespace {
// Lines, vertices, or a points or wireframe representation: geometry that is drawn but is no
// surface, which the G-buffer marks as such (GBufferOutputFS.glsl) and screen-space tests skip.
bool drawsNonSurfaces(vtkProp* p) {
  auto* actor = vtkActor::SafeDownCast(p);
  if (!actor || !actor->GetMapper()) return false;
  if (actor->GetProperty() && actor->GetProperty()->GetRepresentation() != VTK_SURFACE) return true;
  auto* poly = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0));
  return poly && (poly->GetNumberOfLines() > 0 || poly->GetNumberOfVerts() > 0);
}
}  // namespace

double resolvedRadius(const DeferredSettings& s, double sceneRadius) { return s.radius > 0.0 ? s.radius : sceneRadius; }

Falloff resolvedFalloff(const DeferredSettings& s, Falloff sceneFalloff) { return s.falloff.value_or(sceneFalloff); }

FrameContext frameContext(const DeferredSettings& s, double sceneRadius, Falloff sceneFalloff) {
  FrameContext c;
  c.radius = resolvedRadius(s, sceneRadius);
  c.falloff = resolvedFalloff(s, sceneFalloff);
  return c;
}

double radiusFromVisibleBounds(vtkRenderer* renderer, RankExchange* ranks) {
  double b[6];
  visiblePropBounds(renderer, ranks, b);
  const double diag = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
                                (b[5] - b[4]) * (b[5] - b[4]));
  return (b[0] <= b[1] && std::isfinite(diag) && diag > 0.0) ? 0.1 * diag : 1.0;
}

FrameContext resolveFrameContext(const DeferredSettings& s, double sceneRadius, Falloff sceneFalloff,
                                 vtkRenderer* renderer, RankExchange* ranks) {
  FrameContext c = frameContext(s, sceneRadius, sceneFalloff);
  c.ranks = isParallel(ranks) ? ranks : nullptr;
  if (!(c.radius > 0.0)) c.radius = radiusFromVisibleBounds(renderer, c.ranks);
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* p = props->GetNextProp(it))
    if (p->GetVisibility() && (!propCastsAO(p) || drawsNonSurfaces(p))) c.hasNonCasters = true;
  if (c.ranks) {  // one plan on every rank
    std::vector<int> none{c.hasNonCasters ? 0 : 1};
    c.ranks->minimum(none);
    c.hasNonCasters = none[0] == 0;
  }
  return c;
}

}  // namespace aokit
