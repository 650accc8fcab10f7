// The lab contract (docs/guide.md, "Running a lab") for every lab in the one list, without naming
// any: --help, the table, the JSON with its units, and exit status 2 with one
// line naming the option for input no lab accepts.
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <tuple>
#include <vector>

#include "lab_common.h"

using rigid::test::all_labs;
using rigid::test::run_lab;

TEST_CASE("contract: every lab answers --help with its options, units and defaults") {
  for (const std::string& lab : all_labs()) {
    INFO(lab);
    const auto run = run_lab(lab, "--help");
    INFO(run.err);
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
    INFO(run.err);
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
    INFO(run.err);
    CHECK(run.status == 0);
    CHECK(run.out.rfind(lab + " - ", 0) == 0);
    CHECK(run.out.find("textbook") != std::string::npos);
    CHECK(run_lab(lab, "--quiet").out.empty());
  }
}

TEST_CASE("contract: a physical input changed from the text's drops the textbook column") {
  // Any physical input changed from the text's changes the example: no printed value
  // may stand beside it.
  const auto run = run_lab("tire_balancing", "--json --omega 100");
  INFO(run.err);
  REQUIRE(run.status == 0);
  CHECK(run.json()["textbook"].empty());
  // The text's own values typed out are the text's example still.
  const auto same = run_lab("tire_balancing", "--json --omega 90 --mass 10");
  REQUIRE(same.status == 0);
  CHECK(same.json()["textbook"].contains("balance_mass_kg"));
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
      // a side that wraps to 800 in an int is too large, not 800
      {"--figure-size 4294968096x600 --figures /tmp", "--figure-size"},
      {"--figure-size 800x4294967896 --figures /tmp", "--figure-size"},
      // an option given twice: which value was meant is not guessed
      {"--figures a --figures=b", "--figures: given twice: give it once"},
      {"--figure-size 800x600 --figures a --figure-size 900x600", "--figure-size: given twice"},
      // a figure's setting with no figures to draw is refused, not ignored
      {"--figure-format svg", "--figure-format: sets the figures: give --figures DIR too"},
      {"--figure-size 1920x1080", "--figure-size: sets the figures"},
      {"--figure-prefix book-", "--figure-prefix: sets the figures"},
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

TEST_CASE("contract: error lines show user input escaped, never a second forged line") {
  // A newline in the input would print a second "error:" line; an escape sequence
  // would colour the terminal. Both are shown escaped, on one line.
  const auto run = run_lab("poinsot", "--mass \"$(printf '1\\nerror: forged')\" --json");
  CHECK(run.status == 2);
  CHECK(run.one_error_line());
  CHECK(run.err.find("\\n") != std::string::npos);
  const auto esc = run_lab("football", "--preset \"$(printf 'x\\033[31m')\"");
  CHECK(esc.status == 2);
  CHECK(esc.one_error_line());
  CHECK(esc.err.find('\x1b') == std::string::npos);
}

TEST_CASE("contract: a tolerance below double precision is refused, not a crash") {
  for (const char* lab : {"poinsot", "tennis_racquet", "top_nutation"}) {
    INFO(lab);
    const auto run = run_lab(lab, "--json --tolerance 1e-183");
    CHECK(run.status == 2);
    CHECK(run.err.rfind(std::string(lab) + ": error: --tolerance: ", 0) == 0);
  }
}

TEST_CASE("contract: a run too long for the budget is refused naming the option, not left to run") {
  // Bulirsch-Stoer over 1e7 s once ran ten minutes before its step cap refused it:
  // the work budget of a lab's run (right-hand-side evaluations) refuses it instead,
  // the same on every machine.
  const auto run = run_lab("poinsot", "--json --method bulirsch-stoer --t-end 1e7");
  CHECK(run.status == 2);
  CHECK(run.one_error_line());
  CHECK(run.err.rfind("poinsot: error: --tolerance: bulirsch-stoer needs more than 4e+06 "
                      "right-hand-side evaluations, the budget of a run; loosen the tolerance "
                      "or shorten the run",
                      0) == 0);
}

TEST_CASE("contract: a run that ran away is refused, not printed") {
  const auto run = run_lab("top_nutation", "--json --method rk4 --step 0.05");
  CHECK(run.status == 2);
  CHECK(run.err.rfind("top_nutation: error: --step: the run ran away", 0) == 0);
}

TEST_CASE("contract: a step asked for that is longer than the run is refused, not cut short") {
  for (const char* lab : {"poinsot", "tennis_racquet", "top_nutation"}) {
    INFO(lab);
    const auto run = run_lab(lab, "--json --method rk4 --step 100 --t-end 1");
    CHECK(run.status == 2);
    CHECK(run.err.rfind(std::string(lab) + ": error: --step: 100 s is longer than the run", 0) ==
          0);
  }
}

TEST_CASE("contract: a missing value is said as such, not as a vector's count") {
  // "--mass" alone once read "--mass: must be three numbers X,Y,Z": a rule for another option.
  const auto scalar = run_lab("poinsot", "--mass");
  CHECK(scalar.status == 2);
  CHECK(scalar.err.rfind("poinsot: error: --mass: needs a value", 0) == 0);
  // a pair's or vector's count in the inputs' one reader's words, as a live view says it
  const auto pair = run_lab("football", "--inertia 1");
  CHECK(pair.err == "football: error: --inertia: needs 2 numbers separated by commas (got '1')\n");
  const auto vector = run_lab("poinsot", "--omega 1,2");
  CHECK(vector.err == "poinsot: error: --omega: needs 3 numbers separated by commas (got '1,2')\n");
  const auto spaced = run_lab("poinsot", "--omega 1 2 3");
  CHECK(spaced.err == "poinsot: error: --omega: needs 3 numbers separated by commas (got '1')\n");
}

TEST_CASE("contract: the JSON says which version ran, the command as given and every file written",
          "[draws]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rigid_prov_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string csv = (dir / "run.csv").string();
  // An upper-case X in the size and a prefix on the figures' names.
  const auto run = run_lab("tire_balancing", "--json --figures '" + dir.string() +
                                                 "' --figure-size 800X600 --figure-prefix book- "
                                                 "--csv '" +
                                                 csv + "'");
  INFO(run.err);
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const std::string version = j["version"];
  CHECK(run_lab("tire_balancing", "--version").out ==
        "tire_balancing (rigidlab) " + version + "\n");
  // The command as given: the program, then each argument.
  REQUIRE(j["command"].size() == 10);
  CHECK(j["command"][1] == "--json");
  CHECK(j["command"][7] == "book-");
  // Every file by its absolute path, each of them there.
  std::vector<std::string> outputs = j["outputs"];
  REQUIRE(outputs.size() == 4);  // two figures, the CSV and its metadata
  for (const std::string& path : outputs) {
    INFO(path);
    CHECK(fs::path(path).is_absolute());
    CHECK(fs::is_regular_file(path));
  }
  CHECK(outputs[2] == fs::absolute(csv).lexically_normal().string());
  CHECK(outputs[3] == fs::absolute(csv + "-metadata.json").lexically_normal().string());
  CHECK(fs::exists(dir / "book-tire_balancing_scene.png"));
  // Counts are integers.
  const auto poinsot = run_lab("poinsot", "--json --method rk4").json();
  CHECK(poinsot["results"]["steps"].is_number_integer());
  fs::remove_all(dir);
}

TEST_CASE("contract: the textbook's values as numbers in the result's unit, the print beside") {
  const auto j = run_lab("tire_balancing", "--json").json();
  const auto& m0 = j["textbook_values"]["balance_mass_kg"];
  CHECK(m0["value"] == 0.076);
  CHECK(m0["unit"] == "kg");
  CHECK(m0["printed"] == "0.076 (76 g)");
  // a list of numbers, and an expression (no number of its own)
  const auto p = run_lab("poinsot", "--json").json();
  CHECK(p["textbook_values"]["ratios_energy"]["value"] == nlohmann::json({0.44, 0.50, 0.58}));
  CHECK(p["textbook_values"]["principal_moments"]["value"].is_null());
  // The unit suffix says N m, not nanometres; the old key stays one release.
  CHECK(j["results"]["torque_unbalanced_n_m"] == j["results"]["torque_unbalanced_nm"]);
  CHECK(j["units"]["torque_unbalanced_n_m"] == "N m");
}

TEST_CASE("contract: a bad figure prefix or size is refused naming the option") {
  for (const char* args :
       {"--figure-prefix ../x", "--figure-prefix .hidden", "--figure-prefix 'a b'"}) {
    const auto run = run_lab("poinsot", args);
    CHECK(run.status == 2);
    CHECK(run.err.rfind("poinsot: error: --figure-prefix: ", 0) == 0);
  }
  CHECK(run_lab("poinsot", "--figure-size 1920*1080").status == 2);
}

TEST_CASE("contract: an animation with no whole frame, or beyond the work budget, is refused",
          "[draws]") {
  const std::pair<const char*, const char*> cases[] = {
      // 0.1 of a frame, which was stretched to a second of video
      {"--fps 1 --duration 0.1", "holds no whole frame at --fps 1"},
      {"--animation-size 3840x2160 --fps 120 --duration 600", "beyond the budget"},
      {"--animation-size 1920x1080 --fps 60 --duration 81", "beyond the budget"},
  };
  for (const auto& [args, rule] : cases) {
    INFO(args);
    const auto run = run_lab("poinsot", std::string("--animate /tmp/never.webp ") + args);
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.rfind("poinsot: error: --duration: ", 0) == 0);
    CHECK(run.err.find(rule) != std::string::npos);
  }
  CHECK_FALSE(std::filesystem::exists("/tmp/never.webp"));
}

TEST_CASE("contract: a number a double cannot hold breaks the magnitude rule, quoted short") {
  // strtod rounds 1e400 to infinity and 1e-400 to zero; the rule broken is the range
  // 1e-60..1e60, not "finite" or "positive". A 100,000-digit value is quoted by its
  // first 32 characters and its length: the error stays one short line.
  const std::string digits(100000, '7');
  const std::pair<std::string, std::string> cases[] = {
      {"--t-end " + digits, "--t-end: must be between 1e-60 and 1e60 (got 77777777"},
      {"--t-end 1e400", "--t-end: must be between 1e-60 and 1e60 (got 1e400)"},
      {"--t-end 1e-400", "--t-end: must be between 1e-60 and 1e60 (got 1e-400)"},
      {"--t-end 0x1p-2000", "--t-end: must be between 1e-60 and 1e60 (got 0x1p-2000)"},
      {"--omega 1,-1e999,1", "--omega: must be 0 or between 1e-60 and 1e60 in magnitude"},
      {"--t-end 0", "--t-end: must be positive (got 0)"},
      {"--t-end inf", "--t-end: must be finite (got inf)"},
      {"--t-end x" + digits, "--t-end: must be a number (got 'x7777777"},
  };
  for (const auto& [args, error] : cases) {
    INFO(args.substr(0, 60));
    const auto run = run_lab("poinsot", args);
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.rfind("poinsot: error: " + error, 0) == 0);
    CHECK(run.err.size() < 200);
    CHECK(run.out.empty());
  }
  const auto run = run_lab("poinsot", "--t-end " + digits);
  CHECK(run.err.find("... (100000 characters))") != std::string::npos);
}

TEST_CASE("contract: a rule that joins inputs names those of them the user gave") {
  // Eq. 60's 4 a b > 2 (a^2 - b^2) tan 2 theta joins --tilt-deg, --offset and --radius.
  const std::pair<const char*, const char*> cases[] = {
      {"--offset 1e-60", "--offset: no balancing mass reaches this tilt"},
      {"--tilt-deg 44.99", "--tilt-deg: no balancing mass reaches this tilt"},
      {"--tilt-deg 40 --offset 0.001", "--tilt-deg, --offset: no balancing mass"},
      {"--offset 0.001 --radius 0.4 --tilt-deg 40", "--tilt-deg, --offset, --radius: no"},
  };
  for (const auto& [args, error] : cases) {
    INFO(args);
    const auto run = run_lab("tire_balancing", args);
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.rfind(std::string("tire_balancing: error: ") + error, 0) == 0);
  }
}

TEST_CASE("contract: --csv's help says what the CSV holds, a time series or a sweep") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rigid_csv_help_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  int sweeps = 0;
  for (const std::string& lab : all_labs()) {
    INFO(lab);
    const std::string help = run_lab(lab, "--help").out;
    const auto at = help.find("\n  --csv ");
    if (at == std::string::npos) continue;
    const std::string line = help.substr(at + 1, help.find('\n', at + 1) - at - 1);
    INFO(line);
    const fs::path csv = dir / (lab + ".csv");
    REQUIRE(run_lab(lab, "--quiet --csv '" + csv.string() + "'").status == 0);
    // The header is the first line that is not a comment; its first column is what a
    // row is taken at: the time (t_s), or the swept quantity (alpha_deg).
    std::ifstream in(csv);
    std::string header;
    while (std::getline(in, header) && header.rfind("#", 0) == 0) {
    }
    const std::string first = header.substr(0, header.find(','));
    INFO(first);
    if (first == "t_s") {
      CHECK(line.find("time") != std::string::npos);
      CHECK(line.find("sweep") == std::string::npos);
    } else {
      ++sweeps;
      CHECK(line.find("a sweep") != std::string::npos);
      CHECK(line.find("no time series") != std::string::npos);
      CHECK(line.find(first.substr(0, first.find('_'))) != std::string::npos);
    }
  }
  CHECK(sweeps == 2);  // lamina_tensor's moment and football's rates, both against alpha
  fs::remove_all(dir);
}
