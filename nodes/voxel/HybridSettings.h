#pragma once
// User settings of the voxelizer + Hybrid AO family (seed 004), as a plain struct with unit, range
// and default on each field (XeGTAO / Filament style), and a pure validate() that every bad value
// meets before anything is allocated: a grid past the memory budget is refused from its size alone.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "core/AOScene.h"
#include "core/Bounds.h"

namespace aokit {

enum class AOMapScale { Half = 2, Quarter = 4 };  // AO map size = screen size / value

// How the triangles become voxels (CpuVoxelizer.h simulates both GPU strategies exactly).
enum class VoxelizingFrame {
  ThreeAxis,  // conservative dominant-axis projection: every voxel a triangle touches, plus a few
              // at its edges (needs image atomics, or one grid per axis merged afterwards)
  Rotated,    // the seed's: one orthographic rasterization along a randomly rotated grid axis,
              // one voxel per covered column centre (ROP logic-op OR into RGBA32UI targets)
  DominantAxis,  // each triangle rasterized along its dominant grid axis, one voxel per covered
                 // column centre: thin like the seed's, nothing lost (needs image atomics too)
};

// Debug views of the GPU pass (HybridPass): the lit frame with AO (None), AO only, normals,
// depth, or the voxel grid seen from the camera (a ray cast through the grid, faces shaded by
// their axis).
enum class HybridView { None, AO, Normals, Depth, Voxels };

enum class RegionMode {
  Auto,  // bounds of the casters within R of the view frustum, clipped to regionBudget
  Box,   // the fixed world box `regionBox`
};

struct HybridSettings {
  // Voxel grid.
  int gridResolution = 256;         //!< voxels along the region's longest side, 64..1024
  double memoryBudgetMiB = 64.0;    //!< MiB the grid may hold, (0, 4096]; 512^3 = 16 MiB, 1024^3 = 128 MiB
  VoxelizingFrame frame = VoxelizingFrame::ThreeAxis;
  std::uint32_t frameSeed = 1;      //!< Rotated: seed of the random rotation (e.g. the frame number)
  bool solid = true;                //!< fill the inside of watertight casters (parity, SolidVoxelizer.h)
                                    //!<   so that long steps cannot pass through a hollow shell
  RegionMode region = RegionMode::Auto;
  Bounds regionBox;                 //!< world units; Box mode only: a valid box of positive volume
  double regionBudget = 64.0;       //!< longest side of the auto region, in units of R, 4..1024
  bool snapToLattice = true;        //!< voxel size on a 2^(1/8) ladder, grid origin on its multiples
                                    //!<   (VoxelFrame::onLattice): a moving camera does not shift the
                                    //!<   voxels; costs up to 9% of the resolution

  // AO sampling (eq. 4).
  int rays = 32;                    //!< rays per AO-map pixel, 1..256 (seed Table 1: 32)
  int steps = 8;                    //!< grid tests per ray, evenly spaced over R, 1..256 (seed: 8)
  bool spanTest = true;             //!< each step tests the voxels between the previous sample and
                                    //!<   this one along the grid's depth axis, in this sample's
                                    //!<   column (one texel of the packed grid): sheets across that
                                    //!<   axis (floors, table tops) are not stepped over; false =
                                    //!<   the seed's single voxel per step
  AOMapScale scale = AOMapScale::Half;
  double spread = 1.0;              //!< cone half-angle as a fraction of 90 degrees, (0, 1]; 1 = the
                                    //!<   whole hemisphere (what the reference integrates); the
                                    //!<   seed's Figure 4 shows 0.25..0.75
  double radius = 0.0;              //!< world units, >= 0; 0 = the scene's AO radius R
  std::optional<Falloff> falloff;   //!< weight k(d) of reference/Falloff.h; empty = the scene's
                                    //!<   (the seed uses Wendland)
  double normalOffset = 2.0;        //!< ray origins lifted along the normal, in voxels, 0..4; below
                                    //!<   sqrt(3) the origin's own voxel can hold the surface
  double jitterCell = 0.25;         //!< cell of the object-space jitter noise, in voxels, (0, 16]
  std::uint32_t jitterSeed = 0;     //!< any value; changes the noise pattern

  // Joint bilateral upsampling (eqs. 5-8). Every kernel is the Wendland w(t, h) of eq. 3; its
  // support h plays the role of a Gaussian's sigma.
  int filterSize = 16;              //!< m: window side in full-resolution pixels, 0..64; 0 = off
                                    //!<   (seed: 16 at half resolution; keep about 8 x scale)
  double normalSupport = 1.0;       //!< h of w_n over 1 - <n(x), n(y)>, (0, 2]; 1 gives creases of
                                    //!<   90 degrees no weight (the seed's 2 still gives them 0.19)
  double positionSupport = 1.0;     //!< h of w_p over |p(x) - p(y)|, in units of R, (0, 4] (seed: 1)
  double aoSupport = 1.0;           //!< h of w_h over |h'(x) - h'(y)|, AO units, (0, 1] (seed: 1)

  // Static plus dynamic (issue 9 item 5; StaticDynamic.h, StaticBake.h).
  bool staticBake = false;          //!< static geometry (no kDynamic in its node mask; ActorKeys.h
                                    //!<   propDynamic false) carries AO baked per vertex from the
                                    //!<   static casters (Embree, once); the grids cover only the
                                    //!<   dynamic casters' bounds grown by R; static receivers
                                    //!<   march the dynamic casters only, dynamic ones all casters
  int bakeRays = 256;               //!< rays per vertex of that bake, 1..4096

  HybridView view = HybridView::None;  //!< GPU pass only: what the frame shows
};

// Bytes of a bit-packed grid of nx x ny x nz voxels (VoxelGrid.h): nx ny ceil(nz / 128) 16.
std::size_t packedGridBytes(int nx, int ny, int nz);

// Throws std::invalid_argument with a one-line message ("hybrid: rays must be in 1..256, got 0")
// on the first bad field. The grid check uses the worst case, a cubic region (res^3 voxels).
void validate(const HybridSettings& s);

}  // namespace aokit
