// The settings core (settings/Schema.h): one table per family from which validation, text parsing,
// help and PrintSelf come, with every default read from the settings struct itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "baseline/VtkSSAOSettings.h"
#include "fields/FieldConstants.h"
#include "fields/FieldSettings.h"
#include "methods/MethodRegistry.h"
#include "pipeline/PipelineSettings.h"
#include "screen/ObscuranceSettings.h"
#include "voxel/HybridSettings.h"

using namespace aokit;

namespace {

enum class Colour { Red, Green };

struct Inner {
  double weight = 0.25;
};

struct Toy {
  int count = 3;
  double size = 0.0;  // 0 = automatic
  int level = 0;      // 0 = "auto"
  bool on = true;
  Colour colour = Colour::Green;
  std::string name = "x";
  Inner inner;
  double lo = 1.0, hi = 2.0;
};

Schema<Inner> innerSchema() {
  Schema<Inner> t("toy");
  t.number("weight", &Inner::weight, Interval::aboveZero(1), "a weight");
  return t;
}

const Schema<Toy>& toySchema() {
  static const Schema<Toy> schema = [] {
    Schema<Toy> t("toy");
    t.integer("count", &Toy::count, 1, 8, "how many");
    t.number("size", &Toy::size, Interval::closed(0.5, 4), "how big, metres", "automatic");
    t.integer("level", &Toy::level, 2, 9, "how deep", "from the size", "auto");
    t.flag("on", &Toy::on, "switched on");
    t.choice("colour", &Toy::colour, {{"red", Colour::Red}, {"green", Colour::Green}}, "its colour");
    t.text("name", &Toy::name, "what it is called");
    t.include(innerSchema(), &Toy::inner);
    t.number("lo", &Toy::lo, Interval::closed(0, 10), "lower end");
    t.number("hi", &Toy::hi, Interval::closed(0, 10), "upper end");
    t.rule([](const Toy& s) { return s.lo < s.hi; }, "lo must be below hi");
    return t;
  }();
  return schema;
}

std::string error(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(SettingsSchema, DefaultsComeFromTheStruct) {
  const auto infos = toySchema().infos();
  ASSERT_EQ(infos.size(), 9u);
  EXPECT_EQ(infos[0].defaultText, "3");
  EXPECT_EQ(infos[1].defaultText, "0");
  EXPECT_EQ(infos[2].defaultText, "auto");
  EXPECT_EQ(infos[3].defaultText, "1");
  EXPECT_EQ(infos[4].defaultText, "green");
  EXPECT_EQ(infos[5].defaultText, "x");
  EXPECT_EQ(infos[6].defaultText, "0.25");
  EXPECT_NO_THROW(toySchema().validate(Toy{}));
}

TEST(SettingsSchema, AnEmptyTextDefaultReadsEmptyAndTheWordGivesItBack) {
  // field's cacheDir defaults to "" (the user's cache); help prints it "empty", and that word,
  // copied from the help, must not become a folder named "empty".
  const auto infos = fieldSchema().infos();
  const auto it = std::find_if(infos.begin(), infos.end(), [](const SettingInfo& i) { return i.key == "cacheDir"; });
  ASSERT_NE(it, infos.end());
  EXPECT_EQ(it->defaultText, "empty");
  EXPECT_EQ(fieldSchema().parse({{"cacheDir", "empty"}}).cacheDirectory, "");
  EXPECT_EQ(fieldSchema().parse({{"cacheDir", "/tmp/x"}}).cacheDirectory, "/tmp/x");
}

TEST(SettingsSchema, ParsesEveryKindFromText) {
  const Toy t = toySchema().parse({{"count", "8"}, {"size", "2.5"}, {"level", "auto"}, {"on", "off"},
                                   {"colour", "red"}, {"name", "cup"}, {"weight", "1"}, {"lo", "0"}});
  EXPECT_EQ(t.count, 8);
  EXPECT_EQ(t.size, 2.5);
  EXPECT_EQ(t.level, 0);
  EXPECT_FALSE(t.on);
  EXPECT_EQ(t.colour, Colour::Red);
  EXPECT_EQ(t.name, "cup");
  EXPECT_EQ(t.inner.weight, 1.0);
  EXPECT_EQ(t.lo, 0.0);
  EXPECT_EQ(toySchema().parse({{"level", "5"}}).level, 5);
  EXPECT_EQ(toySchema().parse({{"size", "0"}}).size, 0.0);  // the meaningful zero
}

TEST(SettingsSchema, RefusesBadTextInOneLineNamingKeyRangeAndValue) {
  const Schema<Toy>& s = toySchema();
  EXPECT_EQ(error([&] { s.parse({{"count", "9"}}); }), "toy: count must be an integer in 1..8, got '9'");
  EXPECT_EQ(error([&] { s.parse({{"count", "2.0"}}); }), "toy: count must be an integer in 1..8, got '2.0'");
  EXPECT_EQ(error([&] { s.parse({{"size", "0x1p1"}}); }),
            "toy: size must be 0 (automatic) or a number in 0.5..4, got '0x1p1'");
  EXPECT_EQ(error([&] { s.parse({{"size", "1e"}}); }), "toy: size must be 0 (automatic) or a number in 0.5..4, got '1e'");
  EXPECT_EQ(error([&] { s.parse({{"size", "nan"}}); }),
            "toy: size must be 0 (automatic) or a number in 0.5..4, got 'nan'");
  EXPECT_EQ(error([&] { s.parse({{"size", "0.1"}}); }),
            "toy: size must be 0 (automatic) or a number in 0.5..4, got '0.1'");
  EXPECT_EQ(error([&] { s.parse({{"level", "1"}}); }),
            "toy: level must be auto (from the size) or an integer in 2..9, got '1'");
  EXPECT_EQ(error([&] { s.parse({{"on", "2"}}); }), "toy: on must be 0 or 1, got '2'");
  EXPECT_EQ(error([&] { s.parse({{"colour", "blue"}}); }), "toy: colour must be one of red, green, got 'blue'");
  EXPECT_EQ(error([&] { s.parse({{"weight", "0"}}); }), "toy: weight must be a number in (0, 1], got '0'");
  EXPECT_EQ(error([&] { s.parse({{"nope", "1"}}); }),
            "toy: unknown setting 'nope' (known: count, size, level, on, colour, name, weight, lo, hi)");
  EXPECT_EQ(error([&] { s.parse({{"lo", "3"}}); }), "toy: lo must be below hi");
}

TEST(SettingsSchema, ValidatesStructsSetFromCode) {
  Toy t;
  t.count = 0;
  EXPECT_EQ(error([&] { toySchema().validate(t); }), "toy: count must be an integer in 1..8, got 0");
  t = {};
  t.colour = static_cast<Colour>(7);
  EXPECT_EQ(error([&] { toySchema().validate(t); }), "toy: colour must be one of red, green, got (none of them)");
  t = {};
  t.inner.weight = NAN;
  EXPECT_EQ(error([&] { toySchema().validate(t); }), "toy: weight must be a number in (0, 1], got nan");
}

TEST(SettingsSchema, HelpAndPrintSayEverySetting) {
  const std::string help = toySchema().help();
  EXPECT_NE(help.find("  count: how many; an integer in 1..8 (default 3)\n"), std::string::npos) << help;
  EXPECT_NE(help.find("  level: how deep; auto (from the size) or an integer in 2..9 (default auto)\n"), std::string::npos)
      << help;
  std::ostringstream printed;
  toySchema().print(printed, Toy{}, "  ");
  EXPECT_NE(printed.str().find("  colour = green\n"), std::string::npos) << printed.str();
}

TEST(SettingsSchema, AKeyListedTwiceIsAProgrammingError) {
  Schema<Toy> t("toy");
  t.integer("count", &Toy::count, 1, 8, "how many");
  EXPECT_THROW(t.integer("count", &Toy::count, 1, 8, "again"), std::logic_error);
  EXPECT_THROW(t.include(innerSchema(), &Toy::inner).include(innerSchema(), &Toy::inner), std::logic_error);
}

// Every family's table: its defaults are valid, each default text reads back to the same value,
// every key has help, and the registry lists exactly the table's keys.
template <class S>
void checkFamily(const Schema<S>& schema, const std::string& method) {
  const S defaults{};
  EXPECT_NO_THROW(schema.validate(defaults)) << method;
  for (const auto& e : schema.entries()) {
    S s{};
    const std::string text = e.get(defaults);
    if (!text.empty()) EXPECT_NO_THROW(schema.set(s, e.info.key, text)) << method << " " << e.info.key << "=" << text;
    EXPECT_EQ(e.get(s), text) << method << " " << e.info.key;
    EXPECT_FALSE(e.info.help.empty()) << method << " " << e.info.key;
  }
  const MethodInfo& info = methodInfo(method);
  ASSERT_EQ(info.settings.size(), schema.entries().size()) << method;
  for (std::size_t i = 0; i < info.settings.size(); ++i) EXPECT_EQ(info.settings[i].key, schema.entries()[i].info.key);
}

TEST(SettingsSchema, EveryFamilyTableRoundTripsItsDefaults) {
  checkFamily(obscuranceSchema(), "obscurance");
  checkFamily(fieldSchema(), "field");
  checkFamily(hybridSchema(), "hybrid");
  checkFamily(vtkSSAOSchema(), "vtkssao");
  checkFamily(pipelineSchema(), "pipeline");
}

TEST(SettingsSchema, TheSharedSettingsHaveOneKeyAndOneMeaningInEveryFamily) {
  // The window: 0 is bilinear taps for every family (it was own-texel for hybrid), and its range
  // is the same on the command line as in C++.
  for (const char* method : {"obscurance", "field", "hybrid", "pipeline"}) {
    const MethodInfo& m = methodInfo(method);
    for (const char* key : {"radius", "falloff", "scale", "window", "tolerance", "hn", "hp", "ha", "view"}) {
      const auto it = std::find_if(m.settings.begin(), m.settings.end(), [&](const SettingInfo& s) { return s.key == key; });
      ASSERT_NE(it, m.settings.end()) << method << " lacks " << key;
      if (std::string(key) == "window") EXPECT_EQ(it->rangeText(), "0 (bilinear taps within the depth tolerance) or an integer in 1..64");
      if (std::string(key) == "hn") EXPECT_EQ(it->defaultText, "1") << method;
    }
  }
  EXPECT_EQ(methodInfo("hybrid").settings[3].defaultText, "16");  // hybrid's window, from its struct
  EXPECT_EQ(methodInfo("field").settings[2].defaultText, "1");    // fields at full resolution
}

// The families' constants functions are pure: settings and frame in, defines and uniforms out.
TEST(FamilyConstants, FieldModesDownsampleAndUniformsFollowTheSettings) {
  FieldSettings s;
  FieldConstants c = makeFieldConstants(s, FrameContext{2.0, Falloff::Binary});
  EXPECT_EQ(c.mode, 0);
  EXPECT_EQ(c.downsample, 1);
  EXPECT_NE(c.defines(1, 0).find("#define FIELD_CUBES 1\n#define FIELD_GRID 0\n#define FIELD_MODE 0\n"), std::string::npos);
  s.eval.combine = FieldCombine::Cone;
  s.common.scale = AOScale::Quarter;
  s.eval.insideOcclusion = 0.25;
  c = makeFieldConstants(s, FrameContext{2.0, Falloff::Binary});
  EXPECT_TRUE(c.cones());
  EXPECT_NE(c.defines(0, 2).find("#define FIELD_CONE 1\n"), std::string::npos);
  EXPECT_NE(c.defines(0, 2).find("#define FIELD_DOWNSAMPLE 4\n"), std::string::npos);
  EXPECT_EQ(c.insideOcclusion, 0.25f);
  s.common.view = DebugView::Count;  // the count view wins over the combine
  EXPECT_EQ(makeFieldConstants(s, FrameContext{2.0, Falloff::Binary}).mode, 2);
  s.eval.insideExponent = 0.0;
  EXPECT_THROW(makeFieldConstants(s, FrameContext{2.0, Falloff::Binary}), std::invalid_argument);
}

TEST(FamilyConstants, PipelineDefinesItsDownsample) {
  PipelineSettings s;
  EXPECT_EQ(makePipelineConstants(s, FrameContext{}).defines(), "#define PIPE_DOWNSAMPLE 2\n");
  s.common.scale = AOScale::Full;
  EXPECT_EQ(makePipelineConstants(s, FrameContext{}).defines(), "#define PIPE_DOWNSAMPLE 1\n");
}
