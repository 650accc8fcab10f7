// Catch2's implementation without a main: compiled once, for the default main
// (test_main.cpp) and for render_test's own.
#define CATCH_CONFIG_RUNNER
#include "catch_runner.h"

#include <catch2/catch.hpp>

namespace rigid::test {

int run_catch(int argc, char** argv) {
  return Catch::Session().run(argc, argv);
}

}  // namespace rigid::test
