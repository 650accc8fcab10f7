// top_nutation's motion and figures in-process: the scene at a time the same in any
// order of asking, the motion kept apart from the report and starting at the 'top'
// figure, and every valid run's figures, the extremes drawn to be seen.
#include <algorithm>
#include <catch2/catch.hpp>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "lab_library.h"
#include "top_nutation/top_nutation.h"

using rigid::lab::top_nutation::compute;
using rigid::lab::top_nutation::Inputs;
using rigid::lab::top_nutation::Motion;
using rigid::test::check_same_scene;
using rigid::test::value;

namespace {

Inputs with_method(const std::string& method) {
  Inputs in;
  in.integration.method = method;
  return in;
}

// A sink that keeps the figures' names, and the scene of one of them.
struct Kept : rigid::lab::FigureSink {
  std::vector<std::string> names;
  std::optional<rigid::render::Scene3D> top;
  void add(const std::string& name, const std::string&, rigid::render::Plot2D) override {
    names.push_back(name);
  }
  void add(const std::string& name, const std::string&, rigid::render::Scene3D scene) override {
    names.push_back(name);
    if (name == "top") top = std::move(scene);
  }
};

}  // namespace

TEST_CASE("top_nutation: the motion's scene at a time is the same in any order of asking") {
  for (const char* method : {"exact", "rk4"}) {
    INFO(method);
    const auto report = compute(with_method(method));
    // The frames' times, and times off them and off the run's samples.
    std::vector<double> times;
    for (int k = 0; k < 24; ++k) times.push_back(report.t_end * k / 24);
    std::vector<double> asked = times;
    for (const double share : {0.013, 0.37, 0.5001, 0.999}) asked.push_back(share * report.t_end);
    const Motion in_order(report, times);
    std::vector<rigid::render::Scene3D> expected;
    for (const double t : asked) expected.push_back(in_order.scene(t));

    // A second motion, sampled ahead at the same times given shuffled, asked in another order.
    std::vector<std::size_t> order(asked.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::mt19937 random(2024);
    std::shuffle(order.begin(), order.end(), random);
    std::vector<double> shuffled = times;
    std::shuffle(shuffled.begin(), shuffled.end(), random);
    const Motion second(report, shuffled);
    for (const std::size_t i : order) {
      INFO("t = " << asked[i]);
      check_same_scene(second.scene(asked[i]), expected[i]);
    }
    // Asked twice, the same scene: nothing is kept from one asking to the next.
    check_same_scene(second.scene(asked[order[0]]), expected[order[0]]);
    CHECK(second.seconds() == report.t_end);
  }
}

TEST_CASE("top_nutation: the band figure fills the turning circles for a fast top too") {
  // At 5000 rpm the band is a tenth of a degree tall: each panel's path spans exactly
  // the band between its turning circles, so its waves, cusps or loops fill the panel.
  Inputs in;
  in.spin_rpm = 5000;
  const auto report = compute(in);
  rigid::test::KeptFigures kept;
  figures(report, kept);
  REQUIRE(kept.plots.count("band") == 1);
  const rigid::render::Plot2D& band = kept.plots.at("band");
  REQUIRE(band.rows() == 3);
  CHECK_THAT(band.panel(0, 0).title, Catch::StartsWith("this run: cusped"));
  const double theta_min = value(report.results(), "theta_min_deg");
  const double theta_max = value(report.results(), "theta_max_deg");
  CHECK(theta_max - theta_min < 0.2);
  const auto& path = band.panel(0, 0).series.at(0).y;
  const auto [lo, hi] = std::minmax_element(path.begin(), path.end());
  // the samples reach the turning points to within their spacing's curvature: 1200 a
  // panel over 3 periods, so 1e-3 of the band
  CHECK(*lo == Approx(theta_min).margin(1e-3 * (theta_max - theta_min)));
  CHECK(*hi == Approx(theta_max).margin(1e-3 * (theta_max - theta_min)));
  // the other two are the other regimes
  std::vector<std::string> titles{band.panel(1, 0).title, band.panel(2, 0).title};
  CHECK_THAT(titles[0] + titles[1], Catch::Contains("wavy") && Catch::Contains("looping"));
}

TEST_CASE("top_nutation: the motion keeps what it needs and starts at the 'top' figure") {
  for (const char* method : {"exact", "rk4"}) {
    INFO(method);
    std::optional<Motion> motion;
    std::optional<rigid::render::Scene3D> at_half;
    {
      const auto report = compute(with_method(method));
      motion.emplace(report);
      at_half = motion->scene(0.5 * report.t_end);
      // The figures: the "top" is the motion's first scene.
      Kept kept;
      figures(report, kept);
      CHECK(kept.names ==
            std::vector<std::string>{"potential", "paths", "band", "theta", "top", "integrators"});
      REQUIRE(kept.top);
      check_same_scene(*kept.top, motion->scene(0.0));
      // The animation's motion: its still is that figure, its span the run's.
      const auto animation = rigid::lab::top_nutation::animation(report, [](double seconds) {
        return std::vector<double>{0.0, 0.25 * seconds};
      });
      CHECK(animation.still == "top");
      CHECK(animation.seconds == report.t_end);
      check_same_scene(animation.scene(0.0), *kept.top);
    }
    // The report is gone: the motion copied what it draws from.
    check_same_scene(motion->scene(0.5 * motion->seconds()), *at_half);
  }
}

TEST_CASE("top_nutation: every valid run draws its figures, the extremes drawn to be seen") {
  using rigid::test::contains;
  using rigid::test::KeptFigures;
  // An arm 1e20 m beside a 5 cm disk: l +- the disk's thickness would be l in doubles; a
  // 1e-20 m disk would not show. Both are drawn at 2% of the picture and say so.
  for (const auto& [arm, radius] : {std::pair{1e20, 0.05}, std::pair{0.04, 1e-20}}) {
    INFO("arm " << arm << ", disk radius " << radius);
    Inputs in;
    in.arm = arm, in.disk_radius = radius;
    KeptFigures kept;
    REQUIRE_NOTHROW(figures(compute(in), kept));
    CHECK(contains(kept.scenes.at("top").title, "(disk enlarged to be seen)"));
  }
  Inputs text;
  KeptFigures kept;
  figures(compute(text), kept);
  CHECK(!contains(kept.scenes.at("top").title, "enlarged"));
  // The exact run is valid at any step and for 1e8 periods; the figure's integrated
  // companion (splitting4 at the run's step) would need more steps than a run may take,
  // so the theta figure shows the exact motion alone and says why.
  Inputs tiny_step = with_method("exact"), long_run = with_method("exact");
  tiny_step.integration.step = 1e-20;
  long_run.periods = 1e8;
  for (const Inputs& in : {tiny_step, long_run}) {
    KeptFigures alone;
    REQUIRE_NOTHROW(figures(compute(in), alone));
    const auto& theta = alone.plots.at("theta");
    CHECK(contains(theta.title, "exact (splitting4 at step"));
    CHECK(contains(theta.title, "would need"));
  }
  KeptFigures beside;
  figures(compute(with_method("exact")), beside);
  CHECK(!contains(beside.plots.at("theta").title, "would need"));
}
