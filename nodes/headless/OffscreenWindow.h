#pragma once
// A headless VTK render window: an OSMesa core-profile context (no X server, DISPLAY unset)
// driving vtkGenericOpenGLRenderWindow, rendering into VTK's own framebuffer (no blit).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vtkNew.h>

class vtkGenericOpenGLRenderWindow;
class vtkRenderer;

namespace aokit {

struct RGBAImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  // RGBA, bottom row first (OpenGL order)
};

class OffscreenWindow {
 public:
  // Throws std::runtime_error when the size is absurd or no OSMesa context can be made.
  OffscreenWindow(int width, int height);
  ~OffscreenWindow();
  OffscreenWindow(const OffscreenWindow&) = delete;
  OffscreenWindow& operator=(const OffscreenWindow&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  vtkRenderer* renderer() const;
  vtkGenericOpenGLRenderWindow* window() const;

  void makeCurrent();
  void render();
  void finish();  // glFinish: for timing
  RGBAImage readColor();

  std::string glRendererString();
  std::string glVersionString();

  static constexpr int kMaxSide = 8192;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int width_, height_;
};

}  // namespace aokit
