#pragma once
// The polygonal meshes a renderer's visible props draw, each with its model-to-world matrix: what
// the world-space families voxelize (hybrid) or bake (fields), and what the mappers people use
// hand VTK:
//   - actors whose mapper's input is vtkPolyData (vtkPolyDataMapper, vtkLODActor, scalar colours);
//   - composite data (vtkMultiBlockDataSet through vtkCompositePolyDataMapper2): every visible
//     polydata leaf, visibility inherited down the tree as the mapper does;
//   - vtkGlyph3DMapper: the source at every (unmasked) input point, scaled, oriented and indexed
//     as the mapper does (VTK keeps its instance matrices private, so they are recomputed);
//   - vtkDataSetMapper over any other dataset: its outer surface (vtkDataSetSurfaceFilter, as
//     the mapper draws it; one filter kept per mapper);
//   - parts of assemblies (vtkAssembly, vtkPropAssembly) with their full matrices.
// Translucent props (no opaque geometry) cast nothing: AO comes from the opaque geometry.
// Any other visible prop that a family would have to cast (an image actor, a volume, a mapper
// over non-geometric data) gets one warning naming it, once per collector, and casts nothing.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

class vtkDataSet;
class vtkDataSetSurfaceFilter;
class vtkMapper;
class vtkPolyData;
class vtkProp;
class vtkRenderer;

namespace aokit {

struct PropMesh {
  vtkProp* prop = nullptr;    // the prop drawing it (an assembly's part for parts)
  vtkPolyData* poly = nullptr;  // its pipeline brought up to date
  glm::dmat4 modelToWorld{1.0};
  bool wholeProp = false;     // the prop's whole geometry, placed by the prop's own matrix (its
                              // GetBounds() are this mesh's world bounds)
  vtkProp* keys = nullptr;    // the prop whose keys (ActorKeys.h) the draw carries: the prop, or for
                              // parts the assembly (VTK hands its keys to its parts as they draw)
  int leaf = 0;               // which mesh of `keys` it is: a composite's polydata leaf (empty and
                              // hidden leaves counted), plus kLeavesPerPart times an assembly part's
                              // path; -1 for a glyph instance
};

constexpr int kLeavesPerPart = 1 << 16;

class RankExchange;
class RankMeshes;

class PropMeshes {
 public:
  explicit PropMeshes(std::string family);
  ~PropMeshes();
  // The meshes of the renderer's visible props that cast AO (ActorKeys.h), in prop order. With
  // the ranks of a parallel renderer: every rank's meshes, each one's pieces merged into the whole
  // (parallel/RankMeshes.h); every rank must call it in the same frames.
  std::vector<PropMesh> collect(vtkRenderer* renderer, RankExchange* ranks = nullptr);
  // Bytes this rank sent to the others in the last collect() (0 in one process).
  std::size_t exchangedBytes() const { return exchanged_; }
  // Props warned about so far (still alive).
  std::size_t warnings() const;

 private:
  void add(vtkProp* prop, vtkProp* keys, const glm::dmat4& world, bool part, std::vector<PropMesh>& out);
  void meshesOf(vtkProp* prop, const glm::dmat4& world, bool part, std::vector<PropMesh>& out);
  void warnOnce(vtkProp* prop, const char* why);
  vtkPolyData* surfaceOf(vtkMapper* mapper, vtkDataSet* input);

  struct Surface {
    vtkWeakPointer<vtkMapper> mapper;
    vtkSmartPointer<vtkDataSetSurfaceFilter> filter;
  };

  std::vector<PropMesh> collectLocal(vtkRenderer* renderer);

  std::string family_;
  std::unique_ptr<RankMeshes> ranks_;
  std::size_t exchanged_ = 0;
  std::vector<vtkWeakPointer<vtkProp>> warned_;  // weak: a new prop at an old address warns too
  std::vector<Surface> surfaces_;                // dropped with their mapper
};

// Row-major VTK matrix to glm (column-major).
glm::dmat4 glmFromVtk(const double m[16]);

}  // namespace aokit
