// Two runs side by side in one folder: each lands its own files whole, neither removes
// or replaces what the other holds or made, and a run's sweep of stale temporaries
// (render/atomic_file.h) leaves a live run's temporaries alone. Every run's files are
// compared byte for byte with what the same command writes alone.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "lab_common.h"

namespace fs = std::filesystem;
using rigid::test::Background;

namespace {

// A folder's entries, name to bytes (anything but a regular file marked as such).
using Files = std::map<std::string, std::string>;
// A lab's command line, writing into the folder given.
using Command = std::function<std::vector<std::string>(const fs::path&)>;

constexpr char kMarker[] = ".rigidlab-tmp-";

fs::path fresh_dir(const std::string& name) {
  const fs::path d =
      fs::temp_directory_path() / ("rigid_side_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string lab(const std::string& name) {
  return std::string(RIGID_LAB_DIR) + "/" + name;
}

Files files_in(const fs::path& dir) {
  Files files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (fs::is_symlink(entry.symlink_status()) || !entry.is_regular_file()) {
      files[name] = "(not a regular file)";
      continue;
    }
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    files[name] = bytes.str();
  }
  return files;
}

std::vector<std::string> names(const Files& files) {
  std::vector<std::string> out;
  for (const auto& file : files) out.push_back(file.first);
  return out;
}

// The folder holds exactly `expected`, byte for byte.
void check_files(const fs::path& dir, const Files& expected) {
  const Files found = files_in(dir);
  CHECK(names(found) == names(expected));
  for (const auto& [name, bytes] : expected) {
    INFO(name);
    const auto it = found.find(name);
    CHECK((it != found.end() && it->second == bytes));
  }
}

// The exit status of a run, -1 if a signal ended it.
int finish(Background& run) {
  const int status = run.wait();
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// What `command` writes alone, into a folder of its own.
Files solo(const Command& command) {
  const fs::path dir = fresh_dir("solo");
  Background run(command(dir));
  REQUIRE(finish(run) == 0);
  const Files files = files_in(dir);
  fs::remove_all(dir);
  return files;
}

// The temporaries of process `pid` in `dir`, of either form of the name.
std::vector<std::string> temporaries_of(const fs::path& dir, pid_t pid) {
  const std::string mark = kMarker + std::to_string(pid) + "-";
  std::vector<std::string> out;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.find(mark) != std::string::npos) out.push_back(name);
  }
  return out;
}

// Stops a running program (SIGSTOP) and waits until it is stopped: false if it ended
// first. It stays waitable (WNOWAIT) for Background::wait either way.
bool stop(pid_t pid) {
  ::kill(pid, SIGSTOP);
  siginfo_t info{};
  while (::waitid(P_PID, pid, &info, WSTOPPED | WEXITED | WNOWAIT) != 0) {
    if (errno != EINTR) return false;
  }
  return info.si_code == CLD_STOPPED;
}

// Starts `command` into `dir` and stops it once it holds a temporary whose name starts
// with `held_prefix`: a live run that holds its temporaries for as long as the test needs. One that
// ended before it was stopped (it outran the polling) is run again, at most five times.
std::unique_ptr<Background> stopped_holding(const Command& command, const fs::path& dir,
                                            const std::string& held_prefix) {
  for (int attempt = 0; attempt < 5; ++attempt) {
    auto run = std::make_unique<Background>(command(dir));
    const auto holds = [&] {
      for (const std::string& name : temporaries_of(dir, run->pid()))
        if (name.rfind(held_prefix, 0) == 0) return true;
      return false;
    };
    if (run->wait_until(holds) && stop(run->pid())) return run;
    run->wait();
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  FAIL("the run never held a temporary " << held_prefix << "... long enough to be stopped");
  return nullptr;
}

}  // namespace

TEST_CASE("side by side: two labs writing into one folder at once each land their own", "[draws]") {
  // Two labs, and two runs of one lab with their own --figure-prefix and inputs, started
  // together into one folder that holds a file of the user's.
  const auto run = [](const std::string& name, std::vector<std::string> args,
                      const std::string& csv) -> Command {
    return [=](const fs::path& d) {
      std::vector<std::string> argv = {lab(name),  "--figure-size", "800x600",         "--figures",
                                       d.string(), "--csv",         (d / csv).string()};
      argv.insert(argv.end(), args.begin(), args.end());
      return argv;
    };
  };
  const std::vector<std::pair<Command, Command>> pairs = {
      {run("poinsot", {}, "a.csv"), run("top_nutation", {}, "b.csv")},
      {run("poinsot", {"--figure-prefix", "one-"}, "one.csv"),
       run("poinsot", {"--figure-prefix", "two-", "--inertia", "2,3,4"}, "two.csv")}};
  for (const auto& [first, second] : pairs) {
    Files expected = solo(first);
    const Files theirs = solo(second);
    expected.insert(theirs.begin(), theirs.end());
    expected["notes.txt"] = "the user's\n";
    const fs::path dir = fresh_dir("shared");
    std::ofstream(dir / "notes.txt") << "the user's\n";
    Background a(first(dir)), b(second(dir));
    CHECK(finish(a) == 0);
    CHECK(finish(b) == 0);
    // Every file of both runs, whole; the user's file; no temporary left.
    check_files(dir, expected);
    fs::remove_all(dir);
  }
}

TEST_CASE("side by side: a run that starts while another holds temporaries leaves them",
          "[draws]") {
  // Two runs of poinsot with the same outputs and other inputs: an animation named too
  // long for the temporary's suffix (its temporary is the hidden short form beside it,
  // which every writer in the folder sweeps), the figures and the CSV. The first is
  // stopped once it holds a figure's temporary (its animation's held since before): a
  // live run, its temporaries of both forms beside the second run's targets.
  const std::string animation = std::string(240, 'a') + ".webp";
  const auto run = [&](const std::string& inertia) -> Command {
    return [=](const fs::path& d) {
      return std::vector<std::string>{lab("poinsot"),
                                      "--inertia",
                                      inertia,
                                      "--animate",
                                      (d / animation).string(),
                                      "--duration",
                                      "0.2",
                                      "--fps",
                                      "10",
                                      "--animation-size",
                                      "320x240",
                                      "--figure-size",
                                      "800x600",
                                      "--figures",
                                      d.string(),
                                      "--csv",
                                      (d / "c.csv").string()};
    };
  };
  const Command first = run("1,2,3"), second = run("2,3,4");
  const Files alone_first = solo(first), alone_second = solo(second);
  REQUIRE((alone_first.at("c.csv") != alone_second.at("c.csv")));
  const fs::path dir = fresh_dir("held");
  const std::unique_ptr<Background> a = stopped_holding(first, dir, "poinsot_");
  const std::vector<std::string> held = temporaries_of(dir, a->pid());
  const auto hidden = [](const std::string& name) { return name.rfind(kMarker, 0) == 0; };
  REQUIRE(std::any_of(held.begin(), held.end(), hidden));   // the animation's
  REQUIRE(!std::all_of(held.begin(), held.end(), hidden));  // a figure's

  Background b(second(dir));
  CHECK(finish(b) == 0);
  // The second run landed all its files whole, beside the first's temporaries, all kept.
  Files landed = files_in(dir);
  for (const std::string& name : held) {
    INFO(name);
    CHECK(landed.erase(name) == 1);
  }
  CHECK(names(landed) == names(alone_second));
  for (const auto& [name, bytes] : alone_second) {
    INFO(name);
    CHECK((landed[name] == bytes));
  }
  // The first, let go, lands its own over them: every file the first run's whole.
  ::kill(a->pid(), SIGCONT);
  CHECK(finish(*a) == 0);
  check_files(dir, alone_first);
  fs::remove_all(dir);
}

TEST_CASE("side by side: runs of one lab to one --csv at once leave one run's whole file") {
  // Four runs with their own inputs write one CSV of some 1.5 MB each, started together,
  // three times over: each run exits 0, and the file is one of the four whole, never a
  // mix, with no temporary left.
  const std::vector<std::string> inertias = {"1,2,3", "2,3,4", "1,3,4", "2,2.5,4"};
  const auto run = [](const std::string& inertia) -> Command {
    return [=](const fs::path& d) {
      return std::vector<std::string>{
          lab("poinsot"), "--inertia", inertia, "--periods", "40", "--csv", (d / "c.csv").string()};
    };
  };
  std::vector<std::string> alone;
  for (const std::string& inertia : inertias) alone.push_back(solo(run(inertia)).at("c.csv"));
  for (int round = 0; round < 3; ++round) {
    INFO("round " << round);
    const fs::path dir = fresh_dir("one_csv");
    std::vector<std::unique_ptr<Background>> runs;
    for (const std::string& inertia : inertias)
      runs.push_back(std::make_unique<Background>(run(inertia)(dir)));
    for (auto& r : runs) CHECK(finish(*r) == 0);
    const Files found = files_in(dir);
    // the CSV and its metadata (the same for each: one lab, one file name)
    CHECK(names(found) == std::vector<std::string>{"c.csv", "c.csv-metadata.json"});
    const std::string bytes = found.count("c.csv") ? found.at("c.csv") : "";
    CHECK(std::count(alone.begin(), alone.end(), bytes) == 1);
    fs::remove_all(dir);
  }
}
