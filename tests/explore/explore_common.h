// What the explorer's tests share: the explorer run as a program (its script in a file,
// its output and exit status taken), a fresh folder, and the explorer held in-process
// without a window.
#pragma once

#include <imgui.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "explorer.h"
#include "lab_common.h"
#include "rigid/render/context.h"

namespace rigid::test {

namespace fs = std::filesystem;

inline std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(RIGID_BINARY_DIR) / "explore-test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Runs the explorer with `args` (and `script`, if any, as its --script file in `dir`),
// after the shell's `before` ("ulimit -f 64; ", say).
inline Run run_explorer(const std::string& args, const std::string& script = "",
                        const fs::path& dir = fs::temp_directory_path(),
                        const std::string& before = "") {
  std::string command = before + std::string(RIGID_EXPLORER) + " " + args;
  if (!script.empty()) {
    const fs::path file = dir / "session.txt";
    std::ofstream(file) << script;
    command += " --script " + file.string();
  }
  const fs::path err_file = dir / ("explorer-" + std::to_string(::getpid()) + ".err");
  command += " 2>" + err_file.string();
  Run run;
  FILE* pipe = ::popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) run.out.append(buffer, n);
  const int status = ::pclose(pipe);
  run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.err = read_file(err_file);
  fs::remove(err_file);
  return run;
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Whether `file` has come, looked for at most `looks` times (a tenth of a second apart).
inline bool comes(const fs::path& file, int looks) {
  for (int k = 0; k < looks && !fs::exists(file); ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return fs::exists(file);
}

// Dear ImGui without a window: frames built and their draw lists made, the figures drawn
// into an off-screen GL context (render_gl's own).
struct Headless {
  Headless() {
    rigid::render::context();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(1280, 720);
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  }
  ~Headless() { ImGui::DestroyContext(); }
  Headless(const Headless&) = delete;
  Headless& operator=(const Headless&) = delete;
  // One frame of the explorer; whether it drew anything.
  bool frame(rigid::explore::Explorer& e) {
    ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
    ImGui::NewFrame();
    e.frame(1.0 / 60.0);
    ImGui::Render();
    return ImGui::GetDrawData()->CmdListsCount > 0;
  }
};

}  // namespace rigid::test
