// The bench chart: one panel per scene, a colour per method, every row a point. Read back from the
// PNG: the image has a panel per scene, and each method's colour appears in it (its points and
// its front), so many settings per method still draw every method.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include "bench/ErrorTimeChart.h"

using namespace aokit;

namespace {

BenchRow row(const std::string& scene, const std::string& method, const std::string& setting, double ms, double rmse) {
  BenchRow r;
  r.scene = scene;
  r.method = method;
  r.setting = setting;
  r.aoMs = ms;
  r.aoQ1Ms = ms * 0.9;
  r.aoQ3Ms = ms * 1.1;
  r.rmse = rmse;
  return r;
}

// Pixels within a few levels of an exact colour.
int countColour(vtkImageData* img, int r, int g, int b) {
  int n = 0;
  const int* dims = img->GetDimensions();
  const int comps = img->GetNumberOfScalarComponents();
  auto* p = static_cast<unsigned char*>(img->GetScalarPointer());
  for (int i = 0; i < dims[0] * dims[1]; ++i, p += comps)
    n += std::abs(p[0] - r) < 8 && std::abs(p[1] - g) < 8 && std::abs(p[2] - b) < 8;
  return n;
}

}  // namespace

TEST(ErrorTimeChart, EveryMethodDrawnInEveryPanel) {
  std::vector<BenchRow> rows;
  for (const std::string scene : {"a", "b"}) {
    rows.push_back(row(scene, "none", "", 0, 0.17));
    rows.push_back(row(scene, "vtkssao", "kernel=32", 150, 0.12));
    for (int i = 0; i < 8; ++i)  // settings that differ in more than a sample count
      rows.push_back(row(scene, "field", "kind=auto,resolution=" + std::to_string(8 * (i + 1)), 60 + 10 * i,
                         0.05 - 0.004 * i));
  }
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("aokit-chart-" + std::to_string(getpid()) + ".png")).string();
  writeErrorTimeChart(path, rows, 480, 360);
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* img = reader->GetOutput();
  EXPECT_EQ(img->GetDimensions()[0], 2 * 480);
  EXPECT_EQ(img->GetDimensions()[1], 360);
  EXPECT_GT(countColour(img, 214, 39, 40), 20) << "vtkssao (second method, red)";
  EXPECT_GT(countColour(img, 31, 119, 180), 100) << "field (third method, blue)";
  if (!getenv("AOKIT_KEEP_CHART")) std::filesystem::remove(path);
  else std::printf("chart: %s\n", path.c_str());
}
