#include "fields/FieldAttachment.h"

#include <mutex>
#include <unordered_map>

namespace aokit {

namespace {
std::mutex& lock() {
  static std::mutex m;
  return m;
}
std::unordered_map<std::uint64_t, std::string>& files() {
  static std::unordered_map<std::uint64_t, std::string> f;
  return f;
}
}  // namespace

void setFieldFile(const Node& node, const std::string& path) {
  std::lock_guard<std::mutex> guard(lock());
  if (path.empty())
    files().erase(node.id());
  else
    files()[node.id()] = path;
}

std::string fieldFileOf(const Node& node) {
  std::lock_guard<std::mutex> guard(lock());
  const auto it = files().find(node.id());
  return it == files().end() ? std::string() : it->second;
}

}  // namespace aokit
