// tennis_racquet launched exactly along a principal axis (--perturbation 0): the
// steady spin stays, and the report says so with the rates a disturbance would have.
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "lab_library.h"
#include "tennis_racquet/tennis_racquet.h"

using rigid::lab::tennis_racquet::compute;
using rigid::lab::tennis_racquet::Inputs;
using rigid::test::contains;
using rigid::test::value;

TEST_CASE("tennis_racquet: a spin exactly along an axis stays there, and says so with the rates") {
  for (const char* axis : {"1", "2", "3"}) {
    INFO("axis " << axis);
    Inputs in;
    in.spin_axis = axis;
    in.perturbation = 0;
    const auto report = compute(in);
    const auto& r = report.results();
    const int k = axis[0] - '1';
    // Euler's equations keep omega on a principal axis: the exact motion does not move.
    for (const double t : {0.1, 1.0, 10.0}) {
      const Eigen::Vector3d w = report.launches[k].omega_body(t);
      CHECK(w(k) == in.omega);
      CHECK(w.norm() == in.omega);
    }
    CHECK(r.at("first_flip_s").is_null());
    CHECK(r.at("growth_rate_measured_per_s").is_null());
    CHECK(r.at("wobble_frequencies_measured_rad_s").is_null());
    CHECK(value(r, "handle_excursion_max_deg") == 0.0);
    // The rates a disturbance would have: the linear theory's, from omega_i = omega itself
    // (at 1e-60 the spin's component is omega to the last bit, so the rates agree exactly).
    Inputs nudged = in;
    nudged.perturbation = 1e-60;
    CHECK(value(r, "growth_rate_per_s") == value(compute(nudged).results(), "growth_rate_per_s"));
    const std::string answer = r.at("answer");
    CHECK(contains(answer,
                   fmt::format("a spin exactly along axis {}", k == 1 ? "2 (in the plane" : axis)));
    CHECK(contains(answer, "nothing wobbles and nothing flips"));
    CHECK(contains(answer, k == 1 ? "unstable: the slightest disturbance grows at"
                                  : "stable: a slight disturbance wobbles at"));
    CHECK(contains(answer, fmt::format("{:.4g}", report.predicted[k].rate)));
    // the film says it stays, not that it turns over
    const auto film = rigid::lab::tennis_racquet::animation(report, [](double seconds) {
      return std::vector<double>{0.0, seconds};
    });
    CHECK(contains(film.scene(0.0).title, fmt::format("spun about axis {}, it stays", axis)));
  }
}
