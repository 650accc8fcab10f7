// tennis_racquet: the command-line adapter of the lab library (tennis_racquet.h).
#include "common/command.h"
#include "tennis_racquet/tennis_racquet.h"

int main(int argc, char** argv) {
  return rigid::lab::run_command(argc, argv, rigid::lab::tennis_racquet::program());
}
