// Tests of the atomic file writer: complete files or none, never a temporary left.
#include "rigid/render/atomic_file.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>
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

// The wait status of a child process that runs `body` (its exit status the body's
// return value): for what would change or end the test process itself.
int in_child(const std::function<int()>& body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const rlimit no_core{0, 0};  // a signal whose default dumps core (SIGQUIT) leaves none
    ::setrlimit(RLIMIT_CORE, &no_core);
    ::_exit(body());
  }
  int status = -1;
  ::waitpid(pid, &status, 0);
  return status;
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

TEST_CASE("atomic file: one transaction never writes one file twice, whatever the spelling",
          "[render][atomic]") {
  // Three spellings of one file (a dot, a folder and its "..", a link to the folder):
  // the second and third writes are refused before they touch anything, and only the
  // first lands.
  const fs::path dir = fresh_dir("twice");
  fs::create_directories(dir / "x");
  fs::create_directory_symlink(dir, dir / "link");
  const auto text = [](const char* t) { return [t](std::FILE* f) { std::fputs(t, f); }; };
  {
    rigid::render::FileTransaction files;
    write_file_atomically((dir / "f.csv").string(), text("first"));
    for (const fs::path& again :
         {dir / "." / "f.csv", dir / "x" / ".." / "f.csv", dir / "link" / "f.csv"}) {
      const std::string msg = message_of(again.string(), text("again"));
      CHECK(msg ==
            "cannot write '" + again.string() + "': another output of this run is the same file");
    }
    // a file beside it is another file
    write_file_atomically((dir / "g.csv").string(), text("second"));
    files.commit();
  }
  CHECK(read(dir / "f.csv") == "first");
  CHECK(read(dir / "g.csv") == "second");
  CHECK(entries(dir) == 4);  // f.csv, g.csv, x, link: no temporary left
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

TEST_CASE("atomic file: a file past the size limit is a failed write, not a death by SIGXFSZ",
          "[render][atomic]") {
  const fs::path dir = fresh_dir("fsize");
  const fs::path file = dir / "big.csv";
  // ulimit -f 4 (4 KiB) in a child, which writes 64 KiB: EFBIG, one line, no temporary.
  const int status = in_child([&] {
    const rlimit small{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &small);
    const std::string msg = message_of(file.string(), [](std::FILE* f) {
      const std::string block(1024, 'x');
      for (int k = 0; k < 64; ++k) std::fwrite(block.data(), 1, block.size(), f);
    });
    const bool said = msg == "cannot write '" + file.string() + "': File too large";
    return said && entries(dir) == 0 ? 0 : 1;
  });
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(entries(dir) == 0);
  fs::remove_all(dir);
}

TEST_CASE("atomic file: a terminating signal mid-write removes the temporary and kills by it",
          "[render][atomic]") {
  const fs::path dir = fresh_dir("signal");
  // The writer itself raises the signal while its temporary is held: no timing involved.
  // (SIGINT and SIGTERM are the test runner's own to handle; the labs' tests send them.)
  for (const int sig : {SIGHUP, SIGQUIT, SIGALRM, SIGUSR1}) {
    INFO("signal " << sig);
    const int status = in_child([&] {
      write_file_atomically((dir / "f.csv").string(), [&](std::FILE* f) {
        std::fputs("half a fi", f);
        std::fflush(f);
        std::raise(sig);
      });
      return 0;
    });
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == sig);
    CHECK(entries(dir) == 0);
  }
  fs::remove_all(dir);
}
