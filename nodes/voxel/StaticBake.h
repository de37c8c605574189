#pragma once
// The static half of static plus dynamic (issue 9 item 5, StaticDynamic.h): AO baked once per
// vertex of every static receiver, from the static casters only, with the Embree reference's own
// estimator at points over its surface, fitted to the vertices (VertexAOBake.h, SurfaceFit). Static is a node mask without kDynamic (core/Node.h; clear it on a
// group and its whole subtree is static). The bake is keyed by instance id, the id SceneRenderer
// tags each actor with (render/ActorKeys.h), so that a technique bakes in prepare(), before any
// renderer exists, and hands the values to the actors later (StaticProps.h applyStaticBake).
// Plain VTK applications bake their props directly (StaticProps.h bakeStaticProps).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <vector>

#include "core/AOScene.h"
#include "core/Node.h"

namespace aokit {

struct StaticBakeOptions {
  int rays = 256;                     //!< rays per surface point, 1..4096 (points R / 8 apart)
  double radius = 1.0;                //!< AO radius R, world units, > 0
  Falloff falloff = Falloff::Binary;  //!< as the reference's
  std::uint64_t seed = 1;             //!< same seed, same values
  int threads = 0;                    //!< 0 = all cores
  std::function<void(double)> progress;  //!< fraction done; throw to cancel
};

struct StaticBake {
  std::map<std::uint32_t, std::vector<float>> perInstance;  // instance id -> AO per vertex of its mesh
  std::size_t occluders = 0;  // static casters the bake saw
  std::size_t vertices = 0;   // baked vertices, all receivers
  std::size_t memoryBytes() const { return vertices * sizeof(float); }
};

// Receivers: drawn instances (kVisible) with kReceivesAO and without kDynamic. Occluders: instances
// with kCastsAO and without kDynamic, drawn or not. Throws std::invalid_argument on bad options,
// std::runtime_error on an Embree error or an invalid mesh, and what progress throws.
StaticBake bakeStaticInstances(Node& root, const StaticBakeOptions& options);

}  // namespace aokit
