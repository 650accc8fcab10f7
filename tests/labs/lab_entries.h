// Every lab as the registry lists it, for tests that take labs by name (live sessions,
// a session computed whole) and read a session's report as the command line writes it.
#pragma once

#include <catch2/catch.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "common/registry.h"
#include "common/writers.h"

namespace rigid::test {

/// The registry's entry of the lab `name` (a test fails where there is none).
inline const rigid::lab::LabEntry& lab(const std::string& name) {
  static const std::vector<rigid::lab::LabEntry> labs = rigid::lab::all_labs();
  for (const rigid::lab::LabEntry& e : labs) {
    if (e.name == name) return e;
  }
  FAIL("no lab " << name);
  return labs.front();
}

/// A session's report as --json writes it.
inline std::string json_of(const rigid::lab::Session& s) {
  std::ostringstream text;
  rigid::lab::write_json(text, s.report(), rigid::lab::RunOutputs{}, "test");
  return text.str();
}

}  // namespace rigid::test
