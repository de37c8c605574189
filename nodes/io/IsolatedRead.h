#pragma once
// Runs a mesh reader in a forked child process, so that the parent survives what third-party
// readers do with corrupt files: VTK's legacy reader segfaults on some, its XML reader can spend
// minutes filling a vector sized by a corrupt header, vtkPLYReader double-frees. The child's
// memory is capped, its output silenced, its time bounded; the mesh comes back through a pipe.
// fork() copies only the calling thread: a lock another thread held at that moment (TBB's
// workers) stays held in the child, so the child reads with VTK's sequential SMP backend, and a
// child that hangs (no CPU used for 3 s, or past its time) is killed and started once more.
#include <cstdint>
#include <functional>
#include <string>

#include "core/TriangleMesh.h"

namespace aokit {

struct ReadResult {
  bool ok = false;   // false: the readers could not make sense of the file
  TriangleMesh mesh;
  std::string why;   // what the reader said when !ok
};

// Calls `read` in a child process. A std::runtime_error thrown by `read` (bad content) is rethrown
// here with its message; a crash, a timeout or running out of memory becomes !ok with a reason.
// Where no child can be started (fork fails), `read` runs in this process instead.
ReadResult readIsolated(const std::function<ReadResult()>& read, std::uintmax_t fileSize);

}  // namespace aokit
