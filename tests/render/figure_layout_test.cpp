// What a reader of every lab's figures relies on, read from their layouts and
// descriptions, not their pixels: no two labels of a figure overlap at the sizes
// figures are made at (a projector's 800x600, the default 1600x1200, a slide's
// 1920x1080), and a figure comparing the integrators lists them as the lab's table
// ranks them, each with a marker of its own, so that curves lying on one another
// each show.
#include <algorithm>
#include <catch2/catch.hpp>
#include <map>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "common/inputs.h"
#include "common/registry.h"
#include "rigid/render/draw.h"

namespace {

using rigid::render::Plot2D;
using rigid::render::Scene3D;
using rigid::render::ScreenRect;

const std::vector<std::pair<int, int>> kSizes = {{800, 600}, {1600, 1200}, {1920, 1080}};

// A label names a point (a scene's label, an annotation, a reference line's), not a
// title or a legend.
bool is_label(const std::string& name) {
  return name != "the title" && name != "the legend" &&
         name.find("'s title") == std::string::npos && name.find("'s legend") == std::string::npos;
}

// Every pair of boxes that overlap, or of labels too near, as "i and j": labels less than
// a third of a line's height apart, or side by side on one line less than a line's height
// apart, for two a space or so apart read as one ("t = 0.769 s t = 0.984 s"). (Titles and
// legends are stacked a padding apart by the layout itself.)
std::vector<std::string> overlaps(const std::vector<std::pair<std::string, ScreenRect>>& boxes) {
  std::vector<std::string> found;
  // (a box reported twice, a one-panel plot's title or legend as the figure's, is one)
  const auto same = [](const ScreenRect& a, const ScreenRect& b) {
    return a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 && a.y1 == b.y1;
  };
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const ScreenRect &a = boxes[i].second, &b = boxes[j].second;
      if (same(a, b)) continue;
      bool near = a.overlaps(b);
      if (is_label(boxes[i].first) && is_label(boxes[j].first)) {
        const double line = std::min(a.height(), b.height()), gap = line / 3, line_gap = line;
        const bool one_line = a.y0 < b.y1 && b.y0 < a.y1;
        const ScreenRect wide{a.x0 - line_gap, a.y0, a.x1 + line_gap, a.y1};
        near = near || a.grown(gap).overlaps(b) || (one_line && wide.overlaps(b));
      }
      if (near) found.push_back("'" + boxes[i].first + "' and '" + boxes[j].first + "'");
    }
  return found;
}

std::vector<std::pair<std::string, ScreenRect>> text_boxes(const Scene3D& scene, int w, int h) {
  const Scene3D::Layout layout = rigid::render::layout(scene, w, h);
  std::vector<std::pair<std::string, ScreenRect>> boxes{{"the title", layout.title},
                                                        {"the legend", layout.legend}};
  for (std::size_t k = 0; k < layout.labels.size(); ++k)
    boxes.push_back({scene.labels()[k].text, layout.labels[k]});
  return boxes;
}

std::vector<std::pair<std::string, ScreenRect>> text_boxes(const Plot2D& plot, int w, int h) {
  const Plot2D::Layout layout = rigid::render::layout(plot, w, h);
  std::vector<std::pair<std::string, ScreenRect>> boxes{{"the title", layout.title},
                                                        {"the legend", layout.legend}};
  for (int r = 0; r < plot.rows(); ++r)
    for (int c = 0; c < plot.cols(); ++c) {
      const auto& panel = plot.panel(r, c);
      const auto& at = layout.panels.at(static_cast<std::size_t>(r * plot.cols() + c));
      const std::string name = "panel " + std::to_string(r) + "," + std::to_string(c);
      boxes.push_back({name + "'s title", at.title});
      boxes.push_back({name + "'s legend", at.legend});
      for (std::size_t k = 0; k < at.annotations.size(); ++k)
        boxes.push_back({name + ": " + panel.annotations[k].text, at.annotations[k]});
      std::size_t k = 0;
      for (const auto& line : panel.ref_lines)
        if (!line.label.empty() && k < at.ref_labels.size())
          boxes.push_back({name + ": " + line.label, at.ref_labels[k++]});
    }
  return boxes;
}

// The method a legend entry names: its text before the comma ("vern9, tol 1e-12").
std::string method_of(const std::string& label) {
  return label.substr(0, label.find(','));
}

}  // namespace

TEST_CASE("figures: no two labels, titles or legends of a figure touch, at any size") {
  for (const rigid::lab::LabEntry& entry : rigid::lab::all_labs()) {
    SECTION(entry.name) {
      auto session = entry.make();
      session->wait();
      for (const rigid::lab::NamedFigure& f : session->figures()) {
        for (const auto& [w, h] : kSizes) {
          INFO(entry.name << "_" << f.name << " at " << w << "x" << h);
          const auto boxes =
              std::visit([&](const auto& fig) { return text_boxes(fig, w, h); }, f.figure);
          CHECK(overlaps(boxes) == std::vector<std::string>{});
        }
      }
    }
  }
}

TEST_CASE("figures: the integrators are listed as the table ranks them, each its own marker") {
  int compared = 0;
  for (const rigid::lab::LabEntry& entry : rigid::lab::all_labs()) {
    auto session = entry.make();
    session->wait();
    // the table's ranking at equal cost: equal_cost_rank_<method>, a projected run aside
    std::map<std::size_t, std::string> ranked;
    for (const auto& [key, value] : session->report().results().items()) {
      const std::string prefix = "equal_cost_rank_";
      if (key.rfind(prefix, 0) != 0 || key.find("_project") != std::string::npos) continue;
      ranked[value.get<std::size_t>()] = key.substr(prefix.size());
    }
    for (const rigid::lab::NamedFigure& f : session->figures()) {
      if (f.name != "integrators" || ranked.empty()) continue;
      INFO(entry.name << "_" << f.name);
      ++compared;
      const Plot2D& plot = std::get<Plot2D>(f.figure);
      std::vector<std::string> listed, expected;
      std::set<rigid::render::Marker> markers;
      std::set<double> phases;
      for (const auto& s : plot.panel(0, 0).series) {
        listed.push_back(rigid::lab::json_key(method_of(s.label)));
        CHECK(s.marker != rigid::render::Marker::kNone);
        CHECK(s.marker_spacing > 0);
        markers.insert(s.marker);
        phases.insert(s.marker_phase);
      }
      for (const auto& [rank, key] : ranked)
        if (std::find(listed.begin(), listed.end(), key) != listed.end()) expected.push_back(key);
      CHECK(listed == expected);
      CHECK(listed.size() >= 8);  // every method drawn but those the cost stops
      CHECK(markers.size() == listed.size());
      CHECK(phases.size() == listed.size());
    }
  }
  CHECK(compared == 2);  // poinsot and top_nutation
}

TEST_CASE("figures: each legend entry of a plot names a series with a point inside its axes") {
  for (const rigid::lab::LabEntry& entry : rigid::lab::all_labs()) {
    SECTION(entry.name) {
      auto session = entry.make();
      session->wait();
      for (const rigid::lab::NamedFigure& f : session->figures()) {
        const auto* plot = std::get_if<Plot2D>(&f.figure);
        if (plot == nullptr) continue;
        const Plot2D::Layout layout = rigid::render::layout(*plot, 800, 600);
        for (int r = 0; r < plot->rows(); ++r)
          for (int c = 0; c < plot->cols(); ++c) {
            const auto& at = layout.panels.at(static_cast<std::size_t>(r * plot->cols() + c));
            for (const auto& s : plot->panel(r, c).series) {
              if (s.label.empty()) continue;
              INFO(entry.name << "_" << f.name << ": '" << s.label << "'");
              bool inside = false;
              for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k)
                inside = inside || (s.x[k] >= at.x_lo && s.x[k] <= at.x_hi && s.y[k] >= at.y_lo &&
                                    s.y[k] <= at.y_hi);
              CHECK(inside);
            }
          }
      }
    }
  }
}
