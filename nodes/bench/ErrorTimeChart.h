#pragma once
// The bench chart: one panel per scene, RMSE against AO time, each method a curve over its
// settings. Drawn with VTK's charts in an offscreen window.
#include <string>
#include <vector>

#include "bench/BenchResult.h"

namespace aokit {

void writeErrorTimeChart(const std::string& path, const std::vector<BenchRow>& rows, int panelWidth = 480,
                         int panelHeight = 360);

}  // namespace aokit
