// GLEW (linked by Debian's X11 VTK) loads GL entry points through glXGetProcAddressARB and checks
// a GLX display. With only an OSMesa context current those answer nothing, so glewInit fails and
// VTK never initializes its context. These definitions interpose on libGLX's: while an OSMesa
// context is current they answer from OSMesa; otherwise they forward to the real libGLX, so a
// process can still open X windows. (Recipe: ../shared/notes/osmesa-vtk.md, items 4-5.)
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <cstring>

using AokitProc = void (*)();

namespace {
char dummyDisplay;  // any non-null pointer: GLEW only tests for null

template <class F>
F realGlx(const char* name) {
  return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
}
bool osmesaCurrent() { return OSMesaGetCurrentContext() != nullptr; }
}  // namespace

extern "C" {

void* glXGetCurrentDisplay();
int glXQueryVersion(void* dpy, int* major, int* minor);
const char* glXGetClientString(void* dpy, int name);

AokitProc glXGetProcAddressARB(const unsigned char* name) {
  if (!osmesaCurrent()) {
    auto real = realGlx<AokitProc (*)(const unsigned char*)>("glXGetProcAddressARB");
    return real ? real(name) : nullptr;
  }
  const char* n = reinterpret_cast<const char*>(name);
  if (std::strcmp(n, "glXGetCurrentDisplay") == 0) return reinterpret_cast<AokitProc>(&glXGetCurrentDisplay);
  if (std::strcmp(n, "glXQueryVersion") == 0) return reinterpret_cast<AokitProc>(&glXQueryVersion);
  if (std::strcmp(n, "glXGetClientString") == 0) return reinterpret_cast<AokitProc>(&glXGetClientString);
  if (std::strncmp(n, "glX", 3) == 0) return nullptr;  // no other GLX under OSMesa
  return reinterpret_cast<AokitProc>(OSMesaGetProcAddress(n));
}

AokitProc glXGetProcAddress(const unsigned char* name) { return glXGetProcAddressARB(name); }

void* glXGetCurrentDisplay() {
  if (!osmesaCurrent()) {
    auto real = realGlx<void* (*)()>("glXGetCurrentDisplay");
    return real ? real() : nullptr;
  }
  return &dummyDisplay;
}

int glXQueryVersion(void* dpy, int* major, int* minor) {
  if (!osmesaCurrent()) {
    auto real = realGlx<int (*)(void*, int*, int*)>("glXQueryVersion");
    return real ? real(dpy, major, minor) : 0;
  }
  if (major) *major = 1;
  if (minor) *minor = 4;
  return 1;
}

const char* glXGetClientString(void* dpy, int name) {
  if (!osmesaCurrent()) {
    auto real = realGlx<const char* (*)(void*, int)>("glXGetClientString");
    return real ? real(dpy, name) : "";
  }
  return "";
}

}  // extern "C"
