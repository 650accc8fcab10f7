#include "common/inputs.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "rigid/support/text.h"

namespace rigid::lab {

namespace {
// Every result is a product of at most five inputs (m a^2 omega^2, say); inside
// this range of magnitudes no such product overflows or underflows a double.
constexpr double kSmallest = 1e-60, kLargest = 1e60;
// A number inside an input's own range that a double holds with fewer digits (a
// subnormal, which turned 5e-324 deg into a zero angle), or not at all (1e-400).
constexpr char kBelowNormal[] =
    "is nonzero and below 2.2e-308 in magnitude, where a double loses "
    "its digits";
}  // namespace

const char kNumberRule[] =
    "Numbers: finite; an input with a range of its own (its help states it) is held to that "
    "range, and if nonzero to at least 2.2e-308 in magnitude (where a double keeps all its "
    "digits); any other is 0 or between 1e-60 and 1e60 in magnitude (a positive one, between "
    "1e-60 and 1e60), so that no result overflows or underflows a double.";

std::string json_key(const std::string& name) {
  std::string key = name.substr(name.find_first_not_of('-'));
  for (char& c : key) {
    if (c == '-') c = '_';
  }
  return key;
}

InputRule::InputRule(InputKind kind, std::string flag, std::string help)
    : kind_(kind), flag_(std::move(flag)), key_(json_key(flag_)), help_(std::move(help)) {}

InputRule& InputRule::unit(const std::string& unit) {
  unit_ = unit;
  return *this;
}
InputRule& InputRule::positive() {
  bound_ = Bound::kPositive;
  return *this;
}
InputRule& InputRule::non_negative() {
  bound_ = Bound::kNonNegative;
  return *this;
}
InputRule& InputRule::open_range(double lo, double hi) {
  bound_ = Bound::kOpenRange;
  lo_ = lo;
  hi_ = hi;
  return *this;
}
InputRule& InputRule::range_from(double lo, double hi) {
  bound_ = Bound::kRangeFrom;
  lo_ = lo;
  hi_ = hi;
  return *this;
}
InputRule& InputRule::or_zero() {
  or_zero_ = true;
  return *this;
}
InputRule& InputRule::nonzero() {
  nonzero_ = true;
  return *this;
}
InputRule& InputRule::symbol(const std::string& markup) {
  symbol_ = markup;
  return *this;
}
InputRule& InputRule::numerical() {
  physical_ = false;
  return *this;
}
InputRule& InputRule::lab_default(const std::string& what) {
  lab_default_ = what;
  return *this;
}
InputRule& InputRule::words(const std::vector<std::string>& names, const std::string& meaning) {
  words_ = names;
  help_ += " (" + meaning + ")";
  return *this;
}
InputRule& InputRule::choices(const std::vector<std::string>& names) {
  choices_ = names;
  std::string list;
  for (const auto& choice : names) list += (list.empty() ? "" : "|") + choice;
  help_ += " (" + list + ")";
  return *this;
}
InputRule& InputRule::excludes(const std::string& other, const std::string& rule) {
  pairings_.push_back({Pairing::Kind::kExcludes, {other}, rule});
  return *this;
}
InputRule& InputRule::requires_input(const std::string& other, const std::string& rule) {
  return requires_any({other}, rule);
}
InputRule& InputRule::requires_any(const std::vector<std::string>& others,
                                   const std::string& rule) {
  pairings_.push_back({Pairing::Kind::kRequires, others, rule});
  return *this;
}

std::string Pairing::stated() const {
  std::string names;
  for (std::size_t i = 0; i < others.size(); ++i) {
    names += (i == 0 ? "" : i + 1 == others.size() ? " or " : ", ") + others[i];
  }
  return (kind == Kind::kExcludes ? "not with " : "only with ") + names;
}

void check_pairings(const std::vector<const InputRule*>& rules,
                    const std::function<bool(const std::string&)>& given) {
  for (const InputRule* rule : rules) {
    if (!given(rule->flag())) continue;
    for (const Pairing& p : rule->pairings()) {
      const bool any = std::any_of(p.others.begin(), p.others.end(), given);
      if (any == (p.kind == Pairing::Kind::kExcludes)) throw InputError(rule->flag(), p.rule);
    }
  }
}

std::string InputRule::description() const {
  std::string text = help_;
  if (!unit_.empty()) text += " [" + unit_ + "]";
  std::string notes = range_text();
  if (!lab_default_.empty())
    notes += std::string(notes.empty() ? "" : "; ") + "default: " + lab_default_;
  // the alternatives excluded stated as one ("not with --ellipsoid, --mass or --box")
  Pairing excluded{Pairing::Kind::kExcludes, {}, ""};
  for (const Pairing& p : pairings_) {
    if (p.kind == Pairing::Kind::kExcludes) {
      excluded.others.insert(excluded.others.end(), p.others.begin(), p.others.end());
    }
  }
  if (!excluded.others.empty()) notes += (notes.empty() ? "" : "; ") + excluded.stated();
  for (const Pairing& p : pairings_) {
    if (p.kind == Pairing::Kind::kRequires) notes += (notes.empty() ? "" : "; ") + p.stated();
  }
  if (!notes.empty()) text += " (" + notes + ")";
  return text;
}

bool InputRule::takes_word(const std::string& text) const {
  return std::find(words_.begin(), words_.end(), text) != words_.end();
}

std::string InputRule::word_list() const {
  std::string list;
  for (const std::string& w : words_) list += (list.empty() ? "" : "|") + w;
  return list;
}

std::string quoted_text(const std::string& text) {
  constexpr std::size_t kWhole = 40, kHead = 32;
  if (text.size() <= kWhole) return text;
  // Never inside a character: back off over the continuation bytes of the one the cut
  // falls in (at most 3; a longer run is invalid bytes, each shown escaped on the way out).
  std::size_t cut = kHead;
  for (int k = 0; k < 3 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80; ++k) --cut;
  // Its length in characters, an invalid byte one, as a terminal line shows it.
  std::size_t characters = 0;
  for (std::size_t i = 0; i < text.size(); ++characters) {
    char32_t code = 0;
    i += std::max(1, support::detail::utf8_sequence(text, i, code));
  }
  return fmt::format("{}... ({} characters)", text.substr(0, cut), characters);
}

namespace {

/// Whether a number's text spells a value a double cannot hold (1e400, 1e-400, a
/// 100,000-digit integer) rather than inf or nan, or a zero: strtod rounds the first
/// to infinity and the second to zero, and then "must be finite" or "must be positive"
/// would name the wrong rule.
bool beyond_double(double value, const std::string& text) {
  std::string lower;
  for (const char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower.find("inf") != std::string::npos || lower.find("nan") != std::string::npos) {
    return false;
  }
  if (std::isinf(value)) return true;
  if (value != 0.0) return false;
  // Zero: beyond range only if the mantissa has a nonzero digit.
  std::size_t i = lower.find_first_not_of("+- \t");
  const bool hex = lower.compare(i == std::string::npos ? 0 : i, 2, "0x") == 0;
  if (hex) i += 2;
  for (; i < lower.size(); ++i) {
    const char c = lower[i];
    if (hex ? c == 'p' : c == 'e') break;
    if ((c >= '1' && c <= '9') || (hex && c >= 'a' && c <= 'f')) return true;
  }
  return false;
}

}  // namespace

bool InputRule::own_range() const {
  return bound_ == Bound::kOpenRange || bound_ == Bound::kRangeFrom;
}

std::string InputRule::range_text() const {
  const std::string unit = unit_.empty() ? "" : " " + unit_;
  const std::string zero = or_zero_ ? "0, or " : "";
  if (bound_ == Bound::kOpenRange)
    return fmt::format("{}between {} and {}{}, exclusive", zero, lo_, hi_, unit);
  if (bound_ == Bound::kRangeFrom)
    return fmt::format("{}at least {} and below {}{}", zero, lo_, hi_, unit);
  return "";
}

std::string InputRule::broken(double value, const std::string& text) const {
  const auto fail = [&](const std::string& rule) {
    return rule + " (got " + quoted_text(text) + ")";
  };
  const std::string range_rule = "must be " + range_text();
  const std::string magnitude_rule = bound_ == Bound::kPositive
                                         ? "must be between 1e-60 and 1e60"
                                         : "must be 0 or between 1e-60 and 1e60 in magnitude";
  if (beyond_double(value, text)) {
    // An input with a range of its own is held to that range alone; a value inside it
    // that no double holds (1e-400) is refused as such, not by the general magnitudes.
    if (!own_range()) return fail(magnitude_rule);
    return fail(std::isinf(value) ? range_rule : kBelowNormal);
  }
  if (!std::isfinite(value)) return fail("must be finite");
  if (or_zero_ && value == 0.0) return "";
  switch (bound_) {
    case Bound::kPositive:
      if (!(value > 0.0)) return fail("must be positive");
      break;
    case Bound::kNonNegative:
      if (value < 0.0) return fail("must not be negative");
      break;
    case Bound::kOpenRange:
      if (!(value > lo_ && value < hi_)) return fail(range_rule);
      break;
    case Bound::kRangeFrom:
      if (!(value >= lo_ && value < hi_)) return fail(range_rule);
      break;
    case Bound::kFinite:
      break;
  }
  const double magnitude = std::abs(value);
  if (own_range() && magnitude != 0.0 && magnitude < std::numeric_limits<double>::min()) {
    return fail(kBelowNormal);
  }
  if (!own_range() && magnitude != 0.0 && (magnitude < kSmallest || magnitude > kLargest)) {
    return fail(magnitude_rule);
  }
  return "";
}

std::string InputRule::broken(const InputValue& value) const {
  const auto each = [this](const auto& v) -> std::string {
    for (Eigen::Index i = 0; i < v.size(); ++i) {
      if (std::string why = broken(v(i), fmt::format("{:g}", v(i))); !why.empty()) return why;
    }
    return "";
  };
  if (const auto* x = std::get_if<double>(&value)) return broken(*x, fmt::format("{:g}", *x));
  if (const auto* v = std::get_if<Eigen::Vector2d>(&value)) return each(*v);
  if (const auto* v = std::get_if<Eigen::Vector3d>(&value)) {
    if (std::string why = each(*v); !why.empty()) return why;
    if (nonzero_ && v->isZero(0.0)) return "must not be the zero vector";
    return "";
  }
  if (const auto* w = std::get_if<std::string>(&value)) {
    if (kind_ == InputKind::kChoice &&
        std::find(choices_.begin(), choices_.end(), *w) == choices_.end()) {
      std::string list;
      for (const auto& c : choices_) list += (list.empty() ? "" : ",") + c;
      return *w + " not in {" + list + "}";
    }
    if (kind_ == InputKind::kVector && !takes_word(*w)) {
      return "expects three numbers X,Y,Z" +
             (words_.empty() ? std::string() : " or one of " + word_list());
    }
  }
  return "";
}

Json to_json(const InputValue& value) {
  if (const auto* x = std::get_if<double>(&value)) return *x;
  if (const auto* v = std::get_if<Eigen::Vector2d>(&value)) return Json::array({(*v)(0), (*v)(1)});
  if (const auto* v = std::get_if<Eigen::Vector3d>(&value)) {
    return Json::array({(*v)(0), (*v)(1), (*v)(2)});
  }
  if (const auto* w = std::get_if<std::string>(&value)) return *w;
  if (const auto* b = std::get_if<bool>(&value)) return *b;
  return nullptr;
}

std::optional<double> read_number(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return std::nullopt;
  const std::size_t last = text.find_last_not_of(" \t");
  const std::string t = text.substr(first, last - first + 1);
  char* end = nullptr;
  const double x = std::strtod(t.c_str(), &end);
  if (end != t.c_str() + t.size()) return std::nullopt;
  return x;
}

std::variant<InputValue, std::string> read_input(const InputRule& rule, const std::string& text) {
  if (text.empty() && !rule.lab_default_text().empty()) return InputValue();
  switch (rule.kind()) {
    case InputKind::kNumber: {
      const auto x = read_number(text);
      if (!x) return "must be a number (got '" + quoted_text(text) + "')";
      if (std::string why = rule.broken(*x, text); !why.empty()) return why;
      // -0 is 0 (adding +0.0 makes it so), as in the results: a -0 typed where 0 is the
      // default leaves the input at its default, which the command that reproduces a
      // state then leaves out
      return InputValue(*x + 0.0);
    }
    case InputKind::kPair:
    case InputKind::kVector: {
      if (rule.takes_word(text)) return InputValue(text);
      const std::size_t count = rule.kind() == InputKind::kVector ? 3 : 2;
      std::vector<double> xs;
      std::stringstream parts(text);
      for (std::string part; std::getline(parts, part, ',');) {
        const auto x = read_number(part);
        if (!x) {
          return "each component must be a number (got '" + quoted_text(part) + "')" +
                 (rule.word_names().empty() ? "" : ", or the value one of " + rule.word_list());
        }
        if (std::string why = rule.broken(*x, part); !why.empty()) return why;
        xs.push_back(*x + 0.0);
      }
      if (xs.size() != count) {
        return fmt::format("needs {} numbers separated by commas (got '{}')", count,
                           quoted_text(text));
      }
      const InputValue v = count == 3 ? InputValue(Eigen::Vector3d(xs[0], xs[1], xs[2]))
                                      : InputValue(Eigen::Vector2d(xs[0], xs[1]));
      if (std::string why = rule.broken(v); !why.empty()) return why;
      return v;
    }
    case InputKind::kChoice: {
      if (std::string why = rule.broken(InputValue(text)); !why.empty()) return why;
      return InputValue(text);
    }
    case InputKind::kFlag:
      if (text.empty() || text == "on" || text == "true" || text == "1") return InputValue(true);
      if (text == "off" || text == "false" || text == "0") return InputValue(false);
      return "is a switch: on or off (got '" + quoted_text(text) + "')";
  }
  return std::string("cannot be read");
}

std::variant<Size, std::string> read_size(const std::string& text, const SizeLimits& limits) {
  const std::string rule =
      fmt::format("must be WxH{} with {} <= W <= {} and {} <= H <= {} (got '{}')",
                  limits.even ? ", both even," : "", limits.min_width, limits.max_width,
                  limits.min_height, limits.max_height, quoted_text(text));
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos) return rule;
  const auto side = [](const std::string& digits, int lo, int hi, int& out) {
    if (digits.empty() || digits.size() > 9 ||
        digits.find_first_not_of("0123456789") != std::string::npos) {
      return false;
    }
    const long value = std::stol(digits);
    if (value < lo || value > hi) return false;
    out = static_cast<int>(value);
    return true;
  };
  Size size;
  if (!side(text.substr(0, x), limits.min_width, limits.max_width, size.width) ||
      !side(text.substr(x + 1), limits.min_height, limits.max_height, size.height) ||
      (limits.even && (size.width % 2 != 0 || size.height % 2 != 0))) {
    return rule;
  }
  return size;
}

std::string refusal_message(const std::exception& e, const std::vector<const InputRule*>& rules,
                            const std::function<bool(const std::string&)>& given) {
  const auto blamed = [&] {
    for (const InputRule* r : rules) {
      if (r->physical() && given(r->flag())) return r->flag();
    }
    for (const InputRule* r : rules) {  // then a numerical one
      if (given(r->flag())) return r->flag();
    }
    return std::string("--inputs");
  };
  const auto* input = dynamic_cast<const InputError*>(&e);
  if (input == nullptr) return blamed() + ": " + e.what();
  if (input->input.empty()) return blamed() + ": " + input->rule;
  if (input->joint.empty()) return input->what();
  std::vector<std::string> named;
  for (const std::string& flag : input->joint) {
    if (given(flag)) named.push_back(flag);
  }
  return InputError::joined(named.empty() ? input->joint : named) + ": " + input->rule;
}

}  // namespace rigid::lab
