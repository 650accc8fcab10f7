// The explorer as a student and an instructor meet it, under Xvfb (ctest runs this
// program inside xvfb-run): a scripted session of every lab saves the figure the
// command line draws and the numbers its JSON prints, and the command it copies
// reproduces them; a value that breaks a rule shows the rule and the view stays the
// last valid one; real mouse input (xdotool) moves a slider and turns the view; bad
// options are one line and exit 2, before any window opens.
#include <imgui.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <random>
#include <sstream>
#include <thread>

#include "common/registry.h"
#include "explore_common.h"
#include "explorer.h"
#include "rigid/render/image_match.h"
#include "rigid/render/png.h"

extern char** environ;

namespace fs = std::filesystem;
using rigid::test::comes;
using rigid::test::fresh_dir;
using rigid::test::Headless;
using rigid::test::lines_of;
using rigid::test::read_file;
using rigid::test::Run;
using rigid::test::run_explorer;

namespace {

// One change a student might make to a lab: its first number input moved along its
// slider, else another choice of its first choice input; as the flag and its text.
std::pair<std::string, std::string> a_change(rigid::lab::Session& s) {
  for (std::size_t i = 0; i < s.input_count(); ++i) {
    const auto& rule = s.rule(i);
    const auto value = s.value(i);
    if (rule.kind() != rigid::lab::InputKind::kNumber || !rule.physical() ||
        !std::holds_alternative<double>(value)) {
      continue;
    }
    for (double factor : {1.25, 0.8, 1.5}) {
      const std::string text = rigid::lab::argument_text(std::get<double>(value) * factor);
      if (!s.set_text(i, text)) return {rule.flag(), text};
    }
  }
  for (std::size_t i = 0; i < s.input_count(); ++i) {
    const auto& rule = s.rule(i);
    if (rule.kind() != rigid::lab::InputKind::kChoice) continue;
    for (const std::string& c : rule.choices()) {
      if (!(s.value(i) == rigid::lab::InputValue(c)) && !s.set_text(i, c)) return {rule.flag(), c};
    }
  }
  FAIL("no input of " << s.name() << " to change");
  return {};
}

// Pixels of `img` inside [x0, x1) x [y0, y1) that are not the background's white.
long drawn_pixels(const rigid::render::Image& img, int x0, int y0, int x1, int y1) {
  long n = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const std::uint8_t* p = img.at(x, y);
      if (p[0] < 200 || p[1] < 200 || p[2] < 200) ++n;
    }
  }
  return n;
}

// The explorer's layout at 1280x720 (explorer.cpp): inputs on the left 340 px, numbers
// on the right 390 px, the scene between them above the time bar.
constexpr int kSceneX0 = 340, kSceneX1 = 1280 - 390, kSceneY1 = 400;

void check_scripted_session(const std::string& lab) {
  auto session = [&] {
    for (const auto& e : rigid::lab::all_labs()) {
      if (e.name == lab) return e.make();
    }
    return std::unique_ptr<rigid::lab::Session>();
  }();
  REQUIRE(session);
  const auto [flag, value] = a_change(*session);
  session->wait();
  REQUIRE(!session->figures().empty());
  const std::string figure = session->figures().front().name;
  const fs::path dir = fresh_dir(lab);
  std::string script = "set " + flag + " " + value +
                       "\n"
                       "play 0.5\n"
                       "turn 25 10\n"
                       "zoom 1.2\n"
                       "frames 2\n"
                       "screenshot " +
                       (dir / "shot.png").string() + "\nsave-figure " + figure + " " +
                       (dir / "explorer.png").string() + " 800x600\nsave-figure " + figure + " " +
                       (dir / "explorer.pdf").string() + " 800x600\nexport-json " +
                       (dir / "explorer.json").string() + "\n";
  if (session->has_time_series()) script += "export-csv " + (dir / "explorer.csv").string() + "\n";
  script += "print-command\nquit\n";
  const Run run = run_explorer(lab, script, dir);
  INFO(run.out << run.err);
  INFO(run.err);
  REQUIRE(run.status == 0);
  const auto lines = lines_of(run.out);
  REQUIRE(!lines.empty());
  // the command it copies: the lab and the one input changed
  const std::string command = lines.back();
  CHECK(command == lab + " " + flag + "=" + value);

  // that command, run as a process, prints the numbers the explorer exported and draws
  // the figure it saved
  std::string cli_args = command.substr(lab.size()) + " --json --figure-size 800x600 --figures " +
                         (dir / "cli").string();
  if (session->has_time_series()) cli_args += " --csv " + (dir / "cli.csv").string();
  const Run cli = rigid::test::run_lab(lab, cli_args);
  INFO(cli.err);
  REQUIRE(cli.status == 0);
  const auto expected = cli.json();
  const auto shown = nlohmann::json::parse(read_file(dir / "explorer.json"));
  CHECK(shown["inputs"] == expected["inputs"]);
  CHECK(shown["results"] == expected["results"]);
  CHECK(shown["notes"] == expected["notes"]);
  // and names that command as the command line's JSON names its own argv
  CHECK(shown["command"] == nlohmann::json({lab, flag + "=" + value}));
  const auto drawn = rigid::render::read_png((dir / "explorer.png").string());
  const auto by_cli =
      rigid::render::read_png((dir / "cli" / (lab + "_" + figure + ".png")).string());
  CHECK(drawn.width == 800);
  CHECK(rigid::render::mismatch(drawn, by_cli).empty());
  // the same figure as a PDF (its drawing against the PNG's: figure_test.cpp)
  CHECK(read_file(dir / "explorer.pdf").rfind("%PDF-", 0) == 0);
  if (session->has_time_series()) {
    CHECK(read_file(dir / "explorer.csv") == read_file(dir / "cli.csv"));
  }
  // the window as shown: its size, a scene drawn in the middle
  const auto shot = rigid::render::read_png((dir / "shot.png").string());
  CHECK(shot.width == 1280);
  CHECK(shot.height == 720);
  CHECK(drawn_pixels(shot, kSceneX0, 0, kSceneX1, kSceneY1) > 2000);
}

}  // namespace

TEST_CASE("explore: a scripted session saves the command line's figure and numbers") {
  for (const std::string& lab : rigid::test::all_labs()) {
    SECTION(lab) {
      check_scripted_session(lab);
    }
  }
}

TEST_CASE("explore: a typed value that breaks a rule shows the rule and the view stays valid") {
  const fs::path dir = fresh_dir("refused");
  const Run run = run_explorer("top_nutation",
                               "frames 2\n"
                               "set --mass -1\n"
                               "set --arm abc\n"
                               "set --theta0-deg 1e400\n"
                               "frames 2\n"
                               "screenshot " +
                                   (dir / "shot.png").string() + "\nprint-json\nquit\n",
                               dir);
  INFO(run.out << run.err);
  INFO(run.err);
  REQUIRE(run.status == 0);
  CHECK(run.out.find("refused: --mass: must be positive (got -1)") != std::string::npos);
  CHECK(run.out.find("refused: --arm: must be a number (got 'abc')") != std::string::npos);
  // beyond a double, refused by the rule it breaks, as the command line refuses it
  CHECK(run.out.find("refused: --theta0-deg: must be 0 or between 1e-60 and 1e60 in magnitude "
                     "(got 1e400)") != std::string::npos);
  // the numbers are the last valid inputs' (the textbook's), whole and finite
  const auto json = nlohmann::json::parse(run.out.substr(run.out.find('{')));
  const Run cli = rigid::test::run_lab("top_nutation", "--json");
  CHECK(json["results"] == cli.json()["results"]);
  // the rule is shown in red beside its field, in the inputs panel
  const auto shot = rigid::render::read_png((dir / "shot.png").string());
  long red = 0;
  for (int y = 0; y < shot.height; ++y) {
    for (int x = 0; x < kSceneX0; ++x) {
      const std::uint8_t* p = shot.at(x, y);
      if (p[0] > 150 && p[1] < 90 && p[2] < 90) ++red;
    }
  }
  CHECK(red > 100);
  CHECK(drawn_pixels(shot, kSceneX0, 0, kSceneX1, kSceneY1) > 2000);
}

TEST_CASE("explore: real mouse input moves a slider and turns the view (xdotool)") {
  const fs::path dir = fresh_dir("mouse");
  const fs::path before = dir / "before.png", after = dir / "after.png";
  // The mass slider (the first, at y = 144) dragged right, then the scene dragged: one
  // mouse event a step. After each, the test makes go-K and the script, which waits for
  // it, draws two frames (the event is taken in) and answers with ack-K: no step counts
  // on how long the other side takes.
  const std::vector<std::string> steps{"mousemove --sync --window $W 60 144",
                                       "mousedown 1",
                                       "mousemove --sync --window $W 120 144",
                                       "mousemove --sync --window $W 150 144",
                                       "mouseup 1",
                                       "mousemove --sync --window $W 600 250",
                                       "mousedown 1",
                                       "mousemove --sync --window $W 650 260",
                                       "mousemove --sync --window $W 700 270",
                                       "mouseup 1"};
  const auto go = [&](std::size_t k) { return dir / ("go-" + std::to_string(k)); };
  const auto ack = [&](std::size_t k) { return dir / ("ack-" + std::to_string(k) + ".png"); };
  {
    std::ofstream script(dir / "session.txt");
    script << "frames 3\nscreenshot " << before.string() << "\n";
    for (std::size_t k = 0; k < steps.size(); ++k) {
      script << "wait-for " << go(k).string() << "\nframes 2\nscreenshot " << ack(k).string()
             << "\n";
    }
    script << "frames 2\nscreenshot " << after.string() << "\nprint-command\nquit\n";
  }
  const std::string command = std::string(RIGID_EXPLORER) + " top_nutation --script " +
                              (dir / "session.txt").string() + " >" + (dir / "out.txt").string() +
                              " 2>&1";
  pid_t pid = 0;
  std::string shell = "/bin/sh", dash_c = "-c", line = command;
  char* argv[] = {shell.data(), dash_c.data(), line.data(), nullptr};
  REQUIRE(::posix_spawn(&pid, "/bin/sh", nullptr, nullptr, argv, environ) == 0);
  // the first screenshot says the window is up
  REQUIRE(comes(before, 300));
  for (std::size_t k = 0; k < steps.size(); ++k) {
    INFO(steps[k]);
    const std::string act = "W=$(xdotool search --sync --name 'rigidlab explore') && xdotool " +
                            steps[k] + " && touch " + go(k).string();
    CHECK(std::system(act.c_str()) == 0);
    CHECK(comes(ack(k), 300));
  }
  int status = 0;
  REQUIRE(::waitpid(pid, &status, 0) == pid);
  const std::string out = read_file(dir / "out.txt");
  INFO(out);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  // the slider moved the mass up from the text's 2 kg
  const auto at = out.find("top_nutation --mass=");
  REQUIRE(at != std::string::npos);
  CHECK(std::stod(out.substr(at + 20)) > 2.0);
  // and the scene is another picture
  const auto a = rigid::render::read_png(before.string());
  const auto b = rigid::render::read_png(after.string());
  const auto scene_of = [](const rigid::render::Image& img) {
    rigid::render::Image scene;
    scene.width = kSceneX1 - kSceneX0;
    scene.height = kSceneY1;
    for (int y = 0; y < kSceneY1; ++y) {
      for (int x = kSceneX0; x < kSceneX1; ++x) {
        const std::uint8_t* p = img.at(x, y);
        scene.rgb.insert(scene.rgb.end(), p, p + 3);
      }
    }
    return scene;
  };
  CHECK(rigid::render::compare_images(scene_of(a), scene_of(b)).differing_pixels > 1000);
}

TEST_CASE("explore: random slider moves through the window across every lab never break it") {
  // Each move drags one number input of a lab to a random place of its slider (the
  // window's own widget rule, lab::slider_span), now and then types a value, turns the
  // view or plays a little; every lab in turn. Seeded: the same moves every run. The
  // sanitizer build runs this too.
  std::mt19937 rng(27);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::string script;
  int moves = 0;
  for (const auto& entry : rigid::lab::all_labs()) {
    auto s = entry.make();
    script += "lab " + entry.name + "\n";
    std::vector<std::size_t> numbers;
    for (std::size_t i = 0; i < s->input_count(); ++i) {
      if (s->rule(i).kind() == rigid::lab::InputKind::kNumber &&
          std::holds_alternative<double>(s->textbook_value(i))) {
        numbers.push_back(i);
      }
    }
    for (int k = 0; k < 30 && !numbers.empty(); ++k, ++moves) {
      const std::size_t i = numbers[rng() % numbers.size()];
      const auto span = rigid::lab::slider_span(s->rule(i), std::get<double>(s->textbook_value(i)));
      const double x = span.log ? span.lo * std::pow(span.hi / span.lo, u(rng))
                                : span.lo + (span.hi - span.lo) * u(rng);
      script += (u(rng) < 0.8 ? "drag " : "set ") + s->rule(i).flag() + " " +
                rigid::lab::argument_text(x) + "\n";
      if (u(rng) < 0.2) script += "turn " + std::to_string(static_cast<int>(90 * u(rng))) + " 5\n";
      if (u(rng) < 0.2) script += "play 0.1\n";
    }
    script += "frames 2\nprint-json\n";
  }
  script += "quit\n";
  const fs::path dir = fresh_dir("random");
  const Run run = run_explorer("lamina_tensor", script, dir);
  INFO(run.err.substr(0, 2000));
  CHECK(moves >= 150);
  INFO(run.err);
  REQUIRE(run.status == 0);
  // each lab's last numbers: whole JSON objects, no NaN or infinity among them
  std::size_t at = 0;
  int objects = 0;
  while ((at = run.out.find("{\n  \"lab\"", at)) != std::string::npos) {
    const std::size_t end = run.out.find("\n}\n", at);
    REQUIRE(end != std::string::npos);
    const std::string text = run.out.substr(at, end + 2 - at);
    CHECK(text.find("NaN") == std::string::npos);
    CHECK(text.find("Infinity") == std::string::npos);
    CHECK_NOTHROW(nlohmann::json::parse(text));
    at = end;
    ++objects;
  }
  CHECK(objects == static_cast<int>(rigid::lab::all_labs().size()));
}

TEST_CASE("explore: bad options are one line and exit 2 before any window opens") {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"nosuch", "LAB: 'nosuch' is not a lab"},
      {"top_nutation --size 10x10", "--size: must be WxH"},
      {"top_nutation --mass -1", "--mass: must be positive (got -1)"},
      {"top_nutation --mass", "--mass: needs a value"},
      {"top_nutation --mass 1 --mass=2", "--mass: given twice: give it once"},
      {"top_nutation --size 800x600 --size 900x600", "--size: given twice: give it once"},
      {"top_nutation --json", "--json: not an input of top_nutation"},
      {"poinsot --inertia 1,1,3", "I1 + I2 >= I3"},
      {"top_nutation --script /nonexistent/s.txt", "--script: /nonexistent/s.txt: cannot be read"},
  };
  for (const auto& [args, says] : cases) {
    INFO(args);
    const Run run = run_explorer(args + " </dev/null", "", fs::temp_directory_path());
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.find(says) != std::string::npos);
    CHECK(run.out.empty());
  }
  // a script's mistakes are found before the window opens, by file and line
  const fs::path dir = fresh_dir("bad-script");
  const Run run = run_explorer("poinsot", "frames 2\nfly 3\n", dir);
  CHECK(run.status == 2);
  CHECK(run.one_error_line());
  CHECK(run.err.find("session.txt:2: unknown command 'fly'") != std::string::npos);
}

namespace {

// A lab that opens only when the test lets it: its opening has begun, and it may end.
struct Gate {
  std::mutex m;
  std::condition_variable cv;
  bool began = false, open = false, made = false;
  void wait_for(bool Gate::*flag) {
    std::unique_lock<std::mutex> lock(m);
    cv.wait(lock, [&] { return this->*flag; });
  }
  void set(bool Gate::*flag) {
    {
      std::lock_guard<std::mutex> lock(m);
      this->*flag = true;
    }
    cv.notify_all();
  }
};

}  // namespace

TEST_CASE("explore: another lab opens off the frame's thread while the frames go on") {
  Headless imgui;
  Gate gate;
  std::vector<rigid::lab::LabEntry> labs = rigid::lab::all_labs();
  const auto poinsot =
      std::find_if(labs.begin(), labs.end(), [](const auto& l) { return l.name == "poinsot"; });
  REQUIRE(poinsot != labs.end());
  rigid::lab::LabEntry held = *poinsot;
  held.name = "held";
  held.make = [&gate, make = poinsot->make] {
    gate.set(&Gate::began);
    gate.wait_for(&Gate::open);
    auto session = make();
    gate.set(&Gate::made);
    return session;
  };
  labs.push_back(held);
  rigid::explore::Explorer e(labs, "lamina_tensor", {});
  CHECK(imgui.frame(e));
  e.queue(rigid::explore::action::OpenLab{"held"});
  CHECK(e.animating());  // an action queued: the loop does not wait for an event
  CHECK(imgui.frame(e));
  // while the lab opens (held until the test lets it), frames are drawn of the lab before
  gate.wait_for(&Gate::began);
  for (int k = 0; k < 3; ++k) {
    CHECK(imgui.frame(e));
    CHECK(e.opening());
    CHECK(e.animating());
    CHECK(e.session().name() == "lamina_tensor");
  }
  gate.set(&Gate::open);
  gate.wait_for(&Gate::made);
  // it is shown at a frame after it has come (the few instructions between its making and
  // its future's readiness are bounded by tries, not by time)
  for (int tries = 0; tries < 1000000 && e.opening(); ++tries) {
    imgui.frame(e);
    std::this_thread::yield();
  }
  REQUIRE(!e.opening());
  CHECK(imgui.frame(e));
  CHECK(e.session().name() == "poinsot");
  CHECK(e.view().fields.size() == e.session().input_count());
  // a value typed into the new lab's field is taken at the next frame
  e.queue(rigid::explore::action::SetText{"--mass", "2.5"});
  CHECK(imgui.frame(e));
  CHECK(e.command_line() == "poinsot --mass=2.5");
}
