// Catch2 runner for render_test. Run as `render_test --render-child FILE` it
// instead draws the reference plot to FILE and exits, and as `render_test
// --context-child FILE` it writes the facts of its context to FILE: the GL
// context is one per process, so tests that need another backend, sample count
// or thread count use a child.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "catch_runner.h"
#include "render_fixtures.h"
#include "rigid/render/context.h"
#include "rigid/render/draw.h"
#include "rigid/render/png.h"

namespace rigid::render::test {

std::string self_path() {
  char buf[4096];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) throw std::runtime_error("cannot find /proc/self/exe");
  buf[n] = '\0';
  return buf;
}

Image render_in_child(const std::string& env, const std::string& png_path) {
  const std::string cmd = env + " '" + self_path() + "' --render-child '" + png_path + "'";
  const int rc = std::system(cmd.c_str());
  if (rc != 0) throw std::runtime_error("child failed (" + std::to_string(rc) + "): " + cmd);
  return read_png(png_path);
}

std::string context_in_child(const std::string& env, const std::string& path) {
  const std::string cmd = env + " '" + self_path() + "' --context-child '" + path + "'";
  const int rc = std::system(cmd.c_str());
  if (rc != 0) throw std::runtime_error("child failed (" + std::to_string(rc) + "): " + cmd);
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

}  // namespace rigid::render::test

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "--render-child") == 0) {
    try {
      // through GL: these children compare the GL backends, sample counts and threads
      rigid::render::write_png(
          rigid::render::draw_gl(rigid::render::test::reference_plot(), 800, 600), argv[2]);
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "render child: " << e.what() << "\n";
      return 1;
    }
  }
  if (argc == 3 && std::strcmp(argv[1], "--context-child") == 0) {
    try {
      const rigid::render::ContextInfo& info = rigid::render::context();
      std::ofstream(argv[2]) << rigid::render::backend_name(info.backend) << ' ' << info.samples
                             << ' ' << info.gl_version << '\n';
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "context child: " << e.what() << "\n";
      return 1;
    }
  }
  return rigid::test::run_catch(argc, argv);
}
