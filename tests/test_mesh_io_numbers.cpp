// The pieces every input check stands on, against exact values: the one number parser, base64 as
// VTK writes it, the table of ranges and the camera rules.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "io/SceneLimits.h"
#include "io/TextNumbers.h"
#include "io/XmlScan.h"

using namespace aokit;

TEST(TextNumbers, WholeTokensOnly) {
  const std::pair<const char*, double> good[] = {
      {"0", 0.0},   {"-1", -1.0},     {"+2", 2.0},        {".5", 0.5},       {"2.", 2.0},
      {"1e3", 1e3}, {"-1.5E-2", -0.015}, {"007", 7.0},   {"1e-400", 0.0},   {"3.4028234e38", 3.4028234e38}};
  for (const auto& [text, value] : good) {
    double v = -99;
    EXPECT_TRUE(parseReal(text, v)) << text;
    EXPECT_EQ(v, value) << text;
  }
  for (const char* bad : {"", "1.2.3", "0x1g", "0x10", "0x1p3", "abc", "1e", "1e+", "--1", "+-1", "1,5", ".", "e5",
                          "1 ", " 1", "1f", "1..2", "1e5e5", "+", "-"})
    EXPECT_FALSE([&] { double v; return parseReal(bad, v); }()) << "'" << bad << "'";
  for (const char* special : {"nan", "NaN", "-nan", "inf", "-Infinity", "1e999"}) {
    double v = 0;
    EXPECT_TRUE(parseReal(special, v)) << special;
    EXPECT_FALSE(std::isfinite(v)) << special;
  }
}

TEST(TextNumbers, IntegersCountsAndCoordinates) {
  long long v = 0;
  EXPECT_TRUE(parseInteger("-5", -10, 10, v));
  EXPECT_EQ(v, -5);
  EXPECT_TRUE(parseInteger("+5", -10, 10, v));
  for (const char* bad : {"11", "-11", "1.0", "1e1", "+-1", "-", "", "0x5", "5 "})
    EXPECT_FALSE(parseInteger(bad, -10, 10, v)) << "'" << bad << "'";
  EXPECT_EQ(parseCount("4294967295", "n"), 4294967295ull);
  EXPECT_THROW(parseCount("4294967296", "n"), std::runtime_error);
  EXPECT_THROW(parseCount("-1", "n"), std::runtime_error);
  EXPECT_THROW(parseCount("+1", "n"), std::runtime_error);
  EXPECT_EQ(parseCoordinate("-2.5", "v"), -2.5f);
  EXPECT_THROW(parseCoordinate("1e39", "v"), std::runtime_error);  // finite double, infinite float
  try {
    parseCoordinate("1.2.3", "vertex 4");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "vertex 4: '1.2.3' is not a number");
  }
  EXPECT_EQ(printable(std::string("a\nb\x01") + std::string(50, 'x')), "a?b?" + std::string(36, 'x') + "...");
}

TEST(XmlScan, Base64AsVtkWritesIt) {
  std::string out;
  ASSERT_TRUE(decodeBase64("TWFu", out));
  EXPECT_EQ(out, "Man");
  ASSERT_TRUE(decodeBase64("TWE=", out));
  EXPECT_EQ(out, "Ma");
  // Two runs, each padded on its own (a header, then its data), with whitespace between.
  ASSERT_TRUE(decodeBase64("TQ==\n  TWFu", out));
  EXPECT_EQ(out, "MMan");
  EXPECT_FALSE(decodeBase64("TWF", out));    // a truncated group
  EXPECT_FALSE(decodeBase64("T===", out));   // too much padding
  EXPECT_FALSE(decodeBase64("TW=u", out));   // data after padding
  EXPECT_FALSE(decodeBase64("TW!u", out));
  EXPECT_EQ(base64Length(0), 0u);
  EXPECT_EQ(base64Length(4), 8u);
  EXPECT_EQ(base64Length(6), 8u);
}

TEST(SceneLimits, OneTableOfRanges) {
  EXPECT_TRUE(limits::kViewAngle.contains(1.0));
  EXPECT_TRUE(limits::kViewAngle.contains(179.0));
  EXPECT_FALSE(limits::kViewAngle.contains(0.5));
  EXPECT_FALSE(limits::kViewAngle.contains(std::nan("")));
  EXPECT_FALSE(limits::kAORadius.contains(0.0));
  EXPECT_TRUE(limits::kAORadius.contains(1e-9));
  EXPECT_FALSE(limits::kCubeCount.contains(2.5));
  EXPECT_EQ(limits::kViewAngle.describe(), "a number in [1, 179] degrees");
  EXPECT_EQ(limits::kCubeCount.describe(), "an integer in [1, 100]");
  EXPECT_EQ(limits::kSeed64.problemWith("18446744073709551615"), "");
  EXPECT_NE(limits::kSeed64.problemWith("18446744073709551616"), "");
  EXPECT_NE(limits::kSeed64.problemWith("-1"), "");
  EXPECT_EQ(limits::kSeed32.problemWith("4294967295"), "");
  EXPECT_NE(limits::kSeed32.problemWith("4294967296"), "");
  EXPECT_EQ(limits::kViewAngle.problemWith("30"), "");
  EXPECT_NE(limits::kViewAngle.problemWith("0x1E"), "");
}

TEST(SceneLimits, CameraRules) {
  Camera c;  // position (0,-5,3) looking at the origin, up +z: fine
  EXPECT_FALSE(cameraProblem(c));
  c.viewUp = {0, 0, 0};
  ASSERT_TRUE(cameraProblem(c));
  EXPECT_EQ(cameraProblem(c)->field, CameraProblem::ViewUp);
  EXPECT_EQ(cameraProblem(c)->what, "has zero length");
  c.viewUp = glm::normalize(c.focalPoint - c.position) * 3.0;  // parallel, any length
  ASSERT_TRUE(cameraProblem(c));
  EXPECT_EQ(cameraProblem(c)->what, "is parallel to the view direction");
  c = Camera();
  c.focalPoint = c.position;
  ASSERT_TRUE(cameraProblem(c));
  EXPECT_EQ(cameraProblem(c)->field, CameraProblem::FocalPoint);
  c = Camera();
  c.viewAngleDeg = 0.5;
  ASSERT_TRUE(cameraProblem(c));
  EXPECT_EQ(cameraProblem(c)->field, CameraProblem::ViewAngle);
  c = Camera();
  c.position.x = 2e15;
  ASSERT_TRUE(cameraProblem(c));
  EXPECT_EQ(cameraProblem(c)->field, CameraProblem::Position);
}
