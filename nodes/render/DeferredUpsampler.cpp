#include "render/DeferredUpsampler.h"

#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>

#include "DeferredUpsampleFS.h"
#include "render/BilateralUpsample.h"
#include "render/Textures.h"

namespace aokit {

DeferredUpsampler::DeferredUpsampler() : stage_("upsample", DeferredUpsampleFS) {}

void DeferredUpsampler::plan(DeferredPlan& plan, const std::string& defines) {
  if (plan.config.upsample.window > 0) plan.stage(stage_, defines);
}

void DeferredUpsampler::allocate(const DeferredFrame& f) {
  if (f.config.upsample.window <= 0) {
    rows_ = guide_ = nullptr;
    return;
  }
  const TexFormat format = f.config.aoChannels == 4 ? TexFormat::RGBA32F : TexFormat::R32F;
  ensureTexture2D(rows_, f.renWin, format, f.screenWidth, f.targetHeight);
  ensureTexture2D(guide_, f.renWin, TexFormat::RGBA32F, f.screenWidth, f.targetHeight);
}

void DeferredUpsampler::setKernelUniforms(vtkShaderProgram* p, const DeferredConfig& c) {
  p->SetUniformi("aoWindow", c.upsample.window);
  p->SetUniformf("aoPositionRadius", static_cast<float>(c.upsample.positionSupport * c.radius));
  p->SetUniformf("aoNormalSupport", static_cast<float>(c.upsample.normalSupport));
  p->SetUniformf("aoRange", static_cast<float>(c.upsample.aoSupport));
  if (c.upsample.window > 0) {
    const std::vector<float> domain = separableDomainWeights(c.upsample.window, c.downsample);
    p->SetUniform1fv("aoDomainWeights", static_cast<int>(domain.size()), domain.data());
  }
}

bool DeferredUpsampler::run(const DeferredFrame& f, vtkTextureObject* ao) {
  vtkShaderProgram* p = stage_.use(f.renWin);
  if (!p) return false;
  ActiveTextures inputs{ao};
  f.bindCommon(p);
  p->SetUniformi("aoResult", ao->GetTextureUnit());
  p->SetUniformi("aoDownsample", f.config.downsample);
  setKernelUniforms(p, f.config);
  stage_.renderInto(f.fbo, {rows_, guide_});
  return true;
}

void DeferredUpsampler::bindRows(vtkShaderProgram* p) const {
  if (rows_) p->SetUniformi("aoRows", rows_->GetTextureUnit());
  if (guide_) p->SetUniformi("aoRowGuide", guide_->GetTextureUnit());
}

std::size_t DeferredUpsampler::memoryBytes() const { return textureBytes(rows_) + textureBytes(guide_); }

void DeferredUpsampler::release(vtkWindow* w) {
  stage_.release(w);
  rows_ = guide_ = nullptr;
}

}  // namespace aokit
