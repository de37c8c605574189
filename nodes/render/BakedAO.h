#pragma once
// Per-vertex AO baked on the CPU (an occluder's self-occlusion, static geometry's AO) carried to the
// G-buffer as a vertex attribute (GBufferPass::SetBakedAO) and combined into the frame by
// DeferredAOPass (DeferredConfig::bakedAO): total AO = 1 - (1 - baked)(1 - the family's AO).
//
// One owner for an actor's mapper input: its source polydata is set with setActorInput (the scene
// renderer does; a plain VTK actor's first input counts as its source), techniques hand their values
// with setBakedAO, and the mapper draws a shallow copy of the source with the values as point array
// kBakedAOArray. The source itself is never changed: other actors may share it.
#include <vector>

class vtkActor;
class vtkPolyData;

namespace aokit {

struct CreaseSplit;

// The point array that carries the values, and the vertex attribute the G-buffer reads.
constexpr const char* kBakedAOArray = "AOKitBakedAO";

// Sets the actor's source polydata (on its poly-data mapper); values set before are kept when they
// still match the source's point count, and dropped otherwise (the geometry changed).
void setActorInput(vtkActor* actor, vtkPolyData* source);
// Hands the actor `perVertex` (one value in [0, 1] per point of its source, or two: every point's
// front side, then every point's back side, the side opposite its normal, which the G-buffer takes
// where the eye sees it); replaces earlier values. Throws std::invalid_argument when the counts
// differ or the actor has no poly-data input.
void setBakedAO(vtkActor* actor, const std::vector<float>& perVertex);
// The same for values per point of a crease split of the source's surface (splitAtCreases of its
// triangleMeshOf, core/CreaseSplit.h): the drawn copy then has the split's copies after the
// source's points (their point data copied from the vertex each copies), and its polygons and
// strips use them where the split does; vertices, lines, cell order and cell data stay the
// source's. A split the bake refined (core/BakeRefinement.h) adds its midpoints last, their
// coordinates and point data interpolated, and draws its polygons and strips as its triangles, one
// cell each with the cell data of the cell it lies in (cell ids after the lines then differ from
// the source's). Pickers on such an actor report the copy's point ids (the source's, or a copy's
// above its point count). A split without copies or midpoints is setBakedAO above.
void setBakedAO(vtkActor* actor, const std::vector<float>& perPoint, const CreaseSplit& split);
// Removes the values again (the G-buffer then reads 0 for this actor).
void clearBakedAO(vtkActor* actor);
bool hasBakedAO(vtkActor* actor);
// The polydata the actor shows, without the kit's values: what the kit measures and voxelizes
// (the drawn copy may hold crease copies of its points).
vtkPolyData* bakedAOSource(vtkActor* actor);

}  // namespace aokit
