// lamina_tensor: the command-line adapter of the lab library (lamina_tensor.h).
#include "common/command.h"
#include "lamina_tensor/lamina_tensor.h"

int main(int argc, char** argv) {
  return rigid::lab::run_command(argc, argv, rigid::lab::lamina_tensor::program());
}
