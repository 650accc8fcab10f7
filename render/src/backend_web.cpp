// The WebAssembly page's build of what the native renderer finds on the system
// (backends.h, target.h). A browser has no off-screen GL to make (the page hands its
// WebGL2 canvas's context over: use_current_context), no shared libraries to open and
// no cairo: a plot as pixels is drawn with GL, as a live view draws it.
#include <string>

#include "backends.h"
#include "target.h"

namespace rigid::render::detail {

namespace {
constexpr const char* kInBrowser =
    "a web page has no off-screen GL context: it hands its canvas's WebGL2 context over "
    "(use_current_context)";
}  // namespace

void* open_library(std::initializer_list<const char*>, const char* what, std::string& error) {
  error = std::string(what) + " cannot be opened in a web page";
  return nullptr;
}

GlProcLoader make_osmesa_context(std::string& error) {
  error = kInBrowser;
  return nullptr;
}

GlProcLoader make_egl_context(std::string& error, bool) {
  error = kInBrowser;
  return nullptr;
}

Image draw_plot_on_cpu(const Plot2D& plot, int width, int height, FigureTiming* timing) {
  PhaseClock clock(timing);
  render_into_target(plot, width, height, clock);
  return target().finish();
}

}  // namespace rigid::render::detail
