#pragma once
// Per-vertex AO baked on the CPU (an occluder's self-occlusion, static geometry's AO) carried to the
// G-buffer as a vertex attribute (GBufferPass::SetBakedAO) and combined into the frame by
// DeferredAOPass (DeferredConfig::bakedAO): total AO = 1 - (1 - baked)(1 - the family's AO).
#include <vector>

class vtkActor;

namespace aokit {

// The point array that carries the values, and the vertex attribute the G-buffer reads.
constexpr const char* kBakedAOArray = "AOKitBakedAO";

// Gives the actor's mapper a shallow copy of its input with `perVertex` (one value in [0, 1] per
// point) as point array kBakedAOArray, mapped to the G-buffer's attribute; replaces earlier values.
// Throws std::invalid_argument when the counts differ or the actor has no poly-data input.
void setBakedAO(vtkActor* actor, const std::vector<float>& perVertex);
// Removes the values again (the G-buffer then reads 0 for this actor).
void clearBakedAO(vtkActor* actor);
bool hasBakedAO(vtkActor* actor);

}  // namespace aokit
