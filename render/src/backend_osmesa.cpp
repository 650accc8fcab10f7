// Internal: the OSMesa backend (Mesa's software off-screen library, llvmpipe).
#include <GL/osmesa.h>

#include <vector>

#include "backends.h"

namespace rigid::render::detail {

namespace {

GlProc osmesa_proc(const char* name) { return reinterpret_cast<GlProc>(OSMesaGetProcAddress(name)); }

}  // namespace

GlProcLoader make_osmesa_context(std::string& error) {
  const int attribs[] = {OSMESA_FORMAT,                OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,            0,
                         OSMESA_PROFILE,               OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION, 3,
                         OSMESA_CONTEXT_MINOR_VERSION, 3,
                         0};
  OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
  if (ctx == nullptr) {
    error = "OSMesaCreateContextAttribs failed for a GL 3.3 core profile";
    return nullptr;
  }
  // The default framebuffer is never drawn to, but MakeCurrent needs one;
  // it lives as long as the process's context.
  static std::vector<unsigned char> dummy(4 * 4 * 4);
  if (!OSMesaMakeCurrent(ctx, dummy.data(), GL_UNSIGNED_BYTE, 4, 4)) {
    OSMesaDestroyContext(ctx);
    error = "OSMesaMakeCurrent failed";
    return nullptr;
  }
  return &osmesa_proc;
}

}  // namespace rigid::render::detail
