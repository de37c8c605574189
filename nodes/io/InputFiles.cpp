#include "io/InputFiles.h"

#include <sys/stat.h>

#include <mutex>

namespace aokit {
namespace {

struct Input {
  std::string path;
  dev_t device;
  ino_t inode;
};

std::mutex inputsMutex;
std::vector<Input>& inputs() {
  static std::vector<Input> list;
  return list;
}

}  // namespace

void noteInputFile(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return;
  std::lock_guard<std::mutex> lock(inputsMutex);
  for (const Input& in : inputs())
    if (in.device == st.st_dev && in.inode == st.st_ino) return;
  inputs().push_back({path, st.st_dev, st.st_ino});
}

std::string inputNamedBy(const std::string& path) {
  struct stat st {};
  if (path.empty() || stat(path.c_str(), &st) != 0) return {};
  std::lock_guard<std::mutex> lock(inputsMutex);
  for (const Input& in : inputs())
    if (in.device == st.st_dev && in.inode == st.st_ino) return in.path;
  return {};
}

}  // namespace aokit
