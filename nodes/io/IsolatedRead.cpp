#include "io/IsolatedRead.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <new>
#include <stdexcept>

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <vtkSMPTools.h>

namespace aokit {
namespace {

// Wire format, child to parent: status byte, then the message or the mesh arrays.
enum Status : char { kOk = 0, kCannotRead = 1, kBadContent = 2 };

void put(std::string& out, const void* data, std::size_t bytes) {
  out.append(static_cast<const char*>(data), bytes);
}
template <class T>
void putVector(std::string& out, const std::vector<T>& v) {
  const std::uint64_t n = v.size();
  put(out, &n, sizeof n);
  put(out, v.data(), n * sizeof(T));
}

class Reader {
 public:
  explicit Reader(const std::string& in) : in_(in) {}
  template <class T>
  bool getVector(std::vector<T>& v) {
    std::uint64_t n = 0;
    if (!get(&n, sizeof n) || n > (in_.size() - pos_) / sizeof(T)) return false;
    v.resize(n);
    return get(v.data(), n * sizeof(T));
  }
  bool get(void* data, std::size_t bytes) {
    if (in_.size() - pos_ < bytes) return false;
    if (bytes == 0) return true;  // an empty vector's data() may be null: memcpy must not see it
    std::memcpy(data, in_.data() + pos_, bytes);
    pos_ += bytes;
    return true;
  }
  std::string rest() const { return in_.substr(pos_); }

 private:
  const std::string& in_;
  std::size_t pos_ = 0;
};

std::string encode(Status status, const ReadResult& r) {
  std::string out(1, status);
  if (status == kOk) {
    putVector(out, r.mesh.positions);
    putVector(out, r.mesh.normals);
    putVector(out, r.mesh.triangles);
  } else {
    out += r.why;
  }
  return out;
}

// Address space the child may add to what it inherits: generous for real meshes (a reader needs a
// few times the file size), small enough that a corrupt count fails fast instead of swapping.
void capChildMemory(std::uintmax_t fileSize) {
  long pages = 0;
  std::ifstream("/proc/self/statm") >> pages;
  const rlim_t limit = rlim_t(pages) * rlim_t(sysconf(_SC_PAGESIZE)) + (rlim_t(4) << 30) + 64 * rlim_t(fileSize);
  const rlimit r{limit, limit};
  setrlimit(RLIMIT_AS, &r);
}

[[noreturn]] void runChild(int fd, const std::function<ReadResult()>& read, std::uintmax_t fileSize) {
  // Readers print to stdout and stderr from C and C++ alike: silence the descriptors themselves.
  const int devNull = open("/dev/null", O_WRONLY);
  if (devNull >= 0) {
    dup2(devNull, STDOUT_FILENO);
    dup2(devNull, STDERR_FILENO);
  }
  capChildMemory(fileSize);
  // fork() copies only this thread: the parent's TBB workers, and any lock one held at that moment,
  // are gone here, so a reader's vtkSMPTools::For (array ranges) could wait for them forever.
  vtkSMPTools::SetBackend("Sequential");
  std::string out;
  try {
    ReadResult r = read();
    out = encode(r.ok ? kOk : kCannotRead, r);
  } catch (const std::bad_alloc&) {
    ReadResult r;
    r.why = "out of memory while reading (a corrupt count?)";
    out = encode(kCannotRead, r);
  } catch (const std::exception& e) {
    ReadResult r;
    r.why = e.what();
    out = encode(kBadContent, r);
  } catch (...) {
    ReadResult r;
    r.why = "the reader failed";
    out = encode(kCannotRead, r);
  }
  for (std::size_t done = 0; done < out.size();) {
    const ssize_t n = write(fd, out.data() + done, out.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) _exit(1);
    done += static_cast<std::size_t>(n);
  }
  _exit(0);  // no atexit handlers or static destructors: they belong to the parent
}

// CPU time the process has used, in clock ticks (utime + stime of /proc/<pid>/stat); -1 if unknown.
long cpuTicks(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t close = text.rfind(')');  // the command name may hold spaces
  if (close == std::string::npos) return -1;
  std::istringstream fields(text.substr(close + 2));
  std::string field;
  long utime = -1, stime = -1;
  for (int i = 3; i <= 15 && fields >> field; ++i) {
    if (i == 14) utime = std::atol(field.c_str());
    if (i == 15) stime = std::atol(field.c_str());
  }
  return utime < 0 || stime < 0 ? -1 : utime + stime;
}

enum class ChildEnd { Answered, TimedOut, Stuck };

// Collects the child's answer until it closes the pipe, its time is up, or it has used no CPU for
// a while without answering (a lock another thread of this process held at fork() time is never
// released in the child: fork copies the calling thread only).
ChildEnd collect(int fd, pid_t pid, std::chrono::seconds limit, std::string& in) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + limit;
  const auto idleLimit = std::chrono::seconds(3);
  long ticks = cpuTicks(pid);
  auto lastProgress = Clock::now();
  char buf[65536];
  for (;;) {
    const auto now = Clock::now();
    if (now >= deadline) return ChildEnd::TimedOut;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now);
    pollfd p{fd, POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min<long>(left.count(), 500)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) {
      const long t = cpuTicks(pid);
      if (t != ticks || t < 0) {
        ticks = t;
        lastProgress = Clock::now();
      } else if (Clock::now() - lastProgress >= idleLimit) {
        return ChildEnd::Stuck;
      }
      continue;
    }
    if (ready < 0) continue;
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return ChildEnd::Answered;
    in.append(buf, static_cast<std::size_t>(n));
    lastProgress = Clock::now();
  }
}

}  // namespace

ReadResult readIsolated(const std::function<ReadResult()>& read, std::uintmax_t fileSize) {
  const auto limit = std::chrono::seconds(30 + static_cast<long>(fileSize >> 20));  // + 1 s per MiB
  std::string in;
  ChildEnd end = ChildEnd::Answered;
  int status = 0;
  // A child that hangs is tried once more: the lock it waits on was held at the moment of that fork.
  for (int attempt = 0; attempt < 2; ++attempt) {
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) return read();
    const pid_t pid = fork();
    if (pid < 0) {
      close(fds[0]);
      close(fds[1]);
      return read();
    }
    if (pid == 0) {
      close(fds[0]);
      runChild(fds[1], read, fileSize);
    }
    close(fds[1]);
    in.clear();
    end = collect(fds[0], pid, limit, in);
    close(fds[0]);
    if (end != ChildEnd::Answered) kill(pid, SIGKILL);
    status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (end == ChildEnd::Answered) break;
  }
  const bool timedOut = end != ChildEnd::Answered;

  ReadResult r;
  if (timedOut) {
    r.why = end == ChildEnd::Stuck ? std::string("the reader stopped without an answer, twice")
                                   : "the reader did not finish within " + std::to_string(limit.count()) + " s, twice";
    return r;
  }
  if (WIFSIGNALED(status)) {
    r.why = std::string("the reader crashed: ") + strsignal(WTERMSIG(status));
    return r;
  }
  Reader from(in);
  char code = kCannotRead;
  if (!from.get(&code, 1)) {
    r.why = "the reader process ended without an answer";
    return r;
  }
  if (code == kBadContent) throw std::runtime_error(from.rest());
  if (code == kCannotRead) {
    r.why = from.rest();
    return r;
  }
  if (!from.getVector(r.mesh.positions) || !from.getVector(r.mesh.normals) || !from.getVector(r.mesh.triangles)) {
    r.why = "the reader process sent a truncated mesh";
    return r;
  }
  r.ok = true;
  return r;
}

}  // namespace aokit
