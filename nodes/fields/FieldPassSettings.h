#pragma once
// What a user sets on the deferred field pass (FieldPass.h), as a plain struct with unit and range
// on each field and a pure validate(). The evaluator constants (combine, inside-hull blend, grid
// bias and weights) are those of FieldSettings.h; this adds how the pass runs and what it shows.
#include "fields/FieldSettings.h"

namespace aokit {

enum class FieldDebugView {
  None,     // the lit frame times (1 - AO)
  AO,       // 1 - AO as grey
  Normals,  // view-space normals (the G-buffer's)
  Depth,    // exp(-view distance / 8 R)
  Count,    // occluders evaluated per pixel (after culling), grey = count / 8: the cull at work
  Slice,    // the lit frame with a slice through the fields laid over it: A on a plane, A = 0 white,
            //   A = 1 red (FieldPassSliceFS.glsl)
};

struct FieldPassSettings {
  // Evaluator constants (FieldSettings.h has their meaning).
  FieldCombine combine = FieldCombine::Multiply;
  double insideExponent = 2.0;   //!< p of eq. 8, (0, 16]
  double insideOcclusion = 0.5;  //!< A0 of eq. 8, [0, 1]
  double bias = 1.0;             //!< grid normal offset, grid cells, [0, 4]
  GridWeights gridWeights = GridWeights::Normalized;

  // How the pass runs.
  double resolutionScale = 1.0;  //!< AO target size / screen size: 1, 0.5 or 0.25 (then depth-aware
                                 //!< upsampling). Full by default: the contact creases, where fields
                                 //!< are most of their worth, do not survive upsampling (cubes, 512 x
                                 //!< 384: RMSE 0.026 full, 0.042 half with grid6 fields)
  int upsampleWindow = 0;        //!< 0: bilinear taps within the depth tolerance; 2..32: the separable
                                 //!< joint bilateral filter over that many pixels (DeferredAOPass.h)
  double depthTolerance = 0.03;  //!< bilinear upsampling drops taps this far off in view depth,
                                 //!< fraction of the depth, (0, 1]

  FieldDebugView view = FieldDebugView::None;
  int sliceAxis = 2;             //!< slice view: the plane's normal axis, 0 x, 1 y, 2 z
  double slicePosition = 0.05;   //!< slice view: the plane's coordinate on that axis, world units
};

// Throws std::invalid_argument with one line ("field pass: sliceAxis must be 0, 1 or 2 ..., got 3").
void validate(const FieldPassSettings& s);

// The evaluator constants of a FieldSettings (what the pass and the CPU evaluation share).
FieldPassSettings passSettingsFrom(const FieldSettings& s);

std::string fieldDebugViewName(FieldDebugView v);  // "none", "ao", "normals", "depth", "count", "slice"

}  // namespace aokit
