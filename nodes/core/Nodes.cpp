// accept() of every node type and the default visitor walk.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>

#include "core/AOScene.h"
#include "core/Geometry.h"
#include "core/NodeVisitor.h"
#include "core/Transform.h"

namespace aokit {

namespace {
std::atomic<std::uint64_t> nextNodeId{1};
std::atomic<std::uint64_t> revisionClock{1};

// Instance ids: one small integer per path of node ids, handed out on first sight. Hashing the
// path (FNV-1a over 64-bit ids) keeps the key small; 64-bit collisions are not a practical risk.
std::uint32_t instanceIdForPath(std::uint64_t pathHash) {
  static std::mutex mutex;
  static std::map<std::uint64_t, std::uint32_t> ids;
  std::lock_guard<std::mutex> lock(mutex);
  auto [it, added] = ids.emplace(pathHash, static_cast<std::uint32_t>(ids.size() + 1));
  return it->second;
}

std::uint64_t hashStep(std::uint64_t h, std::uint64_t v) {
  for (int b = 0; b < 8; ++b) h = (h ^ ((v >> (8 * b)) & 0xffu)) * 1099511628211ull;
  return h;
}
}  // namespace

Node::Node() : id_(nextNodeId++), revision_(revisionClock++) {}
void Node::touch() { revision_ = revisionClock++; }

void Node::accept(NodeVisitor& v) { v.apply(*this); }
void Group::accept(NodeVisitor& v) { v.apply(*this); }
void Transform::accept(NodeVisitor& v) { v.apply(*this); }
void Geometry::accept(NodeVisitor& v) { v.apply(*this); }
void AOScene::accept(NodeVisitor& v) { v.apply(*this); }

void Group::traverse(NodeVisitor& v) {
  for (auto& c : children_) c->accept(v);
}

void Group::addChild(NodePtr child) {
  if (!child) throw std::invalid_argument("Group::addChild: null child");
  if (child.get() == this) throw std::invalid_argument("Group::addChild: a group cannot contain itself");
  children_.push_back(std::move(child));
  touch();
}

bool Group::removeChild(const Node* child) {
  auto it = std::find_if(children_.begin(), children_.end(), [&](const NodePtr& c) { return c.get() == child; });
  if (it == children_.end()) return false;
  children_.erase(it);
  touch();
  return true;
}

void AOScene::setAORadius(double r) {
  if (!(r > 0.0) || !std::isfinite(r)) throw std::invalid_argument("AO radius must be positive and finite");
  aoRadius_ = r;
  touch();
}

void NodeVisitor::apply(Node&) {}
void NodeVisitor::apply(Group& g) { g.traverse(*this); }
void NodeVisitor::apply(Transform& t) { apply(static_cast<Group&>(t)); }
void NodeVisitor::apply(Geometry& g) { apply(static_cast<Node&>(g)); }
void NodeVisitor::apply(AOScene& s) { apply(static_cast<Group&>(s)); }

namespace {

class InstanceCollector : public NodeVisitor {
 public:
  explicit InstanceCollector(std::uint32_t require) : require_(require) {}
  std::vector<GeometryInstance> out;

  void apply(Group& g) override { descend(g, [&] { g.traverse(*this); }); }
  void apply(AOScene& s) override { apply(static_cast<Group&>(s)); }
  void apply(Transform& t) override {
    descend(t, [&] {
      const glm::dmat4 saved = world_;
      world_ = world_ * t.matrix();
      t.traverse(*this);
      world_ = saved;
    });
  }
  void apply(Geometry& g) override {
    descend(g, [&] { out.push_back({&g, world_, mask_, instanceIdForPath(path_)}); });
  }

 private:
  template <class F>
  void descend(Node& n, F&& f) {
    const std::uint32_t savedMask = mask_;
    const std::uint64_t savedPath = path_;
    mask_ &= n.mask();
    path_ = hashStep(path_, n.id());
    if (mask_ & require_) f();
    mask_ = savedMask;
    path_ = savedPath;
  }
  std::uint32_t require_;
  std::uint32_t mask_ = ~0u;
  std::uint64_t path_ = 14695981039346656037ull;  // FNV-1a offset basis
  glm::dmat4 world_{1.0};
};

}  // namespace

std::vector<GeometryInstance> collectInstances(Node& root, std::uint32_t require) {
  InstanceCollector c(require);
  root.accept(c);
  return std::move(c.out);
}

}  // namespace aokit
