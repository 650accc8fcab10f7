// What the programs' command lines share beyond CLI11 itself.
#pragma once

#include <CLI/CLI.hpp>
#include <algorithm>
#include <string>
#include <vector>

namespace rigid::support {

/// The first option of `app` that takes a value and is given more than once in `args`
/// (as "--name VALUE" or "--name=VALUE"); empty if none. Said as "given twice: give it
/// once", where CLI11 would say "At Most 1 required but received 2" (or 6 for two
/// vectors), which does not say what to do. A flag given twice says the same twice.
inline std::string repeated_option(const CLI::App& app, const std::vector<std::string>& args) {
  std::vector<std::string> seen;
  for (const std::string& arg : args) {
    if (arg == "--") break;  // what follows is not options
    if (arg.rfind("--", 0) != 0) continue;
    const std::string name = arg.substr(0, arg.find('='));
    const CLI::Option* option = app.get_option_no_throw(name);
    if (option == nullptr || option->get_items_expected_max() == 0) continue;
    if (std::find(seen.begin(), seen.end(), name) != seen.end()) return name;
    seen.push_back(name);
  }
  return {};
}

}  // namespace rigid::support
