// Internal: the OSMesa backend (Mesa's software off-screen library, llvmpipe).
// libOSMesa is opened with dlopen on the first figure, not linked: it pulls in
// LLVM, whose loading and relocation would otherwise cost every run of a lab,
// with or without --figures, before main().
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <vector>

#include "backends.h"

namespace rigid::render::detail {

namespace {

struct OSMesaApi {
  decltype(&OSMesaCreateContextAttribs) create = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaDestroyContext) destroy = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc = nullptr;
};

OSMesaApi api;

GlProc osmesa_proc(const char* name) {
  return reinterpret_cast<GlProc>(api.get_proc(name));
}

// Opens libOSMesa and finds its entry points; false with `error` set if it cannot.
bool load(std::string& error) {
  if (api.get_proc != nullptr) return true;
  void* lib = open_library({"libOSMesa.so.8", "libOSMesa.so"}, "libOSMesa", error);
  if (lib == nullptr) return false;
  OSMesaApi a;
  a.create = reinterpret_cast<decltype(a.create)>(dlsym(lib, "OSMesaCreateContextAttribs"));
  a.make_current = reinterpret_cast<decltype(a.make_current)>(dlsym(lib, "OSMesaMakeCurrent"));
  a.destroy = reinterpret_cast<decltype(a.destroy)>(dlsym(lib, "OSMesaDestroyContext"));
  a.get_proc = reinterpret_cast<decltype(a.get_proc)>(dlsym(lib, "OSMesaGetProcAddress"));
  if (!a.create || !a.make_current || !a.destroy || !a.get_proc) {
    error = "libOSMesa lacks OSMesaCreateContextAttribs";
    return false;
  }
  api = a;
  return true;
}

}  // namespace

GlProcLoader make_osmesa_context(std::string& error) {
  if (!load(error)) return nullptr;
  const int attribs[] = {OSMESA_FORMAT,
                         OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,
                         0,
                         OSMESA_PROFILE,
                         OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION,
                         3,
                         OSMESA_CONTEXT_MINOR_VERSION,
                         3,
                         0};
  OSMesaContext ctx = api.create(attribs, nullptr);
  if (ctx == nullptr) {
    error = "OSMesaCreateContextAttribs failed for a GL 3.3 core profile";
    return nullptr;
  }
  // The default framebuffer is never drawn to, but MakeCurrent needs one;
  // it lives as long as the process's context.
  static std::vector<unsigned char> dummy(4 * 4 * 4);
  if (!api.make_current(ctx, dummy.data(), GL_UNSIGNED_BYTE, 4, 4)) {
    api.destroy(ctx);
    error = "OSMesaMakeCurrent failed";
    return nullptr;
  }
  return &osmesa_proc;
}

void* open_library(std::initializer_list<const char*> names, const char* what, std::string& error) {
  for (const char* name : names) {
    if (void* lib = dlopen(name, RTLD_NOW | RTLD_LOCAL)) return lib;
  }
  const char* why = dlerror();
  error = std::string("cannot load ") + what + " (" + (why ? why : "not found") + ")";
  return nullptr;
}

}  // namespace rigid::render::detail
