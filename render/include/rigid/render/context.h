// The process-wide OpenGL context. It is created lazily by the first figure
// (never by merely linking rigid::render) and reused for every figure after.
// Two off-screen backends sit behind one interface: OSMesa (default; Mesa
// dropped it in 25.1) and EGL on EGL_MESA_platform_surfaceless (how a GPU
// machine renders headless). Both give a GL 3.3+ core-profile context. A program
// with a window of its own (the explorer) hands its context over instead
// (use_current_context): figures are then drawn in it. All drawing goes to
// framebuffer objects, never to a window's own buffers; it uses only what
// OpenGL ES 3.0 (WebGL2) also has where the context is ES.
#pragma once

#include <stdexcept>
#include <string>

namespace rigid::render {

/// Thrown when no OpenGL context can be made; what() is one line naming the backend and cause.
class Unavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Which library provides the GL context.
enum class Backend { kAuto, kOSMesa, kEGL, kGLES, kCurrent };

/// Options for the process's context; only honoured by the first call that creates it.
struct ContextOptions {
  /// kAuto reads RIGID_GL_BACKEND (osmesa|egl|gles), else OSMesa, else EGL. kGLES is EGL
  /// with an OpenGL ES 3.0 context: what WebGL2 offers, for checking that the drawing
  /// needs no more.
  Backend backend = Backend::kAuto;
  /// MSAA samples wanted; 0 forces the supersampling fallback (also RIGID_GL_SAMPLES=0).
  int samples = 4;
};

/// Facts about the live context, for logs and tests.
struct ContextInfo {
  Backend backend = Backend::kAuto;
  std::string gl_version;   ///< GL_VERSION string
  std::string gl_renderer;  ///< GL_RENDERER string
  int samples = 0;          ///< MSAA samples used (0: supersampling fallback)
  bool es = false;          ///< an OpenGL ES 3.0+ context (shaders say "#version 300 es")
  double creation_seconds = 0;
};

/// The process's context, made on first call (throws Unavailable if impossible) and current
/// afterwards.
const ContextInfo& context(const ContextOptions& options = {});

/// A GL function's address in the caller's context (glfwGetProcAddress, eglGetProcAddress).
using ProcAddress = void (*(*)(const char*))();

/// Makes the caller's current context (a window's: desktop GL 3.3+ core or OpenGL ES 3.0+)
/// the process's context, loading its functions through `get_proc`; everything drawn after
/// is drawn in it. Throws Unavailable if a context exists already or this one lacks a function.
const ContextInfo& use_current_context(ProcAddress get_proc, const ContextOptions& options = {});

/// True once context() has succeeded in this process (no context is made by asking).
bool context_created();

/// Parses "osmesa" / "egl" / "auto" (case-insensitive); throws std::invalid_argument otherwise.
Backend parse_backend(const std::string& name);

/// "osmesa", "egl" or "auto".
const char* backend_name(Backend backend);

}  // namespace rigid::render
