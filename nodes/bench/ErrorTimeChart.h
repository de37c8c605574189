#pragma once
// The bench chart: one panel per scene, RMSE against AO time; each method one colour and legend
// entry, every setting a point with its time quartiles as a bar, and a line through the method's
// front (the settings no faster one beats in error). Drawn with VTK's charts offscreen.
#include <string>
#include <vector>

#include "bench/BenchResult.h"

namespace aokit {

void writeErrorTimeChart(const std::string& path, const std::vector<BenchRow>& rows, int panelWidth = 480,
                         int panelHeight = 360);

}  // namespace aokit
