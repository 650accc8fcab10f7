// Runs a lab executable as a student would and captures what it prints.
#pragma once

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <catch2/catch.hpp>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace rigid::test {

/// Every lab, in section order, from labs/CMakeLists.txt's one list.
inline std::vector<std::string> all_labs() {
  std::vector<std::string> labs;
  std::stringstream list(RIGID_LABS);
  for (std::string lab; std::getline(list, lab, ',');) labs.push_back(lab);
  return labs;
}

struct Run {
  int status = -1;
  std::string out, err;
  nlohmann::json json() const { return nlohmann::json::parse(out); }
  // Bad input prints exactly one line on stderr.
  bool one_error_line() const { return !err.empty() && err.find('\n') == err.size() - 1; }
};

inline Run run_lab(const std::string& lab, const std::string& args, const std::string& env = "") {
  const std::string err_file =
      "/tmp/rigid_lab_test_" + std::to_string(::getpid()) + "_" + lab + ".err";
  const std::string command =
      env + " " + std::string(RIGID_LAB_DIR) + "/" + lab + " " + args + " 2>" + err_file;
  Run run;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer{};
  size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    run.out.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_file);
  std::stringstream text;
  text << err.rdbuf();
  run.err = text.str();
  std::remove(err_file.c_str());
  return run;
}

/// A program running in the background, its output discarded, for a test that acts
/// on it mid-run: a signal once a file shows, never after a fixed sleep, so that the
/// verdict is the same on a fast machine and a busy one.
class Background {
 public:
  explicit Background(std::vector<std::string> argv) : argv_(std::move(argv)) {
    std::vector<char*> args;
    for (std::string& a : argv_) args.push_back(a.data());
    args.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    // Every signal at its default, as from a terminal: a test run in a shell's background
    // job would otherwise pass on SIGINT and SIGQUIT ignored, and the lab keeps that.
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t all;
    sigfillset(&all);
    posix_spawnattr_setsigdefault(&attributes, &all);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
    if (::posix_spawn(&pid_, args[0], &actions, &attributes, args.data(), environ) != 0) pid_ = -1;
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
  }
  Background(const Background&) = delete;
  Background& operator=(const Background&) = delete;
  ~Background() {
    if (pid_ > 0 && status_ < 0) {
      ::kill(pid_, SIGKILL);
      wait();
    }
  }
  pid_t pid() const { return pid_; }

  /// Polls `ready()` while the program runs: true once it holds, false when the
  /// program ended first (then the moment to act on it never came).
  template <class Ready>
  bool wait_until(Ready ready) {
    while (pid_ > 0) {
      if (ready()) return true;
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        status_ = status;
        return false;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
  }

  /// Its wait status, once it has ended.
  int wait() {
    if (status_ < 0 && pid_ > 0) {
      int status = 0;
      while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
      status_ = status;
    }
    return status_;
  }

 private:
  std::vector<std::string> argv_;
  pid_t pid_ = -1;
  int status_ = -1;
};

/// A CSV file a lab wrote: its header line, its rows of numbers, and the CSV on the
/// Web metadata beside it (FILE-metadata.json; null if there is none).
struct Csv {
  std::string header;
  std::vector<std::vector<double>> rows;
  nlohmann::json metadata;
  /// The metadata's column `name`: its "dc:description" and "schema:unitText".
  nlohmann::json column(const std::string& name) const {
    for (const auto& c : metadata["tableSchema"]["columns"]) {
      if (c["name"] == name) return c;
    }
    return nullptr;
  }
};
inline Csv read_csv(const std::string& path) {
  Csv csv;
  std::ifstream in(path);
  std::getline(in, csv.header);  // the header first: no line before it
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    csv.rows.push_back(std::move(row));
  }
  std::ifstream metadata(path + "-metadata.json");
  if (metadata) csv.metadata = nlohmann::json::parse(metadata);
  return csv;
}

/// Bad input: each (arguments, option) case exits 2 with one line on stderr,
/// "<lab>: error: <option>...", and prints nothing on stdout.
template <class Cases>
void check_bad_inputs(const std::string& lab, const Cases& cases) {
  for (const auto& [args, option] : cases) {
    INFO(args);
    const Run run = run_lab(lab, args);
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.rfind(lab + ": error: " + option, 0) == 0);
    CHECK(run.out.empty());
  }
}

}  // namespace rigid::test
