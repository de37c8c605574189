#include "parallel/RankBounds.h"

#include <vector>

#include <vtkRenderer.h>

#include "parallel/RankExchange.h"

namespace aokit {

void visiblePropBounds(vtkRenderer* renderer, RankExchange* ranks, double bounds[6]) {
  renderer->ComputeVisiblePropBounds(bounds);  // an empty rank's: (+max, -max) on every axis
  if (!isParallel(ranks)) return;
  std::vector<double> v{bounds[0], -bounds[1], bounds[2], -bounds[3], bounds[4], -bounds[5]};
  ranks->minimum(v);
  for (int a = 0; a < 3; ++a) {
    bounds[2 * a] = v[2 * a];
    bounds[2 * a + 1] = -v[2 * a + 1];
  }
}

}  // namespace aokit
