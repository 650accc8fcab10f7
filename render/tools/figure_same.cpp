// figure-same NEW OLD: whether NEW draws what OLD does, by the golden tests' rule
// (image_match.h): a curve a pixel or two away, as another machine's maths library may
// put it, is the same figure. Exit 0 when OLD exists and NEW matches it, 1 when they
// differ (the reason on stdout) or OLD is missing, 2 when NEW cannot be read. The main
// job and the figures target replace a committed figure only on 1.
// figure-same --across-rasterisers NEW OLD: the same by the rule for another rasteriser
// of the same drawing (the web page's WebGL against the command line's figure).
#include <filesystem>
#include <iostream>
#include <string>

#include "rigid/render/image_match.h"
#include "rigid/render/png.h"

int main(int argc, char** argv) {
  rigid::render::MatchRule rule = rigid::render::kSameRenderer;
  if (argc == 4 && std::string(argv[1]) == "--across-rasterisers") {
    rule = rigid::render::kAcrossRasterisers;
    ++argv;
    --argc;
  }
  if (argc != 3) {
    std::cerr << "usage: figure-same [--across-rasterisers] NEW.png OLD.png\n";
    return 2;
  }
  rigid::render::Image fresh;
  try {
    fresh = rigid::render::read_png(argv[1]);
  } catch (const std::exception& e) {
    std::cerr << "figure-same: " << e.what() << "\n";
    return 2;
  }
  if (!std::filesystem::exists(argv[2])) {
    std::cout << "new figure\n";
    return 1;
  }
  try {
    const rigid::render::Image old = rigid::render::read_png(argv[2]);
    if (old.width != fresh.width || old.height != fresh.height) {
      std::cout << "size changed\n";
      return 1;
    }
    const std::string why = rigid::render::mismatch(fresh, old, rule);
    if (!why.empty()) {
      std::cout << "changed:" << why << "\n";
      return 1;
    }
  } catch (const std::exception& e) {
    std::cout << "unreadable: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
