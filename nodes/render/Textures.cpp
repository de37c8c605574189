#include "render/Textures.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <vtkOpenGLBufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

namespace aokit {

namespace {

struct GLFormat {
  unsigned internalFormat, format, type;
  int components, vtkType;
  std::size_t bytes;
};

GLFormat glFormat(TexFormat f) {
  switch (f) {
    case TexFormat::R8: return {GL_R8, GL_RED, GL_UNSIGNED_BYTE, 1, VTK_UNSIGNED_CHAR, 1};
    case TexFormat::RGBA8: return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, VTK_UNSIGNED_CHAR, 4};
    case TexFormat::R16F: return {GL_R16F, GL_RED, GL_FLOAT, 1, VTK_FLOAT, 2};
    case TexFormat::RG16F: return {GL_RG16F, GL_RG, GL_FLOAT, 2, VTK_FLOAT, 4};
    case TexFormat::RGBA16F: return {GL_RGBA16F, GL_RGBA, GL_FLOAT, 4, VTK_FLOAT, 8};
    case TexFormat::R32F: return {GL_R32F, GL_RED, GL_FLOAT, 1, VTK_FLOAT, 4};
    case TexFormat::RG32F: return {GL_RG32F, GL_RG, GL_FLOAT, 2, VTK_FLOAT, 8};
    case TexFormat::RGB32F: return {GL_RGB32F, GL_RGB, GL_FLOAT, 3, VTK_FLOAT, 12};
    case TexFormat::RGBA32F: return {GL_RGBA32F, GL_RGBA, GL_FLOAT, 4, VTK_FLOAT, 16};
    case TexFormat::R32UI: return {GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, 1, VTK_UNSIGNED_INT, 4};
    case TexFormat::RG32UI: return {GL_RG32UI, GL_RG_INTEGER, GL_UNSIGNED_INT, 2, VTK_UNSIGNED_INT, 8};
    case TexFormat::RGBA32UI: return {GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, 4, VTK_UNSIGNED_INT, 16};
  }
  throw std::logic_error("unknown texture format");
}

bool isInteger(TexFormat f) { return f == TexFormat::R32UI || f == TexFormat::RG32UI || f == TexFormat::RGBA32UI; }

vtkSmartPointer<vtkTextureObject> newTexture(vtkOpenGLRenderWindow* renWin, TexFormat format, TexFilter filter) {
  const GLFormat g = glFormat(format);
  auto t = vtkSmartPointer<vtkTextureObject>::New();
  t->SetContext(renWin);
  t->SetInternalFormat(g.internalFormat);
  t->SetFormat(g.format);
  t->SetDataType(g.type);
  // Integer textures cannot be filtered.
  const int f = (filter == TexFilter::Linear && !isInteger(format)) ? vtkTextureObject::Linear : vtkTextureObject::Nearest;
  t->SetMinificationFilter(f);
  t->SetMagnificationFilter(f);
  t->SetWrapS(vtkTextureObject::ClampToEdge);
  t->SetWrapT(vtkTextureObject::ClampToEdge);
  t->SetWrapR(vtkTextureObject::ClampToEdge);
  return t;
}

void check(bool ok, const char* what, int w, int h, int d) {
  if (!ok)
    throw std::runtime_error(std::string("could not allocate a ") + what + " texture of " + std::to_string(w) + "x" +
                             std::to_string(h) + (d > 1 ? "x" + std::to_string(d) : std::string()));
}

}  // namespace

std::size_t texelBytes(TexFormat format) { return glFormat(format).bytes; }
int texelComponents(TexFormat format) { return glFormat(format).components; }

vtkSmartPointer<vtkTextureObject> makeTexture2D(vtkOpenGLRenderWindow* renWin, TexFormat format, int width,
                                                int height, const void* data, TexFilter filter) {
  const GLFormat g = glFormat(format);
  auto t = newTexture(renWin, format, filter);
  const bool ok = data ? t->Create2DFromRaw(width, height, g.components, g.vtkType, const_cast<void*>(data))
                       : t->Allocate2D(width, height, g.components, g.vtkType);
  check(ok, "2D", width, height, 1);
  return t;
}

vtkSmartPointer<vtkTextureObject> makeTexture3D(vtkOpenGLRenderWindow* renWin, TexFormat format, int width,
                                                int height, int depth, const void* data, TexFilter filter) {
  const GLFormat g = glFormat(format);
  auto t = newTexture(renWin, format, filter);
  const bool ok = data ? t->Create3DFromRaw(width, height, depth, g.components, g.vtkType, const_cast<void*>(data))
                       : t->Allocate3D(width, height, depth, g.components, g.vtkType);
  check(ok, "3D", width, height, depth);
  return t;
}

vtkSmartPointer<vtkTextureObject> makeCubeMap(vtkOpenGLRenderWindow* renWin, TexFormat format, int size,
                                              const void* const faces[6], TexFilter filter) {
  const GLFormat g = glFormat(format);
  auto t = newTexture(renWin, format, filter);
  void* raw[6];
  for (int i = 0; i < 6; ++i) raw[i] = const_cast<void*>(faces ? faces[i] : nullptr);
  check(t->CreateCubeFromRaw(size, size, g.components, g.vtkType, raw), "cube-map", size, size, 6);
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // core since 3.2: filter across face edges
  return t;
}

vtkSmartPointer<vtkTextureObject> makeBufferTexture(vtkOpenGLRenderWindow* renWin, TexFormat format,
                                                    std::size_t count, const void* data) {
  const GLFormat g = glFormat(format);
  if (count == 0) throw std::invalid_argument("a buffer texture needs at least one texel");
  vtkNew<vtkOpenGLBufferObject> buffer;
  buffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
  if (!buffer->Upload(static_cast<const unsigned char*>(data), count * g.bytes, vtkOpenGLBufferObject::TextureBuffer))
    throw std::runtime_error("could not upload a buffer texture of " + std::to_string(count) + " texels");
  auto t = newTexture(renWin, format, TexFilter::Nearest);
  check(t->CreateTextureBuffer(static_cast<unsigned>(count), g.components, g.vtkType, buffer), "buffer",
        static_cast<int>(count), 1, 1);
  return t;
}

std::size_t textureBytes(const vtkTextureObject* t) {
  if (!t) return 0;
  auto* tex = const_cast<vtkTextureObject*>(t);
  std::size_t perTexel = 0;
  switch (tex->GetInternalFormat(VTK_VOID, 0, false)) {
    case GL_R8: perTexel = 1; break;
    case GL_RGBA8: case GL_R32F: case GL_R32UI: case GL_RG16F: case GL_RGB10_A2: case GL_DEPTH_COMPONENT32F: perTexel = 4; break;
    case GL_R16F: perTexel = 2; break;
    case GL_RGBA16F: case GL_RG32F: case GL_RG32UI: perTexel = 8; break;
    case GL_RGB32F: perTexel = 12; break;
    case GL_RGBA32F: case GL_RGBA32UI: perTexel = 16; break;
    default: perTexel = static_cast<std::size_t>(tex->GetComponents()) * 4; break;
  }
  const std::size_t faces = tex->GetTarget() == GL_TEXTURE_CUBE_MAP ? 6 : 1;
  return perTexel * faces * tex->GetWidth() * std::max(1u, tex->GetHeight()) * std::max(1u, tex->GetDepth());
}

void ensureTexture2D(vtkSmartPointer<vtkTextureObject>& t, vtkOpenGLRenderWindow* renWin, TexFormat format,
                     int width, int height) {
  const GLFormat g = glFormat(format);
  if (!t || t->GetInternalFormat(VTK_VOID, 0, false) != g.internalFormat) {
    t = makeTexture2D(renWin, format, width, height);
  } else if (static_cast<int>(t->GetWidth()) != width || static_cast<int>(t->GetHeight()) != height) {
    t->Resize(width, height);
  }
}

ActiveTextures::ActiveTextures(std::initializer_list<vtkTextureObject*> textures)
    : ActiveTextures(std::vector<vtkTextureObject*>(textures)) {}

ActiveTextures::ActiveTextures(const std::vector<vtkTextureObject*>& textures) {
  for (vtkTextureObject* t : textures)
    if (t) {
      t->Activate();
      active_.push_back(t);
    }
}

ActiveTextures::~ActiveTextures() {
  for (auto it = active_.rbegin(); it != active_.rend(); ++it) (*it)->Deactivate();
}

}  // namespace aokit
