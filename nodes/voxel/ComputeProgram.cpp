#include "voxel/ComputeProgram.h"

#include <iostream>
#include <vector>

#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkShaderProgram.h>
#include <vtk_glew.h>

namespace aokit {

ComputeProgram::ComputeProgram(std::string name, const char* source) : name_(std::move(name)), source_(source) {}

ComputeProgram::~ComputeProgram() = default;

std::string ComputeProgram::source(const std::string& defines) const {
  std::string s = source_;
  vtkShaderProgram::Substitute(s, "//AOKIT::Defines", defines, false);
  return "#version 430 core\n" + s;
}

namespace {
std::string infoLog(unsigned object, bool program) {
  int length = 0;
  if (program) glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<std::size_t>(length) + 1, '\0');
  if (program) glGetProgramInfoLog(object, length, nullptr, log.data());
  else glGetShaderInfoLog(object, length, nullptr, log.data());
  return log.data();
}
}  // namespace

bool ComputeProgram::ready(vtkOpenGLRenderWindow*, const std::string& defines) {
  if (built_ && defines == defines_) return !failed_;
  release();
  built_ = true;
  defines_ = defines;
  const std::string text = source(defines);
  const char* src = text.c_str();
  const unsigned shader = glCreateShader(GL_COMPUTE_SHADER);
  glShaderSource(shader, 1, &src, nullptr);
  glCompileShader(shader);
  int ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    std::cerr << "aokit: the " << name_ << " compute shader does not compile:\n" << infoLog(shader, false) << "\n";
    glDeleteShader(shader);
    failed_ = true;
    return false;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, shader);
  glLinkProgram(program_);
  glDeleteShader(shader);  // freed with the program
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    std::cerr << "aokit: the " << name_ << " compute program does not link:\n" << infoLog(program_, true) << "\n";
    glDeleteProgram(program_);
    program_ = 0;
    failed_ = true;
    return false;
  }
  failed_ = false;
  return true;
}

int ComputeProgram::location(const char* name) const { return program_ ? glGetUniformLocation(program_, name) : -1; }

void ComputeProgram::setInt(const char* name, int v) const {
  const int l = location(name);
  if (l >= 0) glProgramUniform1i(program_, l, v);
}

void ComputeProgram::setUInt(const char* name, unsigned v) const {
  const int l = location(name);
  if (l >= 0) glProgramUniform1ui(program_, l, v);
}

void ComputeProgram::setIVec3(const char* name, int x, int y, int z) const {
  const int l = location(name);
  if (l >= 0) glProgramUniform3i(program_, l, x, y, z);
}

void ComputeProgram::setMat4(const char* name, const float* m) const {
  const int l = location(name);
  if (l >= 0) glProgramUniformMatrix4fv(program_, l, 1, GL_FALSE, m);
}

void ComputeProgram::dispatch(vtkOpenGLRenderWindow* renWin, unsigned x, unsigned y, unsigned z) const {
  if (!program_ || x == 0 || y == 0 || z == 0) return;
  renWin->GetShaderCache()->ReleaseCurrentShader();
  glUseProgram(program_);
  glDispatchCompute(x, y, z);
  glUseProgram(0);
}

void ComputeProgram::release() {
  if (program_) glDeleteProgram(program_);
  program_ = 0;
  built_ = failed_ = false;
  defines_.clear();
}

}  // namespace aokit
