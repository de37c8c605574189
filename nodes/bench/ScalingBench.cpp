#include "bench/ScalingBench.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartMatrix.h>
#include <vtkChartXY.h>
#include <vtkContextActor.h>
#include <vtkContextScene.h>
#include <vtkFloatArray.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderer.h>
#include <vtkTable.h>

#include "bench/Bench.h"
#include "bench/ChartColors.h"
#include "core/Geometry.h"
#include "core/NodeVisitor.h"
#include "core/TriangleMesh.h"
#include "headless/OffscreenWindow.h"
#include "methods/MethodRegistry.h"
#include "output/ImageFiles.h"
#include "scenes/BuiltinScenes.h"

namespace aokit {

std::vector<std::pair<std::string, std::string>> defaultScalingRuns() {
  return {{"pipeline", ""},
          {"obscurance", "samples=4"},
          {"field", "kind=auto"},
          {"hybrid", "res=256,rays=12,steps=5,scale=0.5"},
          {"vtkssao", "kernel=32"}};
}

namespace {

std::size_t triangleCount(Scene& scene) {
  std::size_t n = 0;
  for (const GeometryInstance& i : collectInstances(*scene.root))
    if (i.geometry && i.geometry->mesh()) n += i.geometry->mesh()->triangles.size();
  return n;
}

void benchPoint(const ScalingConfig& cfg, const std::vector<std::pair<std::string, std::string>>& runs,
                const std::string& axis, Scene scene, int width, int height, std::vector<ScalingRow>& rows) {
  BenchConfig bench;
  bench.scenes = {scene.name};
  bench.runs = runs;
  bench.width = width;
  bench.height = height;
  bench.refSamples = cfg.refSamples;
  bench.frames = cfg.frames;
  bench.seed = cfg.seed;
  bench.measureRawThroughput = false;
  bench.progress = cfg.progress;
  bench.loadScene = [&](const std::string&) { return scene; };
  const std::size_t triangles = triangleCount(scene);
  bench.onRow = [&](const BenchRow& r) {  // streamed: an interrupted run keeps its finished rows
    rows.push_back({axis, triangles, r});
    if (cfg.onRow) cfg.onRow(rows.back());
  };
  runBench(bench);
}

}  // namespace

std::vector<ScalingRow> runScalingBench(const ScalingConfig& cfg) {
  const auto runs = cfg.runs.empty() ? defaultScalingRuns() : cfg.runs;
  for (const auto& r : runs) makeTechnique(r.first, r.second);
  if (cfg.sizes.empty() || cfg.sphereSegments.empty()) throw std::invalid_argument("scaling: no points to measure");
  std::vector<ScalingRow> rows;
  for (const auto& [w, h] : cfg.sizes) benchPoint(cfg, runs, "resolution", makeBuiltinScene("sphere-plane"), w, h, rows);
  for (const auto& [slices, stacks] : cfg.sphereSegments) {
    Scene scene = makeSpherePlaneScene(slices, stacks);
    scene.name = "sphere-plane (sphere " + std::to_string(slices) + "x" + std::to_string(stacks) + ")";
    benchPoint(cfg, runs, "triangles", std::move(scene), cfg.trianglesWidth, cfg.trianglesHeight, rows);
  }
  return rows;
}

const std::vector<std::string>& scalingCsvColumns() {
  static const std::vector<std::string> cols = [] {
    std::vector<std::string> c = {"axis", "triangles"};
    for (const auto& b : benchCsvColumns()) c.push_back(b);
    return c;
  }();
  return cols;
}

std::string scalingCsvLine(const ScalingRow& r) {
  return r.axis + ',' + std::to_string(r.triangles) + ',' + benchCsvLine(r.row);
}

namespace {
void fillPanel(vtkChartXY* chart, const std::vector<ScalingRow>& rows, const std::string& axis) {
  std::vector<std::string> order;
  for (const auto& r : rows)
    if (r.axis == axis && std::find(order.begin(), order.end(), r.row.method) == order.end())
      order.push_back(r.row.method);
  const bool byPixels = axis == "resolution";
  chart->SetTitle(byPixels ? "AO time against resolution (sphere-plane)"
                           : "AO time against triangles (sphere-plane, 1024x768)");
  // log10 on a linear axis: VTK 9.1's log axes drop these line plots.
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(byPixels ? "megapixels" : "log10 of triangles");
  double maxMs = 0.0;
  for (const auto& r : rows)
    if (r.axis == axis) maxMs = std::max(maxMs, r.row.aoMs);
  vtkAxis* left = chart->GetAxis(vtkAxis::LEFT);
  left->SetTitle("AO time, ms (median of pairs)");
  left->SetBehavior(vtkAxis::FIXED);
  left->SetRange(0.0, maxMs > 0.0 ? 1.3 * maxMs : 1.0);  // headroom for the legend
  chart->SetShowLegend(true);
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::LEFT);
  for (std::size_t mi = 0; mi < order.size(); ++mi) {
    std::vector<const ScalingRow*> pts;
    for (const auto& r : rows)
      if (r.axis == axis && r.row.method == order[mi]) pts.push_back(&r);
    auto table = vtkSmartPointer<vtkTable>::New();
    vtkNew<vtkFloatArray> x, y;
    x->SetName("x");
    y->SetName(order[mi].c_str());
    table->AddColumn(x);
    table->AddColumn(y);
    table->SetNumberOfRows(static_cast<vtkIdType>(pts.size()));
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const BenchRow& b = pts[i]->row;
      table->SetValue(static_cast<vtkIdType>(i), 0,
                      byPixels ? b.width * double(b.height) / 1e6 : std::log10(double(pts[i]->triangles)));
      table->SetValue(static_cast<vtkIdType>(i), 1, b.aoMs);
    }
    const auto* c = kChartColors[mi % 8];
    vtkPlot* line = chart->AddPlot(vtkChart::LINE);
    line->SetInputData(table, 0, 1);
    line->SetColor(c[0], c[1], c[2], 255);
    line->SetWidth(2.0);
    if (auto* marks = vtkPlotPoints::SafeDownCast(line)) marks->SetMarkerStyle(vtkPlotPoints::CIRCLE);
  }
}
}  // namespace

void writeScalingChart(const std::string& path, const std::vector<ScalingRow>& rows) {
  OffscreenWindow window(2 * 560, 420);
  window.renderer()->SetBackground(1, 1, 1);
  vtkNew<vtkChartMatrix> matrix;
  matrix->SetSize(vtkVector2i(2, 1));
  vtkNew<vtkContextActor> actor;
  actor->GetScene()->AddItem(matrix);
  window.renderer()->AddActor(actor);
  fillPanel(vtkChartXY::SafeDownCast(matrix->GetChart(vtkVector2i(0, 0))), rows, "resolution");
  fillPanel(vtkChartXY::SafeDownCast(matrix->GetChart(vtkVector2i(1, 0))), rows, "triangles");
  window.render();
  const RGBAImage img = window.readColor();
  writePNG(path, img.width, img.height, img.pixels);
}

}  // namespace aokit
