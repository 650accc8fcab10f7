#include "catch_runner.h"

int main(int argc, char** argv) {
  return rigid::test::run_catch(argc, argv);
}
