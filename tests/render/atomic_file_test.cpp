// Tests of the atomic file writer: complete files or none, never a temporary left.
#include "rigid/render/atomic_file.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

using rigid::render::write_file_atomically;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("rigid_atomic_test_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

int entries(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    (void)e;
    ++n;
  }
  return n;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string message_of(const std::string& path, const std::function<void(std::FILE*)>& write) {
  try {
    write_file_atomically(path, write);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("atomic file: the content arrives whole and no temporary is left", "[render][atomic]") {
  const fs::path dir = fresh_dir("ok");
  const fs::path file = dir / "t.csv";
  write_file_atomically(file.string(), [](std::FILE* f) { std::fputs("t,omega\n0,1\n", f); });
  CHECK(read(file) == "t,omega\n0,1\n");
  // Overwriting replaces the old content; still just the one file.
  write_file_atomically(file.string(), [](std::FILE* f) { std::fputs("new\n", f); });
  CHECK(read(file) == "new\n");
  CHECK(entries(dir) == 1);
  fs::remove_all(dir);
}

TEST_CASE("atomic file: a writer that throws leaves the old file and no temporary",
          "[render][atomic]") {
  const fs::path dir = fresh_dir("throws");
  const fs::path file = dir / "t.csv";
  write_file_atomically(file.string(), [](std::FILE* f) { std::fputs("old\n", f); });
  const std::string msg = message_of(file.string(), [](std::FILE* f) {
    std::fputs("half a fi", f);
    throw std::runtime_error("encoder failed\nbadly");
  });
  // One line naming the file and the reason, the reason's line break flattened.
  CHECK(msg == "cannot write '" + file.string() + "': encoder failed badly");
  CHECK(read(file) == "old\n");
  CHECK(entries(dir) == 1);
  fs::remove_all(dir);
}

TEST_CASE("atomic file: a failed rename removes the temporary", "[render][atomic]") {
  // The target is a directory: the temporary is written, rename() fails.
  const fs::path dir = fresh_dir("rename");
  fs::create_directories(dir / "taken");
  const std::string msg =
      message_of((dir / "taken").string(), [](std::FILE* f) { std::fputs("x", f); });
  CHECK(msg.rfind("cannot write '" + (dir / "taken").string() + "': ", 0) == 0);
  CHECK(entries(dir) == 1);  // just the directory that was in the way
  fs::remove_all(dir);
}

TEST_CASE("atomic file: an unwritable place throws one line, even for a name with a line break",
          "[render][atomic]") {
  const std::string path = "/nonexistent-rigid-dir/a\nb.csv";
  const std::string msg = message_of(path, [](std::FILE* f) { std::fputs("x", f); });
  CHECK(msg == "cannot write '/nonexistent-rigid-dir/a b.csv': No such file or directory");
  CHECK(msg.find('\n') == std::string::npos);
  CHECK_FALSE(fs::exists("/nonexistent-rigid-dir"));
}
