// What every lab's figures say, read from their descriptions (no pixels): each has a
// name of its own and a title, each panel its axes' labels, each legend entry one look
// and something drawn under it. The golden images and the legend test hold the drawing
// of these to the renderer; here they are held to the lab, in a millisecond a figure.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include "common/registry.h"

namespace {

using rigid::render::Color;
using rigid::render::Dash;
using rigid::render::Marker;
using rigid::render::Panel;
using rigid::render::Plot2D;
using rigid::render::Scene3D;

// How an entry looks in a legend: its swatch's colour, dash and marker.
using Look = std::tuple<float, float, float, float, Dash, Marker>;

Look look_of(const rigid::render::Series& s) {
  return {s.color.r, s.color.g, s.color.b, s.color.a, s.dash, s.marker};
}
Look look_of(const Color& c) {
  return {c.r, c.g, c.b, c.a, Dash::kSolid, Marker::kNone};
}

bool any_finite_point(const std::vector<double>& x, const std::vector<double>& y) {
  for (std::size_t k = 0; k < x.size() && k < y.size(); ++k) {
    if (std::isfinite(x[k]) && std::isfinite(y[k])) return true;
  }
  return false;
}

// One panel: a labelled y axis, series of matching lengths, and each label of the
// panel one look, naming something with a point to draw.
void check_panel(const Panel& p, std::map<std::string, Look>& looks) {
  CHECK_FALSE(p.y.label.empty());
  const auto one_look = [&](const std::string& label, const Look& look) {
    if (label.empty()) return;
    INFO("legend entry '" << label << "'");
    const auto [it, first] = looks.emplace(label, look);
    CHECK((first || it->second == look));
  };
  for (const auto& s : p.series) {
    INFO("series '" << s.label << "'");
    CHECK(s.x.size() == s.y.size());
    if (!s.label.empty()) CHECK(any_finite_point(s.x, s.y));
    one_look(s.label, look_of(s));
  }
  for (const auto& b : p.bands) {
    INFO("band '" << b.label << "'");
    CHECK(b.x.size() == b.y_lo.size());
    CHECK(b.x.size() == b.y_hi.size());
    if (!b.label.empty()) CHECK(any_finite_point(b.x, b.y_lo));
    one_look(b.label, look_of(b.color));
  }
  for (const auto& s : p.spans) {
    INFO("span '" << s.label << "'");
    CHECK(std::isfinite(s.lo));
    CHECK(std::isfinite(s.hi));
    CHECK(s.lo <= s.hi);
    one_look(s.label, look_of(s.color));
  }
}

void check_plot(const Plot2D& plot) {
  CHECK_FALSE(plot.title.empty());
  // A figure's shared legend lists a label once for all its panels: one look in all of
  // them. Panels with legends of their own keep a label's look within each.
  std::map<std::string, Look> shared;
  for (int c = 0; c < plot.cols(); ++c) {
    bool x_said = false;  // panels stacked on one x say it once, under the lowest
    for (int r = 0; r < plot.rows(); ++r) {
      INFO("panel " << r << "," << c << " '" << plot.panel(r, c).title << "'");
      std::map<std::string, Look> own;
      check_panel(plot.panel(r, c), plot.shared_legend ? shared : own);
      x_said = x_said || !plot.panel(r, c).x.label.empty();
    }
    INFO("column " << c);
    CHECK(x_said);
  }
}

void check_scene(const Scene3D& scene) {
  std::set<std::string> drawn;
  for (const auto& o : scene.objects()) {
    if (!o.label.empty()) drawn.insert(o.label);
  }
  for (const auto& p : scene.polylines()) {
    if (p.label.empty()) continue;
    INFO("line '" << p.label << "'");
    CHECK(p.points.size() >= 2);
    drawn.insert(p.label);
  }
  // every entry of a still figure's legend names something in it
  for (const std::string& label : scene.legend_labels()) {
    INFO("legend entry '" << label << "'");
    CHECK(drawn.count(label) == 1);
  }
}

}  // namespace

TEST_CASE("figures: each lab's figures say what they show, one look a legend entry") {
  for (const rigid::lab::LabEntry& entry : rigid::lab::all_labs()) {
    SECTION(entry.name) {
      auto session = entry.make();
      session->wait();
      std::set<std::string> names;
      REQUIRE_FALSE(session->figures().empty());
      for (const rigid::lab::NamedFigure& f : session->figures()) {
        INFO(entry.name << "_" << f.name);
        CHECK(names.insert(f.name).second);  // a file name of its own
        if (const auto* scene = std::get_if<Scene3D>(&f.figure)) {
          check_scene(*scene);
        } else {
          check_plot(std::get<Plot2D>(f.figure));
        }
      }
    }
  }
}
