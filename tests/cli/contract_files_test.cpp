// The lab contract's files (docs/guide.md, "Running a lab"): a run lands all its outputs or none,
// writes regular files only, never follows or replaces a link of the user's, leaves no
// temporary when it fails or is killed, and says when its output never arrives.
// (`rigidlab figures` as one transaction: rigidlab_figures_test.cpp.)
#include <signal.h>
#include <sys/resource.h>
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

TEST_CASE("contract: a report that cannot be written leaves none of the run's files", "[draws]") {
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

TEST_CASE("contract: a name no file can have is refused before any work, quoted short", "[draws]") {
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
  // A file past the size limit: EFBIG reported, not a death by SIGXFSZ.
  const std::string file = "/tmp/rigid_xfsz_" + std::to_string(::getpid());
  // (the limit holds for every file written, so stderr comes through the pipe)
  const auto run =
      run_lab("rigidlab", "list", "sh -c 'ulimit -f 0; exec \"$0\" \"$@\" 2>&1 >\"" + file + "\"'");
  CHECK(run.status == 1);
  CHECK(run.out == "rigidlab: error: stdout: the output could not be written (File too large)\n");
  std::remove(file.c_str());
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
  // the metadata beside it (NAME-metadata.json) the longest: 255 bytes
  for (const std::size_t length : {200, 237}) {
    const fs::path long_name = dir / (std::string(length, 'y') + ".csv");
    CHECK(run_lab("poinsot", "--quiet --csv '" + long_name.string() + "'").status == 0);
    CHECK(fs::is_regular_file(long_name));
    CHECK(fs::is_regular_file(long_name.string() + "-metadata.json"));
  }
  // a name with no room for its metadata is refused before anything is written
  const fs::path no_room = dir / (std::string(238, 'z') + ".csv");
  const auto no_room_run = run_lab("poinsot", "--quiet --csv '" + no_room.string() + "'");
  CHECK(no_room_run.status == 2);
  CHECK_THAT(no_room_run.err, Catch::Contains("leaves no room for the metadata beside it"));
  CHECK_FALSE(fs::exists(no_room));
  for (const auto& entry : fs::directory_iterator(dir)) {
    CHECK(entry.path().filename().string().find(".rigidlab-tmp-") == std::string::npos);
  }
  fs::remove_all(dir);
}

TEST_CASE("contract: an interrupted run leaves no file, and stale temporaries are cleared",
          "[draws]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rigid_sig_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // Killed by any signal that ends a process (SIGTERM, SIGINT, SIGHUP, SIGQUIT, SIGALRM)
  // mid-figure, once its first figure is held as a temporary (the figures are, until the
  // run ends): the handler removes it, nothing lands, and the run ends by the signal.
  // Poinsot draws five figures; the signal goes as soon as the first temporary shows,
  // while the others are still to draw.
  const auto has_temporary = [&] {
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.path().filename().string().find(".rigidlab-tmp-") != std::string::npos) return true;
    }
    return false;
  };
  const rlimit no_core{0, 0};  // SIGQUIT's default dumps core: none in the test's folder
  ::setrlimit(RLIMIT_CORE, &no_core);
  for (const int sig : {SIGTERM, SIGINT, SIGHUP, SIGQUIT, SIGALRM}) {
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

TEST_CASE("contract: a --csv that fails after the figures were drawn leaves no figure behind",
          "[draws]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rigid_txn_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string d = dir.string();
  // A file size limit (ulimit -f 1000: 500 KiB at least, 1000 KiB at most) that each
  // figure (under 150 kB at 800x600) keeps and the CSV of 200 periods (some 4 MB) does
  // not: the CSV fails at the end, after the figures were drawn. A failed write, not
  // bad input (the path passed the checks): exit 1, and nothing lands.
  const auto run = run_lab(
      "poinsot",
      "--quiet --figures '" + d + "/F' --figure-size 800x600 --csv '" + d + "/c.csv' --periods 200",
      "ulimit -f 1000 &&");
  CHECK(run.status == 1);
  CHECK(run.one_error_line());
  CHECK(run.err.rfind("poinsot: error: --csv: cannot write '" + d + "/c.csv': ", 0) == 0);
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST_CASE("contract: a file past the size limit (ulimit -f) is a failed write, exit 1", "[draws]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rigid_fsize_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string d = dir.string();
  // Each output larger than 100 KiB, alone in its run: not a death by SIGXFSZ (exit 153)
  // with a temporary left, but EFBIG from the write, one line naming the output, and
  // nothing landed. The limit is set in the shell that runs the lab.
  for (const auto& [lab, outputs, option] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
           {"poinsot", "--csv '" + d + "/c.csv' --periods 200", "--csv"},
           {"poinsot", "--figures '" + d + "/F' --figure-size 2048x2048", "--figures"},
           {"euler_angles", "--animate '" + d + "/a.webp'", "--animate"}}) {
    INFO(lab << " " << outputs);
    const auto run = run_lab(lab, "--quiet " + outputs, "ulimit -f 100 &&");
    CHECK(run.status == 1);
    CHECK(run.one_error_line());
    CHECK(run.err.rfind(lab + ": error: " + option + ": cannot write '" + d + "/", 0) == 0);
    CHECK(run.err.find("File too large") != std::string::npos);
    CHECK(fs::is_empty(dir));
  }
  fs::remove_all(dir);
}

TEST_CASE("contract: two outputs in one place are refused up front, and nothing is written",
          "[draws]") {
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
      // ... or through a folder not there yet and its "..", or a trailing separator
      {"--figures '" + d + "/F/x/..' --csv '" + d + "/F/poinsot_omega.png'", "--csv"},
      {"--figures '" + d + "/F/x/../' --csv '" + d + "/F/poinsot_omega.png'", "--csv"},
      {"--figures '" + d + "/F/' --csv '" + d + "/G/./poinsot_omega.png'", "--csv"},
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
  // A folder named through one not there yet ("x/..") is the folder itself: "x" is not made.
  fs::remove_all(figures);
  CHECK(run_lab("poinsot", "--quiet --figures '" + d + "/F/x/..'").status == 0);
  CHECK(fs::is_regular_file(figures / "poinsot_omega.png"));
  CHECK_FALSE(fs::exists(figures / "x"));
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

TEST_CASE("contract: a figure or animation that fails lands nothing, not even the CSV or folder",
          "[draws]") {
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

// Run only where the renderer is not built (tests/CMakeLists.txt picks by tag): what would
// draw is refused before any work, in one line naming the option and why, and nothing
// is made.
TEST_CASE("contract: without the renderer --figures and --animate are refused in one line",
          "[no-renderer]") {
  namespace fs = std::filesystem;
  const fs::path base =
      fs::temp_directory_path() / ("rigid_no_render_" + std::to_string(::getpid()));
  fs::remove_all(base);
  const std::string why =
      ": needs the renderer, and this build has none (configured with -DRIGID_BUILD_RENDER=OFF)\n";
  for (const std::string& lab : all_labs()) {
    INFO(lab);
    const auto run = run_lab(lab, "--json --figures '" + (base / "figs").string() + "'");
    CHECK(run.status == 2);
    CHECK(run.out.empty());
    CHECK(run.err == lab + ": error: --figures" + why);
  }
  const auto run = run_lab("poinsot", "--animate '" + (base / "motion.webp").string() + "'");
  CHECK(run.status == 2);
  CHECK(run.err == "poinsot: error: --animate" + why);
  CHECK_FALSE(fs::exists(base));
}
