// Lifetime: passes created, rendered and destroyed without ReleaseGraphicsResources, toggled on and
// off, or moved between renderers and windows leave nothing behind: the GL objects alive and the
// resident memory after 130 cycles equal those after the first 25 (memory within 10 MB: a G-buffer leaked per cycle would be 60; passes moved between windows rebuild all they hold on each move; Mesa grows
// its own pools once in the first frames, TechniqueLifecycle's note). One object leaked per cycle
// shows as 100 more.
#include <malloc.h>
#include <unistd.h>

#include <functional>

#include <vtk_glew.h>

#include "DropinRig.h"

using namespace aokit;
using namespace aokit::dropin;

namespace {

struct GLObjects {
  int textures = 0, framebuffers = 0, programs = 0, buffers = 0, vertexArrays = 0;
  bool operator==(const GLObjects& o) const {
    return textures == o.textures && framebuffers == o.framebuffers && programs == o.programs && buffers == o.buffers &&
           vertexArrays == o.vertexArrays;
  }
};

GLObjects liveGLObjects(vtkRenderWindow* window) {
  window->MakeCurrent();
  GLObjects n;
  for (GLuint name = 1; name < 4096; ++name) {
    n.textures += glIsTexture(name) == GL_TRUE;
    n.framebuffers += glIsFramebuffer(name) == GL_TRUE;
    n.programs += glIsProgram(name) == GL_TRUE;
    n.buffers += glIsBuffer(name) == GL_TRUE;
    n.vertexArrays += glIsVertexArray(name) == GL_TRUE;
  }
  return n;
}

std::string describe(const GLObjects& g) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%d textures, %d framebuffers, %d programs, %d buffers, %d VAOs", g.textures,
                g.framebuffers, g.programs, g.buffers, g.vertexArrays);
  return buf;
}

double residentMB() {
  malloc_trim(0);
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1048576.0;
}

// The least resident memory over five cycles (Mesa's transient pools come and go).
double settledMB(const std::function<void()>& cycle) {
  double least = 1e30;
  for (int i = 0; i < 5; ++i) {
    cycle();
    least = std::min(least, residentMB());
  }
  return least;
}

void expectFlat(const char* what, Family family, const std::function<void()>& cycle, vtkRenderWindow* probe) {
  Capture capture;
  for (int i = 0; i < 20; ++i) cycle();
  const GLObjects first = liveGLObjects(probe);
  const double firstMB = settledMB(cycle);
  for (int i = 0; i < 100; ++i) cycle();
  const GLObjects last = liveGLObjects(probe);
  const double lastMB = settledMB(cycle);
  std::printf("%s, %s: after 25 cycles %s, %.1f MB; after 130: %s, %.1f MB\n", familyName(family), what,
              describe(first).c_str(), firstMB, describe(last).c_str(), lastMB);
  EXPECT_TRUE(last == first) << familyName(family) << ", " << what << ": " << describe(first) << " -> " << describe(last);
#ifndef __SANITIZE_ADDRESS__  // AddressSanitizer's quarantine holds freed memory: judged without it
  EXPECT_LT(lastMB - firstMB, 10.0) << familyName(family) << ", " << what;
#endif
  EXPECT_EQ(capture.text().find("rror"), std::string::npos) << familyName(family) << ", " << what << ": "
                                                            << capture.text().substr(0, 400);
}

}  // namespace

TEST(DropinLifetime, PassesMadeAndDroppedWithoutReleaseLeaveNothing) {
  AOKIT_REQUIRE_DISPLAY();
  for (Family family : families()) {
    vtkNew<vtkRenderWindow> window;
    window->SetSize(200, 150);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    SphereFloor scene(renderer);
    expectFlat("created, rendered, destroyed", family, [&] {
      auto pass = makePass(family);
      renderer->SetPass(pass);
      window->Render();
      renderer->SetPass(nullptr);
    }, window);
  }
}

TEST(DropinLifetime, TogglingOnePassLeavesNothing) {
  AOKIT_REQUIRE_DISPLAY();
  for (Family family : families()) {
    vtkNew<vtkRenderWindow> window;
    window->SetSize(200, 150);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    SphereFloor scene(renderer);
    auto pass = makePass(family);
    expectFlat("toggled", family, [&] {
      renderer->SetPass(pass);
      window->Render();
      renderer->SetPass(nullptr);
      window->Render();
    }, window);
  }
}

TEST(DropinLifetime, APassMovedBetweenWindowsLeavesNothing) {
  AOKIT_REQUIRE_DISPLAY();
  for (Family family : families()) {
    vtkNew<vtkRenderWindow> a, b;
    vtkNew<vtkRenderer> ra, rb;
    for (auto [w, r] : {std::make_pair(a.Get(), ra.Get()), std::make_pair(b.Get(), rb.Get())}) {
      w->SetSize(200, 150);
      w->AddRenderer(r);
    }
    SphereFloor sa(ra), sb(rb);
    auto pass = makePass(family);
    expectFlat("moved between windows", family, [&] {
      ra->SetPass(pass);
      a->Render();
      ra->SetPass(nullptr);
      rb->SetPass(pass);
      b->Render();
      rb->SetPass(nullptr);
    }, a);
  }
}
