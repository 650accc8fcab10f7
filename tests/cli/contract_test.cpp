// The lab contract (README, "The labs") for every lab in the one list, without naming
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

TEST_CASE("contract: a report that cannot be written leaves none of the run's files") {
  // The report is printed before the files are renamed in: a full stdout is a failed
  // run, and a failed run leaves nothing.
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rigid_full_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string csv = (dir / "c.csv").string(), figures = (dir / "F").string();
  for (const char* redirect : {"> /dev/full", ">&-"}) {
    INFO(redirect);
    const auto run = run_lab("poinsot", "--csv " + csv + " --figures " + figures + " " + redirect);
    CHECK(run.status == 1);
    CHECK(run.one_error_line());
    CHECK(run.err.rfind("poinsot: error: stdout: ", 0) == 0);
    CHECK(fs::is_empty(dir));
  }
  fs::remove_all(dir);
}

TEST_CASE("contract: a name no file can have is refused before any work, quoted short") {
  // 100,000 bytes in one name (NAME_MAX is 255), and a path of 5,000 bytes in parts
  // of 200 (PATH_MAX is 4096): refused up front, naming the option, the name cut to
  // its first 32 characters and its length.
  const std::string long_name(100000, 'a');
  std::string long_path;
  for (int i = 0; i < 25; ++i) long_path += std::string(200, 'd') + "/";
  for (const auto& [args, option, rule] :
       {std::tuple{"--animate " + long_name + ".mp4", "--animate",
                   "holds a name longer than 255 bytes"},
        std::tuple{"--csv " + long_name + ".csv", "--csv", "holds a name longer than 255 bytes"},
        std::tuple{"--figures " + long_path, "--figures", "is a path longer than 4095 bytes"}}) {
    INFO(option);
    const auto run = run_lab("poinsot", args);
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.rfind(std::string("poinsot: error: ") + option + ": '", 0) == 0);
    CHECK(run.err.find(rule) != std::string::npos);
    CHECK(run.err.size() < 200);
    CHECK(run.out.empty());
  }
}

TEST_CASE("contract: output that never arrives is an error, not a silent exit 0") {
  for (const std::string& lab : all_labs()) {
    INFO(lab);
    // A full disk (/dev/full) and a closed stdout: exit 1 and one line on stderr.
    for (const char* redirect : {"> /dev/full", ">&-"}) {
      for (const char* what : {"--json ", "--help ", "--version "}) {
        INFO(what << redirect);
        const auto run = run_lab(lab, std::string(what) + redirect);
        CHECK(run.status == 1);
        CHECK(run.one_error_line());
        CHECK(run.err.rfind(lab + ": error: stdout: ", 0) == 0);
      }
    }
  }
  // The front door's own output likewise.
  for (const char* what : {"list", "list --names", "--version", "--help", "list --help"}) {
    INFO(what);
    const auto run = run_lab("rigidlab", std::string(what) + " > /dev/full");
    CHECK(run.status == 1);
    CHECK(run.one_error_line());
    CHECK(run.err.rfind("rigidlab: error: stdout: ", 0) == 0);
  }
}

TEST_CASE("contract: --csv writes regular files only and never follows or replaces a link") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rigid_csv_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path target = dir / "target.csv", link = dir / "link.csv";
  std::ofstream(target) << "keep\n";
  fs::create_symlink(target, link);
  const std::pair<std::string, std::string> refused[] = {
      {link.string(), "symbolic link"},
      {"/dev/null", "not a regular file"},
      {dir.string(), "directory"},
      {(dir / (std::string(252, 'x') + ".csv")).string(), "longer than 255 bytes"},
  };
  for (const auto& [path, rule] : refused) {
    INFO(path);
    const auto run = run_lab("poinsot", "--json --csv '" + path + "'");
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.rfind("poinsot: error: --csv: ", 0) == 0);
    CHECK(run.err.find(rule) != std::string::npos);
  }
  // The link and its target are untouched; any name the filesystem takes is written, the
  // longest (255 bytes) too, whose temporary is a hidden one beside it.
  CHECK(fs::is_symlink(link));
  std::ifstream kept(target);
  std::string line;
  std::getline(kept, line);
  CHECK(line == "keep");
  for (const std::size_t length : {200, 251}) {
    const fs::path long_name = dir / (std::string(length, 'y') + ".csv");
    CHECK(run_lab("poinsot", "--quiet --csv '" + long_name.string() + "'").status == 0);
    CHECK(fs::is_regular_file(long_name));
  }
  for (const auto& entry : fs::directory_iterator(dir)) {
    CHECK(entry.path().filename().string().find(".rigidlab-tmp-") == std::string::npos);
  }
  fs::remove_all(dir);
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

TEST_CASE("contract: an interrupted run leaves no file, and stale temporaries are cleared") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rigid_sig_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // Killed by SIGTERM (or SIGINT) mid-figure, once its first figure is held as a
  // temporary (the figures are, until the run ends): the handler removes it, nothing
  // lands, and the run ends by the signal. Poinsot draws five figures; the signal goes
  // as soon as the first temporary shows, while the others are still to draw.
  const auto has_temporary = [&] {
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.path().filename().string().find(".rigidlab-tmp-") != std::string::npos) return true;
    }
    return false;
  };
  for (const int sig : {SIGTERM, SIGINT}) {
    INFO("signal " << sig);
    rigid::test::Background lab({std::string(RIGID_LAB_DIR) + "/poinsot", "--json", "--figure-size",
                                 "2048x2048", "--figures", dir.string()});
    REQUIRE(lab.wait_until(has_temporary));
    ::kill(lab.pid(), sig);
    const int status = lab.wait();
    CHECK((WIFSIGNALED(status) && WTERMSIG(status) == sig));
    CHECK(fs::is_empty(dir));
  }
  // A temporary a killed run left (its pid gone) is removed by the next writer, and
  // only that: the user's files with names like it are not ours and stay.
  const fs::path stale = dir / "out.csv.rigidlab-tmp-999999999-0123456789abcdef";
  std::ofstream(stale) << "partial\n";
  const fs::path figures = dir / "F";
  fs::create_directories(figures);
  const std::vector<fs::path> users = {dir / "out.csv.tmp-2024-01-05-backup",
                                       dir / "out.csv.tmp-99999",
                                       dir / "out.csv.rigidlab-tmp-99999",
                                       dir / "out.csv.rigidlab-tmp-999999999-0123456789ABCDEF",
                                       dir / "out.csv.rigidlab-tmp-999999999-0123456789abcdef.bak",
                                       figures / "poinsot_omega.png.tmp-2023-notes",
                                       figures / "poinsot_omega.png.tmp-99999"};
  for (const fs::path& p : users) std::ofstream(p) << "the user's\n";
  REQUIRE(run_lab("poinsot", "--quiet --csv '" + (dir / "out.csv").string() + "' --figures '" +
                                 figures.string() + "'")
              .status == 0);
  CHECK_FALSE(fs::exists(stale));
  CHECK(fs::is_regular_file(dir / "out.csv"));
  for (const fs::path& p : users) {
    INFO(p);
    CHECK(fs::is_regular_file(p));
  }
  fs::remove_all(dir);
}

TEST_CASE("contract: a run too long for the budget is refused naming the option, not left to run") {
  // Bulirsch-Stoer over 1e7 s once ran ten minutes before its step cap refused it:
  // the work budget of a lab's run (right-hand-side evaluations) refuses it instead,
  // the same on every machine.
  const auto run = run_lab("poinsot", "--json --method bulirsch-stoer --t-end 1e7");
  CHECK(run.status == 2);
  CHECK(run.one_error_line());
  CHECK(run.err.rfind("poinsot: error: --tolerance: bulirsch-stoer needs more than 8e+06 "
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

TEST_CASE("contract: a --csv that fails after the figures were drawn leaves no figure behind") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rigid_txn_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // /proc passes the up-front check (a directory; root may write anywhere) but takes
  // no new file: the CSV fails at the end, after both figures were drawn.
  const auto run = run_lab("tire_balancing",
                           "--quiet --figures '" + dir.string() + "' --csv /proc/rigid_test.csv");
  CHECK(run.status == 2);
  CHECK(run.err.rfind("tire_balancing: error: --csv: ", 0) == 0);
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
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

TEST_CASE(
    "contract: the JSON says which version ran, the command as given and every file written") {
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
  REQUIRE(outputs.size() == 3);
  for (const std::string& path : outputs) {
    INFO(path);
    CHECK(fs::path(path).is_absolute());
    CHECK(fs::is_regular_file(path));
  }
  CHECK(outputs.back() == fs::absolute(csv).lexically_normal().string());
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

TEST_CASE("contract: two outputs in one place are refused up front, and nothing is written") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rigid_same_" + std::to_string(::getpid()));
  const fs::path figures = dir / "F";
  fs::create_directories(figures);
  fs::create_directory_symlink(figures, dir / "G");
  const std::string d = dir.string();
  const struct {
    std::string args, option;
  } cases[] = {
      // --csv and --animate naming one file, directly or through another spelling
      {"--csv '" + d + "/same.webp' --animate '" + d + "/same.webp'", "--animate"},
      {"--csv '" + d + "/same.webp' --animate '" + d + "/F/../same.webp'", "--animate"},
      // the CSV where --figures writes a figure, directly or through a link to the folder
      {"--figures '" + d + "/F' --csv '" + d + "/F/poinsot_omega.png'", "--csv"},
      {"--figures '" + d + "/F' --csv '" + d + "/G/poinsot_polhodes.png'", "--csv"},
      // the figures' folder inside the CSV's file
      {"--figures '" + d + "/out.csv/F' --csv '" + d + "/out.csv'", "--figures"},
  };
  for (const auto& c : cases) {
    INFO(c.args);
    const auto run = run_lab("poinsot", c.args);
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.rfind("poinsot: error: " + c.option + ": ", 0) == 0);
    CHECK(fs::is_empty(figures));
    CHECK_FALSE(fs::exists(dir / "same.webp"));
    CHECK_FALSE(fs::exists(dir / "out.csv"));
  }
  // A CSV of another name in the figures' folder is the user's choice, and lands beside them.
  CHECK(run_lab("poinsot", "--quiet --figures '" + d + "/F' --csv '" + d + "/F/run.csv'").status ==
        0);
  CHECK(fs::is_regular_file(figures / "run.csv"));
  CHECK(fs::is_regular_file(figures / "poinsot_omega.png"));
  fs::remove_all(dir);
}

TEST_CASE("contract: any bytes in a file name: JSON stays valid, stderr and stdout escaped") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rigid_bytes_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // 0xff is no UTF-8 at all, U+009B is the 8-bit CSI, U+202E turns the text around.
  const std::string name = "c\xff\xc2\x9b\xe2\x80\xae.csv";
  const std::string quoted = "'" + (dir / name).string() + "'";
  const auto run = run_lab("poinsot", "--json --csv " + quoted);
  INFO(run.err);
  REQUIRE(run.status == 0);
  const nlohmann::json json = run.json();  // parses: every string is UTF-8
  const std::string written = json["outputs"].back().get<std::string>();
  CHECK(written.find("c\\xff\\u{009b}") == std::string::npos);  // JSON shows the CSI as is
  CHECK(written.find("c\\xff\xc2\x9b\xe2\x80\xae.csv") != std::string::npos);
  CHECK(fs::is_regular_file(dir / name));  // the file itself has the name given
  // The table lists the command's inputs; an error line shows the bytes escaped.
  const auto bad = run_lab("poinsot", "--mass 'x\xff\xc2\x9b\xe2\x80\xae'");
  CHECK(bad.status == 2);
  CHECK(bad.one_error_line());
  CHECK(bad.err.find("x\\xff\\u{009b}\\u{202e}") != std::string::npos);
  CHECK(bad.err.find('\xff') == std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("contract: a figure or animation that fails lands nothing, not even the CSV or folder") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rigid_none_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string d = dir.string();
  // No renderer to be had: the figures fail after the CSV was ready.
  for (const std::string& outputs :
       {"--csv '" + d + "/c.csv' --figures '" + d + "/F/sub'",
        "--csv '" + d + "/c.csv' --animate '" + d + "/a.webp' --duration 0.5 --fps 4",
        "--csv '" + d + "/c.csv' --animate '" + d + "/a.webp' --duration 0.5 --fps 4 --figures '" +
            d + "/F'"}) {
    INFO(outputs);
    const auto run = run_lab("poinsot", "--json " + outputs, "RIGID_GL_BACKEND=bogus");
    CHECK(run.status == 1);
    CHECK(run.out.empty());
    CHECK(run.err.find("RIGID_GL_BACKEND") != std::string::npos);
    CHECK(fs::is_empty(dir));
  }
  fs::remove_all(dir);
}

TEST_CASE("contract: an animation with no whole frame, or beyond the work budget, is refused") {
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

TEST_CASE("contract: SIGTERM to rigidlab figures reaches its labs, which leave no temporaries") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rigid_term_" + std::to_string(::getpid()));
  const std::vector<std::string> labs = rigid::test::all_labs();
  // What the staging folder holds: the names of its files (the labs draw there first).
  const auto staged = [&] {
    std::vector<std::string> names;
    std::error_code ec;
    for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
      names.push_back(it->path().filename().string());
    return names;
  };
  const auto drawn_by = [&](auto is_lab) {
    return [&, is_lab] {
      for (const std::string& name : staged()) {
        for (const std::string& lab : labs) {
          if (is_lab(lab) && name.rfind(lab + "_", 0) == 0) return true;
        }
      }
      return false;
    };
  };
  // During the first lab alone (once a figure of it shows), and during the others
  // (once a figure of another lab shows).
  const auto first = [&](const std::string& lab) { return lab == labs.front(); };
  const auto others = [&](const std::string& lab) { return lab != labs.front(); };
  for (const bool during_others : {false, true}) {
    INFO((during_others ? "during the other labs" : "during the first lab alone"));
    // To rigidlab alone (not its process group, as a terminal's Ctrl-C or timeout would).
    rigid::test::Background rigidlab({std::string(RIGID_LAB_DIR) + "/rigidlab", "figures",
                                      "--figure-size", "2048x2048", "--out", dir.string()});
    const bool ready = during_others ? rigidlab.wait_until(drawn_by(others))
                                     : rigidlab.wait_until(drawn_by(first));
    REQUIRE(ready);
    ::kill(rigidlab.pid(), SIGTERM);
    const int status = rigidlab.wait();
    // rigidlab died of the signal, after its labs
    CHECK((WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM));
    // Every lab it ran has stopped (none still writes into the folder) and left no temporary.
    const std::string still = "pgrep -f -- '[-]-figures " + dir.string() + "' > /dev/null 2>&1";
    CHECK(std::system(still.c_str()) != 0);  // (the bracket keeps pgrep's own shell out)
    // Nothing landed (the labs drew into a staging folder), and the folder it made is gone.
    CHECK(!fs::exists(dir));
    fs::remove_all(dir);
  }
}

TEST_CASE("contract: rigidlab figures says a killed run's staging folder is left and keeps it") {
  // kill -9 leaves OUT/.rigidlab-stage-PID (no handler runs); the next run names it for
  // the user to remove, and leaves it: it did not make it
  namespace fs = std::filesystem;
  const fs::path out = fs::temp_directory_path() / ("rigid_left_" + std::to_string(::getpid()));
  const fs::path left = out / ".rigidlab-stage-2147483646";  // a pid no process has
  fs::create_directories(left);
  const std::string err = (out.string() + ".err");
  const std::string command = std::string(RIGID_LAB_DIR) +
                              "/rigidlab figures --figure-size 800x600 --out '" + out.string() +
                              "' 2> '" + err + "'";
  CHECK(std::system(command.c_str()) == 0);
  std::ifstream in(err);
  const std::string said((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(said.find("rigidlab: warning: figures: " + left.string() +
                  " was left by a run that was killed") != std::string::npos);
  CHECK(fs::is_directory(left));
  fs::remove_all(out);
  fs::remove(err);
}

TEST_CASE("contract: rigidlab figures lands every lab's figures or none") {
  namespace fs = std::filesystem;
  const fs::path base = fs::temp_directory_path() / ("rigid_all_" + std::to_string(::getpid()));
  fs::create_directories(base);
  const fs::path out = base / "figs";
  const std::string rigidlab = std::string(RIGID_LAB_DIR) + "/rigidlab figures --out '";
  REQUIRE(std::system((rigidlab + out.string() + "' >/dev/null 2>&1").c_str()) == 0);
  std::size_t pngs = 0;
  for (const auto& entry : fs::directory_iterator(out)) {
    CHECK(entry.path().extension() == ".png");  // no staging folder or temporary left
    ++pngs;
  }
  CHECK(pngs >= all_labs().size());
  fs::remove_all(out);
  // A full disk (a 200 kB tmpfs, where this user may mount one): every lab fails, none
  // of their figures lands, the folder rigidlab made goes, a file of the user's stays.
  const fs::path disk = base / "disk";
  fs::create_directories(disk);
  const std::string mount = "mount -t tmpfs -o size=200k tmpfs '" + disk.string() + "' 2>/dev/null";
  if (std::system(mount.c_str()) == 0) {
    std::ofstream(disk / "mine.txt") << "keep\n";
    const int status =
        std::system((rigidlab + (disk / "figs").string() + "' >/dev/null 2>&1").c_str());
    CHECK(WEXITSTATUS(status) == 1);
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(disk)) left.push_back(entry.path().filename());
    CHECK(left == std::vector<std::string>{"mine.txt"});
    CHECK(std::system(("umount '" + disk.string() + "'").c_str()) == 0);
  } else {
    WARN("cannot mount a tmpfs here: the full-disk half is not run");
  }
  // A directory where one figure goes: refused whole (exit 2, one line), nothing lands,
  // the user's files stay as they were.
  const fs::path taken = base / "taken";
  fs::create_directories(taken / "poinsot_omega.png");
  std::ofstream(taken / "tire_balancing_mass.png") << "mine\n";
  const int blocked = std::system((rigidlab + taken.string() + "' >/dev/null 2>&1").c_str());
  CHECK(WEXITSTATUS(blocked) == 2);
  std::vector<std::string> kept;
  for (const auto& entry : fs::directory_iterator(taken)) kept.push_back(entry.path().filename());
  std::sort(kept.begin(), kept.end());
  CHECK(kept == std::vector<std::string>{"poinsot_omega.png", "tire_balancing_mass.png"});
  fs::remove_all(base);
}

TEST_CASE("contract: a failed run removes no link of the user's, dangling or not") {
  namespace fs = std::filesystem;
  const fs::path base = fs::temp_directory_path() / ("rigid_link_" + std::to_string(::getpid()));
  fs::remove_all(base);
  fs::create_directories(base);
  fs::create_symlink("nowhere", base / "dangling");
  // --figures at a dangling link, or below one: the folder cannot be made, and the link
  // (which fs::exists calls missing) is not the run's to remove
  for (const std::string figures : {"dangling", "dangling/sub"}) {
    INFO(figures);
    const auto run =
        run_lab("tire_balancing", "--quiet --figures '" + (base / figures).string() + "'");
    CHECK(run.status == 2);
    CHECK(fs::is_symlink(base / "dangling"));
  }
  const std::string rigidlab = std::string(RIGID_LAB_DIR) + "/rigidlab figures --out '";
  const int status =
      std::system((rigidlab + (base / "dangling").string() + "' >/dev/null 2>&1").c_str());
  CHECK(WEXITSTATUS(status) == 2);
  CHECK(fs::is_symlink(base / "dangling"));
  fs::remove_all(base);
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
