#include "fields/FieldTextures.h"

#include <algorithm>
#include <string>

#include <vtkOpenGLRenderWindow.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "fields/CapIntegralTable.h"
#include "fields/ConeTables.h"
#include "fields/HorizonLimit.h"
#include "render/Textures.h"

namespace aokit {

namespace {
void setSampler(vtkShaderProgram* p, const char* name, vtkTextureObject* t) { p->SetUniformi(name, t->GetTextureUnit()); }
}  // namespace

bool FieldTextures::upload(vtkOpenGLRenderWindow* renWin, const FieldGpuData& fields, const OccluderGpuData& occluders,
                           bool cones, std::string& error) {
  GLint maxTexels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
  const std::size_t largest = std::max(fields.texels4.size() / 4, fields.texels3.size() / 3);
  if (largest > static_cast<std::size_t>(maxTexels)) {
    error = "the fields need buffer textures of " + std::to_string(largest) + " texels, this GL allows " +
            std::to_string(maxTexels) + "; showing the frame without AO";
    return false;
  }
  if (fieldsDirty_) {
    texels4_ = makeBufferTexture(renWin, TexFormat::RGBA32F, fields.texels4.size() / 4, fields.texels4.data());
    texels3_ = makeBufferTexture(renWin, TexFormat::RGB32F, fields.texels3.size() / 3, fields.texels3.data());
    fieldInts_ = makeBufferTexture(renWin, TexFormat::RGBA32UI, fields.fieldInts.size() / 4, fields.fieldInts.data());
    fieldFloats_ = makeBufferTexture(renWin, TexFormat::RGBA32F, fields.fieldFloats.size() / 4, fields.fieldFloats.data());
    fieldsDirty_ = false;
  }
  if (occludersDirty_) {
    occluderFloats_ = makeBufferTexture(renWin, TexFormat::RGBA32F, occluders.floats.size() / 4, occluders.floats.data());
    occluderInts_ = makeBufferTexture(renWin, TexFormat::RGBA32UI, occluders.ints.size() / 4, occluders.ints.data());
    occludersDirty_ = false;
  }
  uploadedBytes_ = (fields.texels4.size() + fields.texels3.size() + fields.fieldFloats.size() + occluders.floats.size()) *
                       sizeof(float) +
                   (fields.fieldInts.size() + occluders.ints.size()) * sizeof(std::uint32_t);
  if (!capTable_) {
    const CapIntegralTable& cap = capIntegralTable();
    capTable_ = makeTexture2D(renWin, TexFormat::R32F, CapIntegralTable::kWidth, CapIntegralTable::kHeight,
                              cap.texels.data(), TexFilter::Linear);
    constexpr int h = HorizonTable::kSize;
    horizonTable_ = makeTexture3D(renWin, TexFormat::R32F, h, h, h, horizonTable().texels.data(), TexFilter::Linear);
  }
  if (cones && !clipTable_) {  // the cone tables only where cones are merged
    const ClipTable& clip = clipTable();
    clipTable_ = makeTexture2D(renWin, TexFormat::RG32F, ClipTable::kSize, ClipTable::kSize, clip.texels.data(),
                               TexFilter::Linear);
    constexpr int m = MergeTable::kSize;
    mergeTable_ = makeTexture3D(renWin, TexFormat::R32F, m, m, m, mergeTable().texels.data(), TexFilter::Linear);
  }
  return true;
}

std::vector<vtkTextureObject*> FieldTextures::textures(bool cones) const {
  std::vector<vtkTextureObject*> out{texels4_,        texels3_,     fieldInts_,  fieldFloats_, occluderFloats_,
                                     occluderInts_,   capTable_,    horizonTable_};
  if (cones) out.insert(out.end(), {clipTable_, mergeTable_});
  return out;
}

void FieldTextures::bind(vtkShaderProgram* p, const FieldConstants& c) const {
  setSampler(p, "fieldTexels4", texels4_);
  setSampler(p, "fieldTexels3", texels3_);
  setSampler(p, "fieldInts", fieldInts_);
  setSampler(p, "fieldFloats", fieldFloats_);
  setSampler(p, "occluderFloats", occluderFloats_);
  setSampler(p, "occluderInts", occluderInts_);
  setSampler(p, "fieldCapLUT", capTable_);
  setSampler(p, "fieldHorizonLUT", horizonTable_);
  if (c.cones()) {
    setSampler(p, "fieldClipLUT", clipTable_);
    setSampler(p, "fieldMergeLUT", mergeTable_);
  }
  p->SetUniformf("fieldInsideExponent", c.insideExponent);
  p->SetUniformf("fieldInsideOcclusion", c.insideOcclusion);
  p->SetUniformf("fieldBias", c.bias);
}

std::size_t FieldTextures::memoryBytes() const {
  return uploadedBytes_ + textureBytes(capTable_) + textureBytes(horizonTable_) + textureBytes(clipTable_) +
         textureBytes(mergeTable_);
}

void FieldTextures::release() {
  texels4_ = texels3_ = fieldInts_ = fieldFloats_ = occluderFloats_ = occluderInts_ = nullptr;
  capTable_ = horizonTable_ = clipTable_ = mergeTable_ = nullptr;
  uploadedBytes_ = 0;
  fieldsDirty_ = occludersDirty_ = true;
}

}  // namespace aokit
