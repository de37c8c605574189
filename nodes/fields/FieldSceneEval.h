#pragma once
// Algorithm 3 of seed 000 on the CPU, for one receiver point: the specification the deferred field
// pass (FieldPass.h, shaders/FieldEval.glsl) mirrors pixel by pixel.
//
// Every occluder k is a baked field placed in the world by O_k (occluder coordinates -> world, a
// similarity: rotation, uniform scale, translation; FieldInstances.h bakes any other linear part
// into the mesh). At a receiver point p with unit normal n (world) and instance id `pixelId`:
//   skip k when its instance id is that of the pixel (an occluder's own shadow is its
//     self-occlusion, baked apart; the field would count its inside as occluding);
//   cube: RadialFieldEval.h's world form (x = O^-1 p - centre, n_f = normalize(O^T n), Upsilon
//     back to world by O's linear part); grid: GridFieldEval.h with R = identity;
//   combine cube-field occluders first, then grid-field ones, each in the given order (what the
//     pass's loops do): multiply (1 - A = prod (1 - A_k)) or cones (OccluderCombine.h; a grid
//     occluder has no cap and enters as the cap around n of its occlusion).
// Occluders are never culled here: the pass's tile culling must not change this result.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/Bounds.h"
#include "fields/BakedField.h"
#include "fields/FieldEvalSettings.h"
#include "fields/OccluderCombine.h"

namespace aokit {

struct FieldOccluder {
  int field = 0;                      // index into the scene's list of distinct fields
  glm::dmat4 occluderToWorld{1.0};    // O, a similarity
  std::uint32_t instanceId = 0;       // GeometryInstance::id; 0 = skipped by no pixel
  // Where its own pixels are, for occluders that share an id (a composite's leaves, a glyph
  // mapper's instances: one prop): the pixels of instanceId inside this box (world). Invalid (the
  // default): every pixel of instanceId.
  Bounds ownBox;
};

// True when a pixel of instance `pixelId` at p (world) is the occluder's own (its field skips it).
bool ownPixel(const FieldOccluder& o, std::uint32_t pixelId, const glm::dvec3& p);

// One occluder's contribution at p (world), for combining: A_k after the fades, and for cube
// fields the cap (Omega, Upsilon in world space, T_LUT value).
OccluderSample evaluateOccluder(const BakedField& field, const glm::dmat4& occluderToWorld, const glm::dvec3& p,
                                const glm::dvec3& n, const FieldEvalSettings& settings);

// The combined occlusion in [0, 1] at p, n of a pixel of instance `pixelId`.
double evaluateFieldScene(const std::vector<std::shared_ptr<const BakedField>>& fields,
                          const std::vector<FieldOccluder>& occluders, const glm::dvec3& p, const glm::dvec3& n,
                          std::uint32_t pixelId, const FieldEvalSettings& settings);

}  // namespace aokit
