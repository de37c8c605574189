#pragma once
#include <vector>

#include "core/Node.h"

namespace aokit {

class Group : public Node {
 public:
  void accept(NodeVisitor& visitor) override;
  // Visits every child (called from visitors that want to go deeper).
  void traverse(NodeVisitor& visitor);

  void addChild(NodePtr child);
  bool removeChild(const Node* child);
  std::size_t childCount() const { return children_.size(); }
  const NodePtr& child(std::size_t i) const { return children_.at(i); }

 private:
  std::vector<NodePtr> children_;
};

using GroupPtr = std::shared_ptr<Group>;

}  // namespace aokit
