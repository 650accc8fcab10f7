// poinsot: the command-line adapter of the lab library (poinsot.h).
#include "common/command.h"
#include "poinsot/poinsot.h"

int main(int argc, char** argv) {
  return rigid::lab::run_command(argc, argv, rigid::lab::poinsot::program());
}
