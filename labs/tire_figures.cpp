#include "tire_figures.h"

#include <stdexcept>

namespace rigid::lab {

void draw_tire_figures(Lab&, const CrookedWheel&, double, double) {
  throw std::runtime_error("this build has no renderer yet");
}

}  // namespace rigid::lab
