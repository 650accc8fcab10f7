// euler_angles: the command-line adapter of the lab library (euler_angles.h).
#include "common/command.h"
#include "euler_angles/euler_angles.h"

int main(int argc, char** argv) {
  return rigid::lab::run_command(argc, argv, rigid::lab::euler_angles::program());
}
