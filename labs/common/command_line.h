// A lab's command line: argv into the lab's inputs and the command's options
// (command_options.h). CLI11 does what it is good at, --help, the grouping and
// the completion's list of options; each value's text is read by the input table's
// one reader (inputs.h: read_input, read_size), so the command line, a live view and
// a script give one text one verdict. Then the options are checked together (a
// setting for an output not asked for, two outputs at one path, an animation
// beyond the pixel budget), before any work, as InputError "--option: rule".
#pragma once

#include <CLI/CLI.hpp>
#include <list>
#include <optional>
#include <string>
#include <vector>

#include "common/command.h"
#include "common/command_options.h"

namespace rigid::lab {

class CommandLine {
 public:
  /// The command of lab `name`, its inputs bound to their Inputs; `csv` says what its
  /// --csv writes (empty: it takes none), `animation` whether it takes --animate.
  CommandLine(const std::string& name, const std::string& title,
              const std::vector<BoundInput>& inputs, const std::string& csv, bool animation);
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  /// Reads argv into the inputs and the options and checks them; throws InputError.
  /// Returns the exit status where --help or --version was answered (printed), none
  /// where the lab is to run.
  std::optional<int> parse(int argc, char** argv);
  const CommandOptions& options() const { return options_; }

  /// What a refusal says (refusal_message): an InputError's "--option: rule", where an
  /// error that names no input, or a rule of core's, is said of the first input given (a
  /// physical one first), and a joint rule of those among its inputs that were given.
  std::string message(const std::exception& e) const;

 private:
  // One lab input as a CLI11 option: where CLI11 stores what was typed.
  struct Slot {
    const BoundInput* input = nullptr;
    CLI::Option* cli = nullptr;
    CLI::Option* old = nullptr;  // the input's old name, still taken for one release
    double number = 0.0;
    std::string word;
    bool on = false;
    std::string text;  // a vector's or pair's text (or word) as given
  };

  /// The command's own option `flag` as a rule: its help and how it goes with the other
  /// options (a setting for an output not asked for), checked with the lab's inputs'.
  InputRule& own_option(const std::string& flag, const std::string& help);
  void add_run_options();
  void add_figure_options();
  void add_animation_options(bool has_t_end);
  void bind(const BoundInput& input);
  void bind_old_name(Slot& slot);
  void read_argv(int argc, char** argv);
  void store();
  InputValue given_value(Slot& slot) const;
  void check_pairings() const;
  void check_output_paths() const;
  void check_animation_path() const;
  void check_renderer() const;
  bool given(const std::string& flag) const;
  static bool given(const Slot& slot) {
    return slot.cli->count() > 0 || (slot.old != nullptr && slot.old->count() > 0);
  }

  CLI::App app_;
  std::list<Slot> slots_;
  std::list<InputRule> own_;  // the command's own options' rules (their pairings)
  CommandOptions options_;
  bool csv_enabled_, animation_enabled_;
  // the options' texts as CLI11 stores them (and --help shows the defaults)
  std::string figure_format_name_ = "png", figure_size_ = "1600x1200";
  std::string animation_size_ = "1280x720";
};

}  // namespace rigid::lab
