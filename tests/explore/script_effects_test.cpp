// Every script command pinned by what it does, in-process and without a window: the
// session's inputs after it, the view's state (time, speed, orbit, the scene and plot
// chosen, the parts hidden), the scene the explorer describes for drawing (its items
// and camera, not its pixels), and every file written, byte for byte the lab's own
// writer's. And every command's words counted and typed when the script is read, so
// that a slip in the script's table or its parser is a refusal that names its rule.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "common/registry.h"
#include "common/writers.h"
#include "explore_common.h"
#include "explorer.h"
#include "rigid/render/draw.h"
#include "rigid/render/png.h"
#include "scene_cache.h"
#include "script.h"

using namespace rigid::test;
namespace ex = rigid::explore;
using rigid::lab::InputValue;
using rigid::render::Scene3D;

namespace {

using Inputs = std::vector<std::pair<std::string, std::string>>;

// What the command line computes for `lab` at `inputs` (each its flag and text): a
// session of its own, whole.
std::unique_ptr<rigid::lab::Session> session_at(const std::string& lab, const Inputs& inputs) {
  for (const auto& entry : rigid::lab::all_labs()) {
    if (entry.name != lab) continue;
    auto s = entry.make();
    for (const auto& [flag, text] : inputs) REQUIRE_FALSE(s->set_text(s->find(flag), text));
    s->wait();
    return s;
  }
  FAIL("no lab " << lab);
  return nullptr;
}

// The JSON the lab's own writer prints for `s`, its command named by hand.
std::string json_of(const rigid::lab::Session& s, const std::vector<std::string>& command) {
  rigid::lab::RunOutputs outputs;
  outputs.command = command;
  std::ostringstream text;
  rigid::lab::write_json(text, s.report(), outputs, RIGID_VERSION);
  return text.str();
}

InputValue value_of(const ex::Explorer& e, const std::string& flag) {
  const std::size_t i = e.session().find(flag);
  REQUIRE(i < e.session().input_count());
  return e.session().value(i);
}
const ex::Field& field_of(const ex::Explorer& e, const std::string& flag) {
  return e.view().fields.at(e.session().find(flag));
}

// Whether any surface or line of `scene` is labelled `label`.
bool draws(const Scene3D& scene, const std::string& label) {
  for (const auto& o : scene.objects())
    if (o.label == label) return true;
  for (const auto& p : scene.polylines())
    if (p.label == label) return true;
  return false;
}

bool same_camera(const rigid::render::Camera& a, const rigid::render::Camera& b) {
  return a.eye == b.eye && a.target == b.target && a.up == b.up && a.fov_y_deg == b.fov_y_deg &&
         a.orthographic == b.orthographic && a.ortho_height == b.ortho_height;
}

// The scene the explorer describes for drawing its view now, at 640x480 (a cache of its
// own, as a fresh view would make it).
Scene3D described(const ex::Explorer& e) {
  ex::SceneCache cache;
  return cache.view_scene(e.session(), e.view(), 640, 480);
}

// The explorer held in-process, its window a close flag and a known frame.
struct Bench {
  Headless imgui;
  bool closed = false;
  rigid::render::Image frame_image{8, 6, std::vector<std::uint8_t>(8 * 6 * 3)};
  ex::Explorer e;

  explicit Bench(const std::string& lab)
      : e(rigid::lab::all_labs(), lab,
          ex::Window{nullptr, [this] { return frame_image; }, [this] { closed = true; }, nullptr}) {
    for (std::size_t k = 0; k < frame_image.rgb.size(); ++k)
      frame_image.rgb[k] = static_cast<std::uint8_t>(k * 37);
  }

  struct Ran {
    std::string out, err;
    int frames = 0;
  };
  // Runs `text` as a script to its end, as the window does (a step a frame); `each` after
  // every frame.
  Ran run(const std::string& text, const std::function<void()>& each = {}) {
    auto script = std::make_unique<ex::Script>(ex::Script::parse(text + "\n", "s.txt", all_labs()));
    std::ostringstream out, err;
    script->report_to(out);
    script->errors_to(err);
    closed = false;
    e.run(std::move(script));
    Ran ran;
    for (; !closed; ++ran.frames) {
      REQUIRE(ran.frames < 100000);
      imgui.frame(e);
      e.after_render();
      if (each) each();
    }
    ran.out = out.str();
    ran.err = err.str();
    return ran;
  }
};

// The one line a script's text is refused with when read ("" if it is not).
std::string refusal(const std::string& text) {
  try {
    ex::Script::parse(text + "\n", "s.txt", all_labs());
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// Every command, how many words follow it (at least, at most), and words it takes (as
// many as it may: a sample that must be read).
struct Spec {
  std::string op;
  int min, max;
  std::string words;
};
std::vector<Spec> specs(const fs::path& dir) {
  const std::string d = dir.string() + "/";
  return {{"set", 1, 2, "--mass 2"},
          {"unset", 1, 1, "--t-end"},
          {"drag", 2, 2, "--mass 2"},
          {"textbook", 0, 0, ""},
          {"lab", 1, 1, "poinsot"},
          {"play", 1, 1, "1"},
          {"pause", 0, 0, ""},
          {"seek", 1, 1, "1"},
          {"speed", 1, 1, "2"},
          {"turn", 2, 2, "30 -10"},
          {"zoom", 1, 1, "1.5"},
          {"reset-view", 0, 0, ""},
          {"show-scene", 1, 1, "motion"},
          {"show-plot", 1, 1, "omega"},
          {"hide", 1, 1, "herpolhode"},
          {"show", 1, 1, "herpolhode"},
          {"frames", 1, 1, "3"},
          {"wait", 1, 1, "1"},
          {"wait-for", 1, 1, d + "go"},
          {"screenshot", 1, 1, d + "s.png"},
          {"save-figure", 2, 3, "omega " + d + "f.svg 200x150"},
          {"save-view", 1, 2, d + "v.png 200x150"},
          {"export-json", 1, 1, d + "r.json"},
          {"export-csv", 1, 1, d + "r.csv"},
          {"record", 1, 1, d + "m.webp"},
          {"print-command", 0, 0, ""},
          {"print-json", 0, 0, ""},
          {"quit", 0, 0, ""}};
}

// The first `n` of `words`, after `op`.
std::string line_of(const std::string& op, const std::string& words, int n) {
  std::istringstream in(words);
  std::string line = op, w;
  for (int k = 0; k < n && in >> w; ++k) line += " " + w;
  return line;
}

}  // namespace

TEST_CASE("explore: every script command's count of words is checked when the script is read") {
  const fs::path dir = fresh_dir("effects-words");
  std::string names;
  std::vector<Spec> all = specs(dir);
  std::sort(all.begin(), all.end(), [](const Spec& a, const Spec& b) { return a.op < b.op; });
  for (const Spec& s : all) {
    INFO(s.op);
    names += (names.empty() ? "" : ", ") + s.op;
    CHECK(refusal(line_of(s.op, s.words, s.max)).empty());
    CHECK(refusal(line_of(s.op, s.words, s.min)).empty());
    const std::string takes =
        s.op + " takes " +
        (s.min == s.max ? std::to_string(s.min)
                        : std::to_string(s.min) + " to " + std::to_string(s.max)) +
        " words (got ";
    // one word too many, after every word it may take
    CHECK(refusal(line_of(s.op, s.words, s.max) + " extra") ==
          "s.txt:1: " + takes + std::to_string(s.max + 1) + ")");
    if (s.min > 0) {
      CHECK(refusal(line_of(s.op, s.words, s.min - 1)) ==
            "s.txt:1: " + takes + std::to_string(s.min - 1) + ")");
    }
  }
  // no command the script reads but these (each pinned below by its effect)
  CHECK(refusal("nope") == "s.txt:1: unknown command 'nope' (one of " + names + ")");
  // a word in quotes is one word, blanks and all
  CHECK(refusal("hide \"energy ellipsoid\"").empty());
  CHECK(refusal("hide energy ellipsoid") == "s.txt:1: hide takes 1 words (got 2)");
  CHECK(refusal("hide \"energy ellipsoid") == "s.txt:1: a quote is not closed");
}

TEST_CASE("explore: every script command's words are of their type when the script is read") {
  const fs::path dir = fresh_dir("effects-types");
  const std::string folder = (dir / "folder.webp").string();
  fs::create_directory(folder);
  const std::vector<std::pair<std::string, std::string>> refused{
      {"play x", "play must be a number (got 'x')"},
      {"seek x", "seek must be a number (got 'x')"},
      {"speed x", "speed must be a number (got 'x')"},
      {"zoom x", "zoom must be a number (got 'x')"},
      {"frames x", "frames must be a number (got 'x')"},
      {"frames 1.5", "frames must be a whole number"},
      {"wait x", "wait must be a number (got 'x')"},
      {"turn x 0", "turn's first angle must be a number (got 'x')"},
      {"turn 0 x", "turn's second angle must be a number (got 'x')"},
      {"save-figure omega " + (dir / "f.png").string() + " big",
       "save-figure: size: must be WxH, each 16 to 8192 (got 'big')"},
      {"save-view " + (dir / "v.png").string() + " 100", "save-view: size: must be WxH"},
      {"record " + (dir / "m.avi").string(), "record: the file name must end in .mp4 or .webp"},
      {"lab nope", "lab: 'nope' is not a lab (one of "},
  };
  for (const auto& [line, says] : refused) {
    INFO(line);
    CHECK(refusal(line).rfind("s.txt:1: " + says, 0) == 0);
  }
  // each word that names a file it writes is a file it may write
  for (const std::string op :
       {"screenshot", "save-view", "export-json", "export-csv", "record", "save-figure omega"}) {
    INFO(op);
    const std::string why = refusal(op + " " + folder);
    CHECK(why.rfind("s.txt:1: " + op.substr(0, op.find(' ')) + ": '", 0) == 0);
    CHECK(why.find("' is a directory, not a file") != std::string::npos);
  }
}

TEST_CASE("explore: set, drag, unset and textbook change the session's inputs and its fields") {
  Bench b("poinsot");
  b.run("set --omega 1,2,0.5\nset --method rk4\nset --t-end 5");
  CHECK(value_of(b.e, "--omega") == InputValue(Eigen::Vector3d(1, 2, 0.5)));
  CHECK(value_of(b.e, "--method") == InputValue(std::string("rk4")));
  CHECK(value_of(b.e, "--t-end") == InputValue(5.0));
  CHECK(field_of(b.e, "--omega").text == "1,2,0.5");
  CHECK(field_of(b.e, "--t-end").text == "5");
  CHECK(b.e.command_line() == "poinsot --omega=1,2,0.5 --t-end=5 --method=rk4");
  b.run("unset --t-end");
  CHECK(std::holds_alternative<std::monostate>(value_of(b.e, "--t-end")));
  CHECK(field_of(b.e, "--t-end").text.empty());
  CHECK(b.e.command_line() == "poinsot --omega=1,2,0.5 --method=rk4");

  // a refused value is printed, the state stays, and its field shows what was typed and why
  const Bench::Ran refused = b.run("set --mass -1\nset --omega 1,2,3,4\nset --nope 1");
  CHECK(refused.out ==
        "s.txt:1: refused: --mass: must be positive (got -1)\n"
        "s.txt:2: refused: --omega: needs 3 numbers separated by commas (got "
        "'1,2,3,4')\n"
        "s.txt:3: refused: --nope: poinsot has no such input\n");
  CHECK(refused.err.empty());
  CHECK(value_of(b.e, "--mass") == InputValue(M_PI));
  CHECK(value_of(b.e, "--omega") == InputValue(Eigen::Vector3d(1, 2, 0.5)));
  CHECK(field_of(b.e, "--omega").text == "1,2,3,4");
  CHECK(field_of(b.e, "--omega").refusal ==
        "--omega: needs 3 numbers separated by commas (got '1,2,3,4')");
  CHECK(field_of(b.e, "--mass").refusal == "--mass: must be positive (got -1)");

  // `drag` holds the slider while its frame is built, as a hand does; `set` does not
  bool held = false;
  b.run("set --mass 2", [&] { held = held || b.e.view().interacting; });
  CHECK_FALSE(held);
  CHECK(value_of(b.e, "--mass") == InputValue(2.0));
  b.run("drag --mass 2.5", [&] { held = held || b.e.view().interacting; });
  CHECK(held);
  CHECK(value_of(b.e, "--mass") == InputValue(2.5));
  CHECK(field_of(b.e, "--mass").text == "2.5");
  b.imgui.frame(b.e);
  CHECK_FALSE(b.e.view().interacting);

  b.run("textbook");
  CHECK(b.e.session().at_textbook());
  CHECK(b.e.command_line() == "poinsot");
  for (std::size_t i = 0; i < b.e.session().input_count(); ++i) {
    CHECK(b.e.view().fields[i].text == rigid::lab::argument_text(b.e.session().value(i)));
    CHECK(b.e.view().fields[i].refusal.empty());
  }
}

TEST_CASE("explore: a field for a vector or a pair takes exactly its count of numbers") {
  int checked = 0;
  for (const auto& entry : rigid::lab::all_labs()) {
    auto s = entry.make();
    for (std::size_t i = 0; i < s->input_count(); ++i) {
      const auto kind = s->rule(i).kind();
      if (kind != rigid::lab::InputKind::kVector && kind != rigid::lab::InputKind::kPair) continue;
      const std::string flag = s->rule(i).flag();
      INFO(entry.name << " " << flag);
      const bool vector = kind == rigid::lab::InputKind::kVector;
      const InputValue before = s->value(i);
      // its own numbers, one too many and one too few
      std::string own = rigid::lab::argument_text(before);
      if (own.empty() || own.find(',') == std::string::npos) own = vector ? "1,1,1" : "1,1";
      const std::string more = own + "," + own.substr(own.rfind(',') + 1);
      const std::string fewer = own.substr(0, own.rfind(','));
      for (const std::string& text : {more, fewer}) {
        const auto why = s->set_text(i, text);
        REQUIRE(why);
        CHECK(why->message == flag + ": needs " + (vector ? "3" : "2") +
                                  " numbers separated by commas (got '" + text + "')");
        CHECK(s->value(i) == before);
      }
      ++checked;
    }
  }
  // poinsot's four vectors, euler_angles' three, lamina_tensor's axis, tennis_racquet's
  // inertia; football's and top_nutation's pairs
  CHECK(checked == 11);
}

TEST_CASE("explore: a switch set on is in the command, the JSON and the file exported") {
  struct Case {
    std::string lab, flag;
    Inputs before;  // what the switch needs set first
  };
  const fs::path dir = fresh_dir("effects-switches");
  for (const Case& c : {Case{"lamina_tensor", "--examples", {}},
                        Case{"poinsot", "--project", {{"--method", "rk4"}}},
                        Case{"tennis_racquet", "--project", {{"--method", "rk4"}}}}) {
    INFO(c.lab << " " << c.flag);
    Bench b(c.lab);
    std::string script, args;
    for (const auto& [flag, text] : c.before) {
      script += "set " + flag + " " + text + "\n";
      args += " " + flag + "=" + text;
    }
    const fs::path file = dir / (c.lab + ".json");
    const Bench::Ran on = b.run(script + "set " + c.flag + " on\nprint-command\nprint-json\n" +
                                "export-json " + file.string());
    CHECK(value_of(b.e, c.flag) == InputValue(true));
    Inputs inputs = c.before;
    inputs.emplace_back(c.flag, "on");
    std::vector<std::string> command{c.lab};
    for (const auto& [flag, text] : c.before) command.push_back(flag + "=" + text);
    command.push_back(c.flag);
    const std::string json = json_of(*session_at(c.lab, inputs), command);
    CHECK(on.out == c.lab + args + " " + c.flag + "\n" + json);
    CHECK(read_file(file) == json);
    // off, and on again by its name alone (a switch's field with no text)
    CHECK(b.run("set " + c.flag + " off\nprint-command").out == c.lab + args + "\n");
    CHECK(value_of(b.e, c.flag) == InputValue(false));
    CHECK(b.run("set " + c.flag + "\nprint-command").out == c.lab + args + " " + c.flag + "\n");
  }
}

TEST_CASE("explore: seek, speed, play, pause and frames move the motion's time as they say") {
  Bench b("poinsot");
  const double seconds = b.e.session().animation()->seconds;
  REQUIRE(seconds > 30);
  b.run("seek 1.25");
  CHECK(b.e.view().time == 1.25);
  CHECK_FALSE(b.e.view().playing);
  b.run("seek 1000");
  CHECK(b.e.view().time == seconds);
  b.run("speed 2");
  CHECK(b.e.view().speed == 2);
  b.run("speed 1000");
  CHECK(b.e.view().speed == ex::fastest(*b.e.session().animation()));
  b.run("speed 0.1");
  CHECK(b.e.view().speed == 0.1);

  // `play S` plays S s of the motion, a frame 1/30 s of it at the speed set
  int playing = 0;
  const auto count = [&] { playing += b.e.view().playing ? 1 : 0; };
  b.run("seek 0\nspeed 1\nplay 2.5", count);
  CHECK(playing == 75);
  CHECK(b.e.view().time == Approx(2.5).epsilon(1e-12));
  CHECK_FALSE(b.e.view().playing);
  playing = 0;
  b.run("seek 0.5\nspeed 2\nplay 2", count);
  CHECK(playing == 30);
  CHECK(b.e.view().time == Approx(2.5).epsilon(1e-12));

  // `frames N` draws N frames more, the motion still
  const int three = b.run("frames 3").frames, ten = b.run("frames 10").frames;
  CHECK(ten - three == 7);
  CHECK(b.e.view().time == Approx(2.5).epsilon(1e-12));

  // `pause` stops a motion the window was playing
  b.e.apply(ex::action::Play{true});
  REQUIRE(b.e.view().playing);
  ex::Script pause = ex::Script::parse("pause\n", "s.txt");
  pause.step(b.e);
  CHECK_FALSE(b.e.view().playing);
}

TEST_CASE("explore: turn, zoom and reset-view set the orbit the scene is seen through") {
  Bench b("poinsot");
  const Scene3D plain = described(b.e);
  b.run("turn 30 -10\nzoom 1.5");
  CHECK(b.e.view().orbit.yaw_deg == 30);
  CHECK(b.e.view().orbit.pitch_deg == -10);
  CHECK(b.e.view().orbit.zoom == 1.5);
  // each adds to the last
  b.run("turn 30 -10\nzoom 2");
  CHECK(b.e.view().orbit.yaw_deg == 60);
  CHECK(b.e.view().orbit.pitch_deg == -20);
  CHECK(b.e.view().orbit.zoom == 3);
  const Scene3D turned = described(b.e);
  CHECK(same_camera(turned.camera, b.e.view().orbit.apply(plain.camera)));
  CHECK_FALSE(same_camera(turned.camera, plain.camera));
  b.run("reset-view");
  CHECK(b.e.view().orbit.is_identity());
  CHECK(same_camera(described(b.e).camera, plain.camera));
  b.run("turn 200 0\nturn 200 0");
  CHECK(b.e.view().orbit.yaw_deg == 40);
}
