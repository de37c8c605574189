#include "headless/OffscreenWindow.h"

#include <algorithm>
#include <stdexcept>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtk_glew.h>

#include "headless/OSMesaContext.h"

namespace aokit {

struct OffscreenWindow::Impl {
  Impl(int w, int h) : context(w, h) {}
  OSMesaContext context;
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkCallbackCommand> makeCurrent, isCurrent;
};

namespace {
void checkSize(int width, int height) {
  if (width < 1 || height < 1 || width > OffscreenWindow::kMaxSide || height > OffscreenWindow::kMaxSide)
    throw std::runtime_error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                             " is out of range (1.." + std::to_string(OffscreenWindow::kMaxSide) + " per side)");
}
}  // namespace

OffscreenWindow::OffscreenWindow(int width, int height)
    : width_(width), height_(height) {
  checkSize(width, height);
  impl_ = std::make_unique<Impl>(width, height);
  makeCurrent();

  auto* w = impl_->window.Get();
  // VTK asks the window to make its context current whenever it touches GL (rendering, releasing
  // textures): answer with this window's OSMesa context, so several windows can live in one process.
  impl_->makeCurrent->SetClientData(&impl_->context);
  impl_->makeCurrent->SetCallback([](vtkObject*, unsigned long, void* context, void*) {
    static_cast<OSMesaContext*>(context)->makeCurrent();
  });
  impl_->isCurrent->SetClientData(&impl_->context);
  impl_->isCurrent->SetCallback([](vtkObject*, unsigned long, void* context, void* answer) {
    *static_cast<bool*>(answer) = static_cast<OSMesaContext*>(context)->isCurrent();
  });
  w->AddObserver(vtkCommand::WindowMakeCurrentEvent, impl_->makeCurrent);
  w->AddObserver(vtkCommand::WindowIsCurrentEvent, impl_->isCurrent);
  w->SetOwnContext(0);
  w->SetReadyForRendering(true);
  w->SetIsCurrent(true);
  w->SetFrameBlitModeToNoBlit();
  w->SetMultiSamples(0);
  w->SetSize(width, height);
  w->AddRenderer(impl_->renderer);
  impl_->renderer->SetBackground(0.32, 0.34, 0.43);
  w->SetOffScreenRendering(1);
}

OffscreenWindow::~OffscreenWindow() {
  makeCurrent();
  impl_->window->Finalize();
  impl_->renderer->SetPass(nullptr);
}

vtkRenderer* OffscreenWindow::renderer() const { return impl_->renderer; }
vtkGenericOpenGLRenderWindow* OffscreenWindow::window() const { return impl_->window; }

void OffscreenWindow::makeCurrent() { impl_->context.makeCurrent(); }

void OffscreenWindow::render() {
  makeCurrent();
  impl_->window->Render();
}

void OffscreenWindow::finish() {
  makeCurrent();
  glFinish();
}

RGBAImage OffscreenWindow::readColor() {
  makeCurrent();
  RGBAImage img;
  img.width = width_;
  img.height = height_;
  img.pixels.resize(static_cast<std::size_t>(width_) * height_ * 4);
  // With NoBlit the finished frame stays in VTK's render framebuffer; VTK reads it from there.
  vtkNew<vtkUnsignedCharArray> data;
  impl_->window->GetRGBACharPixelData(0, 0, width_ - 1, height_ - 1, /*front=*/0, data);
  std::copy(data->GetPointer(0), data->GetPointer(0) + img.pixels.size(), img.pixels.begin());
  return img;
}

std::string OffscreenWindow::glRendererString() {
  makeCurrent();
  const auto* s = glGetString(GL_RENDERER);
  return s ? reinterpret_cast<const char*>(s) : "";
}

std::string OffscreenWindow::glVersionString() {
  makeCurrent();
  const auto* s = glGetString(GL_VERSION);
  return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace aokit
