// Runs a lab executable as a student would and captures what it prints.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
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

}  // namespace rigid::test
