// What a bench program prints: a progress line on stderr while it works and one
// final line (rigid/support/progress.h: live on a terminal, the final line alone
// otherwise, nothing with --quiet), and with --verbose a line per measurement on
// stdout. The numbers themselves go to the JSON, and from there to results.md.
#pragma once

#include <cstdarg>
#include <cstdio>
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

/// Reads --verbose and --quiet from argv[i]; false if it is neither.
inline bool output_option(const std::string& arg) {
  if (arg == "--verbose") return output().verbose = true;
  if (arg == "--quiet") return output().quiet = true;
  return false;
}

}  // namespace bench
