// football: the command-line adapter of the lab library (football.h).
#include "common/command.h"
#include "football/football.h"

int main(int argc, char** argv) {
  return rigid::lab::run_command(argc, argv, rigid::lab::football::program());
}
