// top_nutation's figures (figures.h).
#include "figures.h"

namespace rigid::lab::top_nutation {

void draw(FigureSet& /*set*/, const Figures& /*f*/) {}

}  // namespace rigid::lab::top_nutation
