// Tests of the atomic file writer: complete files or none, never a temporary left.
#include "rigid/render/atomic_file.h"

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cerrno>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using rigid::render::write_file_atomically;
using rigid::render::write_text_atomically;
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

namespace {

// A process of this user that lives until this object goes: it waits on a pipe that
// closes when the object does.
class LiveProcess {
 public:
  LiveProcess() {
    int fds[2];
    REQUIRE(::pipe(fds) == 0);
    pid_ = ::fork();
    if (pid_ == 0) {
      ::close(fds[1]);
      char c;
      while (::read(fds[0], &c, 1) < 0 && errno == EINTR) {
      }
      ::_exit(0);
    }
    ::close(fds[0]);
    write_end_ = fds[1];
  }
  ~LiveProcess() {
    ::close(write_end_);
    ::waitpid(pid_, nullptr, 0);
  }
  LiveProcess(const LiveProcess&) = delete;
  LiveProcess& operator=(const LiveProcess&) = delete;
  pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
  int write_end_ = -1;
};

// The id of a process that has ended and been reaped: no process has it (ids are
// handed out in turn, and come round again only after pid_max more processes).
pid_t gone_process() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  ::waitpid(pid, nullptr, 0);
  return pid;
}

// A temporary's name for the target `base` ("" for the hidden short form) by process `pid`.
std::string temporary(const std::string& base, const std::string& pid,
                      const std::string& random = "0123456789abcdef") {
  return base + ".rigidlab-tmp-" + pid + "-" + random;
}

}  // namespace

TEST_CASE("atomic file: the sweep removes a dead run's temporaries and nothing else",
          "[render][atomic]") {
  const fs::path dir = fresh_dir("sweep");
  const LiveProcess live;
  const std::string alive = std::to_string(live.pid()), gone = std::to_string(gone_process());
  const std::string self = std::to_string(::getpid());
  // Its process gone: the stale temporaries of this target, by both forms of the name.
  const std::vector<std::string> stale = {temporary("t.csv", gone), temporary("", gone)};
  // A live process's (another of this user's, this one's, pid 1's), of either form.
  std::vector<std::string> kept = {temporary("t.csv", alive), temporary("", alive),
                                   temporary("t.csv", self), temporary("t.csv", "1")};
  // The user's files, their process gone too, a character off our pattern.
  for (const std::string& decoy :
       {temporary("t.csv", gone, "0123456789abcde"), temporary("t.csv", gone, "0123456789abcdef0"),
        temporary("t.csv", gone, "0123456789ABCDEF"), temporary("t.csv", "0" + gone),
        temporary("t.csv", gone) + ".bak", temporary("t.csv", ""), temporary("t.csv", "0"),
        temporary("t.csv", gone + "x"), temporary("t.csv", "12345678901"),
        temporary("t.csv", "9999999999"),  // 10 digits, past any process id (pid_t)
        temporary("t.csv", "-" + gone),
        temporary("t.csv", gone).substr(1 + std::string("t.csv").size()),
        temporary("t.csv", gone, "0123456789abcdeg"),
        "t.csv.rigidlab-tmp-" + gone + "_0123456789abcdef", "t.csv.rigidlab-tmp-" + gone}) {
    kept.push_back(decoy);
  }
  for (const std::string& name : stale) std::ofstream(dir / name) << "partial\n";
  for (const std::string& name : kept) std::ofstream(dir / name) << "the user's\n";
  // Of our exact pattern and their process gone, but not a regular file of this user:
  // a pipe, links (to a file, to nothing), a folder, and another user's file.
  std::vector<std::string> not_files = {
      temporary("t.csv", gone, "000000000000f1f0"), temporary("t.csv", gone, "000000000000f11c"),
      temporary("t.csv", gone, "000000000000dead"), temporary("", gone, "000000000000d1a0")};
  REQUIRE(::mkfifo((dir / not_files[0]).c_str(), 0600) == 0);
  fs::create_symlink(dir / kept.front(), dir / not_files[1]);
  fs::create_symlink(dir / "nowhere", dir / not_files[2]);
  fs::create_directory(dir / not_files[3]);
  if (::geteuid() == 0) {
    const std::string theirs = temporary("t.csv", gone, "00000000000f0e55");
    std::ofstream(dir / theirs) << "another user's\n";
    REQUIRE(::chown((dir / theirs).c_str(), 65534, 65534) == 0);
    not_files.push_back(theirs);
  }

  write_file_atomically((dir / "t.csv").string(), [](std::FILE* f) { std::fputs("new\n", f); });
  CHECK(read(dir / "t.csv") == "new\n");
  for (const std::string& name : stale) {
    INFO(name);
    CHECK_FALSE(fs::exists(fs::symlink_status(dir / name)));
  }
  for (const std::string& name : kept) {
    INFO(name);
    CHECK(read(dir / name) == "the user's\n");
  }
  for (const std::string& name : not_files) {
    INFO(name);
    CHECK(fs::exists(fs::symlink_status(dir / name)));
  }
  // Nothing else: no temporary of this write left either.
  CHECK(entries(dir) == static_cast<int>(1 + kept.size() + not_files.size()));
  fs::remove_all(dir);
}

TEST_CASE("atomic file: the sweep keeps a temporary of another user's live process",
          "[render][atomic]") {
  // kill(pid, 0) says EPERM of a live process this user may not signal: alive, not gone.
  // As root, a child that becomes another user (nobody) writes beside a temporary of
  // its own named with the test's pid (root's, alive); as another user, pid 1's.
  const bool root = ::geteuid() == 0;
  if (!root && ::kill(1, 0) == 0) {
    WARN("pid 1 is this user's here: no process of another user to name");
    return;
  }
  const fs::path dir = fresh_dir("eperm");
  const std::string owner = std::to_string(root ? ::getpid() : 1);
  const fs::path held = dir / temporary("t.csv", owner);
  if (root) REQUIRE(::chown(dir.c_str(), 65534, 65534) == 0);
  const int status = in_child([&] {
    if (root && (::setgid(65534) != 0 || ::setuid(65534) != 0)) return 2;
    std::ofstream(held) << "held\n";
    write_text_atomically((dir / "t.csv").string(), "new\n");
    return read(held) == "held\n" && read(dir / "t.csv") == "new\n" ? 0 : 1;
  });
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  fs::remove_all(dir);
}
