// Internal: the libraries opened on first use (dlopen), and the two ways to get a GL
// context. Each of those returns the backend's GetProcAddress once its context is
// current, or nullptr with `error` set.
#pragma once

#include <dlfcn.h>

#include <initializer_list>
#include <string>

namespace rigid::render::detail {

using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char*);

/// dlopen()s the first of `names` that loads; nullptr with `error` naming `what` if none does.
void* open_library(std::initializer_list<const char*> names, const char* what, std::string& error);

/// Looks up `name` in `lib` into `fn`; false if it is missing.
template <class F>
bool bind_symbol(void* lib, const char* name, F& fn) {
  fn = reinterpret_cast<F>(dlsym(lib, name));
  return fn != nullptr;
}

/// A library's entry points as a table, its list written once as X(library, function)
/// lines: RIGID_ENTRY_POINT declares the member `function`, typed by the function's own
/// declaration in its header; RIGID_BIND_ENTRY_POINT, chained after `true`, looks it up
/// by name in `library` (open_library's handle) into the table `api`, false if missing.
#define RIGID_ENTRY_POINT(library, function) decltype(&::function) function = nullptr;
#define RIGID_BIND_ENTRY_POINT(library, function) \
  &&::rigid::render::detail::bind_symbol(library, #function, api.function)

/// Makes an OSMesa GL 3.3+ core context current (tiny dummy buffer; drawing goes to FBOs).
GlProcLoader make_osmesa_context(std::string& error);
/// Makes an EGL surfaceless GL 3.3+ core context current (no surface at all), or with
/// `es` an OpenGL ES 3.0 one.
GlProcLoader make_egl_context(std::string& error, bool es = false);

}  // namespace rigid::render::detail
