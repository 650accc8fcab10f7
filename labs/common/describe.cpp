// A lab's inputs described for a front door (registry.h).
#include <variant>

#include "common/registry.h"

namespace rigid::lab {

namespace {

const char* kind_name(InputKind kind) {
  switch (kind) {
    case InputKind::kNumber:
      return "number";
    case InputKind::kPair:
      return "pair";
    case InputKind::kVector:
      return "vector";
    case InputKind::kChoice:
      return "choice";
    case InputKind::kFlag:
      return "flag";
  }
  return "number";
}

// The numbers' bound as data: its kind, its ends where it has them, and whether 0 is
// allowed below it.
Json bound_json(const InputRule& r) {
  using Bound = InputRule::Bound;
  Json out = {{"or_zero", r.takes_zero()}};
  switch (r.bound()) {
    case Bound::kFinite:
      out["kind"] = "finite";
      break;
    case Bound::kPositive:
      out["kind"] = "positive";
      break;
    case Bound::kNonNegative:
      out["kind"] = "non_negative";
      break;
    case Bound::kOpenRange:
      out["kind"] = "open_range";
      out["lo"] = r.lo();
      out["hi"] = r.hi();
      break;
    case Bound::kRangeFrom:
      out["kind"] = "range_from";
      out["lo"] = r.lo();
      out["hi"] = r.hi();
      break;
  }
  return out;
}

}  // namespace

Json describe(const LabEntry& lab) {
  Json inputs = Json::array();
  for (const InputInfo& info : lab.inputs) {
    const InputRule& r = info.rule;
    inputs.push_back({{"flag", r.flag()},
                      {"key", r.key()},
                      {"kind", kind_name(r.kind())},
                      {"help", r.help()},
                      {"description", r.description()},
                      {"unit", r.unit_text()},
                      {"choices", r.choices()},
                      {"words", r.word_names()},
                      {"range", r.range_text()},
                      {"bound", bound_json(r)},
                      {"lab_default", r.lab_default_text()},
                      {"numerical", !r.physical()},
                      {"default", argument_text(info.textbook)},
                      {"has_default", !std::holds_alternative<std::monostate>(info.textbook)}});
  }
  return {{"name", lab.name},
          {"title", lab.title},
          {"csv", lab.csv},
          {"has_motion", lab.has_motion},
          {"textbook_example", lab.textbook_example},
          {"inputs", inputs}};
}

}  // namespace rigid::lab
