#pragma once
// The visible props' bounds of a parallel renderer: every rank's, as one box (VTK's order: xmin,
// xmax, ymin, ymax, zmin, zmax; xmin > xmax when no rank shows anything). One reduction of 48
// bytes; with no exchange (or one rank) the renderer's own ComputeVisiblePropBounds.
class vtkRenderer;

namespace aokit {

class RankExchange;

void visiblePropBounds(vtkRenderer* renderer, RankExchange* ranks, double bounds[6]);

}  // namespace aokit
