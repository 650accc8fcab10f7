// Catch2's implementation without a main: compiled once, for the default main
// (test_main.cpp) and for render_test's own.
#define CATCH_CONFIG_RUNNER
#include "catch_runner.h"

#include <catch2/catch.hpp>

namespace rigid::test {

int run_catch(int argc, char** argv) {
  Catch::Session session;
  if (const int status = session.applyCommandLine(argc, argv); status != 0) return status;
  // A test name that selects nothing (Catch2 splits a name at its commas) fails, rather
  // than passing with nothing run.
  auto& warnings = session.configData().warnings;
  warnings = static_cast<Catch::WarnAbout::What>(warnings | Catch::WarnAbout::NoTests);
  return session.run();
}

}  // namespace rigid::test
