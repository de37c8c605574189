// The fuzz harness (issue 10 item 6): seeded mutants of every input format and of scene files,
// plus special files, each run through `aokit render` and judged: no crash, no hang, exactly one
// line on stderr and exit 1 or 2 when refused, no output left behind by a refused run, a PNG when
// accepted, and no acceptance of a mutant that must be refused (tests/fuzz/Mutator.h).
//
// In the normal test run (CTest label "fuzz") each specimen gets AOKIT_FUZZ_PER_SPECIMEN mutants
// (default 18: about 300 in all with the special files). The long run (scripts/fuzz-long.sh)
// sets AOKIT_FUZZ_SECONDS and runs FuzzLong.Campaign, which reports counts per class and outcome.
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <atomic>
#include <cctype>
#include <cstdlib>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "CliHarness.h"
#include "fuzz/Mutator.h"
#include "fuzz/Specimens.h"

namespace fs = std::filesystem;
using clitest::CliResult;

namespace {

long envLong(const char* name, long fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::strtol(v, nullptr, 10) : fallback;
}

std::uint64_t mix(std::uint64_t a, std::uint64_t b) { return fuzz::Rng(a * 0x9E3779B97F4A7C15ull ^ b).next(); }

// What happened to one mutant. Findings are the outcomes that break the rules.
struct Outcome {
  std::string kind;  // refused, accepted, warned, or a finding: crash, hang, multi-line, partial-output,
                     // silent-accept, missing-output, slow
  std::string detail;
  bool finding() const { return kind != "refused" && kind != "accepted" && kind != "warned"; }
};

// A case to run: files to create in a fresh folder, the arguments (with {dir} replaced), and
// whether it must be refused.
struct Case {
  std::string label, cls;
  bool mustRefuse = false;
  std::vector<std::pair<std::string, std::string>> files;  // name -> bytes
  std::function<void(const fs::path&)> prepare;             // special files
  std::vector<std::string> args;
  std::set<std::string> outputs;  // names a refused run must not leave behind
};

constexpr double kHangSeconds = 60.0;   // the CLI is killed here
constexpr double kSlowSeconds = 10.0;   // a refusal slower than this is a finding (the rule is < 1 s)

Outcome judge(const Case& c, const fs::path& dir) {
  for (const auto& [name, bytes] : c.files) std::ofstream(dir / name, std::ios::binary) << bytes;
  if (c.prepare) c.prepare(dir);
  std::vector<std::string> args;
  for (std::string a : c.args) {
    if (const auto p = a.find("{dir}"); p != std::string::npos) a.replace(p, 5, dir.string());
    args.push_back(a);
  }
  const auto before = clitest::listing(dir);
  const CliResult r = clitest::runAokit(args, kHangSeconds);
  const auto after = clitest::listing(dir);
  if (r.timedOut) return {"hang", "killed after " + std::to_string(int(kHangSeconds)) + " s"};
  if (r.signal) return {"crash", "signal " + std::to_string(r.signal) + ": " + r.err};
  if (r.code != 0 && r.code != 1 && r.code != 2) return {"crash", "exit " + std::to_string(r.code) + ": " + r.err};
  if (r.code != 0) {
    if (!clitest::oneLine(r.err)) return {"multi-line", r.err};
    if (after != before) return {"partial-output", "a refused run changed its folder: " + r.err};
    if (r.seconds > kSlowSeconds) return {"slow", std::to_string(r.seconds) + " s: " + r.err};
    return {"refused", r.err};
  }
  if (c.mustRefuse) return {"silent-accept", r.out};
  const fs::path png = dir / "out.png";
  if (!fs::exists(png) || clitest::readAll(png).substr(1, 3) != "PNG") return {"missing-output", r.err};
  if (!r.err.empty()) return {clitest::oneLine(r.err) ? "warned" : "multi-line", r.err};
  return {"accepted", ""};
}

Case mutantCase(const fuzz::Specimen& s, std::uint64_t seed) {
  const fuzz::Mutant m = fuzz::mutate(s, seed);
  Case c;
  c.label = m.specimen + " seed " + std::to_string(seed);
  c.cls = m.cls;
  c.mustRefuse = m.mustRefuse;
  c.files = m.companions;
  c.files.emplace_back("mutant" + m.ext, m.bytes);
  c.args = {"render", "--scene", "{dir}/mutant" + m.ext, "--size", "16x12", "-o", "{dir}/out.png"};
  return c;
}

// Special files as inputs and outputs: each must be refused at once, never waited on.
std::vector<Case> specialCases() {
  std::vector<Case> cases;
  auto add = [&](const std::string& label, std::function<void(const fs::path&)> prepare, std::string input,
                 std::string output = "{dir}/out.png") {
    Case c;
    c.label = label;
    c.cls = "special-file";
    c.mustRefuse = true;
    c.prepare = std::move(prepare);
    c.args = {"render", "--scene", input, "--size", "16x12", "-o", output};
    cases.push_back(c);
  };
  const std::string tent = fuzz::offSpecimen().bytes;
  add("directory input", [](const fs::path& d) { fs::create_directories(d / "x.off"); }, "{dir}/x.off");
  add("fifo input", [](const fs::path& d) { mkfifo((d / "x.stl").c_str(), 0644); }, "{dir}/x.stl");
  add("/dev/zero input", [](const fs::path& d) { fs::create_symlink("/dev/zero", d / "x.ply"); }, "{dir}/x.ply");
  add("/dev/null input", [](const fs::path& d) { fs::create_symlink("/dev/null", d / "x.obj"); }, "{dir}/x.obj");
  add("dangling link input", [](const fs::path& d) { fs::create_symlink(d / "gone.vtk", d / "x.vtk"); }, "{dir}/x.vtk");
  add("link loop input", [](const fs::path& d) { fs::create_symlink(d / "x.vtp", d / "x.vtp"); }, "{dir}/x.vtp");
  add("empty input", [](const fs::path& d) { std::ofstream(d / "x.vtu"); }, "{dir}/x.vtu");
  add("sparse 2 GiB input", [](const fs::path& d) { fs::resize_file((std::ofstream(d / "x.off"), d / "x.off"), 2ull << 30); },
      "{dir}/x.off");
  add("sparse 2 GiB scene", [](const fs::path& d) { fs::resize_file((std::ofstream(d / "x.json"), d / "x.json"), 2ull << 30); },
      "{dir}/x.json");
  add("fifo scene", [](const fs::path& d) { mkfifo((d / "x.json").c_str(), 0644); }, "{dir}/x.json");
  auto withTent = [tent](std::function<void(const fs::path&)> more) {
    return [tent, more](const fs::path& d) {
      std::ofstream(d / "tent.off") << tent;
      more(d);
    };
  };
  add("output is a directory", withTent([](const fs::path& d) { fs::create_directories(d / "o.png"); }), "{dir}/tent.off",
      "{dir}/o.png");
  add("output is a fifo nobody reads", withTent([](const fs::path& d) { mkfifo((d / "o.png").c_str(), 0644); }),
      "{dir}/tent.off", "{dir}/o.png");
  add("output is the input", withTent([](const fs::path&) {}), "{dir}/tent.off", "{dir}/tent.off");
  add("output links to the input", withTent([](const fs::path& d) { fs::create_symlink(d / "tent.off", d / "o.png"); }),
      "{dir}/tent.off", "{dir}/o.png");
  add("output in a missing folder", withTent([](const fs::path&) {}), "{dir}/tent.off", "{dir}/no/o.png");
  if (geteuid() == 0)
    add("output is a full device", withTent([](const fs::path& d) { mknod((d / "full").c_str(), S_IFCHR | 0666, makedev(1, 7)); }),
        "{dir}/tent.off", "{dir}/full");
  return cases;
}

// Counts per (class, outcome), and the findings with what reproduces them.
class Tally {
 public:
  void add(const Case& c, const Outcome& o, const fs::path& dir, const fs::path& keep) {
    std::lock_guard<std::mutex> lock(mutex_);
    static const bool verbose = envLong("AOKIT_FUZZ_VERBOSE", 0) != 0;
    if (verbose) std::printf("%-22s %-14s %s: %s", c.cls.c_str(), o.kind.c_str(), c.label.c_str(),
                             o.detail.empty() || o.detail.back() != '\n' ? (o.detail + "\n").c_str() : o.detail.c_str());
    ++counts_[c.cls][o.kind];
    ++total_;
    if (!o.finding()) return;
    std::string where;
    if (!keep.empty()) {  // keep the mutant for reproduction
      const fs::path to = keep / (o.kind + "-" + std::to_string(findings_.size()));
      std::error_code ec;
      fs::create_directories(to, ec);
      for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.is_regular_file()) fs::copy_file(e.path(), to / e.path().filename(), ec);
      where = " (kept in " + to.string() + ")";
    }
    findings_.push_back(o.kind + " [" + c.cls + "] " + c.label + where + ": " + o.detail.substr(0, 300));
  }
  const std::vector<std::string>& findings() const { return findings_; }
  std::string report() const {
    std::set<std::string> kinds;
    for (const auto& [cls, byKind] : counts_)
      for (const auto& [kind, n] : byKind) kinds.insert(kind);
    std::ostringstream out;
    out << "| class |";
    for (const auto& k : kinds) out << " " << k << " |";
    out << "\n|---|";
    for (std::size_t i = 0; i < kinds.size(); ++i) out << "---|";
    out << "\n";
    for (const auto& [cls, byKind] : counts_) {
      out << "| " << cls << " |";
      for (const auto& k : kinds) out << " " << (byKind.count(k) ? byKind.at(k) : 0) << " |";
      out << "\n";
    }
    out << "\n" << total_ << " runs, " << findings_.size() << " findings\n";
    for (const auto& f : findings_) out << "- " << f << "\n";
    return out.str();
  }

 private:
  std::mutex mutex_;
  std::map<std::string, std::map<std::string, int>> counts_;
  std::vector<std::string> findings_;
  long total_ = 0;
};

// Runs cases from `next()` on `jobs` threads until it returns false.
void runCases(int jobs, const std::function<bool(Case&)>& next, Tally& tally, const fs::path& keep) {
  std::mutex nextMutex;
  std::vector<std::thread> workers;
  for (int w = 0; w < jobs; ++w)
    workers.emplace_back([&, w] {
      for (long i = 0;; ++i) {
        Case c;
        {
          std::lock_guard<std::mutex> lock(nextMutex);
          if (!next(c)) return;
        }
        const fs::path dir = fs::temp_directory_path() /
                             ("aokit-fuzz-" + std::to_string(getpid()) + "-" + std::to_string(w) + "-" + std::to_string(i));
        fs::remove_all(dir);
        fs::create_directories(dir);
        tally.add(c, judge(c, dir), dir, keep);
        std::error_code ec;
        fs::remove_all(dir, ec);
      }
    });
  for (auto& t : workers) t.join();
}

const std::vector<fuzz::Specimen>& specimens() {
  static const std::vector<fuzz::Specimen> all = fuzz::allSpecimens();
  return all;
}

}  // namespace

// Every specimen as written must be accepted: the mutants start from valid files.
TEST(FuzzSpecimens, AreValid) {
  for (const auto& s : specimens()) {
    SCOPED_TRACE(s.name);
    Case c;
    c.label = s.name;
    c.cls = "none";
    c.files = s.companions;
    c.files.emplace_back("specimen" + s.ext, s.bytes);
    c.args = {"render", "--scene", "{dir}/specimen" + s.ext, "--size", "16x12", "-o", "{dir}/out.png"};
    const fs::path dir = fs::temp_directory_path() / ("aokit-specimen-" + std::to_string(getpid()) + "-" + s.name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    const Outcome o = judge(c, dir);
    EXPECT_EQ(o.kind, "accepted") << o.detail;
    fs::remove_all(dir);
  }
}

class Fuzz : public ::testing::TestWithParam<std::size_t> {};

TEST_P(Fuzz, Mutants) {
  const fuzz::Specimen& s = specimens()[GetParam()];
  const long count = envLong("AOKIT_FUZZ_PER_SPECIMEN", 18);
  const std::uint64_t base = std::uint64_t(envLong("AOKIT_FUZZ_SEED", 2024));
  long i = 0;
  Tally tally;
  runCases(2, [&](Case& c) {
    if (i >= count) return false;
    c = mutantCase(s, mix(base, GetParam() * 1000003 + std::uint64_t(i++)));
    return true;
  }, tally, {});
  std::printf("%s\n", tally.report().c_str());
  EXPECT_TRUE(tally.findings().empty()) << tally.report();
}

INSTANTIATE_TEST_SUITE_P(Specimens, Fuzz, ::testing::Range<std::size_t>(0, fuzz::allSpecimens().size()),
                         [](const ::testing::TestParamInfo<std::size_t>& info) {
                           std::string name = fuzz::allSpecimens()[info.param].name;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

TEST(FuzzSpecial, Files) {
  const auto cases = specialCases();
  std::size_t i = 0;
  Tally tally;
  runCases(2, [&](Case& c) {
    if (i >= cases.size()) return false;
    c = cases[i++];
    return true;
  }, tally, {});
  std::printf("%s\n", tally.report().c_str());
  EXPECT_TRUE(tally.findings().empty()) << tally.report();
}

// The long run: AOKIT_FUZZ_SECONDS of mutants over every specimen (and the special files now and
// then), on AOKIT_FUZZ_JOBS workers from seed AOKIT_FUZZ_SEED; the report (classes x outcomes,
// findings with their kept mutants) goes to AOKIT_FUZZ_REPORT. See scripts/fuzz-long.sh.
TEST(FuzzLong, Campaign) {
  const long seconds = envLong("AOKIT_FUZZ_SECONDS", 0);
  if (seconds <= 0) GTEST_SKIP() << "set AOKIT_FUZZ_SECONDS (scripts/fuzz-long.sh) for the long run";
  const int jobs = int(envLong("AOKIT_FUZZ_JOBS", 2));
  const std::uint64_t base = std::uint64_t(envLong("AOKIT_FUZZ_SEED", 1));
  const char* reportPath = std::getenv("AOKIT_FUZZ_REPORT");
  const fs::path keep = std::getenv("AOKIT_FUZZ_FINDINGS") ? fs::path(std::getenv("AOKIT_FUZZ_FINDINGS")) : fs::path();
  const auto specials = specialCases();
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  std::uint64_t index = 0;
  Tally tally;
  runCases(jobs, [&](Case& c) {
    if (std::chrono::steady_clock::now() >= end) return false;
    const std::uint64_t i = index++;
    if (i % 100 == 99) {
      c = specials[(i / 100) % specials.size()];
    } else {
      const std::size_t which = i % specimens().size();
      c = mutantCase(specimens()[which], mix(base, i));
    }
    return true;
  }, tally, keep);
  const std::string report = "# aokit fuzz run\n\nseed " + std::to_string(base) + ", " + std::to_string(seconds) +
                             " s, " + std::to_string(jobs) + " jobs\n\n" + tally.report();
  std::printf("%s\n", report.c_str());
  if (reportPath) std::ofstream(reportPath) << report;
  EXPECT_TRUE(tally.findings().empty());
}
