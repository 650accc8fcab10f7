// football's figures read from their descriptions: what a legend names is drawn, and
// where alpha is tiny (the Earth) the rates have a second panel worth reading.
#include <algorithm>
#include <catch2/catch.hpp>

#include "football/football.h"
#include "lab_library.h"

using rigid::lab::football::compute;
using rigid::lab::football::Inputs;
using rigid::test::KeptFigures;

namespace {

Inputs preset(const char* name) {
  Inputs in;
  in.preset = name;
  return in;
}

}  // namespace

TEST_CASE(
    "football: the cones' legend names only paths wide enough to draw, and the Earth's rates "
    "stand beside its flattening") {
  for (const char* name : {"football", "frisbee", "earth"}) {
    INFO(name);
    const auto report = compute(preset(name));
    KeptFigures figures;
    rigid::lab::football::figures(report, figures);
    const auto& cones = figures.scenes.at("cones");
    // a labelled path spans at least a hundredth of the scene's unit length (the
    // Earth's omega path, 1.8e-7 degrees about L, is a point at any size)
    for (const auto& line : cones.polylines()) {
      if (line.label.empty()) continue;
      INFO(line.label);
      double span = 0;
      for (const auto& p : line.points) span = std::max(span, (p - line.points.front()).norm());
      CHECK(span > 0.01);
    }
    // where alpha is tiny the rates are flat in it: a second panel against the flattening
    const bool tiny = report.alpha_deg < 0.5;
    CHECK(figures.plots.at("rates").cols() == (tiny ? 2 : 1));
  }
}
