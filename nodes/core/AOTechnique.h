#pragma once
// The swappable AO slot of an AOScene (as osgShadow's ShadowTechnique). Method nodes of every
// family derive from this; the scene renderer calls attach/detach/update, never draws through it.
#include <cstddef>
#include <string>
#include <vector>

class vtkRenderer;

namespace aokit {

class AOScene;


class AOTechnique {
 public:
  virtual ~AOTechnique() = default;

  virtual std::string name() const = 0;
  // Install passes / shader replacements on the renderer. Called when bound or re-bound.
  virtual void attach(vtkRenderer* renderer, AOScene& scene) = 0;
  // Remove everything attach() installed.
  virtual void detach(vtkRenderer* renderer) = 0;
  // Once per frame before rendering: pick up moved transforms, camera changes.
  virtual void update(vtkRenderer* /*renderer*/, AOScene& /*scene*/) {}
  // Bytes held on the GPU and CPU by this technique (reported by the bench).
  virtual std::size_t memoryBytes() const { return 0; }
  // Reads the last frame's AO as occlusion in [0, 1] (1 = fully occluded), row-major, bottom row
  // first, width * height floats. Returns false when this technique cannot expose it directly; the
  // caller then reads 1 - luminance of an AO-only (white, ambient-only) frame.
  virtual bool readAO(vtkRenderer* /*renderer*/, std::vector<float>& /*ao*/) { return false; }
};

}  // namespace aokit
