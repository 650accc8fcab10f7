// The command's drawing where the renderer is not built (command_render.h): it says
// so, and the command line refuses --figures and --animate with that, before any
// work, so the two functions that would draw are never reached.
#include <stdexcept>

#include "common/command_render.h"

namespace rigid::lab {
namespace {

const char* const kMissing =
    "needs the renderer, and this build has none (configured with -DRIGID_BUILD_RENDER=OFF)";

}  // namespace

std::string renderer_missing() {
  return kMissing;
}

bool animation_format_known(const std::string&) {
  return false;
}

void draw_figures(const CommandOptions&, const Computed&, RunOutputs&, FigureLog&) {
  throw std::logic_error(kMissing);
}

Json encode_animation(const CommandOptions&, const Animation&, const Report&) {
  throw std::logic_error(kMissing);
}

}  // namespace rigid::lab
