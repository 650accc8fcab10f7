// Every script command pinned by what it does, in-process and without a window: the
// session's inputs after it, the view's state (time, speed, orbit, the scene and plot
// chosen, the parts hidden), the scene the explorer describes for drawing (its items
// and camera, not its pixels), and every file written, byte for byte the lab's own
// writer's. (Each command's words, counted and typed when read: script_words_test.cpp.)
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "common/session.h"
#include "effects_bench.h"
#include "tire_balancing/tire_balancing.h"

using namespace rigid::test::effects;

TEST_CASE(
    "explore: set and drag and unset and textbook change the session's inputs and its fields") {
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

TEST_CASE("explore: a switch set on is in the command and the JSON and the file exported") {
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

TEST_CASE(
    "explore: seek and speed and play and pause and frames move the motion's time as they say") {
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
  CHECK(ex::fastest(*b.e.session().animation()) == ex::kMaxSpeed);

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

TEST_CASE("explore: a motion too long to watch at 10x plays in 10 s and starts so") {
  Bench b("football");
  b.run("speed 1e6");
  CHECK(b.e.view().speed == ex::kMaxSpeed);
  b.run("set --preset earth");  // its precession, hundreds of days
  const double seconds = b.e.session().animation()->seconds;
  REQUIRE(seconds > ex::kMaxSpeed * ex::kLongMotionPlay);
  CHECK(b.e.view().speed == seconds / ex::kLongMotionPlay);
  b.run("speed 1\nspeed 1e6");
  CHECK(b.e.view().speed == seconds / ex::kLongMotionPlay);
}

TEST_CASE("explore: show-scene and show-plot choose by name what is drawn") {
  {
    Bench b("poinsot");
    const rigid::lab::Session& s = b.e.session();
    b.run("show-scene herpolhode\nshow-plot integrators");
    CHECK(ex::view_choices(s, true).at(b.e.view().scene_choice) == "herpolhode");
    CHECK(ex::view_choices(s, false).at(b.e.view().plot_choice) == "integrators");
    const auto& herpolhode = std::get<Scene3D>(ex::figure_named(s, "herpolhode")->figure);
    const Scene3D shown = described(b.e);
    CHECK(shown.title == herpolhode.title);
    CHECK(shown.objects().size() == herpolhode.objects().size());
    CHECK(ex::shown_plot(s, b.e.view())->title ==
          std::get<rigid::render::Plot2D>(ex::figure_named(s, "integrators")->figure).title);
    b.run("show-scene motion\nshow-plot omega");
    CHECK(b.e.view().scene_choice == 0);
    CHECK(b.e.view().plot_choice == 0);
    CHECK(described(b.e).title == s.report().figure_title(s.animation()->scene(0).title));
    CHECK(ex::shown_plot(s, b.e.view())->title ==
          std::get<rigid::render::Plot2D>(ex::figure_named(s, "omega")->figure).title);
    // a figure of the whole report is had right after new inputs, as the command line
    // draws it at them: the comparison is waited for, not refused for the first look
    for (const char* method : {"rk4", "vern9", "exact"}) {
      INFO(method);
      const Bench::Ran ran =
          b.run(std::string("set --method ") + method + "\nshow-plot integrators");
      CHECK(ran.err.empty());
      CHECK(ex::view_choices(s, false).at(b.e.view().plot_choice) == "integrators");
      CHECK_FALSE(s.pending());
    }
  }
  // the motion's strip by its one word, where the lab has one (one explorer at a time:
  // Dear ImGui's context is one)
  Bench racquet("tennis_racquet");
  const rigid::lab::Session& r = racquet.e.session();
  racquet.run("show-plot growth");
  CHECK(ex::view_choices(r, false).at(racquet.e.view().plot_choice) == "growth");
  racquet.run("seek 1\nshow-plot strip");
  CHECK(racquet.e.view().plot_choice == 0);
  CHECK(ex::shown_plot(r, racquet.e.view())->title == r.animation()->strip(1.0).title);
}

TEST_CASE("explore: a scene or plot or part the lab does not show ends the script with exit 2") {
  Bench b("poinsot");
  const ex::ViewState before = b.e.view();
  const std::vector<std::pair<std::string, std::string>> refused{
      {"show-scene nope", "show-scene: poinsot shows no 'nope'"},
      {"show-plot nope", "show-plot: poinsot shows no 'nope'"},
      {"show-plot strip", "show-plot: poinsot shows no 'strip'"},
      {"hide nope", "hide: the scene shows no part named 'nope'"},
      {"show nope", "show: the scene shows no part named 'nope'"},
  };
  for (const auto& [line, says] : refused) {
    INFO(line);
    const Bench::Ran ran = b.run(line + "\nset --mass 2");
    CHECK(ran.err == "s.txt:1: " + says + "\n");
    CHECK(value_of(b.e, "--mass") == InputValue(M_PI));  // the script ended there
    CHECK(b.e.view().scene_choice == before.scene_choice);
    CHECK(b.e.view().plot_choice == before.plot_choice);
    CHECK(b.e.view().hidden.empty());
  }
  CHECK(b.e.status() == 2);
}

TEST_CASE("explore: every export writes the bytes the lab's own writers give") {
  const fs::path dir = fresh_dir("effects-exports");
  const auto at = [&](const char* name) { return (dir / name).string(); };
  Bench b("poinsot");
  const Bench::Ran ran = b.run(
      "set --omega 1,2,0.5\nturn 20 10\nhide \"energy ellipsoid\"\n"
      "save-figure omega " +
      at("omega.svg") +
      " 400x300\n"
      "save-figure omega " +
      at("omega-1600.svg") +
      "\n"
      "save-figure herpolhode " +
      at("herpolhode.png") +
      " 200x150\n"
      "save-view " +
      at("view.png") +
      " 200x150\n"
      "export-json " +
      at("r.json") + "\nexport-csv " + at("r.csv") +
      "\n"
      "screenshot " +
      at("shot.png") + "\nprint-command\nprint-json");
  CHECK(ran.err.empty());
  const auto lab = session_at("poinsot", {{"--omega", "1,2,0.5"}});
  const std::string json = json_of(*lab, {"poinsot", "--omega=1,2,0.5"});
  CHECK(ran.out == "poinsot --omega=1,2,0.5\n" + json);
  CHECK(read_file(at("r.json")) == json);
  CHECK(read_file(at("r.csv")) == rigid::lab::csv_text(lab->report().time_series()));
  CHECK(read_file(at("r.csv-metadata.json")) ==
        rigid::lab::csv_metadata_text(lab->report().time_series(), at("r.csv"), RIGID_VERSION));

  // the figures, as the lab's --figures draws them
  const auto& omega = std::get<rigid::render::Plot2D>(ex::figure_named(*lab, "omega")->figure);
  rigid::render::save_figure(omega, at("lab-omega.svg"), rigid::render::FigureFormat::kSvg, 400,
                             300);
  rigid::render::save_figure(omega, at("lab-omega-1600.svg"), rigid::render::FigureFormat::kSvg,
                             1600, 1200);
  const auto& herpolhode = std::get<Scene3D>(ex::figure_named(*lab, "herpolhode")->figure);
  rigid::render::write_png(rigid::render::draw(herpolhode, 200, 150), at("lab-herpolhode.png"));
  CHECK(svg_file(at("omega.svg")) == svg_file(at("lab-omega.svg")));
  CHECK(svg_file(at("omega-1600.svg")) == svg_file(at("lab-omega-1600.svg")));
  CHECK(read_file(at("herpolhode.png")) == read_file(at("lab-herpolhode.png")));

  // the view as described: turned, its part hidden, at its size
  ex::SceneCache cache;
  const Scene3D view = cache.view_scene(b.e.session(), b.e.view(), 200, 150);
  CHECK_FALSE(draws(view, "energy ellipsoid"));
  CHECK(b.e.view().orbit.yaw_deg == 20);
  rigid::render::save_png(view, at("lab-view.png"), 200, 150);
  CHECK(read_file(at("view.png")) == read_file(at("lab-view.png")));
  CHECK(rigid::render::read_png(at("view.png")).width == 200);

  // the window's frame, as it read it
  rigid::render::write_png(b.frame_image, at("frame.png"));
  CHECK(read_file(at("shot.png")) == read_file(at("frame.png")));
}

// tire_balancing with its time series and figures taken away: a lab that gives neither,
// as the explorer must expect of a lab (each of today's gives both at every input)
rigid::lab::tire_balancing::Report without_series(const rigid::lab::tire_balancing::Inputs& in) {
  rigid::lab::tire_balancing::Report report = rigid::lab::tire_balancing::program().compute(in);
  report.series({});
  return report;
}
void no_figures(const rigid::lab::tire_balancing::Report&, rigid::lab::FigureSink&) {}

TEST_CASE("explore: an export the lab cannot give ends the script with exit 2 and no file") {
  const fs::path dir = fresh_dir("effects-unavailable");
  const auto at = [&](const char* name) { return (dir / name).string(); };
  auto program = rigid::lab::tire_balancing::program();
  program.compute = without_series;
  program.figures = no_figures;
  std::vector<rigid::lab::LabEntry> labs = rigid::lab::all_labs();
  rigid::lab::LabEntry no_series = rigid::lab::lab_entry(&rigid::lab::tire_balancing::program);
  no_series.name = "no_series";
  no_series.make = [program] {
    auto p = program;
    p.name = "no_series";
    return rigid::lab::make_session(p);
  };
  labs.push_back(no_series);
  struct Case {
    std::string lab, line, says;
  };
  for (const Case& c :
       {Case{"poinsot", "save-figure nope " + at("a.png"),
             "save-figure: poinsot has no figure named 'nope'"},
        Case{"lamina_tensor", "record " + at("a.mp4"),
             "record: lamina_tensor has no motion to record"},
        Case{"no_series", "save-view " + at("a.png"), "save-view: this lab draws no 3D scene"},
        Case{"no_series", "export-csv " + at("a.csv"),
             "export-csv: this run has no time series"}}) {
    INFO(c.line);
    Bench b(c.lab, labs);
    const Bench::Ran ran = b.run(c.line + "\nprint-command");
    CHECK(ran.err == "s.txt:1: " + c.says + "\n");
    CHECK(ran.out.empty());  // the script ended there
    CHECK(b.e.status() == 2);
    CHECK(fs::is_empty(dir));
  }
  // the lab without a series still exports its JSON
  Bench b("no_series", labs);
  CHECK(b.run("export-json " + at("r.json")).err.empty());
  CHECK(b.e.status() == 0);
  CHECK(fs::exists(at("r.json")));
}

TEST_CASE("explore: lab opens another lab and quit ends the script and wait and wait-for hold it") {
  Bench b("poinsot");
  // `lab` last: the script's end waits for the lab it asked for, as a next command would
  b.run("hide \"energy ellipsoid\"\nshow-scene herpolhode\nturn 10 0\nlab top_nutation");
  const rigid::lab::Session& s = b.e.session();
  CHECK(s.name() == "top_nutation");
  CHECK(s.at_textbook());
  REQUIRE(b.e.view().fields.size() == s.input_count());
  CHECK(field_of(b.e, "--mass").text == "2");
  CHECK(b.e.view().hidden.empty());
  CHECK(b.e.view().scene_choice == 0);
  CHECK(b.e.view().orbit.is_identity());
  CHECK_FALSE(b.e.view().playing);
  // a lab without motion: play draws its frames, the time stays 0
  b.run("lab lamina_tensor\nplay 1\nseek 3\nframes 0");
  CHECK(b.e.session().name() == "lamina_tensor");
  CHECK(b.e.view().time == 0);
  CHECK_FALSE(b.e.view().playing);

  const Bench::Ran quit = b.run("quit\nset --mass 2\nprint-command");
  CHECK(b.closed);
  CHECK(quit.out.empty());
  CHECK(value_of(b.e, "--mass") == InputValue(1.0));
  CHECK(b.e.status() == 0);

  // `wait` holds the script, the window live, for its wall time
  ex::Script wait = ex::Script::parse("wait 600\nset --mass 2\n", "s.txt");
  for (int k = 0; k < 5; ++k) {
    CHECK(wait.step(b.e));
    CHECK(wait.waiting());
    b.imgui.frame(b.e);
  }
  CHECK(value_of(b.e, "--mass") == InputValue(1.0));
  // `wait-for` holds it until the file comes
  const fs::path go = fresh_dir("effects-wait") / "go";
  ex::Script wait_for = ex::Script::parse("wait-for " + go.string() + "\nset --mass 2\n", "s.txt");
  for (int k = 0; k < 5; ++k) {
    CHECK(wait_for.step(b.e));
    CHECK(wait_for.waiting());
  }
  CHECK(value_of(b.e, "--mass") == InputValue(1.0));
  std::ofstream(go) << "";
  CHECK(wait_for.step(b.e));
  CHECK_FALSE(wait_for.waiting());
  CHECK(value_of(b.e, "--mass") == InputValue(2.0));
  CHECK_FALSE(wait_for.step(b.e));
  CHECK(wait_for.status() == 0);

  // A command after `lab` acts on the lab it opened, never on the one left.
  b.run("lab top_nutation\nset --mass 2.5");
  CHECK(b.e.session().name() == "top_nutation");
  CHECK(value_of(b.e, "--mass") == InputValue(2.5));
}

TEST_CASE("explore: wait and wait-for keep their time on a clock the test moves") {
  Bench b("poinsot");
  const fs::path dir = fresh_dir("effects-clock");
  b.run("set --mass 2");
  // On a clock the test moves: `wait 30` holds the script until 30 s have passed, and a
  // file awaited that does not come within the script's 600 s of waiting ends it, exit 1
  // (nothing the script asked was wrong: what it waited for did not happen).
  using Clock = std::chrono::steady_clock;
  Clock::time_point now{};
  const auto clock = [&now] { return now; };
  ex::Script timed = ex::Script::parse("wait 30\nset --mass 3\n", "s.txt");
  timed.clock_from(clock);
  CHECK(timed.step(b.e));
  now += std::chrono::seconds(29);
  CHECK(timed.step(b.e));
  CHECK(value_of(b.e, "--mass") == InputValue(2.0));
  now += std::chrono::seconds(1);
  CHECK(timed.step(b.e));  // the wait ends, and `set` comes in the same step
  CHECK(value_of(b.e, "--mass") == InputValue(3.0));
  std::ostringstream said;
  ex::Script never =
      ex::Script::parse("wait-for " + (dir / "never").string() + "\nset --mass 4\n", "s.txt");
  never.clock_from(clock);
  never.errors_to(said, "rigidlab-explore");
  CHECK(never.step(b.e));
  now += std::chrono::seconds(599);
  CHECK(never.step(b.e));
  now += std::chrono::seconds(2);
  CHECK_FALSE(never.step(b.e));
  CHECK(never.status() == 1);
  CHECK(said.str().find("wait-for: '") != std::string::npos);
  CHECK(said.str().find("' did not come within the script's wait of 600 s in all") !=
        std::string::npos);
  CHECK(value_of(b.e, "--mass") == InputValue(3.0));
}

TEST_CASE("explore: record writes the motion the lab's own --animate writes") {
  // the explorer as a program (its recording's lab is beside it), under Xvfb
  const fs::path dir = fresh_dir("effects-record");
  const Run run = run_explorer(
      "poinsot", "set --omega 1,2,0.5\nrecord " + (dir / "explorer.webp").string() + "\n", dir);
  INFO(run.err);
  REQUIRE(run.status == 0);
  const Run lab =
      run_lab("poinsot", "--omega=1,2,0.5 --animate " + (dir / "lab.webp").string() + " --quiet");
  INFO(lab.err);
  REQUIRE(lab.status == 0);
  CHECK(read_file(dir / "explorer.webp").size() > 1000);
  CHECK(read_file(dir / "explorer.webp") == read_file(dir / "lab.webp"));
}
