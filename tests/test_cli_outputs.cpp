// Where outputs go (issue 10 item 3): never renamed over anything but a regular file, devices and
// FIFOs written directly or refused, write errors reported in one line with a non-zero exit, no
// output over an input, and VTK's own error text folded into aokit's one line.
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <thread>

#include "CliHarness.h"

using clitest::CliTest;
using clitest::runAokit;
namespace fs = std::filesystem;

namespace {

bool isCharDevice(const std::string& p) {
  struct stat st {};
  return stat(p.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

const std::string kTriangle = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

}  // namespace

class CliOutputs : public CliTest {
 protected:
  // A private copy of a character device (as root), so that a regression replaces the copy,
  // never the machine's own /dev/full or /dev/null. Without root, the real node (whose folder a
  // non-root user cannot rename into anyway).
  std::string device(const char* name, unsigned major, unsigned minor) {
    const std::string copy = path(name);
    if (geteuid() == 0 && mknod(copy.c_str(), S_IFCHR | 0666, makedev(major, minor)) == 0) return copy;
    return std::string("/dev/") + name;
  }
};

TEST_F(CliOutputs, FullDeviceGivesOneLineAndStaysADevice) {
  const std::string full = device("full", 1, 7);
  expectRefused({"render", "--size", "32x24", "-o", full}, "full: cannot write (No space left on device)");
  EXPECT_TRUE(isCharDevice(full));
  expectRefused({"render", "--size", "32x24", "--ao-float", full, "-o", path("a.png")}, "full: cannot write (No space left");
  EXPECT_TRUE(isCharDevice(full));
  // The other way round: the float file is complete before the PNG fails; it must not stay either
  // (expectRefused compares the folder's listing).
  expectRefused({"render", "--size", "32x24", "--ao-float", path("a.f32"), "-o", full}, "full: cannot write (No space left");
  EXPECT_TRUE(isCharDevice(full));
}

TEST_F(CliOutputs, NullDeviceTakesTheOutputAndStaysADevice) {
  const std::string null = device("null", 1, 3);
  const auto r = runAokit({"render", "--size", "32x24", "-o", null});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_TRUE(isCharDevice(null));
}

TEST_F(CliOutputs, FifoIsWrittenDirectlyOrRefused) {
  const std::string fifo = path("pipe");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
  expectRefused({"render", "--size", "32x24", "-o", fifo}, "pipe: is a FIFO that no process reads");
  std::string received;
  std::thread reader([&] {
    std::ifstream in(fifo, std::ios::binary);
    received.assign(std::istreambuf_iterator<char>(in), {});
  });
  const auto r = runAokit({"render", "--size", "32x24", "-o", fifo});
  reader.join();
  EXPECT_EQ(r.code, 0) << r.err;
  ASSERT_GE(received.size(), 8u);
  EXPECT_EQ(received.substr(1, 3), "PNG");
  struct stat st {};
  ASSERT_EQ(stat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

TEST_F(CliOutputs, OutputNamingAnInputIsRefused) {
  const std::string mesh = write("mesh.off", kTriangle);
  expectRefused({"render", "--scene", mesh, "--size", "16x16", "-o", mesh}, "is the input file");
  fs::create_symlink(mesh, path("link.png"));
  expectRefused({"render", "--scene", mesh, "--size", "16x16", "-o", path("link.png")}, "is the input file");
  fs::create_directories(path("sub"));
  expectRefused({"render", "--scene", mesh, "--size", "16x16", "-o", path("sub/../mesh.off")}, "is the input file");
  fs::create_hard_link(mesh, path("hard.off"));
  expectRefused({"render", "--scene", path("hard.off"), "--size", "16x16", "-o", mesh}, "is the input file");
  expectRefused({"render", "--scene", mesh, "--size", "16x16", "--ao-float", mesh, "-o", path("x.png")},
                "is the input file");
  // Through a scene file: the meshes it names are inputs too, and so is the file itself.
  const std::string scene = write("scene.json", R"({"aoRadius": 1, "camera": {"position": [0, -3, 2], "focalPoint": [0, 0, 0]},
                                                    "objects": [{"mesh": "mesh.off"}]})");
  expectRefused({"render", "--scene", scene, "--size", "16x16", "-o", mesh}, "is the input file");
  expectRefused({"render", "--scene", scene, "--size", "16x16", "-o", scene}, "is the input file");
  for (const char* ext : {".png", ".f32", "-stderr.f32"})
    fs::create_symlink(mesh, path(std::string("ref") + ext));
  expectRefused({"reference", "--scene", mesh, "--size", "16x16", "--samples", "1", "-o", path("ref")},
                "is the input file");
  EXPECT_EQ(clitest::readAll(mesh), kTriangle);
}

TEST_F(CliOutputs, PathsThatAreNotFilesAreRefused) {
  fs::create_directories(path("folder"));
  expectRefused({"render", "--size", "16x16", "-o", path("folder")}, "folder: is a directory");
  expectRefused({"render", "--size", "16x16", "-o", path("missing/a.png")}, "folder " + path("missing") + " does not exist");
  expectRefused({"render", "--size", "16x16", "-o", ""}, "an output path is empty");
  if (geteuid() == 0 && mknod(path("block").c_str(), S_IFBLK | 0600, makedev(7, 0)) == 0)
    expectRefused({"render", "--size", "16x16", "-o", path("block")}, "block: is a block device");
}

// Root ignores permissions, so the read-only and full folders are small tmpfs mounts when root
// may mount (skipped otherwise); a plain chmod serves other users.
class CliMountedOutputs : public CliOutputs {
 protected:
  bool mountTmpfs(const std::string& where, const char* options) {
    fs::create_directories(where);
    if (geteuid() != 0 || mount("tmpfs", where.c_str(), "tmpfs", 0, options) != 0) return false;
    mounted_.push_back(where);
    return true;
  }
  void TearDown() override {
    for (const auto& m : mounted_) umount(m.c_str());
    CliOutputs::TearDown();
  }
  std::vector<std::string> mounted_;
};

TEST_F(CliMountedOutputs, ReadOnlyFolder) {
  const std::string ro = path("ro");
  if (geteuid() == 0) {
    if (!mountTmpfs(ro, "size=64k") || mount(nullptr, ro.c_str(), nullptr, MS_REMOUNT | MS_RDONLY, nullptr) != 0)
      GTEST_SKIP() << "cannot mount a read-only tmpfs here";
  } else {
    fs::create_directories(ro);
    fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
  }
  expectRefused({"render", "--size", "16x16", "-o", ro + "/a.png"}, "a.png: cannot create a file in " + ro);
}

TEST_F(CliMountedOutputs, FullDiskFoldsVtkErrorIntoOneLine) {
  if (!mountTmpfs(path("small"), "size=8k")) GTEST_SKIP() << "cannot mount a small tmpfs here";
  // vtkPNGWriter runs out of space: its own two-line error must not reach the terminal.
  const auto r = expectRefused({"render", "--size", "256x256", "-o", path("small/a.png")}, "a.png: cannot write PNG");
  EXPECT_EQ(r.err.find("vtkPNGWriter"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("ERROR"), std::string::npos) << r.err;
  expectRefused({"render", "--size", "64x64", "--ao-float", path("small/a.f32"), "-o", path("a.png")},
                "a.f32: cannot write (No space left on device)");
  EXPECT_TRUE(fs::is_empty(path("small")));
}
