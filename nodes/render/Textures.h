#pragma once
// GPU textures for render passes, in one place: 2D targets (float and integer), 3D textures, cube
// maps and buffer textures, each with its GL format spelled out once. Every AO family builds its
// targets and look-up tables through these, so formats and byte counts stay consistent.
#include <cstddef>
#include <initializer_list>
#include <vector>

#include <vtkSmartPointer.h>

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

namespace aokit {

enum class TexFormat {
  R8,        // unsigned normalized
  RGBA8,     // unsigned normalized
  R16F,
  RG16F,
  RGBA16F,
  R32F,
  RG32F,
  RGB32F,    // for buffer textures mostly (3-float records); not colour-renderable
  RGBA32F,
  R32UI,     // integer: sampled with usampler*, texelFetch only
  RG32UI,
  RGBA32UI,
};

enum class TexFilter { Nearest, Linear };

// Bytes of one texel of the format.
std::size_t texelBytes(TexFormat format);
// Components (1..4) of the format.
int texelComponents(TexFormat format);

// A 2D texture, clamped at the edges. `data` (optional) holds width x height texels in the
// format's own layout (floats for the float formats, uint8 for R8/RGBA8, uint32 for the integer
// ones; 16F formats take floats and convert); nullptr allocates without uploading.
vtkSmartPointer<vtkTextureObject> makeTexture2D(vtkOpenGLRenderWindow* renWin, TexFormat format, int width,
                                                int height, const void* data = nullptr,
                                                TexFilter filter = TexFilter::Nearest);

// Makes `t` a width x height texture of the format: allocated when null or of another format,
// resized when of another size, left alone otherwise (render targets that follow the screen).
void ensureTexture2D(vtkSmartPointer<vtkTextureObject>& t, vtkOpenGLRenderWindow* renWin, TexFormat format,
                     int width, int height);

// A 3D texture (clamped), `data` as above with x fastest, then y, then z.
vtkSmartPointer<vtkTextureObject> makeTexture3D(vtkOpenGLRenderWindow* renWin, TexFormat format, int width,
                                                int height, int depth, const void* data = nullptr,
                                                TexFilter filter = TexFilter::Nearest);

// A cube map of size x size faces in GL order (+X, -X, +Y, -Y, +Z, -Z), seamless filtering on.
vtkSmartPointer<vtkTextureObject> makeCubeMap(vtkOpenGLRenderWindow* renWin, TexFormat format, int size,
                                              const void* const faces[6], TexFilter filter = TexFilter::Linear);

// A buffer texture (samplerBuffer / usamplerBuffer) over `count` texels; the buffer object is kept
// alive by the texture. For lists too long for uniforms (occluder lists, tile lists).
vtkSmartPointer<vtkTextureObject> makeBufferTexture(vtkOpenGLRenderWindow* renWin, TexFormat format,
                                                    std::size_t count, const void* data);

// GPU bytes of a texture made by these helpers (0 for null).
std::size_t textureBytes(const vtkTextureObject* texture);

// Textures bound to texture units while alive (null entries skipped), released in reverse order.
class ActiveTextures {
 public:
  explicit ActiveTextures(std::initializer_list<vtkTextureObject*> textures);
  explicit ActiveTextures(const std::vector<vtkTextureObject*>& textures);
  ~ActiveTextures();
  ActiveTextures(const ActiveTextures&) = delete;
  ActiveTextures& operator=(const ActiveTextures&) = delete;

 private:
  std::vector<vtkTextureObject*> active_;
};

}  // namespace aokit
