#pragma once
// Base of the scene graph (OSG style). Nodes are shared through std::shared_ptr: one ownership rule.
#include <cstdint>
#include <memory>
#include <string>

namespace aokit {

class NodeVisitor;

// Traversal masks, as osgShadow's CastsShadow/ReceivesShadow masks.
enum NodeMask : std::uint32_t {
  kCastsAO = 1u << 0,     // occludes others (enters voxelizers, fields, the reference)
  kReceivesAO = 1u << 1,  // is shaded with AO
  kVisible = 1u << 2,     // drawn at all
  kDynamic = 1u << 3,     // may move or deform; cleared on static subtrees, whose AO a technique may
                          // bake once (on by default, so the AND along a path makes everything
                          // under a static group static)
  kDefaultMask = kCastsAO | kReceivesAO | kVisible | kDynamic,
};

class Node {
 public:
  Node();
  virtual ~Node() = default;
  virtual void accept(NodeVisitor& visitor);

  // Unique for the life of the process (never reused): the basis of stable instance ids.
  std::uint64_t id() const { return id_; }

  const std::string& name() const { return name_; }
  void setName(std::string name) { name_ = std::move(name); }

  std::uint32_t mask() const { return mask_; }
  void setMask(std::uint32_t mask) { mask_ = mask; touch(); }
  bool castsAO() const { return mask_ & kCastsAO; }
  bool receivesAO() const { return mask_ & kReceivesAO; }
  bool isDynamic() const { return mask_ & kDynamic; }
  // Clears (or sets) kDynamic only: setDynamic(false) on a group marks its whole subtree static.
  void setDynamic(bool on) { setMask(on ? (mask_ | kDynamic) : (mask_ & ~std::uint32_t(kDynamic))); }

  // Set from one process-wide counter on every change that a renderer must pick up, so it only
  // grows, and the largest revision under a root is a change counter for the whole scene
  // (sceneRevision() in core/Scene.h). Lets updates skip untouched nodes.
  std::uint64_t revision() const { return revision_; }

 protected:
  void touch();

 private:
  std::string name_;
  std::uint32_t mask_ = kDefaultMask;
  std::uint64_t id_;
  std::uint64_t revision_;
};

using NodePtr = std::shared_ptr<Node>;

}  // namespace aokit
