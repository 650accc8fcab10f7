// top_nutation: the command-line adapter of the lab library (top_nutation.h).
#include "common/command.h"
#include "top_nutation/top_nutation.h"

int main(int argc, char** argv) {
  return rigid::lab::run_command(argc, argv, rigid::lab::top_nutation::program());
}
