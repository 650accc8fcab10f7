// support::Subprocess as rigidlab and the explorer use it: a child's output read whole
// or as it comes, its exit status, a child that cannot start, one asked to end, and the
// first of several to end, and one that ends with its parent.
#include "rigid/support/subprocess.h"

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <system_error>

using rigid::support::Redirect;
using rigid::support::Subprocess;

namespace {

Subprocess shell(const std::string& line, const Subprocess::Options& options) {
  return Subprocess("/bin/sh", {"sh", "-c", line}, options);
}

}  // namespace

TEST_CASE("subprocess: a child's stdout read to its end, and its exit status") {
  Subprocess child = shell("printf 'one\\ntwo\\n'; echo hidden >&2; exit 3",
                           {Redirect::pipe(), Redirect::null(), nullptr});
  CHECK(child.read_to_end() == "one\ntwo\n");
  CHECK(child.wait() == 3);
  CHECK(child.exit_status() == 3);
}

TEST_CASE("subprocess: a child's stderr read as it comes, and the child asked to end") {
  // the child writes a line, then runs until it is asked to end
  Subprocess child =
      shell("echo progress >&2; exec sleep 600", {Redirect::null(), Redirect::pipe(), nullptr});
  std::string err;
  // read without waiting, as the explorer's frames do, until the line has come (bounded
  // by tries, not by time)
  for (int tries = 0; tries < 10000000 && err.find('\n') == std::string::npos; ++tries) {
    err += child.read_available();
  }
  CHECK(err == "progress\n");
  CHECK_FALSE(child.poll());
  CHECK(child.terminate() == -1);  // ended by SIGTERM, not by an exit
  CHECK(child.poll());
}

TEST_CASE("subprocess: a program that is not there cannot start, and says why") {
  try {
    Subprocess child("/nonexistent/program", {"program"}, {});
    FAIL("it started");
  } catch (const std::system_error& e) {
    CHECK(e.code() == std::errc::no_such_file_or_directory);
  }
}

TEST_CASE("subprocess: a child written into a file, and the first of several to end") {
  std::FILE* file = std::tmpfile();
  REQUIRE(file != nullptr);
  std::vector<Subprocess> children;
  children.push_back(shell("exec sleep 600", {Redirect::null(), Redirect::null(), nullptr}));
  children.push_back(shell("echo written; exit 0", {Redirect::file(::fileno(file)), {}, nullptr}));
  CHECK(Subprocess::wait_any(children) == 1);
  CHECK(children[1].exit_status() == 0);
  std::rewind(file);
  char line[32] = {};
  CHECK(std::fgets(line, sizeof line, file) != nullptr);
  CHECK(std::string(line) == "written\n");
  std::fclose(file);
  // the one left is asked to end when it goes
  CHECK_FALSE(children[0].poll());
}

TEST_CASE("subprocess: a child started to end with its parent ends when the parent is killed") {
  Subprocess::Options options{Redirect::pipe(), Redirect::null()};
  options.end_with_parent = true;
  // started by fork and exec: its output, its exit status and a failed start as before
  Subprocess echo = shell("echo forked; exit 4", options);
  CHECK(echo.read_to_end() == "forked\n");
  CHECK(echo.wait() == 4);
  CHECK_THROWS_AS(Subprocess("/nonexistent/program", {"program"}, options), std::system_error);
  // a parent (this test's child) starts one and is killed by SIGKILL, which no handler
  // sees; this test adopts the orphan (a subreaper) and learns how it ended
  REQUIRE(::prctl(PR_SET_CHILD_SUBREAPER, 1) == 0);
  int ends[2] = {-1, -1};
  REQUIRE(::pipe(ends) == 0);
  const pid_t parent = ::fork();
  REQUIRE(parent >= 0);
  if (parent == 0) {
    Subprocess child = shell("exec sleep 600", {Redirect::null(), Redirect::null(), nullptr,
                                                /*end_with_parent=*/true});
    const pid_t pid = child.pid();
    if (::write(ends[1], &pid, sizeof pid) != sizeof pid) ::_exit(1);
    for (;;) ::pause();
  }
  ::close(ends[1]);
  pid_t orphan = 0;
  REQUIRE(::read(ends[0], &orphan, sizeof orphan) == sizeof orphan);
  ::close(ends[0]);
  REQUIRE(::kill(parent, SIGKILL) == 0);
  REQUIRE(::waitpid(parent, nullptr, 0) == parent);
  int status = 0;
  REQUIRE(::waitpid(orphan, &status, 0) == orphan);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);
  ::prctl(PR_SET_CHILD_SUBREAPER, 0);
}
