// The plot description: panels and what the builders add to them. Part of
// the description library: no GL, no fonts.
#include "rigid/render/plot2d.h"

#include <stdexcept>

namespace rigid::render {

namespace {

// Where panel (row, col) of a rows x cols grid sits in the row-major list.
std::size_t panel_index(int row, int col, int rows, int cols) {
  if (row < 0 || row >= rows || col < 0 || col >= cols)
    throw std::out_of_range("Plot2D::panel: no such panel");
  return static_cast<std::size_t>(row) * cols + col;
}

}  // namespace

// ---- Panel builders --------------------------------------------------------

Series& Panel::add_line(std::vector<double> xs, std::vector<double> ys, std::string label) {
  Series s;
  s.x = std::move(xs);
  s.y = std::move(ys);
  s.label = std::move(label);
  series.push_back(std::move(s));
  return series.back();
}

Series& Panel::add_points(std::vector<double> xs, std::vector<double> ys, std::string label,
                          Marker marker) {
  Series& s = add_line(std::move(xs), std::move(ys), std::move(label));
  s.width = 0;
  s.marker = marker;
  return s;
}

Band& Panel::add_band(std::vector<double> xs, std::vector<double> lo, std::vector<double> hi,
                      std::string label) {
  Band b;
  b.x = std::move(xs);
  b.y_lo = std::move(lo);
  b.y_hi = std::move(hi);
  b.label = std::move(label);
  bands.push_back(std::move(b));
  return bands.back();
}

Span& Panel::add_span(double lo, double hi, bool vertical, std::string label) {
  Span s;
  s.lo = lo;
  s.hi = hi;
  s.vertical = vertical;
  s.label = std::move(label);
  spans.push_back(std::move(s));
  return spans.back();
}

RefLine& Panel::add_ref_line(double value, bool vertical, std::string label) {
  RefLine r;
  r.value = value;
  r.vertical = vertical;
  r.label = std::move(label);
  ref_lines.push_back(std::move(r));
  return ref_lines.back();
}

Annotation& Panel::annotate(double x_, double y_, std::string text) {
  Annotation a;
  a.x = x_;
  a.y = y_;
  a.text = std::move(text);
  annotations.push_back(std::move(a));
  return annotations.back();
}

Plot2D::Plot2D(int rows, int cols) : rows_(rows), cols_(cols) {
  if (rows < 1 || cols < 1 || rows * cols > 64)
    throw std::invalid_argument("Plot2D: rows and cols must be 1..8 panels each way");
  panels_.resize(static_cast<std::size_t>(rows) * cols);
}

Panel& Plot2D::panel(int row, int col) {
  return panels_[panel_index(row, col, rows_, cols_)];
}

const Panel& Plot2D::panel(int row, int col) const {
  return panels_[panel_index(row, col, rows_, cols_)];
}

}  // namespace rigid::render
