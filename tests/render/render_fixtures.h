// Shared figures for the renderer tests, also drawn by the child processes
// that the backend and thread-count tests start.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "rigid/render/image.h"
#include "rigid/render/plot2d.h"

namespace rigid::render::test {

/// A plot with lines, a band, markers, a log panel and text: exercises everything 2D.
inline Plot2D reference_plot() {
  Plot2D plot(1, 2);
  plot.title = "Reference: \\omega_1, \\dot{\\theta}, 10^{-6}";
  Panel& a = plot.panel(0, 0);
  a.x.label = "t (s)";
  a.y.label = "\\omega (rad/s)";
  std::vector<double> t, y1, y2, lo, hi;
  for (int i = 0; i <= 200; ++i) {
    t.push_back(0.05 * i);
    y1.push_back(std::sin(t.back()));
    y2.push_back(0.5 * std::cos(1.7 * t.back()));
    lo.push_back(y2.back() - 0.2);
    hi.push_back(y2.back() + 0.2);
  }
  a.add_band(t, lo, hi, "band");
  a.add_line(t, y1, "\\omega_1");
  a.add_line(t, y2, "\\omega_2").dash = Dash::kDashed;
  Panel& b = plot.panel(0, 1);
  b.x.scale = Scale::kLog10;
  b.y.scale = Scale::kLog10;
  b.x.label = "n";
  b.y.label = "error";
  std::vector<double> n, e;
  for (int k = 0; k < 10; ++k) {
    n.push_back(std::pow(2.0, k + 3));
    e.push_back(std::pow(n.back(), -2.0));
  }
  b.add_line(n, e, "RK2").marker = Marker::kCircle;
  return plot;
}

/// Absolute path of this test executable (for re-invoking it as a child).
std::string self_path();

/// Runs this executable as a child with extra environment settings, drawing reference_plot() to a
/// PNG; returns it.
Image render_in_child(const std::string& env, const std::string& png_path);
/// The context a child process makes with `env`: "backend samples GL_VERSION".
std::string context_in_child(const std::string& env, const std::string& path);

}  // namespace rigid::render::test
