#include "voxel/GpuVoxelizer.h"

#include <algorithm>
#include <iostream>
#include <cmath>
#include <stdexcept>
#include <string>

#include <vtkOpenGLRenderWindow.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "VoxelMergeCS.h"
#include "VoxelizeCS.h"
#include "render/Textures.h"
#include "voxel/ComputeProgram.h"

namespace aokit {

namespace {
constexpr unsigned kLocalSize = 64;         // VoxelizeCS.glsl's local_size_x
constexpr int kTile = 16;                   // VoxelizeCS.glsl's VOX_TILE: columns per tile side
constexpr int kMaxSide = 2048;              // (kMaxSide / kTile)^2 tiles fit one dispatch's rows
constexpr unsigned kMaxGroups = 65535;      // the smallest GL_MAX_COMPUTE_WORK_GROUP_COUNT allowed

int modeOf(VoxelizeMethod m) {
  switch (m) {
    case VoxelizeMethod::ThreeAxis: return 0;
    case VoxelizeMethod::DominantCentre: return 1;
    case VoxelizeMethod::ColumnCentre: return 2;
    case VoxelizeMethod::Exact: break;
  }
  throw std::invalid_argument("GPU voxelizer: the exact method runs on the CPU only");
}

std::string modeDefine(int mode) { return "#define VOX_MODE " + std::to_string(mode) + "\n"; }

unsigned handleOf(vtkTextureObject* t) { return t ? t->GetHandle() : 0u; }

void clear(vtkTextureObject* t) {
  const unsigned zero = 0;
  glClearTexImage(t->GetHandle(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}
}  // namespace

glm::dmat4 worldToGrid(const VoxelFrame& frame) {
  const glm::dmat3 r = glm::transpose(frame.axes) / frame.voxelSize;
  glm::dmat4 m(r);
  m[3] = glm::dvec4(-(r * frame.origin), 1.0);
  return m;
}

GpuVoxelizer::GpuVoxelizer()
    : surface_(std::make_unique<ComputeProgram>("voxelize", VoxelizeCS)),
      parity_(std::make_unique<ComputeProgram>("voxelize parity", VoxelizeCS)),
      merge_(std::make_unique<ComputeProgram>("voxel merge", VoxelMergeCS)) {}

GpuVoxelizer::~GpuVoxelizer() = default;

const char* GpuVoxelizer::ready(vtkOpenGLRenderWindow* renWin, VoxelizeMethod method, bool solid, bool trim) {
  // GL 4.3 compute and image atomics, 4.4 texture clears, 4.5 direct state access: a context
  // without them (an old or macOS driver) gets the frame without AO, never a null call.
  if (!glDispatchCompute || !glMemoryBarrier || !glBindImageTexture || !glClearTexImage || !glCreateBuffers ||
      !glNamedBufferData || !glGetTextureImage || !glProgramUniformMatrix4fv || !glBindBufferBase) {
    if (!reportedMissing_)
      std::cerr << "aokit: the GPU voxelizer needs OpenGL 4.5 (compute shaders, image atomics, direct state "
                   "access); this context lacks them\n";
    reportedMissing_ = true;
    return "voxelize";
  }
  if (!surface_->ready(renWin, modeDefine(modeOf(method)))) return "voxelize";
  if (solid && !parity_->ready(renWin, modeDefine(3))) return "voxelize parity";
  if (solid && !merge_->ready(renWin, trim ? "#define VOX_TRIM 1\n" : "#define VOX_TRIM 0\n")) return "voxel merge";
  return nullptr;
}

void GpuVoxelizer::allocate(vtkOpenGLRenderWindow* renWin, const glm::ivec3& dims, bool solid) {
  VoxelGrid check(dims);  // throws on dims beyond the layout's limits
  if (std::max({dims.x, dims.y, dims.z}) > kMaxSide)
    throw std::invalid_argument("GPU voxelizer: at most " + std::to_string(kMaxSide) + " voxels per axis");
  const int w = 4 * dims.x, h = dims.y * check.slabs();
  int maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (w > maxSize || h > maxSize)
    throw std::invalid_argument("GPU voxelizer: a grid of " + std::to_string(dims.x) + " x " + std::to_string(dims.y) +
                                " x " + std::to_string(dims.z) + " needs a " + std::to_string(w) + " x " +
                                std::to_string(h) + " texture, over this context's limit of " +
                                std::to_string(maxSize));
  auto sized = [&](vtkSmartPointer<vtkTextureObject>& t) {
    if (!t) t = makeTexture2D(renWin, TexFormat::R32UI, w, h);
    else if (static_cast<int>(t->GetWidth()) != w || static_cast<int>(t->GetHeight()) != h) t->Resize(w, h);
  };
  sized(grid_);
  if (solid) sized(parityGrid_);
  else parityGrid_ = nullptr;
  dims_ = dims;
}

void GpuVoxelizer::run(vtkOpenGLRenderWindow* renWin, ComputeProgram& program, vtkTextureObject* target,
                       const VoxelFrame& frame, const CasterDraw& caster) {
  const CasterMesh& mesh = *caster.mesh;
  glm::dmat4 shift(1.0);
  shift[3] = glm::dvec4(mesh.shift, 1.0);
  const glm::mat4 modelToGrid(worldToGrid(frame) * caster.modelToWorld * shift);
  program.setMat4("voxModelToGrid", &modelToGrid[0][0]);
  program.setIVec3("voxDims", frame.dims.x, frame.dims.y, frame.dims.z);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, mesh.positions);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, mesh.indices);
  glBindImageTexture(0, handleOf(target), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);

  // A triangle's columns along any grid axis: at most floor(its extent in voxels) + 2, and no more
  // than the grid has. The stretch of the model -> grid map is at most its Frobenius norm.
  const glm::dmat3 linear(worldToGrid(frame) * caster.modelToWorld);
  double stretch = 0.0;
  for (int c = 0; c < 3; ++c) stretch += glm::dot(linear[c], linear[c]);
  stretch = std::sqrt(stretch);
  const int longestAxis = std::max({frame.dims.x, frame.dims.y, frame.dims.z});
  auto tilesFor = [&](float extent) {
    const double columns = std::min<double>(std::floor(extent * stretch) + 2.0, longestAxis);
    return static_cast<int>(std::ceil(columns / kTile));
  };
  // Classes of 1, 2, 4, ... tiles per axis; the triangles are sorted largest first, so each class
  // is one range of them, found by binary search.
  std::size_t end = mesh.triangles;
  for (int tiles = 1; end > 0; tiles *= 2) {
    // The first triangle (largest first) that needs no more than `tiles` tiles per axis.
    const auto firstFit = std::partition_point(mesh.extents.begin(), mesh.extents.begin() + end,
                                               [&](float e) { return tilesFor(e) > tiles; });
    const std::size_t begin = static_cast<std::size_t>(firstFit - mesh.extents.begin());
    program.setInt("voxTiles", tiles);
    const std::size_t perDispatch = static_cast<std::size_t>(kMaxGroups) * kLocalSize;
    for (std::size_t first = begin; first < end; first += perDispatch) {
      const std::size_t n = std::min(perDispatch, end - first);
      program.setUInt("voxFirst", static_cast<unsigned>(first));
      program.setUInt("voxCount", static_cast<unsigned>(first + n));
      program.dispatch(renWin, static_cast<unsigned>((n + kLocalSize - 1) / kLocalSize),
                       static_cast<unsigned>(tiles * tiles));
    }
    end = begin;
  }
}

void GpuVoxelizer::voxelize(vtkOpenGLRenderWindow* renWin, const VoxelFrame& frame,
                            const std::vector<CasterDraw>& casters, VoxelizeMethod method, bool solid, bool trim) {
  modeOf(method);
  allocate(renWin, frame.dims, solid);
  clear(grid_);
  bool anySolid = false;
  for (const CasterDraw& c : casters) anySolid = anySolid || (c.mesh && c.mesh->watertight);
  trim = trim && solid && anySolid;  // the open casters after the merge: trimming is for closed ones
  for (const CasterDraw& c : casters)
    if (c.mesh && (!trim || c.mesh->watertight)) run(renWin, *surface_, grid_, frame, c);
  if (solid && anySolid) {
    clear(parityGrid_);
    for (const CasterDraw& c : casters)
      if (c.mesh && c.mesh->watertight) run(renWin, *parity_, parityGrid_, frame, c);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindImageTexture(0, handleOf(grid_), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    glBindImageTexture(1, handleOf(parityGrid_), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
    merge_->setIVec3("voxDims", frame.dims.x, frame.dims.y, frame.dims.z);
    merge_->dispatch(renWin, (frame.dims.x + 7) / 8, (frame.dims.y + 7) / 8);
    glBindImageTexture(1, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
  }
  if (trim) {
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    for (const CasterDraw& c : casters)
      if (c.mesh && !c.mesh->watertight) run(renWin, *surface_, grid_, frame, c);
  }
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  // Later stages sample the grid as a texture, or read it back.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

bool GpuVoxelizer::readBack(VoxelGrid& out) const {
  if (!grid_) return false;
  out = VoxelGrid(dims_);
  std::vector<std::uint32_t>& words = out.words();
  // Rows of 4 nx words: every pack alignment fits.
  glGetTextureImage(grid_->GetHandle(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                    static_cast<GLsizei>(words.size() * sizeof(std::uint32_t)), words.data());
  return true;
}

std::size_t GpuVoxelizer::memoryBytes() const { return textureBytes(grid_) + textureBytes(parityGrid_); }

void GpuVoxelizer::release(vtkWindow* window) {
  surface_->release();
  parity_->release();
  merge_->release();
  if (grid_) grid_->ReleaseGraphicsResources(window);
  if (parityGrid_) parityGrid_->ReleaseGraphicsResources(window);
  grid_ = parityGrid_ = nullptr;
  dims_ = glm::ivec3(0);
}

}  // namespace aokit
