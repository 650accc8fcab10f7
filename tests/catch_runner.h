// Catch2's runner, compiled once (catch_runner.cpp): for a test program's main.
#pragma once

namespace rigid::test {

/// Runs the test cases that argv selects, as Catch2's own main would.
int run_catch(int argc, char** argv);

}  // namespace rigid::test
