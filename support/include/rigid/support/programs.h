// The programs beside this one: rigidlab runs the labs and the explorer from the
// folder it lives in (bin/ when installed, build/labs/ in a build tree), a lab
// hands --explore to the explorer, the explorer records through a lab.
#pragma once

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace rigid::support {

/// The folder of the running executable (the working folder if /proc cannot say).
inline std::filesystem::path own_directory() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::current_path() : self.parent_path();
}

/// Where the program `name` is: beside this one (an installed tree), else in the build
/// tree's `folder` (labs/ or explore/) beside this one's.
inline std::filesystem::path program_path(const std::string& name, const std::string& folder) {
  const std::filesystem::path dir = own_directory();
  std::error_code ec;
  const std::filesystem::path beside = dir / name;
  if (std::filesystem::exists(beside, ec)) return beside;
  return dir.parent_path() / folder / name;
}

/// The explorer (rigidlab-explore).
inline std::filesystem::path explorer_path() {
  return program_path("rigidlab-explore", "explore");
}

/// Replaces this process with `path` run with `args` (args[0] is the name it sees);
/// returns only if that failed, with errno's text.
inline std::string exec(const std::filesystem::path& path, const std::vector<std::string>& args) {
  // execv's argv is of char*: the strings' own buffers, copied here, are writable
  std::vector<std::string> words = args;
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  ::execv(path.c_str(), argv.data());
  return std::strerror(errno);
}

}  // namespace rigid::support
