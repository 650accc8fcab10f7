// Internal: the GL 3.3 core functions rigid::render calls (all of them also in
// OpenGL ES 3.0 but glTexImage2DMultisample, which an ES context never calls), loaded through the
// active backend's GetProcAddress into one table (no loader library needed).
#pragma once

#include <GL/glcorearb.h>

#include <string>

namespace rigid::render::detail {

// X-macro list: (return type, name, parameters).
#define RIGID_GL_FUNCTIONS(X)                                                            \
  X(GLenum, GetError, (void))                                                            \
  X(const GLubyte*, GetString, (GLenum))                                                 \
  X(void, GetIntegerv, (GLenum, GLint*))                                                 \
  X(void, Viewport, (GLint, GLint, GLsizei, GLsizei))                                    \
  X(void, Scissor, (GLint, GLint, GLsizei, GLsizei))                                     \
  X(void, Enable, (GLenum))                                                              \
  X(void, Disable, (GLenum))                                                             \
  X(void, ClearColor, (GLfloat, GLfloat, GLfloat, GLfloat))                              \
  X(void, Clear, (GLbitfield))                                                           \
  X(void, BlendFunc, (GLenum, GLenum))                                                   \
  X(void, BlendFuncSeparate, (GLenum, GLenum, GLenum, GLenum))                           \
  X(void, DepthMask, (GLboolean))                                                        \
  X(void, DepthFunc, (GLenum))                                                           \
  X(void, CullFace, (GLenum))                                                            \
  X(void, FrontFace, (GLenum))                                                           \
  X(void, PixelStorei, (GLenum, GLint))                                                  \
  X(void, ReadPixels, (GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*))           \
  X(void, Finish, (void))                                                                \
  X(void, GenFramebuffers, (GLsizei, GLuint*))                                           \
  X(void, DeleteFramebuffers, (GLsizei, const GLuint*))                                  \
  X(void, BindFramebuffer, (GLenum, GLuint))                                             \
  X(void, FramebufferRenderbuffer, (GLenum, GLenum, GLenum, GLuint))                     \
  X(GLenum, CheckFramebufferStatus, (GLenum))                                            \
  X(void, BlitFramebuffer,                                                               \
    (GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLbitfield, GLenum))        \
  X(void, GenRenderbuffers, (GLsizei, GLuint*))                                          \
  X(void, DeleteRenderbuffers, (GLsizei, const GLuint*))                                 \
  X(void, BindRenderbuffer, (GLenum, GLuint))                                            \
  X(void, RenderbufferStorage, (GLenum, GLenum, GLsizei, GLsizei))                       \
  X(void, RenderbufferStorageMultisample, (GLenum, GLsizei, GLenum, GLsizei, GLsizei))   \
  X(void, GenTextures, (GLsizei, GLuint*))                                               \
  X(void, BindTexture, (GLenum, GLuint))                                                 \
  X(void, ActiveTexture, (GLenum))                                                       \
  X(void, TexImage2D,                                                                    \
    (GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum, const void*))        \
  X(void, TexSubImage2D,                                                                 \
    (GLenum, GLint, GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, const void*))        \
  X(void, TexParameteri, (GLenum, GLenum, GLint))                                        \
  X(void, TexImage2DMultisample, (GLenum, GLsizei, GLenum, GLsizei, GLsizei, GLboolean)) \
  X(void, FramebufferTexture2D, (GLenum, GLenum, GLenum, GLuint, GLint))                 \
  X(void, DeleteTextures, (GLsizei, const GLuint*))                                      \
  X(GLuint, CreateShader, (GLenum))                                                      \
  X(void, ShaderSource, (GLuint, GLsizei, const GLchar* const*, const GLint*))           \
  X(void, CompileShader, (GLuint))                                                       \
  X(void, GetShaderiv, (GLuint, GLenum, GLint*))                                         \
  X(void, GetShaderInfoLog, (GLuint, GLsizei, GLsizei*, GLchar*))                        \
  X(void, DeleteShader, (GLuint))                                                        \
  X(GLuint, CreateProgram, (void))                                                       \
  X(void, AttachShader, (GLuint, GLuint))                                                \
  X(void, BindAttribLocation, (GLuint, GLuint, const GLchar*))                           \
  X(void, LinkProgram, (GLuint))                                                         \
  X(void, GetProgramiv, (GLuint, GLenum, GLint*))                                        \
  X(void, GetProgramInfoLog, (GLuint, GLsizei, GLsizei*, GLchar*))                       \
  X(void, UseProgram, (GLuint))                                                          \
  X(GLint, GetUniformLocation, (GLuint, const GLchar*))                                  \
  X(void, Uniform1i, (GLint, GLint))                                                     \
  X(void, Uniform1f, (GLint, GLfloat))                                                   \
  X(void, Uniform2f, (GLint, GLfloat, GLfloat))                                          \
  X(void, Uniform3f, (GLint, GLfloat, GLfloat, GLfloat))                                 \
  X(void, Uniform4f, (GLint, GLfloat, GLfloat, GLfloat, GLfloat))                        \
  X(void, UniformMatrix3fv, (GLint, GLsizei, GLboolean, const GLfloat*))                 \
  X(void, UniformMatrix4fv, (GLint, GLsizei, GLboolean, const GLfloat*))                 \
  X(void, GenVertexArrays, (GLsizei, GLuint*))                                           \
  X(void, BindVertexArray, (GLuint))                                                     \
  X(void, GenBuffers, (GLsizei, GLuint*))                                                \
  X(void, DeleteBuffers, (GLsizei, const GLuint*))                                       \
  X(void, DeleteVertexArrays, (GLsizei, const GLuint*))                                  \
  X(void, BindBuffer, (GLenum, GLuint))                                                  \
  X(void, BufferData, (GLenum, GLsizeiptr, const void*, GLenum))                         \
  X(void, EnableVertexAttribArray, (GLuint))                                             \
  X(void, VertexAttribPointer, (GLuint, GLint, GLenum, GLboolean, GLsizei, const void*)) \
  X(void, DrawArrays, (GLenum, GLint, GLsizei))                                          \
  X(void, DrawElements, (GLenum, GLsizei, GLenum, const void*))

struct GlFunctions {
#define RIGID_GL_MEMBER(ret, name, params) ret(APIENTRY* name) params = nullptr;
  RIGID_GL_FUNCTIONS(RIGID_GL_MEMBER)
#undef RIGID_GL_MEMBER
};

/// The loaded table; valid once the context exists.
extern GlFunctions gl;

/// Fills `gl` through get_proc; returns the name of the first missing function, or "".
using GlProc = void (*)();
std::string load_gl(GlProc (*get_proc)(const char*));

/// The shaders' first lines for the context: "#version 330 core", or for OpenGL ES
/// "#version 300 es" with the precision ES asks a fragment shader to state.
void set_shader_version(bool es);

/// Compiles and links a vertex + fragment shader pair, each source without its version
/// line (set_shader_version's is put first); throws std::runtime_error with the log on
/// failure.
GLuint build_program(const char* vertex_src, const char* fragment_src,
                     const char* const* attributes, int attribute_count);

}  // namespace rigid::render::detail
