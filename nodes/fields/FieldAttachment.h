#pragma once
// Field files attached to Geometry nodes: what a scene file's `"field": "FILE"` on an object says
// (nodes/io/SceneFile.cpp), read by the field technique at prepare() instead of baking.
// Kept beside the scene graph, keyed by Node::id() (unique for the life of the process, never
// reused), so the graph's core classes need not know about fields. Thread-safe.
#include <string>

#include "core/Node.h"

namespace aokit {

// Attaches `path` to the node (replacing an earlier one); an empty path detaches.
void setFieldFile(const Node& node, const std::string& path);
// The attached field file, or empty.
std::string fieldFileOf(const Node& node);

}  // namespace aokit
