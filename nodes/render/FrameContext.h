#pragma once
// What a family's constants are made from besides its settings: the AO radius and falloff of this
// frame, resolved once, here, from the settings, the scene and (for a plain VTK scene with neither)
// the renderer's visible bounds.
#include <cstddef>

#include "core/AOScene.h"

class vtkRenderer;

namespace aokit {

struct DeferredSettings;
class RankExchange;

struct FrameContext {
  double radius = 1.0;                //!< R, world units, > 0
  Falloff falloff = Falloff::Binary;  //!< k(d) over R
  bool hasNonCasters = false;         //!< some visible prop is drawn but casts no AO (ActorKeys.h), or
                                      //!<   draws lines or points, which are no surface
  RankExchange* ranks = nullptr;      //!< the ranks of a parallel renderer (parallel/RankExchange.h);
                                      //!<   null: one process
  std::size_t exchangedBytes = 0;     //!< what this rank sent to the others this frame
};

// The settings' radius when set (> 0), else sceneRadius (which may itself be 0 = unknown).
double resolvedRadius(const DeferredSettings& s, double sceneRadius);
// The settings' falloff when set, else the scene's.
Falloff resolvedFalloff(const DeferredSettings& s, Falloff sceneFalloff);
// Radius and falloff from the settings, else the scene's (no renderer: sceneRadius must be > 0
// where the settings leave the radius open).
FrameContext frameContext(const DeferredSettings& s, double sceneRadius, Falloff sceneFalloff);
// A radius for a scene that names none: a tenth of the diagonal of the visible props' bounds
// (1 when there are none).
double radiusFromVisibleBounds(vtkRenderer* renderer, RankExchange* ranks = nullptr);
// The frame's context: radius from the settings, else the scene's (> 0), else the visible bounds;
// whether a visible prop casts no AO.
// With the ranks of a parallel renderer, bounds and props are every rank's.
FrameContext resolveFrameContext(const DeferredSettings& s, double sceneRadius, Falloff sceneFalloff,
                                 vtkRenderer* renderer, RankExchange* ranks = nullptr);

}  // namespace aokit
