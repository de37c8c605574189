#pragma once
// The one output writer every command uses. Regular files are written to a temporary file beside
// the target and renamed into place only when complete, so an error or Ctrl-C never leaves a
// half-written output file. Nothing but a regular file (or nothing) is ever renamed over: a
// symbolic link is followed to its target, a character device or FIFO (-o /dev/null, -o
// /dev/stdout in a pipe) is written directly once the whole output exists, anything else
// (a directory, a block device, a socket, a dangling link) is refused. Every failure, a full disk
// included, throws std::runtime_error with one line naming the path.
#include <functional>
#include <iosfwd>
#include <string>

namespace aokit {

// Where the bytes for `path` go: replaced by rename (a regular file or nothing) or streamed into
// (a character device or a FIFO). Throws the one-line refusals described above.
struct Destination {
  std::string path;  // symbolic links followed
  bool stream = false;
};
Destination resolveOutput(const std::string& path);

// Calls write(tmpPath), then moves the result into place as described above. On any exception the
// temporary file is removed and the exception rethrown. Refuses a path that names a file this
// process has read as input (io/InputFiles.h).
void writeAtomically(const std::string& path, const std::function<void(const std::string& tmpPath)>& write);

// The same for writers that produce a stream: the stream is flushed and checked here, so a full
// disk cannot go unnoticed in a buffer that a destructor flushes.
void writeStreamAtomically(const std::string& path, const std::function<void(std::ostream& out)>& write);

// Creates a directory (and parents); throws a one-line error when it cannot.
void ensureDirectory(const std::string& dir);

}  // namespace aokit
