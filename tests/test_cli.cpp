// The aokit executable's error paths: every bad input gives one line on stderr, a non-zero exit,
// and no output file (not even a half-written one).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

namespace {

struct CliRun {
  int code = -1;
  std::string out, err;
};

CliRun aokit(const std::string& args) {
  static int counter = 0;
  const fs::path errFile = fs::temp_directory_path() / ("aokit-cli-err-" + std::to_string(getpid()) + "-" +
                                                        std::to_string(counter++));
  const std::string cmd = "env -u DISPLAY " + std::string(AOKIT_CLI) + " " + args + " 2>" + errFile.string();
  CliRun r;
  FILE* p = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
  std::ifstream e(errFile);
  r.err.assign(std::istreambuf_iterator<char>(e), {});
  fs::remove(errFile);
  return r;
}

class CliErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("aokit-cli-" + std::to_string(getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }

  std::string write(const std::string& name, const std::string& content) {
    const fs::path p = dir / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }
  // A failing run: non-zero, one line on stderr naming `expect`, nothing left in the output folder.
  void expectError(const std::string& args, const std::string& expect) {
    const auto before = std::distance(fs::directory_iterator(dir), fs::directory_iterator{});
    const CliRun r = aokit(args);
    EXPECT_NE(r.code, 0) << args;
    EXPECT_NE(r.err.find(expect), std::string::npos) << args << "\nstderr: " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\nstderr: " << r.err;
    const auto after = std::distance(fs::directory_iterator(dir), fs::directory_iterator{});
    EXPECT_EQ(before, after) << args << ": left a file behind";
  }
  std::string out(const std::string& name) const { return (dir / name).string(); }
  fs::path dir;
};

}  // namespace

TEST_F(CliErrors, NeedsASubcommand) {
  expectError("", "ubcommand");
  expectError("frobnicate", "frobnicate");
}

TEST_F(CliErrors, UnknownOptionsAndScenes) {
  expectError("render --no-such-option -o " + out("a.png"), "no-such-option");
  expectError("render --scene no-such-scene -o " + out("a.png"), "unknown scene 'no-such-scene'");
}

TEST_F(CliErrors, MissingAndMalformedMeshes) {
  expectError("render --scene " + out("missing.off") + " -o " + out("a.png"), "missing.off");
  const std::string garbage = write("garbage.off", std::string("\x01\x02\xff\xfe not a mesh"));
  expectError("render --scene " + garbage + " -o " + out("a.png"), "garbage.off");
  const std::string empty = write("empty.obj", "");
  expectError("render --scene " + empty + " -o " + out("a.png"), "empty.obj");
  const std::string nan = write("nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
  expectError("render --scene " + nan + " -o " + out("a.png"), "nan.off");
}

TEST_F(CliErrors, MalformedSceneFile) {
  const std::string bad = write("bad.json", "{ \"objects\": [ ");
  expectError("render --scene " + bad + " -o " + out("a.png"), "bad.json");
}

TEST_F(CliErrors, AbsurdImageSizes) {
  expectError("render --size 0x10 -o " + out("a.png"), "--size");
  expectError("render --size 100000x100 -o " + out("a.png"), "--size");
  expectError("render --size banana -o " + out("a.png"), "--size");
}

TEST_F(CliErrors, BadMethodsSettingsAndCamera) {
  expectError("render --method no-such -o " + out("a.png"), "unknown method 'no-such'");
  expectError("render --method vtkssao --setting kernel=0 -o " + out("a.png"), "kernel");
  expectError("render --method vtkssao --setting wobble=1 -o " + out("a.png"), "wobble");
  expectError("render --camera-position nan,0,0 -o " + out("a.png"), "camera-position");
  expectError("render --ao-radius -1 -o " + out("a.png"), "ao-radius");
  expectError("bench --methods no-such -o " + out("bench"), "unknown method 'no-such'");
  expectError("reference --samples 0 -o " + out("ref"), "samples");
}

TEST_F(CliErrors, UnwritableOutputLeavesNothing) {
  expectError("render --size 32x24 -o " + out("no-such-dir/a.png"), "a.png");
}

TEST_F(CliErrors, RenderWritesAPng) {
  const CliRun r = aokit("render --size 64x48 -o " + out("ok.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream f(out("ok.png"), std::ios::binary);
  char magic[8] = {};
  f.read(magic, 8);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  EXPECT_EQ(r.err.find("GLEW"), std::string::npos) << "GLEW must initialize under OSMesa: " << r.err;
}

// bench and demo create their output folder (README: `bash scripts/demo.sh` writes a new aokit-demo/).
TEST_F(CliErrors, BenchAndDemoCreateTheirOutputFolder) {
  const CliRun bench = aokit("bench --scenes sphere-plane --methods none --size 32x24 --samples 4 --frames 1 "
                             "--no-temporal -o " + out("new-bench"));
  ASSERT_EQ(bench.code, 0) << bench.err;
  EXPECT_TRUE(fs::is_regular_file(out("new-bench/results.csv")));
  const CliRun demo = aokit("demo --size 32x24 -o " + out("new-demo"));
  ASSERT_EQ(demo.code, 0) << demo.err;
  EXPECT_TRUE(fs::is_regular_file(out("new-demo/report.md")));
}

TEST_F(CliErrors, HelpEverywhere) {
  for (const char* sub : {"", "render", "reference", "bench", "demo"}) {
    const CliRun r = aokit(std::string(sub) + " --help");
    EXPECT_EQ(r.code, 0) << sub;
    EXPECT_NE(r.out.find("--"), std::string::npos) << sub;
  }
}
