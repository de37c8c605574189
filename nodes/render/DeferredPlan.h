#pragma once
// What a deferred AO family asks of the shared pipeline each frame (render/DeferredAOPass.h): the
// pipeline's configuration and the family's programs with their #defines, which the base builds
// once, before anything is drawn, so that a program that does not compile leaves the frame
// without AO instead of half-drawn.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "render/DeferredSettings.h"
#include "render/FrameContext.h"

class vtkOpenGLRenderWindow;

namespace aokit {

class FullScreenStage;

struct DeferredConfig {
  int downsample = 1;        // 1, 2 or 4: the AO target is the screen size / downsample
  int aoChannels = 1;        // 1: occlusion in .r; 4: 1 - W per colour in .rgb, 1 - O in .a
  double guard = 0.0;        // G-buffer guard band, fraction of the screen on each side, 0..1
  bool instanceIds = false;  // G-buffer instance-id target (GBufferPass::SetInstanceIds)
  bool bakedAO = false;      // combine per-vertex baked AO (render/BakedAO.h): 1 - (1 - baked)(1 - AO)
  double radius = 1.0;       // the AO radius R (world units): position kernel, depth debug view
  UpsampleSettings upsample;
  DebugView view = DebugView::Off;  // Off, AO, Normals and Depth are the combine's; others the family's overlay
  bool facetNormals = false;  // the G-buffer's normal is the facet's (GBufferPass::SetFacetNormals)
  int accumulate = 1;         // still frames in the running mean (render/AOAccumulator.h); 1 = off
};

// The configuration a family's common settings give (downsample, upsampling, view, R).
DeferredConfig makeDeferredConfig(const DeferredSettings& s, const FrameContext& frame);

struct DeferredPlan {
  vtkOpenGLRenderWindow* renWin = nullptr;  // the window the programs are built for
  DeferredConfig config;
  // Full-screen stages and their defines; RenderAO binds them with FullScreenStage::use().
  std::vector<std::pair<FullScreenStage*, std::string>> stages;
  // Other programs (compute): a name for the report, and a builder that returns false on failure.
  std::vector<std::pair<std::string, std::function<bool()>>> programs;
  bool overlay = false;       // RenderOverlay() draws after the combine (the family's debug views)
  bool resultTarget = false;  // a second AO target, DeferredFrame::resultTarget, for a last stage

  void stage(FullScreenStage& s, std::string defines) { stages.emplace_back(&s, std::move(defines)); }
  void program(std::string name, std::function<bool()> build) { programs.emplace_back(std::move(name), std::move(build)); }
};

}  // namespace aokit
