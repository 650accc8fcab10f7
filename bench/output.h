// What a bench program prints: a progress line on stderr while it works and one
// final line (rigid/support/progress.h: live on a terminal, the final line alone
// otherwise, nothing with --quiet), and with --verbose a line per measurement on
// stdout. The numbers themselves go to the JSON, and from there to results.md.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "rigid/support/progress.h"

namespace bench {

struct OutputSettings {
  bool verbose = false;  ///< --verbose: a line per measurement on stdout
  bool quiet = false;    ///< --quiet: no progress line, no final line
};
inline OutputSettings& output() {
  static OutputSettings settings;
  return settings;
}

/// A measurement's line on stdout, with --verbose only (printf's format).
__attribute__((format(printf, 1, 2))) inline void detail(const char* format, ...) {
  if (!output().verbose) return;
  va_list args;
  va_start(args, format);
  std::vprintf(format, args);
  va_end(args);
}

/// What a bench program's command line gives it.
struct Arguments {
  std::filesystem::path dir = ".";  ///< where its JSON goes
  bool quick = false;               ///< --quick: fewer repetitions, for a smoke run
};

/// The command line of a bench program (CLI11): `program` and `what` for --help,
/// the output folder DIR if `takes_dir` (required if `needs_dir`), --quick if
/// `takes_quick`, and --verbose and --quiet (output()). Returns the status to exit
/// with: 0 after --help, 2 after one line naming a bad option and its rule; or -1 to
/// go on.
inline int parse_arguments(int argc, char** argv, const std::string& program,
                           const std::string& what, Arguments& args, bool takes_dir = true,
                           bool takes_quick = true, bool needs_dir = false) {
  CLI::App app(what, program);
  if (takes_dir) {
    auto* dir = app.add_option("DIR", args.dir, "the bench's folder, where its JSON goes")
                    ->type_name("DIR");
    if (needs_dir)
      dir->required();
    else
      dir->capture_default_str();
  }
  if (takes_quick) app.add_flag("--quick", args.quick, "fewer repetitions: a smoke run");
  app.add_flag("--verbose", output().verbose, "a line per measurement on stdout");
  app.add_flag("--quiet", output().quiet, "no progress line, no final line");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << program << ": error: " << e.what() << " (see --help)\n";
    return 2;
  }
  return -1;
}

}  // namespace bench
