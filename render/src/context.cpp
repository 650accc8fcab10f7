// The process-wide GL context: backend choice, creation, capability checks.
#include "rigid/render/context.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string_view>

#include "backends.h"
#include "gl.h"

namespace rigid::render {

namespace {

std::unique_ptr<ContextInfo> g_info;
std::mutex g_mutex;

// The context just made current: its functions loaded, its facts read.
ContextInfo describe(Backend used, detail::GlProcLoader loader, const ContextOptions& options,
                     std::chrono::steady_clock::time_point t0) {
  const std::string missing = detail::load_gl(loader);
  if (!missing.empty())
    throw Unavailable(std::string("rigid::render: ") + backend_name(used) +
                      " context lacks GL function " + missing);
  auto& gl = detail::gl;
  ContextInfo info;
  info.backend = used;
  info.gl_version = reinterpret_cast<const char*>(gl.GetString(GL_VERSION));
  info.gl_renderer = reinterpret_cast<const char*>(gl.GetString(GL_RENDERER));
  info.es = info.gl_version.rfind("OpenGL ES", 0) == 0;
  if (!info.es && gl.TexImage2DMultisample == nullptr)
    throw Unavailable(std::string("rigid::render: ") + backend_name(used) +
                      " context lacks GL function glTexImage2DMultisample");
  detail::set_shader_version(info.es);
  GLint max_samples = 0;
  gl.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
  int samples = options.samples;
  // RIGID_GL_SAMPLES, a developer's switch (the bench's 2x2 supersampling against MSAA):
  // a whole number, else ignored.
  if (const char* env = std::getenv("RIGID_GL_SAMPLES"); env != nullptr) {
    const std::string_view text(env);
    int n = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (error == std::errc() && end == text.data() + text.size() && !text.empty()) samples = n;
  }
  samples = std::min(samples, static_cast<int>(max_samples));
  // Fewer than 2 samples is no antialiasing: use 2×2 supersampling instead.
  info.samples = samples >= 2 ? samples : 0;
  info.creation_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return info;
}

detail::GlProcLoader try_backend(Backend b, std::string& error) {
  if (b == Backend::kOSMesa) return detail::make_osmesa_context(error);
  return detail::make_egl_context(error, b == Backend::kGLES);
}

ContextInfo create(const ContextOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  Backend wanted = options.backend;
  if (wanted == Backend::kAuto) {
    const char* env = std::getenv("RIGID_GL_BACKEND");
    try {
      if (env != nullptr && *env != '\0') wanted = parse_backend(env);
    } catch (const std::invalid_argument&) {
      throw Unavailable(std::string("rigid::render: RIGID_GL_BACKEND=") + env +
                        " is not one of osmesa, egl, gles, auto");
    }
  }
  // Auto tries OSMesa first, then EGL (never ES); an explicit choice has no fallback.
  std::string errors;
  detail::GlProcLoader loader = nullptr;
  Backend used = Backend::kAuto;
  for (Backend b : {Backend::kOSMesa, Backend::kEGL, Backend::kGLES}) {
    if (wanted != Backend::kAuto ? wanted != b : b == Backend::kGLES) continue;
    std::string error;
    loader = try_backend(b, error);
    if (loader != nullptr) {
      used = b;
      break;
    }
    errors += std::string(errors.empty() ? "" : "; ") + backend_name(b) + ": " + error;
  }
  if (loader == nullptr)
    throw Unavailable("rigid::render: no OpenGL context could be made (" + errors + ")");
  return describe(used, loader, options, t0);
}

}  // namespace

const ContextInfo& context(const ContextOptions& options) {
  std::lock_guard<std::mutex> lock(g_mutex);
  if (!g_info) g_info = std::make_unique<ContextInfo>(create(options));
  return *g_info;
}

const ContextInfo& use_current_context(ProcAddress get_proc, const ContextOptions& options) {
  std::lock_guard<std::mutex> lock(g_mutex);
  if (g_info) throw Unavailable("rigid::render: a GL context is in use already");
  g_info = std::make_unique<ContextInfo>(
      describe(Backend::kCurrent, get_proc, options, std::chrono::steady_clock::now()));
  return *g_info;
}

bool context_created() {
  std::lock_guard<std::mutex> lock(g_mutex);
  return g_info != nullptr;
}

Backend parse_backend(const std::string& name) {
  std::string s = name;
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  if (s == "osmesa") return Backend::kOSMesa;
  if (s == "egl") return Backend::kEGL;
  if (s == "gles") return Backend::kGLES;
  if (s == "auto") return Backend::kAuto;
  throw std::invalid_argument("unknown GL backend '" + name + "' (use osmesa, egl, gles or auto)");
}

const char* backend_name(Backend backend) {
  switch (backend) {
    case Backend::kOSMesa:
      return "osmesa";
    case Backend::kEGL:
      return "egl";
    case Backend::kGLES:
      return "gles";
    case Backend::kCurrent:
      return "current";
    case Backend::kAuto:
      break;
  }
  return "auto";
}

}  // namespace rigid::render
