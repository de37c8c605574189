#pragma once
#include <glm/glm.hpp>
#include <cstdint>
#include <vector>

namespace aokit {

class Node;
class Group;
class Transform;
class Geometry;
class AOScene;

// Double-dispatch visitor. Defaults walk the whole tree; override what you need.
class NodeVisitor {
 public:
  virtual ~NodeVisitor() = default;
  virtual void apply(Node& node);
  virtual void apply(Group& group);
  virtual void apply(Transform& transform);
  virtual void apply(Geometry& geometry);
  virtual void apply(AOScene& scene);
};

// One geometry placed in the world: what renderers, the reference and bakers consume.
struct GeometryInstance {
  Geometry* geometry = nullptr;
  glm::dmat4 world{1.0};
  std::uint32_t mask = 0;  // effective mask: AND of masks along the path
  // Stable id of this placement (the path of nodes from the root), >= 1: the same path gets the
  // same id for the life of the process, whatever moves; a mesh shown twice gets two ids. Passes
  // write it into the G-buffer (an occluder skips its own field there).
  std::uint32_t id = 0;
};

// Collects every Geometry under root with its accumulated world matrix. Skips subtrees whose
// effective mask has none of the bits in `require`.
std::vector<GeometryInstance> collectInstances(Node& root, std::uint32_t require = ~0u);

}  // namespace aokit
