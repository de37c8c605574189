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
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include "bench/ChartColors.h"
#include "output/ImageFiles.h"
#include "headless/OffscreenWindow.h"

namespace aokit {

namespace {
vtkSmartPointer<vtkTable> xyTable(const std::vector<const BenchRow*>& pts, const std::string& yName) {
  auto table = vtkSmartPointer<vtkTable>::New();
  vtkNew<vtkFloatArray> x, y;
  x->SetName("ao_ms");
  y->SetName(yName.c_str());
  table->AddColumn(x);
  table->AddColumn(y);
  table->SetNumberOfRows(static_cast<vtkIdType>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i) {
    table->SetValue(static_cast<vtkIdType>(i), 0, pts[i]->aoMs);  // never clamped: the bars show the spread
    table->SetValue(static_cast<vtkIdType>(i), 1, pts[i]->rmse);
  }
  return table;
}

// The settings no faster setting of the same method beats in error: what a user picks from.
std::vector<const BenchRow*> paretoFront(std::vector<const BenchRow*> pts) {
  std::sort(pts.begin(), pts.end(), [](auto* a, auto* b) { return a->aoMs < b->aoMs; });
  std::vector<const BenchRow*> front;
  for (const BenchRow* p : pts)
    if (front.empty() || p->rmse < front.back()->rmse) front.push_back(p);
  return front;
}
}  // namespace

void writeErrorTimeChart(const std::string& path, const std::vector<BenchRow>& rows, int panelWidth, int panelHeight) {
  std::vector<std::string> scenes, methodOrder;
  for (const auto& r : rows) {
    if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
    if (std::find(methodOrder.begin(), methodOrder.end(), r.method) == methodOrder.end())
      methodOrder.push_back(r.method);
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
    chart->GetAxis(vtkAxis::BOTTOM)->SetTitle("AO time, ms (median of pairs; bar: quartiles)");
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
        if (r.scene == scenes[si] && r.method == methodOrder[mi]) pts.push_back(&r);
      if (pts.empty()) continue;
      // Every setting a point (one legend entry per method), its best-for-the-time settings a line.
      const auto* c = kChartColors[mi % 8];
      vtkPlot* points = chart->AddPlot(vtkChart::POINTS);
      points->SetInputData(xyTable(pts, methodOrder[mi]), 0, 1);
      points->SetColor(c[0], c[1], c[2], 255);
      points->SetWidth(2.0);
      if (auto* marks = vtkPlotPoints::SafeDownCast(points)) marks->SetMarkerStyle(vtkPlotPoints::CIRCLE);
      const std::vector<const BenchRow*> front = paretoFront(pts);
      if (front.size() > 1) {
        vtkPlot* line = chart->AddPlot(vtkChart::LINE);
        line->SetInputData(xyTable(front, methodOrder[mi] + " front"), 0, 1);
        line->SetColor(c[0], c[1], c[2], 255);
        line->SetWidth(1.5);
        line->SetLegendVisibility(false);
      }
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
