// tire_balancing: the command-line adapter of the lab library (tire_balancing.h).
#include "common/command.h"
#include "tire_balancing/tire_balancing.h"

int main(int argc, char** argv) {
  return rigid::lab::run_command(argc, argv, rigid::lab::tire_balancing::program());
}
