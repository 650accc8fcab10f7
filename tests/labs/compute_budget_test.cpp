// The compute budget, counted, never timed: every lab's answer at its defaults within a
// tenth of kMaxComputeWork (what 100 ms buys), and the dearest inputs each lab accepts
// within all of it (a second on a 2-core laptop; bench/compute_bench.py times it), the
// comparison at equal cost ranked over fewer periods where it must, saying why.
#include <algorithm>
#include <catch2/catch.hpp>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "common/integrated_run.h"
#include "common/registry.h"
#include "lab_entries.h"
#include "rigid/ode_options.h"

using rigid::lab::GivenTexts;
using rigid::lab::Json;
using rigid::lab::kMaxComputeWork;
using rigid::lab::LabEntry;
using rigid::lab::Session;
using rigid::test::json_of;
using rigid::test::lab;

namespace {

struct Answer {
  Json results;
  double work = 0.0;  // work_done's count across the computation
};

// The lab at `given`, computed whole on this thread, and the work it did.
Answer answer(const LabEntry& lab, const GivenTexts& given) {
  const double before = rigid::work_done();
  auto made = lab.make_at(given);
  const double work = rigid::work_done() - before;
  REQUIRE(std::holds_alternative<std::unique_ptr<Session>>(made));
  return {Json::parse(json_of(*std::get<std::unique_ptr<Session>>(made))).at("results"), work};
}

}  // namespace

TEST_CASE("compute budget: every lab at its defaults within a tenth of the budget") {
  for (const LabEntry& e : rigid::lab::all_labs()) {
    INFO(e.name);
    const Answer a = answer(e, {});
    CHECK(a.work <= 0.1 * kMaxComputeWork);
    // a lab that reports its work reports what was counted
    if (a.results.contains("work")) CHECK(a.results.at("work").get<double>() == a.work);
  }
}

TEST_CASE("compute budget: the dearest inputs accepted stay within it, the ranking shortened") {
  // Each lab's own run near its cap (rk4's 4M steps, a splitting's 4M evaluations, an
  // adaptive method at the tightest tolerance) beside a comparison at equal cost over the
  // most periods it ranks, and runs of 1e8 and 1e9 periods.
  const std::vector<std::pair<std::string, GivenTexts>> cases = {
      {"poinsot", {{"--periods", "1e8"}}},
      {"poinsot", {{"--method", "rk4"}, {"--periods", "1999"}}},
      {"poinsot", {{"--method", "splitting4"}, {"--periods", "399"}}},
      {"poinsot", {{"--method", "vern9"}, {"--tolerance", "1e-14"}, {"--periods", "8000"}}},
      {"poinsot",
       {{"--method", "bulirsch-stoer"}, {"--tolerance", "1e-14"}, {"--periods", "2000"}}},
      {"top_nutation", {{"--arm", "1e12"}, {"--periods", "1e9"}}},
      {"top_nutation", {{"--method", "splitting"}, {"--periods", "1999"}}},
      {"top_nutation", {{"--method", "vern9"}, {"--tolerance", "1e-14"}, {"--periods", "8000"}}},
      {"tennis_racquet", {{"--method", "rk4"}, {"--periods", "1999"}}},
      {"tennis_racquet", {{"--method", "splitting4"}, {"--periods", "399"}}},
  };
  for (const auto& [name, given] : cases) {
    std::string args;
    for (const auto& [flag, text] : given) args += " " + flag + " " + text;
    INFO(name << args);
    const Answer a = answer(lab(name), given);
    INFO("work " << a.work);
    CHECK(a.work <= kMaxComputeWork);
    CHECK(a.work > 0.0);
    if (!a.results.contains("equal_cost_periods")) continue;
    CHECK(a.results.at("work").get<double>() == a.work);
    // at most kMaxRankedPeriods; fewer than the run's only with the reason
    double periods = 0.0;
    for (const auto& [flag, text] : given) {
      if (flag == "--periods") periods = std::stod(text);
    }
    const double ranked = a.results.at("equal_cost_periods").get<double>();
    CHECK(ranked <= rigid::lab::kMaxRankedPeriods);
    const std::string why = a.results.at("recommended_method_reason").get<std::string>();
    if (ranked < std::min(periods, rigid::lab::kMaxRankedPeriods) * (1 - 1e-12)) {
      CHECK_THAT(why, Catch::Contains("the work budget left after the run"));
    }
  }
}
