// Every lab as a live session (session.h), by name, in section order: what the
// explorer offers, what a script or a notebook computes in one call, and what the
// in-process tests go through. Generated from the one list of labs (RIGID_LABS,
// labs/CMakeLists.txt), in the library rigid::lab::all.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "common/session.h"

namespace rigid::lab {

/// An input as the lab declares it: its rule, and its textbook value (the default).
struct InputInfo {
  InputRule rule;
  InputValue textbook;
};

/// A lab, what it takes and how to open it; describing it computes nothing.
struct LabEntry {
  std::string name;
  std::string title;
  /// What --csv writes ("" where the lab writes none).
  std::string csv;
  bool has_motion = false;
  /// Whether the defaults are the text's worked example.
  bool textbook_example = true;
  std::vector<InputInfo> inputs;
  /// At the textbook's example (a live view).
  std::function<std::unique_ptr<Session>()> make;
  /// At the inputs given, computed once and whole (session_at: a script, a notebook).
  std::function<std::variant<std::unique_ptr<Session>, Refusal>(const GivenTexts&)> make_at;
};

/// The entry of the lab that `program` describes.
template <class In, class Rep>
LabEntry lab_entry(LabProgram<In, Rep> (*program)()) {
  const LabProgram<In, Rep> p = program();
  LabEntry e{p.name, p.title, p.csv, p.animation != nullptr, p.textbook_example, {}, {}, {}};
  for (const InputField<In>& f : p.inputs.fields()) e.inputs.push_back({f.rule, f.get(In{})});
  e.make = [program] { return make_session(program()); };
  e.make_at = [program](const GivenTexts& given) { return session_at(program(), given); };
  return e;
}

/// Every lab, in section order.
std::vector<LabEntry> all_labs();

/// What a lab takes, for a front door to build its controls, signature and help from:
/// {name, title, csv, has_motion, textbook_example, inputs: [{flag, key, kind ("number",
/// "pair", "vector", "choice", "flag"), help, description, unit, choices, words, range,
/// bound {kind, lo, hi, or_zero}, lab_default, numerical, default (as the command line
/// takes it), has_default}]}.
Json describe(const LabEntry& lab);

}  // namespace rigid::lab
