// The command as pbrt's cmd/pbrt.cpp is: argv into the options and the lab's inputs
// (command_line.h), the outputs written (command_outputs.h), and what went wrong said
// in one line with its exit status.
#include "common/command.h"

#include <csignal>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "common/command_line.h"
#include "common/command_outputs.h"
#include "rigid/support/memory.h"
#include "rigid/support/programs.h"
#include "rigid/support/text.h"

namespace rigid::lab {
namespace {

// LAB --explore ...: the explorer opens the lab with the other options as its inputs.
int explore(const std::string& name, int argc, char** argv, int at) {
  namespace fs = std::filesystem;
  const fs::path path = support::explorer_path();
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    std::cerr << name
              << ": error: --explore: this build has no explorer (it is built where "
                 "libglfw3-dev and libimgui-dev are installed)\n";
    return 2;
  }
  // named as the lab, so that its messages ("LAB: error: ...") read as the lab's
  std::vector<std::string> args{name, name};
  for (int k = 1; k < argc; ++k) {
    if (k != at) args.emplace_back(argv[k]);
  }
  const std::string why = support::exec(path, args);
  std::cerr << name << ": error: --explore: cannot run " << support::terminal_safe(path.string())
            << " (" << why << ")\n";
  return 1;
}

}  // namespace

int run_command(const std::string& name, const std::string& title,
                const std::vector<BoundInput>& inputs, const std::string& csv, bool animation,
                int argc, char** argv, const std::function<Computed()>& compute) {
  for (int k = 1; k < argc; ++k) {
    if (std::strcmp(argv[k], "--explore") == 0) return explore(name, argc, argv, k);
  }
  // A run that draws makes buffers of tens of MB: malloc's huge pages make them cheap.
  for (int k = 1; k < argc; ++k) {
    if (std::strncmp(argv[k], "--figures", 9) == 0 || std::strncmp(argv[k], "--animate", 9) == 0) {
      support::restart_with_huge_pages(argv);
      break;
    }
  }
  // A closed pipe, or a file past the size limit (ulimit -f), is a failed write to
  // report, not a silent death by SIGPIPE or SIGXFSZ.
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
  CommandLine line(name, title, inputs, csv, animation);
  try {
    if (const auto answered = line.parse(argc, argv)) return stdout_written(name, *answered);
    return write_outputs(line.options(), compute);
  } catch (const InputError& e) {
    std::cerr << name << ": error: " << support::terminal_safe(line.message(e)) << '\n';
    return 2;
  } catch (const std::exception& e) {
    // A rule of core's broken where the lab named no input (or a failure it did
    // not foresee): the inputs given are to blame, the first physical one named.
    std::cerr << name << ": error: " << support::terminal_safe(line.message(e)) << '\n';
    return 2;
  }
}

}  // namespace rigid::lab
