#include "fields/FieldCull.h"

#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "FieldPassBoundsFS.h"
#include "render/GBufferPass.h"
#include "render/Textures.h"

namespace aokit {

FieldCull::FieldCull() : cells_("cull", FieldPassBoundsFS), reduce_("cull reduce", FieldPassBoundsFS) {}

bool FieldCull::readTileDepths(const DeferredFrame& f, TileDepths& tiles) {
  tiles.tile = kTile;
  tiles.tilesX = (f.targetWidth + kTile - 1) / kTile;
  tiles.tilesY = (f.targetHeight + kTile - 1) / kTile;
  const int partial[2] = {(f.targetWidth + kStep - 1) / kStep, (f.targetHeight + kStep - 1) / kStep};
  ensureTexture2D(partial_, f.renWin, TexFormat::RG32F, partial[0], partial[1]);
  ensureTexture2D(bounds_, f.renWin, TexFormat::RG32F, tiles.tilesX, tiles.tilesY);
  const int target[2] = {f.targetWidth, f.targetHeight}, count[2] = {tiles.tilesX, tiles.tilesY};
  vtkShaderProgram* p = cells_.use(f.renWin);
  if (!p) return false;
  f.bindCommon(p);
  p->SetUniform2i("fieldTarget", target);
  p->SetUniform2i("fieldTiles", partial);
  cells_.renderInto(f.fbo, {partial_});
  p = reduce_.use(f.renWin);
  if (!p) return false;
  p->SetUniform2i("fieldTiles", count);
  p->SetUniform2i("fieldPartialSize", partial);
  {
    ActiveTextures input{partial_};
    p->SetUniformi("fieldPartial", partial_->GetTextureUnit());
    reduce_.renderInto(f.fbo, {bounds_});
  }
  // A small read (8 bytes a tile); it waits for the G-buffer, which every later draw reads anyway.
  tiles.zRange.resize(2 * static_cast<std::size_t>(tiles.tilesX) * tiles.tilesY);
  f.state->PushReadFramebufferBinding();
  f.fbo->Bind(GL_READ_FRAMEBUFFER);
  f.fbo->AddColorAttachment(0, bounds_);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, tiles.tilesX, tiles.tilesY, GL_RG, GL_FLOAT, tiles.zRange.data());
  f.fbo->RemoveColorAttachment(0);
  f.state->PopReadFramebufferBinding();
  return true;
}

std::size_t FieldCull::memoryBytes() const { return textureBytes(partial_) + textureBytes(bounds_); }

void FieldCull::release(vtkWindow* w) {
  cells_.release(w);
  reduce_.release(w);
  partial_ = nullptr;
  bounds_ = nullptr;
}

TargetGeometry targetGeometry(const DeferredFrame& f) {
  TargetGeometry g;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) g.clip[r][c] = f.clip[r][c];
  g.gbufferWidth = f.gbuffer->GetWidth();
  g.gbufferHeight = f.gbuffer->GetHeight();
  g.guardX = f.gbuffer->GetGuardX();
  g.guardY = f.gbuffer->GetGuardY();
  g.screenWidth = f.screenWidth;
  g.screenHeight = f.screenHeight;
  g.downsample = f.config.downsample;
  g.targetWidth = f.targetWidth;
  g.targetHeight = f.targetHeight;
  return g;
}

}  // namespace aokit
