// The explorer held in-process for the effects tests (script_effects_test.cpp,
// view_effects_test.cpp): a bench, and what a command's effect is read from.
#pragma once

#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <functional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "common/registry.h"
#include "common/session.h"
#include "common/writers.h"
#include "explore_common.h"
#include "explorer.h"
#include "rigid/render/draw.h"
#include "rigid/render/png.h"
#include "scene_cache.h"
#include "script.h"
#include "tire_balancing/tire_balancing.h"

namespace rigid::test::effects {

using namespace rigid::test;
namespace ex = rigid::explore;
using rigid::lab::InputValue;
using rigid::render::Scene3D;

using Inputs = std::vector<std::pair<std::string, std::string>>;

// What the command line computes for `lab` at `inputs` (each its flag and text): a
// session of its own, whole.
inline std::unique_ptr<rigid::lab::Session> session_at(const std::string& lab,
                                                       const Inputs& inputs) {
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
inline std::string json_of(const rigid::lab::Session& s, const std::vector<std::string>& command) {
  rigid::lab::RunOutputs outputs;
  outputs.command = command;
  std::ostringstream text;
  rigid::lab::write_json(text, s.report(), outputs, RIGID_VERSION);
  return text.str();
}

inline InputValue value_of(const ex::Explorer& e, const std::string& flag) {
  const std::size_t i = e.session().find(flag);
  REQUIRE(i < e.session().input_count());
  return e.session().value(i);
}
inline const ex::Field& field_of(const ex::Explorer& e, const std::string& flag) {
  return e.view().fields.at(e.session().find(flag));
}

// Whether any surface or line of `scene` is labelled `label`.
inline bool draws(const Scene3D& scene, const std::string& label) {
  for (const auto& o : scene.objects())
    if (o.label == label) return true;
  for (const auto& p : scene.polylines())
    if (p.label == label) return true;
  return false;
}

// An SVG file's text, the id cairo numbers its surfaces by in the process made plain (a
// drawing's second surface in one process is "surface11", where a lab's first is "surface1").
inline std::string svg_file(const std::string& path) {
  return std::regex_replace(read_file(path), std::regex("id=\"surface[0-9]+\""), "id=\"surface\"");
}

inline bool same_camera(const rigid::render::Camera& a, const rigid::render::Camera& b) {
  return a.eye == b.eye && a.target == b.target && a.up == b.up && a.fov_y_deg == b.fov_y_deg &&
         a.orthographic == b.orthographic && a.ortho_height == b.ortho_height;
}

// The scene the explorer describes for drawing its view now, at 640x480 (a cache of its
// own, as a fresh view would make it).
inline Scene3D described(const ex::Explorer& e) {
  ex::SceneCache cache;
  return cache.view_scene(e.session(), e.view(), 640, 480);
}

// The explorer held in-process, its window a close flag and a known frame.
struct Bench {
  Headless imgui;
  bool closed = false;
  rigid::render::Image frame_image{8, 6, std::vector<std::uint8_t>(8 * 6 * 3)};
  ex::Explorer e;

  explicit Bench(const std::string& lab,
                 std::vector<rigid::lab::LabEntry> labs = rigid::lab::all_labs())
      : e(std::move(labs), lab,
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

}  // namespace rigid::test::effects
