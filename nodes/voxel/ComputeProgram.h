#pragma once
// One GL 4.3 compute program, kept outside VTK's shader cache (which builds vertex, geometry and
// fragment programs only). The source's "//AOKIT::Defines" line receives the shape-changing
// #defines; the program is rebuilt only when they change. Dispatching first releases the program
// VTK's cache last bound: the cache skips re-binding a program it believes is still current, so
// a foreign glUseProgram left in place would make VTK's next draw run with the wrong program.
// Every call needs the context current.
#include <string>

class vtkOpenGLRenderWindow;

namespace aokit {

class ComputeProgram {
 public:
  ComputeProgram(std::string name, const char* source);
  ~ComputeProgram();  // forgets GL objects it could not delete: call release() while the context lives
  ComputeProgram(const ComputeProgram&) = delete;
  ComputeProgram& operator=(const ComputeProgram&) = delete;

  // Compiles and links (when the defines changed). False when it does not build; the log is
  // printed once per set of defines.
  bool ready(vtkOpenGLRenderWindow* renWin, const std::string& defines);
  unsigned handle() const { return program_; }
  const std::string& name() const { return name_; }
  // The source as compiled for `defines` ("#version 430 core" first).
  std::string source(const std::string& defines) const;

  // Uniforms of the ready program (ignored when the program does not use them).
  void setInt(const char* name, int v) const;
  void setUInt(const char* name, unsigned v) const;
  void setIVec3(const char* name, int x, int y, int z) const;
  void setMat4(const char* name, const float* columnMajor) const;

  // glDispatchCompute(x, y, z) with this program, then unbinds it.
  void dispatch(vtkOpenGLRenderWindow* renWin, unsigned x, unsigned y = 1, unsigned z = 1) const;
  // Deletes the GL program (the context must be current).
  void release();

 private:
  int location(const char* name) const;
  std::string name_;
  const char* source_;
  std::string defines_;
  unsigned program_ = 0;
  bool built_ = false, failed_ = false;
};

}  // namespace aokit
