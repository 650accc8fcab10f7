// Legends cannot lie: every legend entry of every lab's figures (the textbook's inputs,
// 800x600), recoloured alone, changes its swatch and pixels outside the legend (one
// source for both, and the entry names something drawn), and where it is drawn some of
// its pixels are the swatch's colour (what a reader matches them by).
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "common/registry.h"
#include "rigid/render/draw.h"

namespace {

using rigid::render::Color;
using rigid::render::Image;
using rigid::render::ScreenRect;

constexpr int kWidth = 800, kHeight = 600;
// A colour no figure uses: what a recoloured entry is drawn in.
constexpr Color kProbe{1.0f, 0.0f, 1.0f, 1.0f};

bool inside(const ScreenRect& r, int x, int y) {
  return !r.empty() && x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
}

struct Changed {
  std::vector<std::array<int, 3>> legend, elsewhere;  // the original's colours there
};

// The pixels a recolouring changed, inside the legend boxes and elsewhere, with the
// colours the original had there.
Changed changed(const Image& a, const Image& b, const std::vector<ScreenRect>& legends) {
  Changed c;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const std::uint8_t *p = a.at(x, y), *q = b.at(x, y);
      if (std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2]) < 24) continue;
      bool in_legend = false;
      for (const ScreenRect& r : legends) in_legend = in_legend || inside(r, x, y);
      (in_legend ? c.legend : c.elsewhere).push_back({p[0], p[1], p[2]});
    }
  }
  return c;
}

// The swatch's colour: the most saturated-from-white of the legend's changed pixels (its
// body, not its antialiased rim).
std::array<int, 3> swatch_colour(const std::vector<std::array<int, 3>>& pixels) {
  std::array<int, 3> best{255, 255, 255};
  int most = -1;
  for (const auto& p : pixels) {
    const int depth = 765 - p[0] - p[1] - p[2];
    if (depth > most) most = depth, best = p;
  }
  return best;
}

double share_near(const std::vector<std::array<int, 3>>& pixels, const std::array<int, 3>& c,
                  int tolerance) {
  if (pixels.empty()) return 0.0;
  std::size_t n = 0;
  for (const auto& p : pixels) {
    n += std::abs(p[0] - c[0]) <= tolerance && std::abs(p[1] - c[1]) <= tolerance &&
         std::abs(p[2] - c[2]) <= tolerance;
  }
  return double(n) / pixels.size();
}

// Entries whose swatch a reader cannot match to what is drawn, found by this test and
// not fixed yet: each must still fail (a fixed one fails the test until taken off).
// (None now: the last ones, the herpolhode's lines and contact balls drawn pale, were a
// translucent surface drawn over what lay in front of it, with no depth test.)
const std::set<std::string> kKnownDefects = {};

template <class Figure>
void check_entry(const std::string& where, const Figure& original, const Figure& probed,
                 const std::vector<ScreenRect>& legends) {
  const Image a = rigid::render::draw(original, kWidth, kHeight);
  const Image b = rigid::render::draw(probed, kWidth, kHeight);
  const Changed c = changed(a, b, legends);
  INFO(where << ": " << c.legend.size() << " legend pixels changed, " << c.elsewhere.size()
             << " elsewhere");
  // its swatch follows it, it is drawn, and some of it is drawn in the swatch's colour
  // (5 % within 48 levels: a lit surface's shades spread about its facing colour)
  bool ok = c.legend.size() >= 20 && c.elsewhere.size() >= 20;
  if (ok) {
    const std::array<int, 3> swatch = swatch_colour(c.legend);
    const double share = share_near(c.elsewhere, swatch, 48);
    UNSCOPED_INFO("swatch " << swatch[0] << "," << swatch[1] << "," << swatch[2] << ": "
                            << share * 100 << " % of its drawn pixels within 48 levels of it");
    ok = share >= 0.05;
  }
  if (kKnownDefects.count(where)) {
    INFO("a known defect: fixed? then take it off kKnownDefects");
    CHECK_FALSE(ok);
  } else {
    CHECK(ok);
  }
}

// A legend under the panels names a label's items in every panel: they are drawn alike,
// and recoloured together, the swatch follows.
void check_shared_legend(const std::string& where, const rigid::render::Plot2D& plot,
                         const std::vector<ScreenRect>& legends) {
  std::vector<std::string> labels;
  std::map<std::string, const rigid::render::Series*> first;
  for (int r = 0; r < plot.rows(); ++r)
    for (int col = 0; col < plot.cols(); ++col)
      for (const auto& s : plot.panel(r, col).series) {
        if (s.label.empty()) continue;
        const auto [it, added] = first.emplace(s.label, &s);
        if (added) {
          labels.push_back(s.label);
          continue;
        }
        INFO(where << ": " << s.label << " in another panel");
        const Color &a = s.color, &b = it->second->color;
        CHECK((a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a));
        CHECK(s.dash == it->second->dash);
        CHECK(s.marker == it->second->marker);
      }
  REQUIRE(!labels.empty());
  for (const std::string& label : labels) {
    auto probed = plot;
    for (int r = 0; r < plot.rows(); ++r)
      for (int col = 0; col < plot.cols(); ++col)
        for (auto& s : probed.panel(r, col).series)
          if (s.label == label) s.color = kProbe;
    check_entry(where + ": " + label, plot, probed, legends);
  }
}

}  // namespace

TEST_CASE("legends: each entry's swatch is the colour of what it names and it is drawn") {
  for (const rigid::lab::LabEntry& entry : rigid::lab::all_labs()) {
    SECTION(entry.name) {
      auto session = entry.make();
      session->wait();
      for (const rigid::lab::NamedFigure& f : session->figures()) {
        const std::string where = entry.name + "_" + f.name;
        if (const auto* scene = std::get_if<rigid::render::Scene3D>(&f.figure)) {
          const auto legend = rigid::render::layout(*scene, kWidth, kHeight).legend;
          std::vector<std::string> seen;
          for (const auto& o : scene->objects())
            if (!o.label.empty()) seen.push_back(o.label);
          for (const auto& p : scene->polylines())
            if (!p.label.empty()) seen.push_back(p.label);
          for (const std::string& label : seen)
            check_entry(where + ": " + label, *scene, scene->recolored(label, kProbe), {legend});
        } else {
          const auto& plot = std::get<rigid::render::Plot2D>(f.figure);
          const auto layout = rigid::render::layout(plot, kWidth, kHeight);
          std::vector<ScreenRect> legends{layout.legend};
          for (const auto& p : layout.panels) legends.push_back(p.legend);
          if (!layout.legend.empty()) {
            check_shared_legend(where, plot, legends);
            continue;
          }
          for (int r = 0; r < plot.rows(); ++r) {
            for (int col = 0; col < plot.cols(); ++col) {
              const auto& panel = plot.panel(r, col);
              const std::size_t at = static_cast<std::size_t>(r * plot.cols() + col);
              // an entry shows in the legend only where the panel draws one
              if (layout.panels[at].legend.empty()) continue;
              for (std::size_t k = 0; k < panel.series.size(); ++k) {
                if (panel.series[k].label.empty()) continue;
                auto probed = plot;
                probed.panel(r, col).series[k].color = kProbe;
                check_entry(where + ": " + panel.series[k].label, plot, probed, legends);
              }
              for (std::size_t k = 0; k < panel.bands.size(); ++k) {
                if (panel.bands[k].label.empty()) continue;
                auto probed = plot;
                probed.panel(r, col).bands[k].color = kProbe;
                check_entry(where + ": " + panel.bands[k].label, plot, probed, legends);
              }
              for (std::size_t k = 0; k < panel.spans.size(); ++k) {
                if (panel.spans[k].label.empty()) continue;
                auto probed = plot;
                probed.panel(r, col).spans[k].color = kProbe;
                check_entry(where + ": " + panel.spans[k].label, plot, probed, legends);
              }
            }
          }
        }
      }
    }
  }
}
