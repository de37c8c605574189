#pragma once
// What a deferred AO family asks of the shared pipeline each frame (render/DeferredAOPass.h), as
// plain structs: resolution, channels, G-buffer options, upsampling and debug view.

namespace aokit {

enum class DeferredDebugView {
  None,     // the lit frame times (1 - AO)
  AO,       // 1 - AO as grey (what the AO-only read-back sees)
  Normals,  // view-space normals mapped to [0, 1]
  Depth,    // exp(-view distance / 8 R): near is white
  Result,   // the family's result texture (first channel, grey) on every pixel: its own debug
            // image (voxels, field slices), best at downsample 1 with bilinear upsampling
};

struct UpsampleSettings {
  int window = 0;                //!< m, full-resolution pixels, 0..64: 0 = bilinear 2x2 taps only;
                                 //!< else the separable joint bilateral filter over m x m (1 = each
                                 //!< pixel's own texel, where it passes the range kernels)
  double depthTolerance = 0.03;  //!< bilinear mode: drop taps whose view depth differs from the
                                 //!< pixel's by more than this fraction of it, (0, 1]
  double positionRadius = 0.0;   //!< window mode: support of the position kernel w_p, world units;
                                 //!< 0 = the AO radius
  bool normalKernel = true;      //!< window mode: normal kernel w_n = w(1 - n.n', h_n)
  double normalSupport = 2.0;    //!< window mode: h_n, (0, 2]; 2 is the paper's (a 90-degree
                                 //!< crease keeps weight 0.19), 1 gives it none
  double aoRange = 1.0;          //!< window mode: support of the AO kernel w_h, 0 = off
};

struct DeferredConfig {
  int downsample = 1;       //!< 1, 2 or 4: the AO target is the screen size / downsample
  int aoChannels = 1;       //!< 1: occlusion in .r; 4: 1 - W per colour in .rgb, 1 - O in .a
  double guard = 0.0;       //!< G-buffer guard band, fraction of the screen on each side, 0..1
  bool instanceIds = false; //!< G-buffer instance-id target (GBufferPass::SetInstanceIds)
  bool bakedAO = false;     //!< combine per-vertex baked AO (render/BakedAO.h): 1 - (1 - baked)(1 - AO)
  double radius = 1.0;      //!< the AO radius R (world units): position kernel, depth debug view
  UpsampleSettings upsample;
  DeferredDebugView debugView = DeferredDebugView::None;
};

}  // namespace aokit
