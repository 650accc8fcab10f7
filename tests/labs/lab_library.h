// What the in-process tests of the lab libraries share: reading a report's
// results, and matching the input an InputError names.
#pragma once

#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "common/figures.h"
#include "common/inputs.h"
#include "common/report.h"

namespace rigid::test {

/// The relative difference between a closed form as the lab evaluates it and as a test
/// writes it out: a handful of roundings of half an ulp each. Most such checks agree
/// to the last bit (scripts/tolerance-audit: "exact") or within 2 eps; the allowance
/// is for a compiler that contracts or reorders. A formula that cancels says its own
/// bound beside the check.
inline constexpr double kRoundoff = 4 * DBL_EPSILON;

/// A numeric result by key (throws if absent or not a number).
inline double value(const rigid::lab::Json& results, const char* key) {
  return results.at(key).get<double>();
}

/// The i-th component of a vector result.
inline double element(const rigid::lab::Json& results, const char* key, int i) {
  return results.at(key).at(i).get<double>();
}

/// True when `value` rounds to the text's `printed` at `decimals` decimals: half a
/// unit in the last place the text prints (and roundoff).
inline bool prints_as(double value, double printed, int decimals) {
  return std::abs(value - printed) <= 0.5 * std::pow(10.0, -decimals) + 1e-12;
}

inline bool same_color(const rigid::render::Color& a, const rigid::render::Color& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

/// Two scenes hold the same title, camera, surfaces, lines and labels, bit for bit.
inline void check_same_scene(const rigid::render::Scene3D& a, const rigid::render::Scene3D& b) {
  CHECK(a.title == b.title);
  CHECK(a.camera.eye == b.camera.eye);
  CHECK(a.camera.target == b.camera.target);
  CHECK(a.camera.up == b.camera.up);
  CHECK(a.camera.fov_y_deg == b.camera.fov_y_deg);
  REQUIRE(a.objects().size() == b.objects().size());
  for (std::size_t k = 0; k < a.objects().size(); ++k) {
    const auto& x = a.objects()[k];
    const auto& y = b.objects()[k];
    INFO("object " << k << " " << x.label);
    CHECK(x.shape == y.shape);
    CHECK(x.transform.matrix() == y.transform.matrix());
    CHECK(same_color(x.material.color, y.material.color));
    CHECK(x.material.opacity == y.material.opacity);
    CHECK(x.label == y.label);
    CHECK(x.path == y.path);
    CHECK(x.tube_radius == y.tube_radius);
  }
  REQUIRE(a.polylines().size() == b.polylines().size());
  for (std::size_t k = 0; k < a.polylines().size(); ++k) {
    const auto& x = a.polylines()[k];
    const auto& y = b.polylines()[k];
    CHECK(x.points == y.points);
    CHECK(same_color(x.color, y.color));
    CHECK(x.width == y.width);
    CHECK(x.label == y.label);
  }
  REQUIRE(a.labels().size() == b.labels().size());
  for (std::size_t k = 0; k < a.labels().size(); ++k) {
    CHECK(a.labels()[k].position == b.labels()[k].position);
    CHECK(a.labels()[k].text == b.labels()[k].text);
    CHECK(same_color(a.labels()[k].color, b.labels()[k].color));
  }
}

/// The figures a lab hands over, kept by name in the order given.
struct KeptFigures : rigid::lab::FigureSink {
  std::vector<std::string> names;
  std::map<std::string, rigid::render::Scene3D> scenes;
  std::map<std::string, rigid::render::Plot2D> plots;
  void add(const std::string& name, const std::string&, rigid::render::Plot2D plot) override {
    names.push_back(name);
    plots.emplace(name, std::move(plot));
  }
  void add(const std::string& name, const std::string&, rigid::render::Scene3D scene) override {
    names.push_back(name);
    scenes.emplace(name, std::move(scene));
  }
};

/// Matches an InputError that names `input` ("--mass").
class NamesInput : public Catch::MatcherBase<rigid::lab::InputError> {
 public:
  explicit NamesInput(std::string input) : input_(std::move(input)) {}
  bool match(const rigid::lab::InputError& e) const override { return e.input == input_; }
  std::string describe() const override { return "names the input " + input_; }

 private:
  std::string input_;
};
inline NamesInput names_input(const std::string& input) {
  return NamesInput(input);
}

/// The report's notes that start with `start`, in order.
inline std::vector<std::string> notes_starting(const rigid::lab::Report& report,
                                               const std::string& start) {
  std::vector<std::string> found;
  for (const std::string& note : report.notes()) {
    if (note.rfind(start, 0) == 0) found.push_back(note);
  }
  return found;
}
inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace rigid::test
