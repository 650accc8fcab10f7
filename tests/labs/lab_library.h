// What the in-process tests of the lab libraries share: reading a report's
// results, and matching the input an InputError names.
#pragma once

#include <catch2/catch.hpp>
#include <string>

#include "common/inputs.h"

namespace rigid::test {

/// A numeric result by key (throws if absent or not a number).
inline double value(const rigid::lab::Json& results, const char* key) {
  return results.at(key).get<double>();
}

/// Matches an InputError that names `input` ("--mass").
class NamesInput : public Catch::MatcherBase<rigid::lab::InputError> {
 public:
  explicit NamesInput(std::string input) : input_(std::move(input)) {}
  bool match(const rigid::lab::InputError& e) const override { return e.input == input_; }
  std::string describe() const override { return "names the input " + input_; }

 private:
  std::string input_;
};
inline NamesInput names_input(const std::string& input) {
  return NamesInput(input);
}

}  // namespace rigid::test
