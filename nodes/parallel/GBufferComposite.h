#pragma once
// The G-buffer of every rank composited by depth (RankExchange.h): each texel takes the targets of
// the rank whose surface is nearest there (equal depths: the lowest rank), so every rank holds the
// G-buffer one process would have drawn. Three reductions: the minimum depth (4 bytes a texel), the
// owning rank (4), the owner's texels of every target ORed over zeros elsewhere (the layout's
// bytes: 9 in the lean layout, 11 with baked AO, 15 with instance ids too).
#include <cstddef>
#include <cstdint>
#include <vector>

class vtkOpenGLRenderWindow;

namespace aokit {

class GBufferPass;
class RankExchange;

// One rank's G-buffer on the CPU: window depth per texel and each target's texels, bottom row first.
struct GBufferImage {
  std::vector<float> depth;
  std::vector<std::vector<std::uint8_t>> targets;
  std::vector<std::size_t> texelBytes;  // of each target
};

// Replaces `image` (the same size and layout on every rank) by the composite of every rank's.
// Returns the bytes this rank contributed to the reductions.
std::size_t compositeAcrossRanks(GBufferImage& image, RankExchange& ranks);

// The G-buffer's targets and depth, read back exactly (context current); false before a frame.
bool readGBuffer(GBufferPass& gbuffer, GBufferImage& out);
// Writes `image` (read from the same G-buffer) back into its textures (context current).
void writeGBuffer(GBufferPass& gbuffer, const GBufferImage& image);

// readGBuffer, compositeAcrossRanks, writeGBuffer: the bytes contributed, 0 with one rank.
std::size_t compositeGBuffer(GBufferPass& gbuffer, RankExchange& ranks);

}  // namespace aokit
