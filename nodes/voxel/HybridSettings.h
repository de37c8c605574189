#pragma once
// User settings of the voxelizer + Hybrid AO family (seed 004), as a plain struct whose member
// initializers are the defaults, its schema (key, range, help: hybridSchema()), and a pure
// validate() that every bad value meets before anything is allocated: a grid past the memory
// budget is refused from its size alone. The debug view "voxels" ray-casts the grid from the
// camera, faces shaded by their axis, over the frame.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "core/Bounds.h"
#include "render/DeferredSettings.h"

namespace aokit {

// How the triangles become voxels (CpuVoxelizer.h simulates both GPU strategies exactly).
enum class VoxelizingFrame {
  ThreeAxis,  // conservative dominant-axis projection: every voxel a triangle touches, plus a few
              // at its edges (needs image atomics, or one grid per axis merged afterwards)
  Rotated,    // the seed's: one orthographic rasterization along a randomly rotated grid axis,
              // one voxel per covered column centre (ROP logic-op OR into RGBA32UI targets)
  DominantAxis,  // each triangle rasterized along its dominant grid axis, one voxel per covered
                 // column centre: thin like the seed's, nothing lost (needs image atomics too)
};

// How a ray leaves its own surface's voxels.
enum class RayLift {
  Normal,  // the seed's: the origin lifted along the normal by the offset (near casters seen from
           // the lifted point look larger: two tubes a voxel apart over-occlude by half)
  Ray,     // the ray starts on the surface; steps lower than the offset above its tangent plane
           // are not tested (rays as the reference's; the lowest offset of grazing rays is lost)
  Graze,   // between: each ray's origin lifted by offset max(0, 1 - reach cos theta) along the
           // normal, steps lower than the offset above the tangent plane not tested (little
           // parallax for rays near the normal, grazing rays start above the surface's voxels)
};           // Ray and Graze march as Normal where the lifted point's voxel is set (a crease).

struct HybridSettings {
  DeferredSettings common = deferredDefaults(AOScale::Half, 16);  //!< radius, falloff (the seed uses
                                    //!<   Wendland), half resolution, bilateral window m = 16 (the
                                    //!<   seed's; keep about 8 x downsample), kernels, view

  // Voxel grid.
  int gridResolution = 384;         //!< voxels along the region's longest side (the seed's 256
                                    //!<   fattens contacts and creases: 384 errs less on 14 of
                                    //!<   the 15 bench scenes at 1.4x the AO time, README)
  double memoryBudgetMiB = 64.0;    //!< MiB the grid may hold; 512^3 = 16 MiB, 1024^3 = 128 MiB
  VoxelizingFrame frame = VoxelizingFrame::DominantAxis;  //!< one voxel per column centre along each
                                    //!<   triangle's dominant axis: casters not fattened by up to a
                                    //!<   voxel each side (ThreeAxis, conservative) over-occlude gaps
  std::uint32_t frameSeed = 1;      //!< Rotated: seed of the random rotation (e.g. the frame number)
  bool solid = true;                //!< fill the inside of watertight casters (parity, SolidVoxelizer.h)
                                    //!<   so that long steps cannot pass through a hollow shell
  bool trimShell = true;            //!< with solid: a closed caster's surface voxels whose centre is
                                    //!<   outside it, beside a voxel inside it, dropped: its boundary
                                    //!<   is its inside, not fattened outward by half a voxel on
                                    //!<   average (thin parts, no inside voxel beside them, keep theirs;
                                    //!<   open casters are never trimmed). README: Trimmed solids
  Bounds regionBox{glm::dvec3(0.0), glm::dvec3(0.0)};  //!< world units: a fixed region of interest
                                    //!<   instead of the view's; all 0 = the view's (hasFixedRegion)
  double regionBudget = 64.0;       //!< longest side of the view's region, in units of R
  bool snapToLattice = true;        //!< voxel size on a 2^(1/8) ladder, grid origin on its multiples
                                    //!<   (VoxelFrame::onLattice): a moving camera does not shift the
                                    //!<   voxels; costs up to 9% of the resolution

  // AO sampling (eq. 4).
  int rays = 16;                    //!< rays per AO-map pixel (seed Table 1: 32; hybrid's error is
                                    //!<   nearly all bias, so 16 lose little and pay for the stride)
  int steps = 8;                    //!< grid tests per ray, evenly spaced over R (seed: 8)
  double stride = 1.0;              //!< most voxels one step may cross: where R / steps is longer
                                    //!<   on the grid, the ray takes more steps (up to 256), since
                                    //!<   a sheet thinner than a step across the grid's x or y is
                                    //!<   stepped over (open boxes, clipped isosurfaces; a finer grid
                                    //!<   then errs more); 0 = steps as set (the seed's)
  bool spanTest = true;             //!< each step tests the voxels between the previous sample and
                                    //!<   this one along the grid's depth axis, in this sample's
                                    //!<   column (one texel of the packed grid): sheets across that
                                    //!<   axis (floors, table tops) are not stepped over; false =
                                    //!<   the seed's single voxel per step
  bool segmentTest = false;         //!< with the span test: the ray walked column by column over R
                                    //!<   (ColumnWalk.h), each column over the depth the ray spends
                                    //!<   in it, no steps (lift=ray, graze start at one): every voxel it
                                    //!<   passes, so no sheet is stepped over (a step to the diagonal
                                    //!<   column passes between two voxels touching at an edge);
                                    //!<   off by default: about 1.3x the AO time (README: Steps
                                    //!<   through every column; Trimmed solids: with trim, better
                                    //!<   than the defaults on 8 of 15 scenes, worse on 4)
  double spread = 1.0;              //!< cone half-angle as a fraction of 90 degrees; 1 = the whole
                                    //!<   hemisphere (what the reference integrates); the seed's
                                    //!<   Figure 4 shows 0.25..0.75
  double normalOffset = 1.0;        //!< ray origins lifted along the normal, in voxels; below
                                    //!<   sqrt(3) the origin's own voxel can hold the surface (the
                                    //!<   march then leaves it for an empty neighbour); 1.25 loses
                                    //!<   the isosurface's thin sheets, 2 darkens contacts
  RayLift lift = RayLift::Normal;    //!< how rays leave their surface's voxels (above)
  double reach = 1.0;               //!< graze: a ray's lift is offset (1 - reach cos theta), at least 0
  double jitterCell = 0.25;         //!< cell of the object-space jitter noise, in voxels
  std::uint32_t jitterSeed = 0;     //!< any value; changes the noise pattern

  // Static plus dynamic (StaticDynamic.h, StaticBake.h).
  bool staticBake = false;          //!< static geometry (no kDynamic in its node mask; ActorKeys.h
                                    //!<   propDynamic false) carries AO baked per vertex from the
                                    //!<   static casters (Embree, once); the grids cover only the
                                    //!<   dynamic casters' bounds grown by R; static receivers
                                    //!<   march the dynamic casters only, dynamic ones all casters
  int bakeRays = 256;               //!< rays per vertex of that bake
};

// Keys, ranges and help of every setting above, and the rules between them (a fixed region is a
// box of positive volume; the grid fits the memory budget).
const Schema<HybridSettings>& hybridSchema();

// Whether the settings fix the region of interest (any of regionBox's coordinates non-zero).
bool hasFixedRegion(const HybridSettings& s);

// Bytes of a bit-packed grid of nx x ny x nz voxels (VoxelGrid.h): nx ny ceil(nz / 128) 16.
std::size_t packedGridBytes(int nx, int ny, int nz);

// Throws std::invalid_argument with a one-line message ("hybrid: rays must be an integer in 1..256, got 0")
// on the first bad field. The grid check uses the worst case, a cubic region (res^3 voxels).
void validate(const HybridSettings& s);

}  // namespace aokit
