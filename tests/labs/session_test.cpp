// Every lab held live (common/session.h), as the explorer holds it: a refused change
// leaves the state as it was and says the rule; the command line a state gives
// reproduces it; a lab computed once from texts given together (session_at) is the
// live session at those inputs; and random slider moves across every lab never leave
// a NaN in what is shown (the report, the figures, the motion), nor crash (the
// sanitizer build runs this too).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <string>
#include <variant>

#include "common/registry.h"
#include "lab_entries.h"
#include "lab_library.h"

using rigid::lab::GivenTexts;
using rigid::lab::InputKind;
using rigid::lab::InputValue;
using rigid::lab::Json;
using rigid::lab::LabEntry;
using rigid::lab::Refusal;
using rigid::lab::Session;
using rigid::test::json_of;
using rigid::test::lab;

namespace {

// Every number in a JSON value is finite (nlohmann writes NaN as null, so the values
// are looked at before writing).
bool all_finite(const Json& j) {
  if (j.is_number_float()) return std::isfinite(j.get<double>());
  if (j.is_array() || j.is_object()) {
    for (const auto& item : j) {
      if (!all_finite(item)) return false;
    }
  }
  return true;
}

bool finite_scene(const rigid::render::Scene3D& scene) {
  for (const auto& o : scene.objects()) {
    if (!o.transform.matrix().allFinite()) return false;
  }
  for (const auto& p : scene.polylines()) {
    for (const auto& point : p.points) {
      if (!point.allFinite()) return false;
    }
  }
  return scene.camera.eye.allFinite() && scene.camera.target.allFinite();
}

bool finite_plot(const rigid::render::Plot2D& plot) {
  for (int r = 0; r < plot.rows(); ++r) {
    for (int c = 0; c < plot.cols(); ++c) {
      for (const auto& series : plot.panel(r, c).series) {
        for (double x : series.x) {
          if (std::isnan(x)) return false;
        }
        for (double y : series.y) {
          if (std::isnan(y)) return false;
        }
      }
    }
  }
  return true;
}

// What a view of the session shows is finite: the report, each figure, the motion at
// its start, middle and end.
void check_shown(const Session& s) {
  INFO(s.name() << " " << json_of(s).substr(0, 400));
  CHECK(all_finite(s.report().results()));
  for (const auto& f : s.figures()) {
    INFO("figure " << f.name);
    if (f.is_scene()) {
      CHECK(finite_scene(std::get<rigid::render::Scene3D>(f.figure)));
    } else {
      CHECK(finite_plot(std::get<rigid::render::Plot2D>(f.figure)));
    }
  }
  if (const rigid::lab::Animation* motion = s.animation()) {
    REQUIRE(std::isfinite(motion->seconds));
    REQUIRE(motion->seconds > 0);
    for (double share : {0.0, 0.5, 1.0}) {
      INFO("motion at " << share * motion->seconds << " s");
      CHECK(finite_scene(motion->scene(share * motion->seconds)));
      if (motion->strip) CHECK(finite_plot(motion->strip(share * motion->seconds)));
    }
  }
}

// The refusal's message ("" if the texts computed).
std::string refused(const std::string& name, const GivenTexts& given) {
  auto made = lab(name).make_at(given);
  if (const auto* r = std::get_if<Refusal>(&made)) return r->message;
  return "";
}

}  // namespace

TEST_CASE("session: every lab opens at the textbook's example, which needs no argument") {
  for (const auto& entry : rigid::lab::all_labs()) {
    INFO(entry.name);
    const auto s = entry.make();
    CHECK(s->name() == entry.name);
    CHECK(s->at_textbook());
    CHECK(s->arguments().empty());
    CHECK(s->report().textbook_inputs());
    check_shown(*s);
  }
}

TEST_CASE("session: a refused change says the rule and leaves the state as it was") {
  const auto labs = rigid::lab::all_labs();
  const auto open = [&](const std::string& name) {
    for (const auto& e : labs) {
      if (e.name == name) return e.make();
    }
    FAIL("no lab " << name);
    return std::unique_ptr<Session>();
  };
  SECTION("a value its own rule refuses") {
    auto s = open("top_nutation");
    REQUIRE(!s->pending());
    const std::string before = json_of(*s);
    const long generation = s->generation();
    const auto refusal = s->set_text(s->find("--mass"), "-1");
    REQUIRE(refusal);
    CHECK(refusal->message == "--mass: must be positive (got -1)");
    CHECK(refusal->inputs == std::vector<std::string>{"--mass"});
    CHECK(json_of(*s) == before);
    CHECK(s->generation() == generation);
    for (const char* text : {"abc", "nan", "inf", "1e400", "", "2,3"}) {
      INFO(text);
      CHECK(s->set_text(s->find("--mass"), text));
      CHECK(json_of(*s) == before);
    }
  }
  SECTION("inputs that together break a rule of the physics") {
    auto s = open("poinsot");
    const std::string before = json_of(*s);
    // 1 + 1 < 3: no rigid body has these principal moments
    const auto refusal = s->set_text(s->find("--inertia"), "1,1,3");
    REQUIRE(refusal);
    CHECK(refusal->message.find("I1 + I2 >= I3") != std::string::npos);
    CHECK(json_of(*s) == before);
  }
  SECTION("a tilt no balancing mass can undo") {
    auto s = open("tire_balancing");
    const std::string before = json_of(*s);
    CHECK(s->set_text(s->find("--tilt-deg"), "45"));
    CHECK(json_of(*s) == before);
    CHECK(!s->set_text(s->find("--tilt-deg"), "2"));
    CHECK(json_of(*s) != before);
  }
}

TEST_CASE("session: the arguments of a state give that state again, digit for digit") {
  std::mt19937 rng(20261127);
  for (const auto& entry : rigid::lab::all_labs()) {
    auto s = entry.make();
    // a few inputs moved to random places of their sliders
    for (std::size_t i = 0; i < s->input_count(); ++i) {
      const auto& rule = s->rule(i);
      const InputValue book = s->textbook_value(i);
      if (rule.kind() != InputKind::kNumber || !std::holds_alternative<double>(book)) continue;
      const auto span = rigid::lab::slider_span(rule, std::get<double>(book));
      std::uniform_real_distribution<double> u(0.0, 1.0);
      const double x = span.log ? span.lo * std::pow(span.hi / span.lo, u(rng))
                                : span.lo + (span.hi - span.lo) * u(rng);
      s->set(i, x);
    }
    INFO(entry.name);
    s->wait();
    auto again = entry.make();
    const auto args = s->arguments();
    for (const std::string& a : args) {
      const auto eq = a.find('=');
      const std::string flag = eq == std::string::npos ? a : a.substr(0, eq);
      const std::string text = eq == std::string::npos ? "" : a.substr(eq + 1);
      INFO(a);
      CHECK(!again->set_text(again->find(flag), text));
    }
    again->wait();
    CHECK(json_of(*again) == json_of(*s));
  }
}

TEST_CASE("session: 1000 random slider moves across every lab show no NaN and never crash") {
  // Each move sets one input of a random lab to a random place of its slider (a number),
  // a random component of its drag (a vector), a random choice or switch; the lab's rules
  // refuse some; what is shown after each is checked. Seeded: the same moves every run.
  std::mt19937 rng(1000);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto labs = rigid::lab::all_labs();
  std::vector<std::unique_ptr<Session>> sessions;
  for (const auto& e : labs) sessions.push_back(e.make());
  int refused = 0, taken = 0;
  for (int move = 0; move < 1000; ++move) {
    Session& s = *sessions[rng() % sessions.size()];
    const std::size_t i = rng() % s.input_count();
    const auto& rule = s.rule(i);
    const InputValue now = s.value(i), book = s.textbook_value(i);
    InputValue next;
    const auto along = [&](double center) {
      const auto span = rigid::lab::slider_span(rule, center);
      return span.log ? span.lo * std::pow(span.hi / span.lo, u(rng))
                      : span.lo + (span.hi - span.lo) * u(rng);
    };
    switch (rule.kind()) {
      case InputKind::kNumber:
        next = along(std::holds_alternative<double>(book) ? std::get<double>(book) : 1.0);
        break;
      case InputKind::kPair:
      case InputKind::kVector: {
        Eigen::Vector3d v(1, 1, 1);
        if (const auto* x = std::get_if<Eigen::Vector3d>(&now)) v = *x;
        if (const auto* x = std::get_if<Eigen::Vector2d>(&now)) v.head<2>() = *x;
        const int k = static_cast<int>(rng() % (rule.kind() == InputKind::kPair ? 2 : 3));
        v[k] = v[k] * (0.1 + 3 * u(rng)) * (u(rng) < 0.2 ? -1 : 1);
        next = rule.kind() == InputKind::kPair ? InputValue(Eigen::Vector2d(v[0], v[1]))
                                               : InputValue(v);
        break;
      }
      case InputKind::kChoice:
        next = rule.choices()[rng() % rule.choices().size()];
        break;
      case InputKind::kFlag:
        next = u(rng) < 0.5;
        break;
    }
    // now and then an optional input goes back to the lab's own choice
    if (!rule.lab_default_text().empty() && u(rng) < 0.25) next = InputValue();
    const std::string before = json_of(s);
    if (s.set(i, next)) {
      ++refused;
      REQUIRE(json_of(s) == before);
    } else {
      ++taken;
      check_shown(s);
      // now and then the whole report (a lab's slow part, on a second thread) too
      if (u(rng) < 0.05) {
        s.wait();
        CHECK(s.whole_error().empty());
        check_shown(s);
      }
    }
  }
  // most moves along a slider are taken, and the rules refuse some
  CHECK(taken > 500);
  CHECK(refused > 0);
}

TEST_CASE("session: a film's one legend lists every part any of its frames shows") {
  // the command line's --animate and the explorer's live view keep the legend of
  // motion_envelope() in every frame: it must not miss a part that shows between the
  // times it is gathered at
  for (const rigid::lab::LabEntry& entry : rigid::lab::all_labs()) {
    auto session = entry.make();
    session->wait();
    const rigid::lab::Animation* motion = session->animation();
    if (motion == nullptr) continue;
    const std::vector<std::string> listed = rigid::lab::motion_envelope(*motion).legend_labels();
    for (int k = 0; k < 97; ++k) {
      const double t = motion->seconds * k / 97;
      for (const std::string& label : motion->scene(t).legend_labels()) {
        INFO(entry.name << " at t = " << t << " s: " << label);
        CHECK(std::find(listed.begin(), listed.end(), label) != listed.end());
      }
    }
  }
}

TEST_CASE("session_at: every lab at no texts is the textbook's, whole, described alike") {
  for (const LabEntry& e : rigid::lab::all_labs()) {
    INFO(e.name);
    auto made = e.make_at({});
    REQUIRE(std::holds_alternative<std::unique_ptr<Session>>(made));
    const auto& at = *std::get<std::unique_ptr<Session>>(made);
    const auto live = e.make();
    CHECK(!at.pending());
    CHECK(json_of(at) == json_of(*live));
    // the entry describes the inputs as the session holds them, computing nothing
    REQUIRE(e.inputs.size() == live->input_count());
    for (std::size_t i = 0; i < e.inputs.size(); ++i) {
      CHECK(e.inputs[i].rule.flag() == live->rule(i).flag());
      CHECK(e.inputs[i].textbook == live->textbook_value(i));
    }
    CHECK(e.has_motion == (live->animation() != nullptr));
    CHECK(e.title == live->title());
  }
}

TEST_CASE("session_at: texts set together equal the same changes made one at a time") {
  const LabEntry& top = lab("top_nutation");
  auto made = top.make_at({{"--mass", "2"}, {"--spin-rpm", "500"}});
  REQUIRE(std::holds_alternative<std::unique_ptr<Session>>(made));
  auto live = top.make();
  REQUIRE(!live->set_text(live->find("--mass"), "2"));
  REQUIRE(!live->set_text(live->find("--spin-rpm"), "500"));
  live->wait();
  CHECK(json_of(*std::get<std::unique_ptr<Session>>(made)) == json_of(*live));
}

TEST_CASE("session_at: a refusal is the command line's message") {
  // a text the one reader refuses
  CHECK(refused("top_nutation", {{"--mass", "-1"}}) == "--mass: must be positive (got -1)");
  CHECK(refused("top_nutation", {{"--mass", "two"}}).rfind("--mass: ", 0) == 0);
  // not the lab's, or given twice
  CHECK(refused("top_nutation", {{"--mas", "1"}}) == "--mas: not an input of top_nutation");
  CHECK(refused("top_nutation", {{"--mass", "1"}, {"--mass", "2"}}) == "--mass: given twice");
  // a pairing among the options given: alternatives, whatever their values
  CHECK(refused("football", {{"--preset", "earth"}, {"--inertia", "1,1"}}) ==
        "--inertia: replaces the moments of --preset; give one or the other");
  CHECK(refused("football", {{"--omega", "1"}, {"--day", "3"}}) ==
        "--day: give the speed once: --omega or --day");
  // a rule of core's the lab words itself
  CHECK(refused("football", {{"--inertia", "1,3"}}) ==
        "--inertia: principal moments must satisfy the triangle inequality I1 + I2 >= I3, got "
        "1 + 1 < 3");
}

TEST_CASE("session: a body's motion is a unit quaternion and a finite omega from t = 0 on") {
  // every lab with a moving body, at the text's example: the attitude a unit quaternion
  // to the closed form's or the integrator's rounding (checked to 1e-12 over 50 times
  // of its first 10 s), the start refused before t = 0
  for (const LabEntry& e : rigid::lab::all_labs()) {
    INFO(e.name);
    const auto session = std::get<std::unique_ptr<Session>>(e.make_at({}));
    const rigid::lab::BodyMotion motion = session->body_motion();
    CHECK(static_cast<bool>(motion) == (e.name != "lamina_tensor"));
    if (!motion) continue;
    for (int k = 0; k < 50; ++k) {
      const rigid::lab::BodyState s = motion(0.2 * k);
      CHECK(std::abs(s.attitude.norm() - 1.0) < 1e-12);
      CHECK(s.omega_body.allFinite());
    }
    CHECK_THROWS_AS(motion(-1e-9), std::invalid_argument);
  }
}

TEST_CASE("session: a figure described alone is the one figures() describes, named alike") {
  for (const LabEntry& e : rigid::lab::all_labs()) {
    INFO(e.name);
    const auto alone = e.make();  // figures named, then each described by itself
    const auto whole = e.make();  // every figure at once
    alone->wait();
    whole->wait();
    const std::vector<rigid::lab::FigureName> names = alone->figure_names();
    CHECK_FALSE(alone->figures_described());  // naming describes none
    const std::vector<rigid::lab::NamedFigure>& figures = whole->figures();
    REQUIRE(names.size() == figures.size());
    for (std::size_t k = 0; k < names.size(); ++k) {
      INFO(names[k].name);
      CHECK(names[k].name == figures[k].name);
      CHECK(names[k].scene == figures[k].is_scene());
      const rigid::lab::NamedFigure* f = alone->figure(names[k].name);
      REQUIRE(f != nullptr);
      CHECK(f->caption == figures[k].caption);
      REQUIRE(f->is_scene() == figures[k].is_scene());
      if (f->is_scene()) {
        rigid::test::check_same_scene(std::get<rigid::render::Scene3D>(f->figure),
                                      std::get<rigid::render::Scene3D>(figures[k].figure));
      } else {
        CHECK(std::get<rigid::render::Plot2D>(f->figure).title ==
              std::get<rigid::render::Plot2D>(figures[k].figure).title);
      }
    }
    CHECK(alone->figure("no such figure") == nullptr);
  }
}
