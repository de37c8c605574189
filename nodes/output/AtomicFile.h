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
#include <vector>

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

// The outputs of one command as one unit. While a group is alive on this thread, writeAtomically
// writes and checks each output's temporary file but puts nothing in place; commit() then streams
// the device and FIFO outputs (the ones that can still fail) and renames the files into place. A
// command that fails on a later output (render --ao-float a.f32 -o /dev/full) leaves none of its
// outputs behind: without commit, the destructor removes every temporary file.
class OutputGroup {
 public:
  OutputGroup();
  ~OutputGroup();
  OutputGroup(const OutputGroup&) = delete;
  OutputGroup& operator=(const OutputGroup&) = delete;
  void commit();

  struct Pending {
    std::string tmp, path;
    Destination to;
  };
  void add(Pending p) { pending_.push_back(std::move(p)); }
  static OutputGroup* current();

 private:
  std::vector<Pending> pending_;
  OutputGroup* previous_;
};

// Creates a directory (and parents); throws a one-line error when it cannot.
void ensureDirectory(const std::string& dir);

}  // namespace aokit
