// Tests of axis tick selection: the 1-2-5 rule and log decades.
#include "rigid/render/ticks.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace rigid::render;

TEST_CASE("ticks: nice_step follows the 1-2-5 rule", "[render][ticks]") {
  CHECK(nice_step(10, 5) == Approx(2));
  CHECK(nice_step(1, 5) == Approx(0.2));
  CHECK(nice_step(7.3, 6) == Approx(1));
  CHECK(nice_step(100, 4) == Approx(20));  // 25 rounds to 20 (closer on a log scale than 50)
  CHECK(nice_step(3e-4, 3) == Approx(1e-4));
  CHECK(nice_step(0.9, 2) == Approx(0.5));
}

TEST_CASE("ticks: linear ticks are multiples of the step inside the range", "[render][ticks]") {
  const Ticks t = linear_ticks(-1.05, 1.05, 4);
  REQUIRE(t.values.size() == 5);
  CHECK(t.values.front() == Approx(-1.0));
  CHECK(t.values.back() == Approx(1.0));
  CHECK(t.labels[0] == "\u22121.0");  // true minus sign
  CHECK(t.labels[2] == "0.0");        // never "-0.0"
  const Ticks u = linear_ticks(0, 100, 5);
  CHECK(u.labels.front() == "0");
  CHECK(u.labels.back() == "100");
}

TEST_CASE("ticks: large values share a power of ten", "[render][ticks]") {
  const Ticks t = linear_ticks(0, 3e6, 3);
  REQUIRE(t.values.size() >= 2);
  CHECK(t.labels[1].find("10^{6}") != std::string::npos);
  // From 1e5 up; five digits (an rpm, a period in s) are written out.
  const Ticks five = linear_ticks(0, 99999, 4);
  for (const std::string& label : five.labels) CHECK(label.find("10^") == std::string::npos);
  CHECK(five.labels[1] == "20000");
  const Ticks six = linear_ticks(0, 1e5, 4);
  CHECK(six.labels[1].find("10^{5}") != std::string::npos);
}

TEST_CASE("ticks: log axis ticks sit at decades labelled 10^{k}", "[render][ticks]") {
  const Ticks t = log_ticks(1e-3, 1e3, 8);
  REQUIRE(t.values.size() == 7);
  for (std::size_t i = 0; i < t.values.size(); ++i) {
    const int k = static_cast<int>(i) - 3;
    CHECK(t.values[i] == Approx(std::pow(10.0, k)));
    CHECK(t.labels[i] == "10^{" + std::to_string(k) + "}");
  }
  CHECK(t.minor.size() == 6 * 8);  // 2..9 in each of the six whole decades
}

TEST_CASE("ticks: many decades are thinned, few fall back to 1-2-5", "[render][ticks]") {
  const Ticks t = log_ticks(1e-18, 1e-2, 8);
  CHECK(t.values.size() <= 9);
  for (double v : t.values) CHECK(std::abs(std::log10(v) - std::round(std::log10(v))) < 1e-9);
  const Ticks f = log_ticks(2, 8, 8);
  CHECK(f.values.size() >= 2);  // no decade inside: linear ticks instead
  // a decade and a bit (an error floored at 1e-12 under a curve at 8e-12): 1, 2 and 5
  // times the powers of ten, the floor's decade labelled
  const Ticks g = log_ticks(3.3e-13, 9.1e-12, 8);
  REQUIRE(g.values.size() == 4);
  CHECK(g.values[0] == Approx(5e-13));
  CHECK(g.values[1] == Approx(1e-12));
  CHECK(g.values[3] == Approx(5e-12));
  CHECK(g.labels[1] == "10^{-12}");
  CHECK(g.labels[2] == "2\u00d710^{-12}");
}
