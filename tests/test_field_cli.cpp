// `aokit bake`: a field file from a mesh; every bad input gives one line on stderr, a non-zero
// exit and no output file; Ctrl-C during a bake leaves nothing behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "CliHarness.h"

#include "fields/FieldFile.h"
#include "scenes/Shapes.h"

using namespace aokit;
namespace fs = std::filesystem;

namespace {

using clitest::CliResult;

// `aokit bake` with space-separated arguments (the test's paths have no spaces).
CliResult bake(const std::string& args, double interruptAfterSeconds = 0.0) {
  std::vector<std::string> argv{"bake"};
  std::istringstream in(args);
  for (std::string a; in >> a;) argv.push_back(a);
  return clitest::runAokit(argv, 120.0, interruptAfterSeconds);
}

void writeOff(const std::string& path, const TriangleMesh& m) {
  std::ofstream o(path);
  o << "OFF\n" << m.positions.size() << " " << m.triangles.size() << " 0\n";
  for (const auto& p : m.positions) o << p.x << " " << p.y << " " << p.z << "\n";
  for (const auto& t : m.triangles) o << "3 " << t.x << " " << t.y << " " << t.z << "\n";
}

class BakeCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("aokit-bake-" + std::to_string(getpid()));
    fs::create_directories(dir);
    box = (dir / "box.off").string();
    writeOff(box, *makeBox({1.0, 2.0, 0.5}));
  }
  void TearDown() override { fs::remove_all(dir); }
  std::size_t files() const { return std::distance(fs::directory_iterator(dir), fs::directory_iterator{}); }
  void expectError(const std::string& args, const std::string& expect) {
    const std::size_t before = files();
    const CliResult r = bake(args);
    EXPECT_NE(r.code, 0) << args;
    EXPECT_NE(r.err.find(expect), std::string::npos) << args << "\nstderr: " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\nstderr: " << r.err;
    EXPECT_EQ(files(), before) << args << ": left a file behind";
  }
  std::string out(const std::string& name) const { return (dir / name).string(); }
  fs::path dir;
  std::string box;
};

}  // namespace

TEST_F(BakeCli, Help) {
  const CliResult r = bake("--help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--kind"), std::string::npos);
  EXPECT_NE(r.out.find("--resolution"), std::string::npos);
}

TEST_F(BakeCli, BadInput) {
  expectError("--mesh " + out("missing.off") + " -o " + out("f.aof"), "missing.off");
  expectError("--mesh " + box + " --kind cone -o " + out("f.aof"), "unknown field kind 'cone'");
  expectError("--mesh " + box + " --resolution 0 -o " + out("f.aof"), "--resolution must be auto or an integer in 2..128");
  expectError("--mesh " + box + " --resolution 100000 -o " + out("f.aof"), "got '100000'");
  expectError("--mesh " + box + " --resolution 12x -o " + out("f.aof"), "got '12x'");
  expectError("--mesh " + box + " --radius -1 -o " + out("f.aof"), "--radius");
  expectError("--mesh " + box + " --falloff gauss -o " + out("f.aof"), "unknown falloff 'gauss'");
  expectError("--mesh " + box + " -o " + out("no-such-folder/f.aof"), "does not exist");
  expectError("--mesh " + box + " -o " + dir.string(), "is a folder");
  expectError("--mesh " + box, "output");
  writeOff(out("empty.off"), TriangleMesh{});
  expectError("--mesh " + out("empty.off") + " -o " + out("f.aof"), "empty.off");
}

TEST_F(BakeCli, WritesAFieldFile) {
  const std::string f = out("box.aof");
  const CliResult r = bake("--mesh " + box + " --kind grid4 --resolution 8 --radius 0.5 --falloff sqrt -o " + f);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("grid4 field, resolution 8"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("done"), std::string::npos) << r.err;  // progress on stderr
  const BakedField field = readFieldFile(f);
  EXPECT_EQ(field.info.kind, FieldKind::Grid4);
  EXPECT_EQ(field.info.resolution, 8);
  EXPECT_EQ(field.info.radius, 0.5);
  EXPECT_EQ(field.info.falloff, Falloff::Sqrt);
  EXPECT_EQ(field.vertexOcclusion.size(), 24u);  // the box's vertices
  // resolution auto: the rule of FieldResolution.h (cube, R = a tenth of the diagonal here).
  const CliResult a = bake("--mesh " + box + " --no-self-occlusion -o " + out("auto.aof"));
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_NE(a.out.find("(auto)"), std::string::npos) << a.out;
  EXPECT_TRUE(readFieldFile(out("auto.aof")).vertexOcclusion.empty());
}

TEST_F(BakeCli, InterruptLeavesNoFile) {
  // A bake of minutes, interrupted after a second: exit non-zero, "interrupted", no file, no temp.
  const std::string sphere = out("sphere.off");
  writeOff(sphere, *makeUVSphere(1.0, 128, 64));
  const std::string f = out("sphere.aof");
  const CliResult r = bake("--mesh " + sphere + " --kind cube --resolution 128 -o " + f, 1.5);
  EXPECT_FALSE(r.timedOut);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("interrupted"), std::string::npos) << r.err;
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().string().find("sphere.aof"), std::string::npos) << e.path();
}
