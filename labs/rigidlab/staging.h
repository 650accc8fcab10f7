// rigidlab figures' staging folder: every lab's figures land in --out together or not
// at all (labs/rigidlab/main.cpp).
#pragma once

#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>
#include <vector>

#include "rigid/support/text.h"

namespace rigid::front_door {
namespace fs = std::filesystem;

// The entries of a folder; `ec` says why a listing failed or stopped (increment(ec):
// a range-for's ++ would throw on a folder that fails mid-listing).
inline std::vector<fs::path> entries_of(const fs::path& dir, std::error_code& ec) {
  std::vector<fs::path> out;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    out.push_back(it->path());
  return out;
}

// Every lab's figures land in `out` together or not at all: the labs draw into a
// staging folder, OUT/.rigidlab-stage-PID-XXXXXX, whose files are renamed into `out`
// only once every lab has succeeded. A failure or a signal removes the staging folder,
// and the folders this run made for `out` if they are left empty.
//
// The staging folder is made here, not by a lab: a lab that fails removes the folders
// it made, and would take the staging folder from under the others. It is made by
// mkdtemp, under a name no folder had: one already there (a killed run's, whose PID
// this run may have been given) is never this run's to fill or remove. If it cannot
// be made, the first lab is given its name and says why, by its own rules for --figures.
class Staging {
 public:
  explicit Staging(const std::string& out) : out_(out) {
    std::error_code ec;
    // the outermost folder of `out` missing now is the first this run makes (a dangling
    // link is there: not this run's to remove)
    for (fs::path p = top();
         !p.empty() && fs::symlink_status(p, ec).type() == fs::file_type::not_found;
         p = p.parent_path()) {
      made_from_ = p;
      if (p == p.parent_path()) break;
    }
    fs::create_directories(out, ec);
    std::string name =
        (fs::path(out) / (".rigidlab-stage-" + std::to_string(::getpid()) + "-XXXXXX")).string();
    ::mkdtemp(name.data());
    dir_ = name;
  }
  const std::string& dir() const { return dir_; }
  // A lab's message about the staging folder, said of `out`, in both forms a lab's
  // line may show a path: escaped (terminal_safe) or, in a file writer's message,
  // with control characters as spaces first.
  std::string said_of_out(std::string text) const {
    const auto spaced = [](std::string s) {
      for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
      return s;
    };
    for (const bool space : {false, true}) {
      const std::string from = rigid::support::terminal_safe(space ? spaced(dir_) : dir_);
      const std::string to = rigid::support::terminal_safe(space ? spaced(out_) : out_);
      for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size()) {
        text.replace(at, from.size(), to);
      }
    }
    return text;
  }
  void discard() const {
    std::error_code ec;
    fs::remove_all(dir_, ec);
    if (made_from_.empty()) return;
    // each folder this run made, innermost first, only if left empty
    for (fs::path p = top(); fs::remove(p, ec) && p != made_from_; p = p.parent_path()) {
    }
  }
  // A staged figure whose place in `out` a directory takes (no rename can replace it):
  // found before any file moves, so that all land or none; "" if there is none.
  std::string blocked() const {
    std::error_code ec;
    for (const fs::path& file : entries_of(dir_, ec)) {
      const fs::path target = fs::path(out_) / file.filename();
      if (fs::is_directory(fs::symlink_status(target, ec)))
        return "'" + target.string() + "' is a directory, not a figure";
    }
    return "";
  }
  // Renames every staged file into `out`; "" or what failed, with how many had landed.
  std::string land() const {
    std::error_code ec;
    const std::vector<fs::path> files = entries_of(dir_, ec);
    if (ec) return "cannot read " + dir_ + ": " + ec.message();
    std::size_t landed = 0;
    for (const fs::path& file : files) {
      if (std::rename(file.c_str(), (fs::path(out_) / file.filename()).c_str()) != 0) {
        const std::string why = std::strerror(errno);
        discard();
        return "moving the figures into " + out_ + " failed after " + std::to_string(landed) +
               " of " + std::to_string(files.size()) + " (" + why + "); those " +
               std::to_string(landed) + " landed";
      }
      ++landed;
    }
    fs::remove(dir_, ec);
    return "";
  }

 private:
  // `out` without a trailing '/', whose parent is the folder it is in
  fs::path top() const {
    const fs::path path(out_);
    return path.has_filename() ? path : path.parent_path();
  }
  std::string out_, dir_;
  fs::path made_from_;  // the outermost folder of `out` this run made; empty if none
};

// Staging folders in `out` of runs killed outright (SIGKILL, a power cut: nothing could
// remove them), said once each for the user to remove: not this run's to delete.
inline void say_left_stages(const std::string& out, const std::string& ours) {
  const std::string stem = ".rigidlab-stage-";
  std::error_code ec;
  for (const fs::path& entry : entries_of(out, ec)) {
    const std::string name = entry.filename().string();
    if (name.rfind(stem, 0) != 0 || entry == fs::path(ours)) continue;
    // named by the PID of the run that made it: one with this run's PID is a killed
    // run's whose PID came round again
    const long pid = std::strtol(name.c_str() + stem.size(), nullptr, 10);
    const bool alive = pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
    if (alive && pid != ::getpid()) continue;
    std::cerr << "rigidlab: warning: figures: " << rigid::support::terminal_safe(entry)
              << " was left by a run that was killed before it could remove it: remove it\n";
  }
}

}  // namespace rigid::front_door
