// The explorer keeps the command line's promises: every file it writes is held to the
// rules of an output (never a link, a folder, a device or a pipe replaced), a script is
// checked and bounded when it is read, its messages escape what a user gave, its window
// never grows past what the renderer can draw, and a recording's lab ends with it.
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "common/registry.h"
#include "explore_common.h"
#include "explorer.h"
#include "rigid/render/png.h"
#include "script.h"

// a run, a fresh folder, the explorer without a window (explore_common.h)
using namespace rigid::test;

namespace {

// Files a test puts where an output is asked for: each must be as it was after the run.
struct Decoys {
  fs::path dir, fifo, link, target, folder;
  // named as a recording's file would be, so that `record` meets them too
  explicit Decoys(const fs::path& d)
      : dir(d),
        fifo(d / "fifo.webp"),
        link(d / "link.webp"),
        target(d / "target"),
        folder(d / "folder.webp") {
    REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
    std::ofstream(target) << "mine";
    fs::create_symlink(target, link);
    fs::create_directory(folder);
  }
  // Whether every decoy is as it was, and nothing else came into the folder but `allowed`.
  bool untouched(const std::vector<std::string>& allowed = {}) const {
    std::error_code ec;
    bool same = fs::is_fifo(fs::symlink_status(fifo)) && fs::is_symlink(fs::symlink_status(link)) &&
                fs::read_symlink(link, ec) == target && read_file(target) == "mine" &&
                fs::is_directory(folder) && fs::is_empty(folder) &&
                fs::is_character_file(fs::symlink_status("/dev/null"));
    for (const auto& entry : fs::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      const bool ours = name == "fifo.webp" || name == "link.webp" || name == "target" ||
                        name == "folder.webp" || name == "session.txt" ||
                        std::find(allowed.begin(), allowed.end(), name) != allowed.end();
      if (!ours) {
        UNSCOPED_INFO("came: " << name);
        same = false;
      }
    }
    return same;
  }
};

// Each command that writes a file, as a script line writing `path`.
std::vector<std::pair<std::string, std::string>> writers(const std::string& path) {
  return {
      {"export-json", "export-json " + path},       {"export-csv", "export-csv " + path},
      {"save-figure", "save-figure omega " + path}, {"save-view", "save-view " + path + " 64x64"},
      {"screenshot", "screenshot " + path},         {"record", "record " + path}};
}

}  // namespace

TEST_CASE("explore: every file it writes is refused where --csv's would be and none is touched") {
  const fs::path dir = fresh_dir("outputs");
  const Decoys decoys(dir);
  const std::string long_name(300, 'n');
  // (the path, what the one line says of it)
  const std::vector<std::pair<std::string, std::string>> paths{
      {decoys.fifo.string(), "is not a regular file (a device, pipe or socket)"},
      {decoys.link.string(), "is a symbolic link; give the file itself"},
      {decoys.folder.string(), "is a directory, not a file"},
      {"/dev/null", "is not a regular file"},
      {(dir / long_name).string() + ".webp", "holds a name longer than 255 bytes"},
      {"/proc/rigidlab-explore-test.webp", "cannot write into directory '/proc'"},
  };
  int tried = 0;
  for (const auto& [path, says] : paths) {
    for (const auto& [command, line] : writers(path)) {
      // a recording's name is first a video's (/dev/null is not)
      if (command == "record" && path == "/dev/null") continue;
      INFO(line);
      ++tried;
      const Run run = run_explorer("poinsot", "frames 1\n" + line + "\nquit\n", dir);
      CHECK(run.status == 2);
      CHECK(run.one_error_line());
      CHECK(run.err.find("session.txt:2: " + command + ": ") != std::string::npos);
      CHECK(run.err.find(says) != std::string::npos);
      CHECK(run.out.empty());
      CHECK(decoys.untouched());
    }
  }
  CHECK(tried == 6 * 6 - 1);
  // the frame log, by the same rules, before any window opens
  for (const auto& [path, says] : paths) {
    INFO(path);
    const Run run = run_explorer("poinsot --frame-log " + path, "", dir);
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.find("--frame-log: ") != std::string::npos);
    CHECK(run.err.find(says) != std::string::npos);
    CHECK(decoys.untouched());
  }
}

TEST_CASE("explore: a path that goes bad after it was given is refused as it is written") {
  Headless imgui;
  const fs::path dir = fresh_dir("late");
  const Decoys decoys(dir);
  rigid::explore::Explorer e(rigid::lab::all_labs(), "poinsot", {});
  // a script read while its file was a plain name, the name a link when it comes to it
  const fs::path path = dir / "late.json";
  rigid::explore::Script script = rigid::explore::Script::parse(
      "frames 1\nexport-json " + path.string() + "\nprint-command\n", "late.txt");
  std::ostringstream out, err;
  script.report_to(out);
  script.errors_to(err);
  fs::create_symlink(decoys.target, path);
  for (int steps = 0; script.step(e); ++steps) {
    REQUIRE(steps < 1000);
    imgui.frame(e);
  }
  CHECK(script.status() == 1);
  CHECK(err.str().rfind("late.txt:2: export-json: '", 0) == 0);
  CHECK(err.str().find("' is a symbolic link; give the file itself\n") != std::string::npos);
  CHECK(out.str().empty());  // the script ended at its failure
  CHECK(fs::read_symlink(path) == decoys.target);
  // in the window, a refusal is the status line's, and the explorer goes on
  e.queue(rigid::explore::action::ExportJson{decoys.fifo.string()});
  imgui.frame(e);
  CHECK(e.view().message_error);
  CHECK(e.view().message.find("is not a regular file") != std::string::npos);
  e.queue(rigid::explore::action::ExportCsv{(dir / "fine.csv").string()});
  // an export waits in the queue for the whole report, the frames going on
  for (int frames = 0; frames < 100000 && e.view().message_error; ++frames) imgui.frame(e);
  CHECK_FALSE(e.view().message_error);
  CHECK(e.view().message == "wrote " + (dir / "fine.csv").string());
  CHECK(decoys.untouched({"late.json", "fine.csv", "fine.csv-metadata.json"}));
}

TEST_CASE("explore: a script's numbers and sizes and labs and work in all are checked when read") {
  const std::vector<std::string> labs{"poinsot", "top_nutation"};
  const std::vector<std::pair<std::string, std::string>> refused{
      {"wait 100000", "1: wait must be 0 to 600 s (got 100000)"},
      {"wait -5", "1: wait must be 0 to 600 s (got -5)"},
      {"wait nan", "1: wait must be a number (got 'nan')"},
      {"wait 1e300", "1: wait must be 0 to 600 s (got 1e300)"},
      {"wait abc", "1: wait must be a number (got 'abc')"},
      {"wait 400\nwait-for x\nwait 300", "3: wait: the script would wait 700 s in all"},
      {"speed 0.1\nplay 3600", "2: play must be 0 to 600 s (got 3600)"},
      {"speed 0.1\nplay 600", "2: play: the script would draw 180000 frames in all"},
      {"play 600\nframes 1", "2: frames: the script would draw 18001 frames in all"},
      {"speed 20\nlab top_nutation\nplay 600\nframes 1", "4: frames: the script would draw"},
      {"frames 2.5", "1: frames must be a whole number"},
      {"speed 0", "1: speed must be 0.1 to 1e+06 times real time (got 0)"},
      {"zoom 0", "1: zoom must be 0.001 to 1000 (got 0)"},
      {"turn 400 0", "1: turn's first angle must be -360 to 360 degrees (got 400)"},
      {"seek -1", "1: seek must be 0 to 1e+06 s (got -1)"},
      {"save-view v.png 10x10", "1: save-view: size: must be WxH, each 16 to 8192 (got '10x10')"},
      {"save-figure omega v.png 9000x100", "1: save-figure: size: must be WxH"},
      {"lab nope", "1: lab: 'nope' is not a lab (one of poinsot, top_nutation)"},
      {"record motion.avi", "1: record: the file name must end in .mp4 or .webp"},
      {"play \x1b[31m", "1: play must be a number (got '\\x1b[31m')"},
  };
  for (const auto& [text, says] : refused) {
    INFO(text);
    try {
      rigid::explore::Script::parse(text + "\n", "s.txt", labs);
      FAIL("accepted");
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()).rfind("s.txt:" + says, 0) == 0);
    }
  }
  // the bounds themselves are within them
  for (const std::string text : {"wait 600", "play 600", "speed 20\nplay 600", "frames 18000",
                                 "speed 0.1\nplay 60", "wait 300\nwait 300", "seek 1e6"}) {
    INFO(text);
    CHECK_NOTHROW(rigid::explore::Script::parse(text + "\n", "s.txt", labs));
  }
  // a size whose drawing would take more memory than the run may use, as --figure-size
  ::setenv("RIGIDLAB_MEMORY_MB", "200", 1);
  try {
    rigid::explore::Script::parse("save-view v.png 2048x2048\n", "s.txt", labs);
    FAIL("accepted");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()) ==
          "s.txt:1: save-view: 2048x2048 takes about 336 MB to draw, more than the 210 MB this "
          "run may use (RIGIDLAB_MEMORY_MB=200); give a smaller size");
  }
  CHECK_NOTHROW(rigid::explore::Script::parse("save-view v.png 800x600\n", "s.txt", labs));
  ::unsetenv("RIGIDLAB_MEMORY_MB");
}

TEST_CASE("explore: a script that is not a regular file of at most 1 MiB cannot be read") {
  const fs::path dir = fresh_dir("script-file");
  const Decoys decoys(dir);
  {
    std::ofstream big(dir / "big.txt");
    big << std::string(rigid::explore::kScriptMaxBytes, '#') << "\nframes 1\n";
  }
  const std::vector<std::pair<std::string, std::string>> cases{
      {"/tmp", "--script: /tmp: cannot be read (a directory)"},
      {decoys.fifo.string(), "cannot be read (not a regular file)"},
      {"/dev/zero", "--script: /dev/zero: cannot be read (not a regular file)"},
      {(dir / "big.txt").string(), "cannot be read (longer than 1048576 bytes, a script's bound)"},
      {(dir / "none.txt").string(), "cannot be read (No such file or directory)"},
      {"''", "--script: needs a file name"},
  };
  for (const auto& [path, says] : cases) {
    INFO(path);
    const Run run = run_explorer("poinsot --script " + path, "", dir);
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.find(says) != std::string::npos);
  }
  CHECK(decoys.untouched({"big.txt"}));
}

TEST_CASE("explore: a refusal when its command comes is exit 2 and names the script escaped") {
  const fs::path dir = fresh_dir("escaped");
  const fs::path script = dir / "p\x1b[31m\u202ex.txt";
  std::ofstream(script) << "frames 1\nshow-scene nope\nprint-command\n";
  const Run run = run_explorer("poinsot --script '" + script.string() + "'", "", dir);
  INFO(run.err);
  CHECK(run.status == 2);
  CHECK(run.one_error_line());
  CHECK(run.err.find('\x1b') == std::string::npos);
  CHECK(run.err.find("\u202e") == std::string::npos);
  CHECK(run.err.find("p\\x1b[31m\\u{202e}x.txt:2: show-scene: poinsot shows no 'nope'") !=
        std::string::npos);
  CHECK(run.out.empty());  // the script ended there
}

TEST_CASE("explore: a recording that cannot be written says why and the script exits 1") {
  const fs::path dir = fresh_dir("record");
  // the lab's own command meets the file-size limit (ulimit -f) as it writes: a failed
  // write, its temporary removed
  const Run run = run_explorer(
      "euler_angles", "record " + (dir / "motion.webp").string() + "\nframes 2\nprint-command\n",
      dir, "ulimit -f 64; ");
  INFO(run.out << run.err);
  CHECK(run.status == 1);
  CHECK(run.one_error_line());
  CHECK(run.err.rfind("rigidlab-explore: error: --script: " + (dir / "session.txt").string() +
                          ":1: recording failed: euler_angles: error: ",
                      0) == 0);
  CHECK(run.out.find("euler_angles\n") == std::string::npos);  // the script ended there
  for (const auto& entry : fs::directory_iterator(dir))
    CHECK(entry.path().filename() == "session.txt");
}

TEST_CASE("explore: a window resized past 8192 pixels a side is held to 8192") {
  // Mesa's software renderer would hold a 32767-pixel-wide window whole (and segfault at
  // 32767 square); the explorer puts the window back before it draws into it
  const fs::path dir = fresh_dir("resize");
  const fs::path script = dir / "session.txt", go = dir / "go", shot = dir / "shot.png";
  std::ofstream(script) << "frames 2\nwait-for " << go.string() << "\nframes 3\nscreenshot "
                        << shot.string() << "\nquit\n";
  rigid::test::Background explorer(
      {RIGID_EXPLORER, "poinsot", "--size", "800x600", "--script", script.string()});
  const std::string act =
      "W=$(xdotool search --sync --name 'rigidlab explore') && xdotool windowsize $W 32767 "
      "600 && touch " +
      go.string();
  CHECK(std::system(act.c_str()) == 0);
  const int status = explorer.wait();
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  const auto image = rigid::render::read_png(shot.string());
  CHECK(image.width == 8192);
  CHECK(image.height == 600);
}

namespace {

// The process `pid` has ended (gone, or a zombie its new parent has not yet reaped).
bool ended(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  if (!std::getline(stat, text)) return true;
  const auto close = text.rfind(')');
  return close == std::string::npos || text.substr(close + 2, 1) == "Z";
}

// The temporary of a recording under way in `dir` ("" if none yet).
std::string temporary_in(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".rigidlab-tmp-") != std::string::npos) return name;
  }
  return "";
}

}  // namespace

TEST_CASE("explore: the explorer ended during a recording ends its lab and nothing lands") {
  for (const int signal : {SIGKILL, SIGTERM, SIGHUP}) {
    INFO("signal " << signal);
    const fs::path dir = fresh_dir("killed-" + std::to_string(signal));
    const fs::path script = dir / "session.txt";
    std::ofstream(script) << "record " << (dir / "motion.webp").string() << "\nframes 1\n";
    rigid::test::Background explorer({RIGID_EXPLORER, "euler_angles", "--script", script.string()});
    // the lab is writing: its temporary (TARGET.rigidlab-tmp-PID-RANDOM) names its process
    std::string temporary;
    REQUIRE(explorer.wait_until([&] { return !(temporary = temporary_in(dir)).empty(); }));
    const std::string pid_text = temporary.substr(temporary.find("-tmp-") + 5);
    const pid_t lab = static_cast<pid_t>(std::stol(pid_text.substr(0, pid_text.find('-'))));
    REQUIRE(::kill(explorer.pid(), signal) == 0);
    explorer.wait();
    // the lab ends by the SIGTERM its parent's death sends (were it let run, it would
    // land the file)
    while (!ended(lab)) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    for (const auto& entry : fs::directory_iterator(dir))
      CHECK(entry.path().filename() == "session.txt");
  }
}

TEST_CASE("explore: a frame's phases lie within its time and need the log they go in") {
  const fs::path dir = fresh_dir("phases");
  const Run alone = run_explorer("poinsot --frame-phases", "", dir);
  CHECK(alone.status == 2);
  CHECK(alone.one_error_line());
  CHECK(alone.err.find("--frame-phases: needs --frame-log") != std::string::npos);
  const fs::path log = dir / "frames.json";
  const Run run = run_explorer("poinsot --frame-phases --frame-log " + log.string(),
                               "frames 2\nplay 0.2\nquit\n", dir);
  REQUIRE(run.status == 0);
  const nlohmann::json frames = nlohmann::json::parse(read_file(log))["frames"];
  REQUIRE(frames.size() >= 8);
  int drew_scene = 0;
  for (const nlohmann::json& f : frames) {
    // the phases are disjoint stretches of the frame's wall time, each timed by one clock
    double sum = 0;
    for (const auto& [name, seconds] : f["phases"].items()) {
      INFO(name);
      CHECK(seconds.get<double>() >= -1e-6);  // widgets: a difference of two readings
      sum += seconds.get<double>();
    }
    CHECK(sum <= f["seconds"].get<double>() + 1e-6);
    if (f["phases"]["scene_draw"].get<double>() > 0) ++drew_scene;
  }
  // playing, each frame draws the scene at its own time
  CHECK(drew_scene >= 6);
}
