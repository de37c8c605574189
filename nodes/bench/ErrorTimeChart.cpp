#include "bench/ErrorTimeChart.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartMatrix.h>
#include <vtkChartXY.h>
#include <vtkContextActor.h>
#include <vtkContextScene.h>
#include <vtkFloatArray.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotLine.h>
#include <vtkPlotPoints.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include "methods/MethodRegistry.h"
#include "output/ImageFiles.h"
#include "headless/OffscreenWindow.h"

namespace aokit {

namespace {
// A curve is a method at fixed switches, swept over its sample count: "vtkssao" over kernel sizes,
// "vtkssao blur=1" as a second curve. Sample-count keys are the swept ones.
std::string curveName(const BenchRow& r) {
  std::string name = r.method;
  for (const auto& kv : parseSettings(r.setting))
    if (kv.first != "kernel" && kv.first != "samples") name += " " + kv.first + "=" + kv.second;
  return name;
}

const unsigned char kColors[][3] = {{0, 0, 0},     {214, 39, 40}, {31, 119, 180}, {44, 160, 44},
                                    {255, 127, 14}, {148, 103, 189}, {140, 86, 75}, {227, 119, 194}};
}

void writeErrorTimeChart(const std::string& path, const std::vector<BenchRow>& rows, int panelWidth, int panelHeight) {
  std::vector<std::string> scenes, methodOrder;
  for (const auto& r : rows) {
    if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
    if (std::find(methodOrder.begin(), methodOrder.end(), curveName(r)) == methodOrder.end())
      methodOrder.push_back(curveName(r));
  }
  if (scenes.empty()) return;
  const int cols = std::min<int>(3, static_cast<int>(scenes.size()));
  const int rowsN = (static_cast<int>(scenes.size()) + cols - 1) / cols;
  OffscreenWindow window(panelWidth * cols, panelHeight * rowsN);
  window.renderer()->SetBackground(1, 1, 1);
  vtkNew<vtkChartMatrix> matrix;
  matrix->SetSize(vtkVector2i(cols, rowsN));
  vtkNew<vtkContextActor> actor;
  actor->GetScene()->AddItem(matrix);
  window.renderer()->AddActor(actor);

  for (std::size_t si = 0; si < scenes.size(); ++si) {
    // vtkChartMatrix counts rows from the bottom; fill from the top-left like reading order.
    const int cx = static_cast<int>(si) % cols, cy = rowsN - 1 - static_cast<int>(si) / cols;
    auto* chart = vtkChartXY::SafeDownCast(matrix->GetChart(vtkVector2i(cx, cy)));
    if (!chart) continue;
    chart->SetTitle(scenes[si]);
    chart->GetAxis(vtkAxis::LEFT)->SetTitle("RMSE vs reference");
    chart->GetAxis(vtkAxis::BOTTOM)->SetTitle("AO time (ms): median of paired differences, bar = quartiles");
    chart->SetShowLegend(true);
    // Error axis from 0, so the gap between curves reads as a ratio.
    double maxErr = 0;
    for (const auto& r : rows)
      if (r.scene == scenes[si]) maxErr = std::max(maxErr, r.rmse);
    vtkAxis* left = chart->GetAxis(vtkAxis::LEFT);
    left->SetBehavior(vtkAxis::FIXED);
    left->SetRange(0.0, maxErr > 0 ? 1.1 * maxErr : 1.0);
    for (std::size_t mi = 0; mi < methodOrder.size(); ++mi) {
      std::vector<const BenchRow*> pts;
      for (const auto& r : rows)
        if (r.scene == scenes[si] && curveName(r) == methodOrder[mi]) pts.push_back(&r);
      if (pts.empty()) continue;
      std::sort(pts.begin(), pts.end(), [](auto* a, auto* b) { return a->aoMs < b->aoMs; });
      vtkNew<vtkTable> table;
      vtkNew<vtkFloatArray> x, y;
      x->SetName("ao_ms");
      y->SetName(methodOrder[mi].c_str());
      table->AddColumn(x);
      table->AddColumn(y);
      table->SetNumberOfRows(static_cast<vtkIdType>(pts.size()));
      for (std::size_t i = 0; i < pts.size(); ++i) {
        table->SetValue(static_cast<vtkIdType>(i), 0, pts[i]->aoMs);  // never clamped: the bars show the spread
        table->SetValue(static_cast<vtkIdType>(i), 1, pts[i]->rmse);
      }
      vtkPlot* plot = chart->AddPlot(pts.size() > 1 ? vtkChart::LINE : vtkChart::POINTS);
      plot->SetInputData(table, 0, 1);
      const auto* c = kColors[mi % 8];
      plot->SetColor(c[0], c[1], c[2], 255);
      plot->SetWidth(2.0);
      if (auto* line = vtkPlotLine::SafeDownCast(plot)) line->SetMarkerStyle(vtkPlotPoints::CIRCLE);
      // Each point's AO-time spread: a horizontal bar over its paired differences' quartiles.
      for (const BenchRow* p : pts) {
        vtkNew<vtkTable> bar;
        vtkNew<vtkFloatArray> bx, by;
        bx->SetName("ao_ms");
        by->SetName("spread");
        bar->AddColumn(bx);
        bar->AddColumn(by);
        bar->SetNumberOfRows(2);
        bar->SetValue(0, 0, p->aoQ1Ms);
        bar->SetValue(1, 0, p->aoQ3Ms);
        bar->SetValue(0, 1, p->rmse);
        bar->SetValue(1, 1, p->rmse);
        vtkPlot* spread = chart->AddPlot(vtkChart::LINE);
        spread->SetInputData(bar, 0, 1);
        spread->SetColor(c[0], c[1], c[2], 160);
        spread->SetWidth(1.0);
        spread->SetLabel("");
        spread->SetLegendVisibility(false);
      }
    }
  }
  window.render();
  const RGBAImage img = window.readColor();
  writePNG(path, img.width, img.height, img.pixels);
}

}  // namespace aokit
