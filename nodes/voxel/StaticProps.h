#pragma once
// Static baked AO on a VTK renderer's actors (render/BakedAO.h): a scene-graph bake
// (StaticBake.h) handed to the actors SceneRenderer made, by instance id; or, for plain VTK, the
// bake of the renderer's own static props. With HybridSettings::staticBake the Hybrid AO pass
// then combines these values with what it marches (DeferredConfig::bakedAO):
//
//   aokit::setPropDynamic(floorActor, false);      // render/ActorKeys.h: this one is static
//   aokit::StaticBakeOptions bake;                 // R, falloff, rays
//   bake.radius = 1.0;
//   aokit::bakeStaticProps(renderer, bake);        // once, before the first frame with static on
#include <cstddef>

#include "voxel/StaticBake.h"

class vtkRenderer;

namespace aokit {

// Puts each baked instance's values on the renderer's actors of that instance id that do not
// carry them yet (a count that no longer matches the actor's points, after the mesh changed, is
// skipped). Returns how many actors got values now.
std::size_t applyStaticBake(vtkRenderer* renderer, const StaticBake& bake);
// Removes the baked values from the renderer's actors of the bake's instance ids.
void clearStaticBake(vtkRenderer* renderer, const StaticBake& bake);

// Plain VTK: bakes the renderer's visible static actors (propDynamic false) that show polydata,
// from the static casters among them, and sets the values on the static receivers (setBakedAO).
// Returns how many actors got values. Throws as bakeStaticInstances.
std::size_t bakeStaticProps(vtkRenderer* renderer, const StaticBakeOptions& options);

}  // namespace aokit
