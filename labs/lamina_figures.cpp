#include "lamina_figures.h"

#include <stdexcept>

namespace rigid::lab {

void draw_lamina_figures(Lab&, const LaminaInputs&, const Mat3&, const PrincipalAxes&) {
  throw std::runtime_error("this build has no renderer yet");
}

}  // namespace rigid::lab
