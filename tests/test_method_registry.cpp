// The method registry: settings strings, typed checks from each method's specs, registration.
#include <gtest/gtest.h>

#include <set>

#include "methods/MethodRegistry.h"

using namespace aokit;

namespace {
std::string error(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(MethodRegistry, ParsesKeyValueLists) {
  EXPECT_TRUE(parseSettings("").empty());
  const SettingMap m = parseSettings("samples=4,m=2");
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m.at("samples"), "4");
  EXPECT_EQ(m.at("m"), "2");
}

TEST(MethodRegistry, RejectsDuplicateKeysEmptyItemsAndBarePairs) {
  EXPECT_NE(error([] { parseSettings("samples=4,samples=8"); }).find("'samples' is given twice"), std::string::npos);
  EXPECT_NE(error([] { parseSettings("samples=4,,m=2"); }).find("empty item"), std::string::npos);
  EXPECT_NE(error([] { parseSettings("samples=4,"); }).find("empty item"), std::string::npos);
  EXPECT_NE(error([] { parseSettings("samples"); }).find("not key=value"), std::string::npos);
  EXPECT_NE(error([] { parseSettings("=4"); }).find("not key=value"), std::string::npos);
  EXPECT_NE(error([] { makeTechnique("obscurance", "samples=4,samples=8"); }).find("obscurance: "), std::string::npos);
}

TEST(MethodRegistry, ChecksValuesAgainstTheSpecs) {
  EXPECT_EQ(error([] { makeTechnique("vtkssao", "kernel=0"); }),
            "vtkssao: kernel must be an integer in 1..1000, got '0'");
  EXPECT_EQ(error([] { makeTechnique("vtkssao", "kernel=3x"); }),
            "vtkssao: kernel must be an integer in 1..1000, got '3x'");
  EXPECT_EQ(error([] { makeTechnique("vtkssao", "blur=2"); }), "vtkssao: blur must be 0 or 1, got '2'");
  EXPECT_EQ(error([] { makeTechnique("vtkssao", "bias=nan"); }), "vtkssao: bias must be a number in 0..1, got 'nan'");
  EXPECT_NE(error([] { makeTechnique("vtkssao", "r=1"); }).find("unknown setting 'r' (known: kernel, radius, bias, blur)"),
            std::string::npos);
  EXPECT_NE(error([] { makeTechnique("none", "x=1"); }).find("it takes none"), std::string::npos);
  EXPECT_NE(error([] { makeTechnique("nope", ""); }).find("unknown method 'nope' (known: none, vtkssao"),
            std::string::npos);
}

TEST(MethodRegistry, ListsTheBaseFrameAndBaselineFirstAndEveryMethodOnce) {
  const auto& all = methods();
  ASSERT_GE(all.size(), 3u);
  EXPECT_EQ(all[0].name, "none");
  EXPECT_EQ(all[1].name, "vtkssao");
  std::set<std::string> names;
  for (const auto& m : all) EXPECT_TRUE(names.insert(m.name).second) << m.name;
  EXPECT_TRUE(names.count("obscurance"));
}

TEST(MethodRegistry, EveryBenchSettingBuildsAndEveryKeyHasHelp) {
  for (const auto& m : methods()) {
    for (const auto& s : m.benchSettings) EXPECT_NO_THROW(makeTechnique(m.name, s)) << m.name << ": " << s;
    const std::string help = settingsHelp(m);
    for (const auto& spec : m.settings) {
      EXPECT_NE(help.find("  " + spec.key + ": "), std::string::npos) << m.name << " " << spec.key;
      EXPECT_FALSE(spec.help.empty()) << m.name << " " << spec.key;
      EXPECT_FALSE(spec.defaultText.empty()) << m.name << " " << spec.key;
    }
  }
}
