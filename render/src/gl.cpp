// Internal: loading the GL function table and building shader programs.
#include "gl.h"

#include <stdexcept>
#include <string>
#include <string_view>

namespace rigid::render::detail {

GlFunctions gl;

std::string load_gl(GlProc (*get_proc)(const char*)) {
  // glTexImage2DMultisample is desktop GL's alone (WebGL2 gives none); an ES context never
  // calls it, and a desktop one lacking it is refused once the kind of context is known.
#define RIGID_GL_LOAD(ret, name, params)                                   \
  gl.name = reinterpret_cast<ret(APIENTRY*) params>(get_proc("gl" #name)); \
  if (gl.name == nullptr && std::string_view(#name) != "TexImage2DMultisample") return "gl" #name;
  RIGID_GL_FUNCTIONS(RIGID_GL_LOAD)
#undef RIGID_GL_LOAD
  return {};
}

namespace {

bool g_es = false;

GLuint compile(GLenum kind, const char* src) {
  GLuint s = gl.CreateShader(kind);
  const char* version = g_es ? "#version 300 es\nprecision highp float;\nprecision highp int;\n"
                             : "#version 330 core\n";
  const char* parts[] = {version, src};
  gl.ShaderSource(s, 2, parts, nullptr);
  gl.CompileShader(s);
  GLint ok = 0;
  gl.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    gl.GetShaderInfoLog(s, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("rigid::render: shader compile failed: ") + log);
  }
  return s;
}

}  // namespace

void set_shader_version(bool es) {
  g_es = es;
}

GLuint build_program(const char* vertex_src, const char* fragment_src,
                     const char* const* attributes, int attribute_count) {
  GLuint vs = compile(GL_VERTEX_SHADER, vertex_src);
  GLuint fs = compile(GL_FRAGMENT_SHADER, fragment_src);
  GLuint p = gl.CreateProgram();
  gl.AttachShader(p, vs);
  gl.AttachShader(p, fs);
  for (int i = 0; i < attribute_count; ++i) gl.BindAttribLocation(p, i, attributes[i]);
  gl.LinkProgram(p);
  gl.DeleteShader(vs);
  gl.DeleteShader(fs);
  GLint ok = 0;
  gl.GetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    gl.GetProgramInfoLog(p, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("rigid::render: shader link failed: ") + log);
  }
  return p;
}

}  // namespace rigid::render::detail
