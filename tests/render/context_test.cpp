// Tests of the GL context: lazy creation, both backends, thread-count independence.
#include "rigid/render/context.h"

#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>

#include "render_fixtures.h"

using namespace rigid::render;
namespace fs = std::filesystem;

namespace {

fs::path tmp(const std::string& name) {
  // One directory per process, so two builds' test runs never share files.
  const fs::path d =
      fs::temp_directory_path() / ("rigid_render_test_ctx_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d / name;
}

}  // namespace

// The context each setting asks for is the one made: the backend named by
// RIGID_GL_BACKEND (OSMesa when unset), the samples of RIGID_GL_SAMPLES (4 by
// default: llvmpipe offers up to 8), and a core profile of at least GL 3.3 read
// as numbers, not compared as strings ("10.0" < "3.3" as text).
TEST_CASE("context: each backend and sample count asked for is the one made, GL 3.3+ core",
          "[render][context]") {
  struct Case {
    const char* env;
    const char* backend;
    int samples;
  };
  for (const Case& c :
       {Case{"RIGID_GL_BACKEND=", "osmesa", 4}, Case{"RIGID_GL_BACKEND=osmesa", "osmesa", 4},
        Case{"RIGID_GL_BACKEND=egl", "egl", 4},
        Case{"RIGID_GL_BACKEND=egl RIGID_GL_SAMPLES=2", "egl", 2},
        Case{"RIGID_GL_BACKEND=osmesa RIGID_GL_SAMPLES=0", "osmesa", 0},
        Case{"RIGID_GL_BACKEND=osmesa RIGID_GL_SAMPLES=1", "osmesa", 0}}) {
    INFO(c.env);
    std::istringstream facts(test::context_in_child(c.env, tmp("context.txt").string()));
    std::string backend, version;
    int samples = -1;
    facts >> backend >> samples >> std::ws;
    std::getline(facts, version);
    CHECK(backend == c.backend);
    CHECK(samples == c.samples);
    INFO("GL_VERSION " << version);
    int major = 0, minor = 0;
    REQUIRE(std::sscanf(version.c_str(), "%d.%d", &major, &minor) == 2);
    CHECK(major * 100 + minor >= 303);
    CHECK(version.find("Core Profile") != std::string::npos);
  }
  CHECK_FALSE(context_created());  // the children's contexts are theirs: none made here
}

TEST_CASE("context: backend names parse, bad names are rejected", "[render][context]") {
  CHECK(parse_backend("OSMesa") == Backend::kOSMesa);
  CHECK(parse_backend("egl") == Backend::kEGL);
  CHECK_THROWS_AS(parse_backend("vulkan"), std::invalid_argument);
}

TEST_CASE("context: OSMesa and EGL draw the same plot", "[render][context][backends]") {
  const Image a = test::render_in_child("RIGID_GL_BACKEND=osmesa", tmp("osmesa.png").string());
  const Image b = test::render_in_child("RIGID_GL_BACKEND=egl", tmp("egl.png").string());
  const ImageDiff d = compare_images(a, b, 16);
  INFO("differing pixels: " << d.differing_pixels << ", max channel diff " << d.max_channel_diff);
  CHECK(d.differing_fraction <= 0.001);
}

TEST_CASE("context: output does not depend on LP_NUM_THREADS", "[render][context][threads]") {
  const Image a = test::render_in_child("LP_NUM_THREADS=1", tmp("t1.png").string());
  const Image b = test::render_in_child("LP_NUM_THREADS=2", tmp("t2.png").string());
  const Image c = test::render_in_child("LP_NUM_THREADS=0", tmp("t0.png").string());
  CHECK(compare_images(a, b, 0).differing_pixels == 0);
  CHECK(compare_images(a, c, 0).differing_pixels == 0);
}

TEST_CASE("context: supersampling fallback draws the same plot closely", "[render][context]") {
  const Image a = test::render_in_child("RIGID_GL_SAMPLES=4", tmp("msaa.png").string());
  const Image b = test::render_in_child("RIGID_GL_SAMPLES=0", tmp("ssaa.png").string());
  // Different antialiasing changes edge pixels only.
  CHECK(compare_images(a, b, 64).differing_fraction <= 0.01);
}

TEST_CASE("context: an impossible backend throws Unavailable in one line", "[render][context]") {
  // RIGID_GL_BACKEND with a bad name fails at creation; run it in a child so
  // this process's context is untouched.
  const int rc = std::system(("RIGID_GL_BACKEND=nonsense '" + test::self_path() +
                              "' --render-child '" + tmp("never.png").string() + "' 2>/dev/null")
                                 .c_str());
  CHECK(rc != 0);
  CHECK_FALSE(fs::exists(tmp("never.png")));
}
