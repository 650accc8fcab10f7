// Internal: the EGL backend on EGL_MESA_platform_surfaceless: no window, no
// display server, no pbuffer; the context is made current with no surface.
// libEGL is opened with dlopen on first use, like libOSMesa, so that linking
// the renderer costs a run without figures nothing.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>

#include <cstring>

#include "backends.h"

namespace rigid::render::detail {

namespace {

// The EGL entry points used here, looked up in the dlopen'ed libEGL.
struct EglApi {
  PFNEGLGETPROCADDRESSPROC eglGetProcAddress = nullptr;
  PFNEGLQUERYSTRINGPROC eglQueryString = nullptr;
  PFNEGLINITIALIZEPROC eglInitialize = nullptr;
  PFNEGLBINDAPIPROC eglBindAPI = nullptr;
  PFNEGLCHOOSECONFIGPROC eglChooseConfig = nullptr;
  PFNEGLCREATECONTEXTPROC eglCreateContext = nullptr;
  PFNEGLMAKECURRENTPROC eglMakeCurrent = nullptr;
  PFNEGLDESTROYCONTEXTPROC eglDestroyContext = nullptr;
};

EglApi api;

bool load(std::string& error) {
  if (api.eglGetProcAddress != nullptr) return true;
  void* lib = open_library({"libEGL.so.1", "libEGL.so"}, "libEGL", error);
  if (lib == nullptr) return false;
  EglApi a;
  bool ok = true;
#define RIGID_EGL_LOAD(name) \
  ok = ok && (a.name = reinterpret_cast<decltype(a.name)>(dlsym(lib, #name))) != nullptr;
  RIGID_EGL_LOAD(eglGetProcAddress)
  RIGID_EGL_LOAD(eglQueryString)
  RIGID_EGL_LOAD(eglInitialize)
  RIGID_EGL_LOAD(eglBindAPI)
  RIGID_EGL_LOAD(eglChooseConfig)
  RIGID_EGL_LOAD(eglCreateContext)
  RIGID_EGL_LOAD(eglMakeCurrent)
  RIGID_EGL_LOAD(eglDestroyContext)
#undef RIGID_EGL_LOAD
  if (!ok) {
    error = "libEGL lacks an EGL 1.4 entry point";
    return false;
  }
  api = a;
  return true;
}

GlProc egl_proc(const char* name) {
  return reinterpret_cast<GlProc>(api.eglGetProcAddress(name));
}

bool has_extension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

}  // namespace

GlProcLoader make_egl_context(std::string& error, bool es) {
  if (!load(error)) return nullptr;
  const char* client_ext = api.eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client_ext, "EGL_MESA_platform_surfaceless")) {
    error = "EGL_MESA_platform_surfaceless is not supported";
    return nullptr;
  }
  auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      api.eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (get_platform_display == nullptr) {
    error = "eglGetPlatformDisplayEXT is missing";
    return nullptr;
  }
  EGLDisplay dpy =
      get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (dpy == EGL_NO_DISPLAY || !api.eglInitialize(dpy, &major, &minor)) {
    error = "eglInitialize failed on the surfaceless platform";
    return nullptr;
  }
  if (!api.eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API)) {
    error = es ? "eglBindAPI(EGL_OPENGL_ES_API) failed" : "eglBindAPI(EGL_OPENGL_API) failed";
    return nullptr;
  }
  // Any config that renders the API; no surface type is needed.
  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT,
                                   EGL_SURFACE_TYPE, 0, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!api.eglChooseConfig(dpy, config_attribs, &config, 1, &count) || count < 1) config = nullptr;
  if (config == nullptr &&
      !has_extension(api.eglQueryString(dpy, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
    error = "no EGL config renders OpenGL";
    return nullptr;
  }
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                    3,
                                    EGL_CONTEXT_MINOR_VERSION,
                                    3,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                    EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                    EGL_NONE};
  // OpenGL ES 3.0, as WebGL2 is: what a browser build of the explorer will have
  const EGLint es_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0,
                               EGL_NONE};
  EGLContext ctx =
      api.eglCreateContext(dpy, config, EGL_NO_CONTEXT, es ? es_attribs : context_attribs);
  if (ctx == EGL_NO_CONTEXT) {
    error = es ? "eglCreateContext failed for OpenGL ES 3.0"
               : "eglCreateContext failed for a GL 3.3 core profile";
    return nullptr;
  }
  if (!api.eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
    api.eglDestroyContext(dpy, ctx);
    error = "eglMakeCurrent without a surface failed";
    return nullptr;
  }
  return &egl_proc;
}

}  // namespace rigid::render::detail
