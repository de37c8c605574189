#include "parallel/GBufferComposite.h"

#include <climits>
#include <cstring>
#include <stdexcept>

#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "parallel/RankExchange.h"
#include "render/GBufferPass.h"

namespace aokit {

std::size_t compositeAcrossRanks(GBufferImage& image, RankExchange& ranks) {
  const std::size_t texels = image.depth.size();
  std::vector<float> nearest = image.depth;
  ranks.minimum(nearest);
  std::vector<int> owner(texels);
  const int me = ranks.rank();
  for (std::size_t i = 0; i < texels; ++i) owner[i] = image.depth[i] == nearest[i] ? me : INT_MAX;
  ranks.minimum(owner);

  // Every target in one buffer: this rank's texels where it owns them, zeros elsewhere.
  std::size_t perTexel = 0;
  for (std::size_t b : image.texelBytes) perTexel += b;
  std::vector<std::uint8_t> merged(texels * perTexel, 0);
  std::size_t offset = 0;
  for (std::size_t t = 0; t < image.targets.size(); ++t) {
    const std::size_t b = image.texelBytes[t];
    if (image.targets[t].size() != texels * b) throw std::invalid_argument("G-buffer composite: a target's size differs");
    for (std::size_t i = 0; i < texels; ++i)
      if (owner[i] == me) std::memcpy(&merged[offset + i * b], &image.targets[t][i * b], b);
    offset += texels * b;
  }
  ranks.bitwiseOr(merged);
  offset = 0;
  for (std::size_t t = 0; t < image.targets.size(); ++t) {
    const std::size_t b = image.texelBytes[t];
    std::memcpy(image.targets[t].data(), &merged[offset], texels * b);
    offset += texels * b;
  }
  image.depth = std::move(nearest);
  return texels * (sizeof(float) + sizeof(int) + perTexel);
}

namespace {

// The format and type that move a target's texels without conversion.
struct Transfer {
  unsigned format, type;
};

Transfer exactTransfer(unsigned internalFormat) {
  switch (internalFormat) {
    case GL_RGBA8: return {GL_RGBA, GL_UNSIGNED_BYTE};
    case GL_RGB10_A2: return {GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV};
    case GL_RGBA32F: return {GL_RGBA, GL_FLOAT};
    case GL_R8: return {GL_RED, GL_UNSIGNED_BYTE};
    case GL_R16F: return {GL_RED, GL_HALF_FLOAT};
    case GL_R32F: return {GL_RED, GL_FLOAT};
    default: break;
  }
  throw std::invalid_argument("G-buffer composite: a target format without an exact transfer");
}

GBufferOptions optionsOf(const GBufferPass& g) {
  GBufferOptions o;
  o.lean = g.GetLean();
  o.bakedAO = g.GetBakedAO();
  o.instanceIds = g.GetInstanceIds();
  o.facetNormals = g.GetFacetNormals();
  return o;
}

// Runs `move` with the texture bound on a unit of its own and byte-aligned rows.
template <class Move>
void withTexture(vtkTextureObject* t, Move&& move) {
  GLint pack = 4, unpack = 4;
  glGetIntegerv(GL_PACK_ALIGNMENT, &pack);
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpack);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  t->Activate();
  move();
  t->Deactivate();
  glPixelStorei(GL_PACK_ALIGNMENT, pack);
  glPixelStorei(GL_UNPACK_ALIGNMENT, unpack);
}

}  // namespace

bool readGBuffer(GBufferPass& gbuffer, GBufferImage& out) {
  vtkTextureObject* depth = gbuffer.GetDepthTexture();
  if (!depth) return false;
  const std::size_t texels = static_cast<std::size_t>(gbuffer.GetWidth()) * gbuffer.GetHeight();
  out.depth.resize(texels);
  withTexture(depth, [&] { glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, out.depth.data()); });
  const std::vector<GBufferTargetFormat> layout = gbufferLayout(optionsOf(gbuffer));
  out.targets.resize(layout.size());
  out.texelBytes.resize(layout.size());
  for (std::size_t k = 0; k < layout.size(); ++k) {
    vtkTextureObject* t = gbuffer.GetTexture(layout[k].target);
    if (!t) return false;
    const Transfer x = exactTransfer(layout[k].internalFormat);
    out.texelBytes[k] = layout[k].bytes;
    out.targets[k].resize(texels * layout[k].bytes);
    withTexture(t, [&] { glGetTexImage(GL_TEXTURE_2D, 0, x.format, x.type, out.targets[k].data()); });
  }
  return true;
}

void writeGBuffer(GBufferPass& gbuffer, const GBufferImage& image) {
  const int w = gbuffer.GetWidth(), h = gbuffer.GetHeight();
  withTexture(gbuffer.GetDepthTexture(),
              [&] { glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, image.depth.data()); });
  const std::vector<GBufferTargetFormat> layout = gbufferLayout(optionsOf(gbuffer));
  for (std::size_t k = 0; k < layout.size() && k < image.targets.size(); ++k) {
    const Transfer x = exactTransfer(layout[k].internalFormat);
    withTexture(gbuffer.GetTexture(layout[k].target),
                [&] { glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, x.format, x.type, image.targets[k].data()); });
  }
}

std::size_t compositeGBuffer(GBufferPass& gbuffer, RankExchange& ranks) {
  if (ranks.ranks() < 2) return 0;
  GBufferImage image;
  // Called right after the G-buffer's Render(): it exists on every rank.
  if (!readGBuffer(gbuffer, image)) throw std::runtime_error("G-buffer composite: no G-buffer to read");
  const std::size_t bytes = compositeAcrossRanks(image, ranks);
  writeGBuffer(gbuffer, image);
  return bytes;
}

}  // namespace aokit
