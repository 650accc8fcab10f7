// Tests of the GL context: lazy creation, both backends, thread-count independence.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "render_fixtures.h"
#include "rigid/render/context.h"

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

TEST_CASE("context: a live context reports a GL 3.3+ core version", "[render][context]") {
  const ContextInfo& info = context();
  CHECK(context_created());
  CHECK(info.gl_version.find("Core") != std::string::npos);
  CHECK(info.gl_version >= std::string("3.3"));
  CHECK((info.samples == 0 || info.samples >= 2));
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
  const int rc = std::system(("RIGID_GL_BACKEND=nonsense '" + test::self_path() + "' --render-child '" +
                              tmp("never.png").string() + "' 2>/dev/null")
                                 .c_str());
  CHECK(rc != 0);
  CHECK_FALSE(fs::exists(tmp("never.png")));
}
