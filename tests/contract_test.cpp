// The lab contract (design.md) for every lab in the one list, without naming
// any: --help, the table, the JSON with its units, and exit status 2 with one
// line naming the option for input no lab accepts.
#include <catch2/catch.hpp>

#include "lab_common.h"

using rigid::test::all_labs;
using rigid::test::run_lab;

TEST_CASE("contract: every lab answers --help with its options, units and defaults") {
  for (const std::string& lab : all_labs()) {
    INFO(lab);
    const auto run = run_lab(lab, "--help");
    CHECK(run.status == 0);
    for (const char* word : {"--json", "--figures", "--figure-size", "--quiet"}) {
      CHECK(run.out.find(word) != std::string::npos);
    }
    // Every number shows its unit in brackets or is a pure number; at least one has a unit.
    CHECK(run.out.find(" [") != std::string::npos);
  }
}

TEST_CASE("contract: every lab's JSON gives each result a unit and the textbook's values") {
  for (const std::string& lab : all_labs()) {
    INFO(lab);
    const auto run = run_lab(lab, "--json");
    REQUIRE(run.status == 0);
    CHECK(run.err.empty());
    const auto j = run.json();
    CHECK(j["lab"] == lab);
    const auto& results = j["results"];
    const auto& units = j["units"];
    REQUIRE(results.is_object());
    CHECK(!results.empty());
    for (const auto& [key, value] : results.items()) {
      INFO(key);
      if (value.is_string()) continue;
      REQUIRE(units.contains(key));
      CHECK(!units[key].get<std::string>().empty());
      // An angle's key says it is in degrees, and its unit agrees.
      const bool deg_key = key.size() > 4 && key.compare(key.size() - 4, 4, "_deg") == 0;
      CHECK(deg_key == (units[key] == "deg"));
    }
    // The defaults are the text's examples: the textbook column is filled, and
    // only for results that exist.
    CHECK(!j["textbook"].empty());
    for (const auto& [key, value] : j["textbook"].items()) CHECK(results.contains(key));
    CHECK(j["figures"].empty());
    CHECK(j["captions"].empty());
  }
}

TEST_CASE("contract: every lab prints a table that starts with its name") {
  for (const std::string& lab : all_labs()) {
    INFO(lab);
    const auto run = run_lab(lab, "");
    CHECK(run.status == 0);
    CHECK(run.out.rfind(lab + " - ", 0) == 0);
    CHECK(run.out.find("textbook") != std::string::npos);
    CHECK(run_lab(lab, "--quiet").out.empty());
  }
}

TEST_CASE("contract: a physical option given drops the textbook column") {
  // Any physical input changes the example: no printed value may stand beside it.
  const auto run = run_lab("tire_balancing", "--json --omega 90");
  REQUIRE(run.status == 0);
  CHECK(run.json()["textbook"].empty());
  // A numerical option (how, not what) keeps it.
  const auto numerical = run_lab("poinsot", "--json --method rk4");
  REQUIRE(numerical.status == 0);
  CHECK(numerical.json()["textbook"].contains("principal_moments"));
}

TEST_CASE("contract: input no lab accepts exits 2 with one line naming the option") {
  const std::pair<const char*, const char*> cases[] = {
      {"--bogus", "--bogus"},
      {"--bogus 5", "--bogus"},
      {"stray", "stray"},
      {"--figure-size 10x10", "--figure-size"},
      {"--figure-size 1600x1200x3", "--figure-size"},
      {"--figure-size big", "--figure-size"},
      {"--figures", "--figures"},
      {"--figures /proc/rigidlab-cannot", "--figures"},
  };
  for (const std::string& lab : all_labs()) {
    for (const auto& [args, option] : cases) {
      INFO(lab << " " << args);
      const auto run = run_lab(lab, args);
      CHECK(run.status == 2);
      CHECK(run.one_error_line());
      CHECK(run.err.rfind(lab + ": error: " + option, 0) == 0);
      CHECK(run.out.empty());
    }
  }
}
