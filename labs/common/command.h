// A lab as a command: options from the lab's input table (CLI11), the lab's
// compute() on the inputs given, then the outputs (the table or --json on
// stdout, --csv, --figures, --animate), which land together or not at all.
// Bad input is one line on stderr, "LAB: error: --option: rule", and exit 2.
//
//   int main(int argc, char** argv) {
//     using namespace rigid::lab::tire_balancing;
//     return rigid::lab::run_command<Inputs, Report>(argc, argv, program());
//   }
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/program.h"

namespace rigid::lab {

/// One input bound to one Inputs object.
struct BoundInput {
  const InputRule* rule;
  std::function<void(const InputValue&)> set;
  InputValue default_value;
};

/// What the command does with a computed report.
struct Computed {
  const Report* report = nullptr;
  std::function<void(FigureSink&)> figures;
  std::function<Animation(const FrameTimes&)> animation;  ///< empty: no motion
};

/// Parses argv into the bound inputs, runs `compute`, writes; returns the exit status.
int run_command(const std::string& name, const std::string& title,
                const std::vector<BoundInput>& inputs, const std::string& csv, bool animation,
                int argc, char** argv, const std::function<Computed()>& compute);

template <class In, class Rep>
int run_command(int argc, char** argv, const LabProgram<In, Rep>& lab) {
  In in;
  std::vector<BoundInput> bound;
  for (const InputField<In>& f : lab.inputs.fields()) {
    bound.push_back({&f.rule, [&in, set = f.set](const InputValue& v) { set(in, v); }, f.get(in)});
  }
  std::optional<Rep> report;
  return run_command(
      lab.name, lab.title, bound, lab.csv, lab.animation != nullptr, argc, argv, [&]() -> Computed {
        report.emplace(lab.compute(in));
        Computed c;
        c.report = &*report;
        c.figures = [&](FigureSink& sink) { lab.figures(*report, sink); };
        if (lab.animation != nullptr) {
          c.animation = [&](const FrameTimes& times) { return lab.animation(*report, times); };
        }
        return c;
      });
}

}  // namespace rigid::lab
