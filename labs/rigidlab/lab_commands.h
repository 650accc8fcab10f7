// Every lab's command (common/command.h) in one program, by name: what rigidlab-draw
// runs in turn.
#pragma once

#include <optional>
#include <string>

namespace rigid::lab {

/// Runs the lab `lab` as its own program would with `argv` (argv[0] its name); its exit
/// status, or nullopt if there is no such lab.
std::optional<int> run_lab_command(const std::string& lab, int argc, char** argv);

}  // namespace rigid::lab
