// A lab's inputs as data: every input's name, unit, symbol, help and rule in one
// table, which the command line (command.h) turns into options and a live view
// into widgets, and which compute() checks before it computes. The table binds
// each rule to a field of the lab's `Inputs` aggregate, so a caller that sets the
// aggregate directly (a test, the explorer) is held to the same rules as one
// that types options.
//
//   InputTable<Inputs> t;
//   t.number("--mass", &Inputs::mass, "mass m of the disk").unit("kg").positive().symbol("m");
//   t.number("--spin", &Inputs::spin, "spin S").lab_default("--spin-rpm");  // std::optional
//
// A field that is a std::optional is an input "used only when given": its
// default is the lab's choice (lab_default says which), and it is recorded
// among the inputs only when it has a value.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace rigid::lab {

using Json = nlohmann::ordered_json;

/// Bad input: names the input (by its option, "--mass") and the rule it breaks.
/// An empty `input` blames no input in particular (a result that overflows for the
/// inputs given); the command line then names the first input given.
/// A rule that joins several inputs (4 a b > 2 (a^2 - b^2) tan 2 theta) names them all
/// in `joint`; the command line then names those of them the user gave.
struct InputError : std::runtime_error {
  InputError(const std::string& input, const std::string& rule)
      : std::runtime_error(input.empty() ? rule : input + ": " + rule), input(input), rule(rule) {}
  InputError(const std::vector<std::string>& inputs, const std::string& rule)
      : InputError(joined(inputs), rule) {
    joint = inputs;
  }
  std::string input, rule;
  std::vector<std::string> joint;

  static std::string joined(const std::vector<std::string>& inputs) {
    std::string text;
    for (const std::string& i : inputs) text += (text.empty() ? "" : ", ") + i;
    return text;
  }
};

/// A user's text as an error message quotes it: whole up to 40 bytes, else its first 32
/// (less the part of a character the cut would split) and its length in characters, so
/// that a 100,000-digit number still makes a one-line error.
std::string quoted_text(const std::string& text);

/// Runs `compute`; an std::invalid_argument from core (a physics rule broken by
/// the inputs) becomes an InputError naming `input`, or the `inputs` its rule joins.
template <class Compute>
auto for_input(const std::string& input, Compute&& compute) -> decltype(compute()) {
  try {
    return compute();
  } catch (const std::invalid_argument& e) {
    throw InputError(input, e.what());
  }
}
template <class Compute>
auto for_inputs(const std::vector<std::string>& inputs, Compute&& compute) -> decltype(compute()) {
  try {
    return compute();
  } catch (const std::invalid_argument& e) {
    throw InputError(inputs, e.what());
  }
}

/// The rule every number keeps, stated once (--help's footer): a range of the input's own,
/// or else the magnitudes of InputRule::broken.
extern const char kNumberRule[];

/// A name as a JSON key: "--tilt-deg" is "tilt_deg", "bulirsch-stoer" is "bulirsch_stoer".
std::string json_key(const std::string& name);

/// The kinds of input a lab takes.
enum class InputKind {
  kNumber,  ///< one number (an angle is a number whose unit is "deg")
  kPair,    ///< two numbers A,B
  kVector,  ///< three numbers X,Y,Z, or one of `words`
  kChoice,  ///< one word of `choices`
  kFlag,    ///< a switch
};

/// An input's value: absent (an optional input not given), a number, two, three,
/// a word (a choice, or a vector's word) or a switch.
using InputValue =
    std::variant<std::monostate, double, Eigen::Vector2d, Eigen::Vector3d, std::string, bool>;

/// How an option goes with others, as data: an alternative it excludes, or the options
/// it acts only with (any one of them). An option that would do nothing, silently, in some
/// company says so here; check_pairings enforces it at every front door (the command
/// line, a live session, and the command's own options alike) and --help states it.
struct Pairing {
  enum class Kind { kExcludes, kRequires };
  Kind kind;
  std::vector<std::string> others;
  std::string rule;  ///< what a refusal says: "give --axis or --axis-deg, not both"
  /// As --help states it: "not with --axis", "only with --figures or --animate".
  std::string stated() const;
};

/// One input's rule and description: what --help, the table's inputs line, a
/// figure's title and a live view's widget show, and what a value must satisfy.
class InputRule {
 public:
  enum class Bound { kFinite, kPositive, kNonNegative, kOpenRange, kRangeFrom };

  InputRule(InputKind kind, std::string flag, std::string help);

  /// The SI unit shown in --help, the inputs and figure titles ("deg" for an angle).
  InputRule& unit(const std::string& unit);
  /// Values must be > 0.
  InputRule& positive();
  /// Values must be >= 0.
  InputRule& non_negative();
  /// Values must lie strictly between lo and hi.
  InputRule& open_range(double lo, double hi);
  /// Values must satisfy lo <= value < hi.
  InputRule& range_from(double lo, double hi);
  /// Besides its own range, the input takes 0 exactly: a case with an answer of its own
  /// (no disturbance, no tilt) below a range whose small end keeps the digits.
  InputRule& or_zero();
  /// A vector must not be (0, 0, 0).
  InputRule& nonzero();
  /// The symbol (text markup) that names this input in figure titles, e.g. "\\theta".
  InputRule& symbol(const std::string& markup);
  /// How to compute (method, tolerance, step, end time), not what is computed:
  /// setting it keeps "the inputs are the textbook's" true.
  InputRule& numerical();
  /// The default is the lab's choice from the other inputs (`what` says how, in --help).
  InputRule& lab_default(const std::string& what);
  /// A vector also takes one of `names` instead of its numbers (`meaning` goes to --help).
  InputRule& words(const std::vector<std::string>& names, const std::string& meaning);
  /// This input and `other` (an option) are alternatives: giving both breaks `rule`.
  InputRule& excludes(const std::string& other, const std::string& rule);
  /// This input means something only with `other` (an option) given; else `rule` is broken.
  InputRule& requires_input(const std::string& other, const std::string& rule);
  /// This input means something only with one of `others` given; else `rule` is broken.
  InputRule& requires_any(const std::vector<std::string>& others, const std::string& rule);

  InputKind kind() const { return kind_; }
  const std::string& flag() const { return flag_; }  ///< "--tilt-deg"
  const std::string& key() const { return key_; }    ///< "tilt_deg", the JSON key
  /// The help text as --help shows it: help, [unit], (default: ...).
  std::string description() const;
  const std::string& help() const { return help_; }
  const std::string& unit_text() const { return unit_; }
  const std::string& symbol_text() const { return symbol_; }
  const std::string& lab_default_text() const { return lab_default_; }
  bool physical() const { return physical_; }
  bool is_nonzero() const { return nonzero_; }
  bool takes_zero() const { return or_zero_; }
  Bound bound() const { return bound_; }
  double lo() const { return lo_; }
  double hi() const { return hi_; }
  const std::vector<std::string>& choices() const { return choices_; }
  const std::vector<std::string>& word_names() const { return words_; }
  /// "a|b|c"
  std::string word_list() const;
  bool takes_word(const std::string& text) const;
  /// How it goes with the other options, in the order declared.
  const std::vector<Pairing>& pairings() const { return pairings_; }

  /// Whether values are held to a range of the input's own (open_range, range_from).
  bool own_range() const;
  /// That range in words ("at least 0 and below 45 deg"), "" if none.
  std::string range_text() const;
  /// The rule a number (one component, as `text` was given) breaks, "" if none.
  /// Every number is finite. One with a range of its own is held to that range and,
  /// if nonzero, to a normal double's magnitude (2.2e-308 up); any other, if nonzero,
  /// lies between 1e-60 and 1e60 in magnitude (kNumberRule): every result is a product
  /// of at most five inputs, which then neither overflows nor underflows a double.
  std::string broken(double value, const std::string& text) const;
  /// The rule a whole value breaks (each component, a vector's nonzero rule, a
  /// choice's words), "" if none.
  std::string broken(const InputValue& value) const;

  /// For choices: the words it takes.
  InputRule& choices(const std::vector<std::string>& names);
  /// The input was named `old_flag` before: the command line still takes the old
  /// name for one release, with a warning, and --help shows only the new one.
  InputRule& renamed_from(const std::string& old_flag) {
    old_flag_ = old_flag;
    return *this;
  }
  const std::string& old_flag() const { return old_flag_; }
  /// How --help names a pair's two numbers, e.g. "I,IS" (default "A,B").
  InputRule& value_name(const std::string& name) {
    value_name_ = name;
    return *this;
  }
  const std::string& value_name() const { return value_name_; }

 private:
  InputKind kind_;
  std::string flag_, key_, help_, unit_, symbol_, lab_default_, value_name_ = "A,B", old_flag_;
  bool physical_ = true, nonzero_ = false;
  Bound bound_ = Bound::kFinite;
  double lo_ = -1, hi_ = -1;
  bool or_zero_ = false;
  std::vector<std::string> choices_, words_;
  std::vector<Pairing> pairings_;
};

/// An input value as JSON: a number, an array, a word or a switch (null if absent).
Json to_json(const InputValue& value);

/// A number as every front door reads one: the whole text but for spaces and tabs around
/// it, as strtod spells numbers (decimal, exponent, hex, inf, nan). A value beyond a
/// double's range is read (as inf or 0) for the input's rule to refuse by name. None
/// where the text is not a number.
std::optional<double> read_number(const std::string& text);

/// A size in pixels, and the sizes a reader of "WxH" takes.
struct Size {
  int width = 0, height = 0;
};
struct SizeLimits {
  int min_width = 1, min_height = 1, max_width = 8192, max_height = 8192;
  bool even = false;  ///< both sides even (H.264's 4:2:0 chroma)
};
/// "1280x720" (or "1280X720") within the limits, or the rule it breaks ("must be WxH with
/// 800 <= W <= 8192 and 600 <= H <= 8192 (got '...')"). Each side is digits alone, compared
/// before it is stored: 4294968096 (which an int would wrap to 800) is too large, not 800.
std::variant<Size, std::string> read_size(const std::string& text, const SizeLimits& limits);

/// The one reader of user text for an input: the command line, a live view's fields and
/// its scripts all call it, so one text gets one verdict and one message everywhere. A
/// number, pair or vector (its parts separated by commas), a word, or a switch (on, off,
/// true, false, 1, 0; empty is on); the value, or the rule the text breaks ("must be
/// positive (got -1)"). An empty text where the lab has a default of its own is that
/// default, unset.
std::variant<InputValue, std::string> read_input(const InputRule& rule, const std::string& text);

/// One input of a lab's Inputs: its rule and how to read and write it.
template <class In>
struct InputField {
  InputRule rule;
  std::function<InputValue(const In&)> get;
  /// Sets the field; an absent value (std::monostate) resets an optional one.
  std::function<void(In&, const InputValue&)> set;
};

/// The table of a lab's inputs, in the order --help and the inputs line list them.
template <class In>
class InputTable {
 public:
  /// A number, or an optional one (used only when given).
  template <class Field>
  InputRule& number(const std::string& flag, Field field, const std::string& help) {
    return add<double>(InputKind::kNumber, flag, field, help);
  }
  /// An angle in degrees: a number with the unit "deg".
  template <class Field>
  InputRule& angle_deg(const std::string& flag, Field field, const std::string& help) {
    return number(flag, field, help).unit("deg");
  }
  /// Two numbers A,B.
  template <class Field>
  InputRule& pair(const std::string& flag, Field field, const std::string& help) {
    return add<Eigen::Vector2d>(InputKind::kPair, flag, field, help);
  }
  /// Three numbers X,Y,Z.
  template <class Field>
  InputRule& vector(const std::string& flag, Field field, const std::string& help) {
    return add<Eigen::Vector3d>(InputKind::kVector, flag, field, help);
  }
  /// Three numbers X,Y,Z, or one word (stored in `word`, "" when numbers were given).
  template <class Field, class WordField>
  InputRule& vector_or_word(const std::string& flag, Field field, WordField word,
                            const std::string& help) {
    InputRule& rule = vector(flag, field, help);
    InputField<In>& f = fields_.back();
    auto vec = f.get;
    auto set_vec = f.set;
    f.get = [vec, word](const In& in) -> InputValue {
      const std::string& w = access(in, word);
      return w.empty() ? vec(in) : InputValue(w);
    };
    f.set = [set_vec, word](In& in, const InputValue& v) {
      if (const auto* w = std::get_if<std::string>(&v)) {
        access(in, word) = *w;
      } else {
        access(in, word).clear();
        set_vec(in, v);
      }
    };
    return rule;
  }
  /// One word of `choices`.
  template <class Field>
  InputRule& choice(const std::string& flag, Field field, const std::vector<std::string>& names,
                    const std::string& help) {
    return add<std::string>(InputKind::kChoice, flag, field, help).choices(names);
  }
  /// A switch.
  template <class Field>
  InputRule& flag(const std::string& flag, Field field, const std::string& help) {
    return add<bool>(InputKind::kFlag, flag, field, help);
  }
  /// The inputs of a part of In (e.g. its integration settings), from that part's own table.
  template <class Part, class Field>
  void include(const InputTable<Part>& part, Field field) {
    for (const InputField<Part>& p : part.fields()) {
      fields_.push_back(
          {p.rule, [get = p.get, field](const In& in) { return get(access(in, field)); },
           [set = p.set, field](In& in, const InputValue& v) { set(access(in, field), v); }});
    }
  }

  const std::vector<InputField<In>>& fields() const { return fields_; }
  /// The field of `flag` (nullptr if none).
  const InputField<In>* find(const std::string& flag) const {
    for (const auto& f : fields_) {
      if (f.rule.flag() == flag) return &f;
    }
    return nullptr;
  }

 private:
  // The field of `in` that `field` (a member pointer, or a callable taking `in`) names,
  // as const as `in` is: a getter reads through a const In, a setter writes through an In.
  template <class Self, class Field>
  static decltype(auto) access(Self& in, Field field) {
    static_assert(std::is_same_v<std::remove_const_t<Self>, In>);
    if constexpr (std::is_member_object_pointer_v<Field>) {
      return (in.*field);
    } else {
      return field(in);
    }
  }
  template <class T, class Field>
  InputRule& add(InputKind kind, const std::string& flag, Field field, const std::string& help) {
    using Stored = std::decay_t<decltype(access(std::declval<In&>(), field))>;
    InputField<In> f{InputRule(kind, flag, help), {}, {}};
    f.get = [field](const In& in) -> InputValue {
      const Stored& value = access(in, field);
      if constexpr (std::is_same_v<Stored, std::optional<T>>) {
        return value ? InputValue(*value) : InputValue();
      } else {
        return InputValue(value);
      }
    };
    f.set = [field](In& in, const InputValue& v) {
      Stored& value = access(in, field);
      if constexpr (std::is_same_v<Stored, std::optional<T>>) {
        if (std::holds_alternative<std::monostate>(v)) {
          value.reset();
        } else {
          value = std::get<T>(v);
        }
      } else {
        value = std::get<T>(v);
      }
    };
    fields_.push_back(std::move(f));
    if constexpr (std::is_same_v<Stored, std::optional<T>>) {
      // an optional field is the lab's default until given; lab_default() says how
      fields_.back().rule.lab_default("the lab's");
    }
    return fields_.back().rule;
  }

  std::vector<InputField<In>> fields_;
};

/// The first pairing (InputRule::pairings) that `rules`, in their order, break among the
/// options `given` names, thrown as an InputError naming the option that declares it. The
/// one check of pairings: the command line gives it what was typed, a lab's compute() (and
/// so a live session) what its inputs set (given_inputs).
void check_pairings(const std::vector<const InputRule*>& rules,
                    const std::function<bool(const std::string&)>& given);

/// What a front door says of a compute() that threw `e`, among the inputs `rules` (in the
/// table's order) of which `given` names those given: an InputError's inputs, of a joint
/// rule only those given; else, where the lab named no input (a rule of core's), the first
/// physical input given, then the first given, blamed ("--inputs" if none was).
std::string refusal_message(const std::exception& e, const std::vector<const InputRule*>& rules,
                            const std::function<bool(const std::string&)>& given);

/// Whether `in` gives input `flag`: an optional one has a value, any other differs from its
/// default, as Session::arguments() would write it on a command line.
template <class In>
bool given_input(const InputTable<In>& table, const In& in, const std::string& flag) {
  const InputField<In>* f = table.find(flag);
  if (f == nullptr) return false;
  const InputValue value = f->get(in);
  return !std::holds_alternative<std::monostate>(value) && !(value == f->get(In{}));
}

/// The first rule `in` breaks, thrown as an InputError naming its input: each
/// value's own rule, then the pairings of the inputs it gives.
template <class In>
void check_inputs(const InputTable<In>& table, const In& in) {
  std::vector<const InputRule*> rules;
  for (const InputField<In>& f : table.fields()) {
    const InputValue value = f.get(in);
    if (const std::string why = f.rule.broken(value); !why.empty()) {
      throw InputError(f.rule.flag(), why);
    }
    rules.push_back(&f.rule);
  }
  check_pairings(rules, [&](const std::string& flag) { return given_input(table, in, flag); });
}

/// The inputs a run records (JSON "inputs", the table's inputs line): every input
/// in the table's order but the optional ones not given.
template <class In>
Json record_inputs(const InputTable<In>& table, const In& in) {
  Json inputs = Json::object();
  for (const InputField<In>& f : table.fields()) {
    const InputValue value = f.get(in);
    if (!std::holds_alternative<std::monostate>(value)) inputs[f.rule.key()] = to_json(value);
  }
  return inputs;
}

/// True when every physical input is the textbook's (the default's): the text's
/// printed values then stand beside the results.
template <class In>
bool textbook_inputs(const InputTable<In>& table, const In& in) {
  const In defaults{};
  for (const InputField<In>& f : table.fields()) {
    if (f.rule.physical() && !(f.get(in) == f.get(defaults))) return false;
  }
  return true;
}

}  // namespace rigid::lab
