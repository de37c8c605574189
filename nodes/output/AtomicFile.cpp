#include "output/AtomicFile.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "io/InputFiles.h"

namespace aokit {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& what, int err = 0) {
  throw std::runtime_error(path + ": " + what + (err ? " (" + std::string(std::strerror(err)) + ")" : ""));
}

}  // namespace

Destination resolveOutput(const std::string& path) {
  if (path.empty()) throw std::runtime_error("an output path is empty");
  fs::path target = path;
  for (int hops = 0;; ++hops) {
    struct stat st {};
    if (lstat(target.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) break;
    if (hops == 40) fail(path, "too many levels of symbolic links");
    std::error_code ec;
    const fs::path link = fs::read_symlink(target, ec);
    if (ec) fail(path, "cannot read the symbolic link", ec.value());
    target = link.is_absolute() ? link : target.parent_path() / link;
  }
  struct stat st {};
  if (stat(target.c_str(), &st) != 0) {
    if (errno != ENOENT) fail(path, "cannot examine the output path", errno);
    const fs::path parent = target.parent_path();
    std::error_code ec;
    if (!parent.empty() && !fs::is_directory(parent, ec)) fail(path, "folder " + parent.string() + " does not exist");
    return {target.string(), false};
  }
  if (S_ISREG(st.st_mode)) return {target.string(), false};
  if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) return {target.string(), true};
  if (S_ISDIR(st.st_mode)) fail(path, "is a directory");
  if (S_ISBLK(st.st_mode)) fail(path, "is a block device; refusing to write to it");
  fail(path, "is not a regular file, a character device or a FIFO; refusing to write to it");
}

namespace {

// Creates an empty file no one else has, so that the writer's name cannot collide.
std::string createTemporary(const fs::path& besides, const std::string& forPath) {
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0;; ++attempt) {
    const std::string name = besides.string() + ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(counter++);
    const int fd = open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      close(fd);
      return name;
    }
    if (errno != EEXIST || attempt == 100) {
      const fs::path dir = besides.parent_path().empty() ? fs::path(".") : besides.parent_path();
      fail(forPath, "cannot create a file in " + dir.string(), errno);
    }
  }
}

// Forces the bytes to the disk, where a full or failing disk reports itself.
void sync(const std::string& tmp, const std::string& path) {
  const int fd = open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail(path, "cannot write", errno);
  const int rc = fsync(fd);
  const int err = errno;
  close(fd);
  if (rc != 0) fail(path, "cannot write", err);
}

// SIGPIPE held back for one scope, so that a FIFO whose reader went away gives EPIPE, not death.
class NoSigPipe {
 public:
  NoSigPipe() {
    sigset_t pipe;
    sigemptyset(&pipe);
    sigaddset(&pipe, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe, &old_);
  }
  ~NoSigPipe() {
    sigset_t pipe, pending;
    sigemptyset(&pipe);
    sigaddset(&pipe, SIGPIPE);
    sigpending(&pending);
    if (sigismember(&pending, SIGPIPE) && !sigismember(&old_, SIGPIPE)) {
      const timespec none{0, 0};
      sigtimedwait(&pipe, nullptr, &none);
    }
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  NoSigPipe(const NoSigPipe&) = delete;
  NoSigPipe& operator=(const NoSigPipe&) = delete;

 private:
  sigset_t old_;
};

// Copies the finished output into a device or FIFO.
void streamInto(const std::string& tmp, const Destination& to, const std::string& path) {
  const int in = open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) fail(path, "cannot read back the output", errno);
  // A FIFO opened without a reader would block forever: open without blocking, then block.
  int out = open(to.path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
  if (out < 0) {
    const int err = errno;
    close(in);
    if (err == ENXIO) fail(path, "is a FIFO that no process reads");
    fail(path, "cannot open for writing", err);
  }
  fcntl(out, F_SETFL, fcntl(out, F_GETFL) & ~O_NONBLOCK);
  NoSigPipe quiet;
  char buf[65536];
  int err = 0;
  for (;;) {
    const ssize_t n = read(in, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) err = errno;
    if (n <= 0) break;
    for (ssize_t done = 0; done < n && err == 0;) {
      const ssize_t w = write(out, buf + done, static_cast<std::size_t>(n - done));
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) err = w < 0 ? errno : EIO;
      else done += w;
    }
    if (err) break;
  }
  close(in);
  if (close(out) != 0 && err == 0 && errno != EINVAL) err = errno;
  if (err) fail(path, "cannot write", err);
}

}  // namespace

void writeAtomically(const std::string& path, const std::function<void(const std::string& tmpPath)>& write) {
  const Destination to = resolveOutput(path);
  if (const std::string input = inputNamedBy(to.path); !input.empty())
    fail(path, "is the input file " + input + "; refusing to write over it");
  const std::string tmp = createTemporary(to.stream ? fs::temp_directory_path() / "aokit-output" : fs::path(to.path), path);
  try {
    write(tmp);
    sync(tmp, path);
    if (OutputGroup* group = OutputGroup::current()) {
      group->add({tmp, path, to});  // put in place by commit(), or removed
      return;
    }
    if (to.stream) {
      streamInto(tmp, to, path);
      fs::remove(tmp);
    } else if (std::rename(tmp.c_str(), to.path.c_str()) != 0) {
      fail(path, "cannot write", errno);
    }
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
}

namespace {
thread_local OutputGroup* currentGroup = nullptr;
}

OutputGroup::OutputGroup() : previous_(currentGroup) { currentGroup = this; }

OutputGroup* OutputGroup::current() { return currentGroup; }

void OutputGroup::commit() {
  currentGroup = previous_;  // from here on, writes go straight to their places again
  for (const Pending& p : pending_)
    if (p.to.stream) streamInto(p.tmp, p.to, p.path);  // throws: the destructor removes the rest
  for (const Pending& p : pending_)
    if (!p.to.stream && std::rename(p.tmp.c_str(), p.to.path.c_str()) != 0) fail(p.path, "cannot write", errno);
  for (const Pending& p : pending_) {
    std::error_code ignored;
    if (p.to.stream) fs::remove(p.tmp, ignored);
  }
  pending_.clear();
}

OutputGroup::~OutputGroup() {
  if (currentGroup == this) currentGroup = previous_;
  for (const Pending& p : pending_) {
    std::error_code ignored;
    fs::remove(p.tmp, ignored);
  }
}

void writeStreamAtomically(const std::string& path, const std::function<void(std::ostream& out)>& write) {
  writeAtomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    write(out);
    errno = 0;
    out.close();
    if (!out) fail(path, "cannot write", errno ? errno : EIO);
  });
}

void ensureDirectory(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir, ec))
    throw std::runtime_error(dir + ": cannot create directory" + (ec ? " (" + ec.message() + ")" : ""));
}

}  // namespace aokit
