// `aokit view`, driven as a person would drive it: synthetic key and mouse events through the
// interactor's own event API (--play), in its real event loop, on CTest's Xvfb. The screenshots are
// judged by numbers: in AO-only mode a pixel is 255 (1 - AO), so AO is read back from the PNG. The
// reference pane (Embree, computed on the worker thread when the camera rests) is the judge of the
// method pane beside it, at the probe points of the sphere over the floor and over the whole pane.
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <sys/wait.h>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <vtkAppendPolyData.h>
#include <vtkCamera.h>
#include <vtkElevationFilter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "DropinRig.h"

namespace {

struct ViewRun {
  int code = -1;
  std::string err;
  std::vector<nlohmann::json> shots;
};

// Runs aokit view with `args` (shell words), screenshots under a fresh prefix.
ViewRun runView(const std::string& args, const std::string& name, bool withDisplay = true) {
  const std::string dir = std::string(::testing::TempDir()) + "aokit-view-" + name;
  std::system(("rm -rf '" + dir + "' && mkdir -p '" + dir + "'").c_str());
  const std::string cmd = std::string(withDisplay ? "" : "env -u DISPLAY ") + "'" AOKIT_CLI "' view " + args +
                          " --shots '" + dir + "/s' > '" + dir + "/out' 2> '" + dir + "/err'";
  ViewRun r;
  const int status = std::system(cmd.c_str());
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
  std::ifstream err(dir + "/err");
  std::getline(err, r.err, '\0');
  std::ifstream lines(dir + "/s.jsonl");
  for (std::string line; std::getline(lines, line);) r.shots.push_back(nlohmann::json::parse(line));
  return r;
}

struct Shot {
  vtkSmartPointer<vtkImageData> image;
  nlohmann::json state;
  int width() const { return state["width"]; }
  int height() const { return state["height"]; }
  // 1 - red / 255 of pixel (x, y), bottom row first (PNG rows come back bottom-first from VTK).
  double ao(int x, int y) const { return 1.0 - image->GetScalarComponentAsDouble(x, y, 0, 0) / 255.0; }
  bool background(int x, int y) const {
    return std::abs(image->GetScalarComponentAsDouble(x, y, 0, 2) - std::lround(255 * 0.43)) <= 1 &&
           std::abs(image->GetScalarComponentAsDouble(x, y, 0, 0) - std::lround(255 * 0.32)) <= 1;
  }
  // Display position of world point p in pane k (the state's camera and viewport).
  bool project(int k, const double p[3], int& x, int& y) const {
    vtkNew<vtkRenderWindow> w;
    w->SetSize(width(), height());
    vtkNew<vtkRenderer> r;
    w->AddRenderer(r);
    const auto& vp = state["panes"][k]["viewport"];
    r->SetViewport(vp[0], vp[1], vp[2], vp[3]);
    const auto& c = state["camera"];
    vtkCamera* cam = r->GetActiveCamera();
    cam->SetPosition(c["position"][0], c["position"][1], c["position"][2]);
    cam->SetFocalPoint(c["focalPoint"][0], c["focalPoint"][1], c["focalPoint"][2]);
    cam->SetViewUp(c["viewUp"][0], c["viewUp"][1], c["viewUp"][2]);
    cam->SetViewAngle(c["viewAngle"]);
    r->SetWorldPoint(p[0], p[1], p[2], 1.0);
    r->WorldToDisplay();
    x = static_cast<int>(std::lround(r->GetDisplayPoint()[0]));
    y = static_cast<int>(std::lround(r->GetDisplayPoint()[1]));
    return x >= 3 && y >= 3 && x + 3 < width() && y + 3 < height();
  }
  // Mean AO over 7 x 7 pixels around world point p in pane k.
  double aoAt(int k, const double p[3]) const {
    int x, y;
    EXPECT_TRUE(project(k, p, x, y)) << "probe off screen";
    double sum = 0.0;
    for (int dy = -3; dy <= 3; ++dy)
      for (int dx = -3; dx <= 3; ++dx) sum += ao(x + dx, y + dy);
    return sum / 49.0;
  }
};

Shot load(const nlohmann::json& state) {
  Shot s;
  s.state = state;
  vtkNew<vtkPNGReader> png;
  png->SetFileName(state["png"].get<std::string>().c_str());
  png->Update();
  s.image = png->GetOutput();
  return s;
}

// Pane 0 (a method) against pane 1 (the reference) pixel by pixel, left half against right half:
// mean |AO difference| over the pixels where both show a surface, above the labels.
double meanDifference(const Shot& s) {
  const int half = s.width() / 2;
  double sum = 0.0;
  long n = 0;
  for (int y = 40; y < s.height(); ++y)
    for (int x = 0; x < half; ++x) {
      if (s.background(x, y) || s.background(x + half, y)) continue;
      sum += std::abs(s.ao(x, y) - s.ao(x + half, y));
      ++n;
    }
  EXPECT_GT(n, 20000) << "the panes show too little surface";
  return n ? sum / n : 1.0;
}

const double kContact[3] = {0.0, -1.0, 0.0}, kOpen[3] = {2.2, 1.5, 0.0};
// 1.0 from the sphere: occluded with R 1.5, and by nothing at all once R is under 1.0.
const double kMid[3] = {0.0, -1.6, 0.0};

}  // namespace

TEST(DropinView, KeysMouseAndTheReferencePane) {
  AOKIT_REQUIRE_DISPLAY();
  const ViewRun r = runView(
      "sphere-plane --size 800x300 --compare obscurance,reference --reference-samples 128 --play "
      "'shot:lit;key:o;rest;shot:obscurance;key:m;wait:200;shot:hybrid;key:-;key:-;rest;shot:narrow;"
      "drag:80,0;rest;shot:turned;key:o;shot:lit-again'",
      "keys");
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(r.shots.size(), 6u) << r.err;
  // The labels are 2D overlays: no family may call them casters that cast nothing.
  EXPECT_EQ(r.err.find("casts no AO"), std::string::npos) << r.err;
  const Shot lit = load(r.shots[0]), obscurance = load(r.shots[1]), hybrid = load(r.shots[2]),
             narrow = load(r.shots[3]), turned = load(r.shots[4]), litAgain = load(r.shots[5]);

  // 'o': AO only, and back.
  EXPECT_FALSE(lit.state["aoOnly"]);
  EXPECT_TRUE(obscurance.state["aoOnly"]);
  EXPECT_FALSE(litAgain.state["aoOnly"]);

  // AO where the closed form has it (the floor just in front of the gap under the sphere), none
  // beyond R of the sphere; the reference pane says how much, the method pane follows it.
  const double refContact = obscurance.aoAt(1, kContact), refOpen = obscurance.aoAt(1, kOpen);
  std::printf("reference pane: contact %.3f open %.3f; obscurance %.3f %.3f; hybrid %.3f %.3f\n", refContact, refOpen,
              obscurance.aoAt(0, kContact), obscurance.aoAt(0, kOpen), hybrid.aoAt(0, kContact), hybrid.aoAt(0, kOpen));
  EXPECT_GT(refContact, 0.2);
  EXPECT_LT(refOpen, 0.02);
  EXPECT_NEAR(obscurance.aoAt(0, kContact), refContact, 0.12);
  EXPECT_LT(obscurance.aoAt(0, kOpen), 0.03);

  // 'm': the next method, in the label and in the pixels.
  EXPECT_EQ(hybrid.state["panes"][0]["method"], "hybrid");
  EXPECT_NE(hybrid.state["panes"][0]["label"].get<std::string>().find("hybrid, R 1.500, AO "), std::string::npos);
  EXPECT_NEAR(hybrid.aoAt(0, kContact), refContact, 0.08);
  const double hybridDiff = meanDifference(hybrid);
  std::printf("hybrid pane against the reference pane: mean |difference| %.4f\n", hybridDiff);
  EXPECT_LT(hybridDiff, 0.04);

  // '-' twice: R / 1.25^2 = 0.96 in every pane. kMid is 1.0 from the sphere: no occluder within R
  // there (AO exactly 0 by the definition), where R 1.5 had some; the reference follows R too.
  EXPECT_DOUBLE_EQ(narrow.state["radius"].get<double>(), 0.96);
  EXPECT_TRUE(narrow.state["panes"][1]["fresh"]);
  std::printf("R 1.5 -> 0.96 at 1.0 from the sphere: reference %.3f -> %.3f, hybrid %.3f -> %.3f; contact "
              "reference %.3f -> %.3f\n", hybrid.aoAt(1, kMid), narrow.aoAt(1, kMid), hybrid.aoAt(0, kMid),
              narrow.aoAt(0, kMid), refContact, narrow.aoAt(1, kContact));
  EXPECT_GT(hybrid.aoAt(1, kMid), 0.08);
  EXPECT_GT(hybrid.aoAt(0, kMid), 0.08);
  EXPECT_LT(narrow.aoAt(1, kMid), 0.01);
  EXPECT_LT(narrow.aoAt(0, kMid), 0.02);
  EXPECT_GT(narrow.aoAt(1, kContact), 0.1);  // 0.56 from the sphere: still within R
  EXPECT_LT(meanDifference(narrow), 0.04);

  // A drag turns the shared camera; the reference pane is computed again for the new view.
  EXPECT_NE(turned.state["camera"]["position"], narrow.state["camera"]["position"]);
  EXPECT_TRUE(turned.state["panes"][1]["fresh"]);
  const double turnedDiff = meanDifference(turned);
  std::printf("after the drag: mean |difference| %.4f\n", turnedDiff);
  EXPECT_LT(turnedDiff, 0.04);

  // Lit, the AO darkens the contact floor against the open floor (the headlight shades both alike).
  EXPECT_GT(lit.aoAt(0, kContact) - lit.aoAt(0, kOpen), 0.15);
}

TEST(DropinView, BadInputGetsOneLine) {
  AOKIT_REQUIRE_DISPLAY();
  struct Case {
    const char* args;
    const char* says;
    bool display;
  };
  const Case cases[] = {
      {"no-such-scene --play shot:x", "unknown scene 'no-such-scene'", true},
      {"sphere-plane --method fog --play shot:x", "not 'fog'", true},
      {"sphere-plane --setting samples=0 --play shot:x", "samples", true},
      {"sphere-plane --compare reference --play shot:x", "needs a method pane", true},
      {"sphere-plane --play 'jump:3'", "'jump:3' is not a step", true},
      {"sphere-plane --play shot:x", "no X display", false},
  };
  for (const Case& c : cases) {
    const ViewRun r = runView(c.args, "bad", c.display);
    EXPECT_EQ(r.code, 1) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << ": " << r.err;
    EXPECT_TRUE(r.shots.empty()) << c.args;
  }
}

// A VTK file as a scientific user has one: a sphere over a floor with a point scalar array. The
// viewer colours by it (lit: the sphere's top and bottom differ in hue) and AO-only still reads the
// AO of the geometry (the contact floor occluded, the open floor not).
TEST(DropinView, VtkFileColouredByItsFirstPointArray) {
  AOKIT_REQUIRE_DISPLAY();
  const std::string file = std::string(::testing::TempDir()) + "aokit-view-sphere-floor.vtp";
  {
    vtkNew<vtkAppendPolyData> both;  // the rig's sphere and floor in one file
    both->AddInputConnection(aokit::dropin::canonicalSphere()->GetOutputPort());
    both->AddInputConnection(aokit::dropin::canonicalFloor()->GetOutputPort());
    vtkNew<vtkElevationFilter> height;  // the point array "Elevation", 0 at z = 0 to 1 at z = 2.2
    height->SetInputConnection(both->GetOutputPort());
    height->SetLowPoint(0, 0, 0);
    height->SetHighPoint(0, 0, 2.2);
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(file.c_str());
    writer->SetInputConnection(height->GetOutputPort());
    ASSERT_EQ(writer->Write(), 1);
  }
  const ViewRun r = runView("'" + file + "' --size 480x360 --ao-radius 1.5 --camera-position 0,-6.5,4 "
                            "--focal-point 0,0,0.7 --play 'shot:lit;key:o;shot:ao'", "vtkfile");
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(r.shots.size(), 2u);
  const Shot lit = load(r.shots[0]), ao = load(r.shots[1]);
  const double top[3] = {0.0, -0.6, 2.0}, bottom[3] = {0.0, -0.9, 0.8};
  int xt, yt, xb, yb;
  ASSERT_TRUE(lit.project(0, top, xt, yt));
  ASSERT_TRUE(lit.project(0, bottom, xb, yb));
  auto channel = [&](int x, int y, int c) { return lit.image->GetScalarComponentAsDouble(x, y, 0, c); };
  std::printf("lit sphere: top rgb %.0f %.0f %.0f, bottom %.0f %.0f %.0f; AO only: contact %.3f open %.3f\n",
              channel(xt, yt, 0), channel(xt, yt, 1), channel(xt, yt, 2), channel(xb, yb, 0), channel(xb, yb, 1),
              channel(xb, yb, 2), ao.aoAt(0, kContact), ao.aoAt(0, kOpen));
  // VTK's default lookup table runs from red (low) to blue (high).
  EXPECT_GT(channel(xt, yt, 2) - channel(xt, yt, 0), 40.0) << "the top should be blue";
  EXPECT_GT(channel(xb, yb, 0) - channel(xb, yb, 2), 40.0) << "the lower sphere should be red";
  EXPECT_GT(ao.aoAt(0, kContact), 0.2);
  EXPECT_LT(ao.aoAt(0, kOpen), 0.03);
}

// accumulate=N in the viewer: a resting view keeps drawing until the mean holds N frames, and a
// drag starts it again.
TEST(DropinView, ARestingViewConverges) {
  AOKIT_REQUIRE_DISPLAY();
  const ViewRun r = runView("sphere-plane --size 400x300 --setting accumulate=8 --play "
                            "'wait:3000;shot:rested;drag:30,0;shot:moved'", "accumulate");
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(r.shots.size(), 2u);
  const std::string rested = r.shots[0]["panes"][0]["label"], moved = r.shots[1]["panes"][0]["label"];
  EXPECT_NE(rested.find(", 8 frames"), std::string::npos) << rested;
  EXPECT_EQ(moved.find(", 8 frames"), std::string::npos) << moved;
}
