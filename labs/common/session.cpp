// The parts of a live lab (session.h) that are the same for every lab.
#include "common/session.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace rigid::lab {

std::size_t Session::find(const std::string& flag) const {
  for (std::size_t i = 0; i < input_count(); ++i) {
    if (rule(i).flag() == flag) return i;
  }
  return input_count();
}

bool Session::at_textbook() const {
  for (std::size_t i = 0; i < input_count(); ++i) {
    if (!(value(i) == textbook_value(i))) return false;
  }
  return true;
}

SliderSpan slider_span(const InputRule& r, double textbook) {
  const double d = std::abs(textbook);
  switch (r.bound()) {
    case InputRule::Bound::kOpenRange:
    case InputRule::Bound::kRangeFrom:
      return {r.takes_zero() ? std::min(0.0, r.lo()) : r.lo(), r.hi(), false};
    case InputRule::Bound::kPositive:
      return d > 0 ? SliderSpan{d / 10, d * 10, true} : SliderSpan{1e-3, 1.0, true};
    case InputRule::Bound::kNonNegative:
      return {0.0, d > 0 ? 10 * d : 1.0, false};
    case InputRule::Bound::kFinite:
      break;
  }
  if (r.unit_text() == "deg") return {-180.0, 180.0, false};
  return d > 0 ? SliderSpan{-10 * d, 10 * d, false} : SliderSpan{-1.0, 1.0, false};
}

std::string argument_text(const InputValue& value) {
  // "{}" is the shortest text that reads back as the same double
  struct Text {
    std::string operator()(std::monostate) const { return {}; }
    std::string operator()(double x) const { return fmt::format("{}", x); }
    std::string operator()(const Eigen::Vector2d& v) const {
      return fmt::format("{},{}", v[0], v[1]);
    }
    std::string operator()(const Eigen::Vector3d& v) const {
      return fmt::format("{},{},{}", v[0], v[1], v[2]);
    }
    std::string operator()(const std::string& word) const { return word; }
    std::string operator()(bool) const { return {}; }
  };
  return std::visit(Text{}, value);
}

Refusal refusal_of(const std::exception& e, const std::string& changed) {
  if (const auto* input = dynamic_cast<const InputError*>(&e)) {
    std::vector<std::string> named = input->joint;
    if (named.empty()) named.push_back(input->input.empty() ? changed : input->input);
    return Refusal{input->input.empty() ? changed + ": " + input->rule : input->what(), named};
  }
  // a rule of core's the lab names no input for: the one just changed broke it
  if (changed.empty()) return Refusal{e.what(), {}};
  return Refusal{changed + ": " + e.what(), {changed}};
}

std::optional<Refusal> Session::set_text(std::size_t i, const std::string& text) {
  const InputRule& r = rule(i);
  const auto parsed = read_input(r, text);
  if (const auto* why = std::get_if<std::string>(&parsed)) {
    return Refusal{r.flag() + ": " + *why, {r.flag()}};
  }
  return set(i, std::get<InputValue>(parsed));
}

std::vector<std::string> Session::arguments() const {
  std::vector<std::string> args;
  for (std::size_t i = 0; i < input_count(); ++i) {
    const InputValue v = value(i);
    if (v == textbook_value(i) || std::holds_alternative<std::monostate>(v)) continue;
    if (const bool* on = std::get_if<bool>(&v)) {
      if (*on) args.push_back(rule(i).flag());
      continue;
    }
    // "=" joins the value even when it starts with '-', which would read as an option
    args.push_back(rule(i).flag() + "=" + argument_text(v));
  }
  return args;
}

}  // namespace rigid::lab
