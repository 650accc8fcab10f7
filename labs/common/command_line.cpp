#include "common/command_line.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "common/command_render.h"
#include "common/output_paths.h"
#include "rigid/support/cli.h"

namespace rigid::lab {
namespace {

// The most pixels an animation may draw, frames x width x height: 3840x2160 for
// 1200 frames (10 s at 120 fps) or 1920x1080 for 4800 frames (80 s at 60 fps).
constexpr double kMaxPixelFrames = 1e10;

// A "WxH" option's check: the inputs' one reader of sizes, into `size`.
CLI::Validator size_check(const SizeLimits& limits, int& width, int& height) {
  return CLI::Validator(
      [limits, &width, &height](std::string& text) -> std::string {
        const auto size = read_size(text, limits);
        if (const auto* why = std::get_if<std::string>(&size)) return *why;
        width = std::get<Size>(size).width;
        height = std::get<Size>(size).height;
        return "";
      },
      "");
}

// A number in [lo, hi] (the inputs' one reader of numbers), or the rule, as the
// options' errors say it; CLI11 then converts the value's shortest text.
CLI::Validator in_range(double lo, double hi, const std::string& what) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const auto v = read_number(text);
        if (!v || !(*v >= lo && *v <= hi))
          return fmt::format("must be {} from {:g} to {:g} (got '{}')", what, lo, hi,
                             quoted_text(text));
        text = fmt::format("{}", *v);
        return "";
      },
      "");
}

}  // namespace

CommandLine::CommandLine(const std::string& name, const std::string& title,
                         const std::vector<BoundInput>& inputs, const std::string& csv,
                         bool animation)
    : app_(title, name), csv_enabled_(!csv.empty()), animation_enabled_(animation) {
  options_.lab = name;
  app_.footer(kNumberRule);
  add_run_options();
  add_figure_options();
  app_.set_version_flag("--version", name + " (rigidlab) " + std::string(RIGID_VERSION),
                        "print the version and exit");
  for (const BoundInput& input : inputs) bind(input);
  if (csv_enabled_) {
    app_.add_option("--csv", options_.csv_path, "write FILE as CSV: " + csv)->type_name("FILE");
  }
  if (animation_enabled_) {
    add_animation_options(std::any_of(inputs.begin(), inputs.end(), [](const BoundInput& in) {
      return in.rule->flag() == "--t-end";
    }));
  }
}

InputRule& CommandLine::own_option(const std::string& flag, const std::string& help) {
  return own_.emplace_back(InputKind::kFlag, flag, help);
}

void CommandLine::add_run_options() {
  app_.add_flag("--json", options_.json, "print one JSON object on stdout instead of the table");
  // with --json it does nothing, and is taken: a script asks for "the JSON, nothing else"
  app_.add_flag("--quiet", options_.quiet,
                "print no table (files are still written; the JSON of --json still prints)");
  // taken before parsing (run_command): the other options are the explorer's to check
  app_.add_flag("--explore",
                "open this lab live in a window with the inputs given (rigidlab-explore)");
  // it times the drawing of figures and frames, and says so only in the JSON
  std::vector<std::string> drawn{"--figures"};
  if (animation_enabled_) drawn.emplace_back("--animate");
  const InputRule& timing =
      own_option("--timing",
                 "the wall time of each figure (and frame) and where it went, in the "
                 "JSON, for bench/")
          .requires_input("--json", "its times are in the JSON: give --json too")
          .requires_any(drawn, "times the drawing: give --figures DIR" +
                                   std::string(animation_enabled_ ? " or --animate FILE" : "") +
                                   " too");
  app_.add_flag("--timing", options_.timing, timing.description());
}

void CommandLine::add_figure_options() {
  app_.add_option("--figures", options_.figures_dir, "write this lab's figures into DIR")
      ->type_name("DIR");
  const auto figure_option = [this](const std::string& flag, const std::string& help) {
    return own_option(flag, help)
        .requires_input("--figures", "sets the figures: give --figures DIR too")
        .description();
  };
  app_.add_option(
          "--figure-format", figure_format_name_,
          figure_option("--figure-format",
                        "png, or svg or pdf for slides and papers (a plot's lines and text "
                        "as vectors, a 3D scene as its image at --figure-size under its text)"))
      ->type_name("FORMAT")
      ->capture_default_str()
      ->check(CLI::Validator(
          [this](std::string& text) -> std::string {
            const auto format = render::figure_format_named(text);
            if (format) options_.figure_format = *format;
            return format ? "" : "must be png, svg or pdf (got '" + text + "')";
          },
          ""));
  // The figure style is laid out for 800x600 and up; 8192 bounds memory.
  app_.add_option("--figure-size", figure_size_,
                  figure_option("--figure-size", "figure size in pixels, 800x600 to 8192x8192"))
      ->type_name("WxH")
      ->capture_default_str()
      ->check(
          size_check({800, 600, 8192, 8192, false}, options_.figure_width, options_.figure_height));
  app_.add_option("--figure-prefix", options_.figure_prefix,
                  figure_option("--figure-prefix",
                                "prefix of the figure files, e.g. 'book-' for "
                                "book-poinsot_omega.png (letters, digits, '-', '_' and '.')"))
      ->type_name("TEXT")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            const bool ok = !text.empty() && text.size() <= 64 && text.front() != '.' &&
                            std::all_of(text.begin(), text.end(), [](char c) {
                              return std::isalnum(static_cast<unsigned char>(c)) || c == '-' ||
                                     c == '_' || c == '.';
                            });
            return ok ? ""
                      : "must be 1 to 64 letters, digits, '-', '_' or '.', not starting "
                        "with '.' (got '" +
                            quoted_text(text) + "')";
          },
          ""));
}

void CommandLine::add_animation_options(bool has_t_end) {
  app_.add_option("--animate", options_.animation_path,
                  "write the motion as an animation to FILE: .mp4 (H.264, for players and "
                  "slides) or .webp (animated WebP, for browsers and READMEs)")
      ->type_name("FILE");
  const auto film_option = [this](const std::string& flag, const std::string& help) {
    return own_option(flag, help)
        .requires_input("--animate", "sets the animation: give --animate FILE too")
        .description();
  };
  app_.add_option("--fps", options_.animation_fps,
                  film_option("--fps", "frames a second of the animation, 1 to 120"))
      ->type_name("NUMBER")
      ->capture_default_str()
      ->transform(in_range(1.0, 120.0, "a number"));
  // The film shows the lab's whole motion: to --t-end where the lab has one.
  app_.add_option("--duration", options_.animation_duration,
                  film_option("--duration", std::string("length of the animation in seconds, "
                                                        "0.1 to 600 (") +
                                                (has_t_end ? "the motion to --t-end is shown in it)"
                                                           : "the lab's motion is shown in it)")))
      ->type_name("NUMBER")
      ->capture_default_str()
      ->transform(in_range(0.1, 600.0, "a number of seconds"));
  // H.264's 4:2:0 chroma needs even sizes; the figure style is laid out from 320x240 up
  app_.add_option(
          "--animation-size", animation_size_,
          film_option("--animation-size", "animation size in pixels, even, 320x240 to 3840x2160"))
      ->type_name("WxH")
      ->capture_default_str()
      ->check(size_check({320, 240, 3840, 2160, true}, options_.animation_width,
                         options_.animation_height));
}

namespace {

// A check that the inputs' one reader (read_input) takes the text, its refusal worded
// as every front door words it.
CLI::Validator read_by(const InputRule& rule) {
  return CLI::Validator(
      [&rule](std::string& text) -> std::string {
        const auto read = read_input(rule, text);
        const auto* why = std::get_if<std::string>(&read);
        return why != nullptr ? *why : "";
      },
      "");
}

}  // namespace

void CommandLine::bind(const BoundInput& input) {
  const InputRule& rule = *input.rule;
  Slot& slot = slots_.emplace_back();
  slot.input = &input;
  switch (rule.kind()) {
    case InputKind::kNumber: {
      if (const auto* x = std::get_if<double>(&input.default_value)) slot.number = *x;
      slot.cli = app_.add_option(rule.flag(), slot.number)
                     ->type_name(rule.unit_text() == "deg" ? "DEG" : "NUMBER")
                     ->capture_default_str();
      // the inputs' one reader (read_input) decides; CLI11 then converts the value's
      // shortest text, which reads back as the same double (a transform: it may rewrite)
      slot.cli->transform(CLI::Validator(
          [&rule](std::string& text) -> std::string {
            const auto read = read_input(rule, text);
            if (const auto* why = std::get_if<std::string>(&read)) return *why;
            text = fmt::format("{}", std::get<double>(std::get<InputValue>(read)));
            return "";
          },
          ""));
      break;
    }
    case InputKind::kPair:
    case InputKind::kVector: {
      // the whole text, its parts and their count read by the inputs' one reader
      std::string default_text;
      if (const auto* v = std::get_if<Eigen::Vector3d>(&input.default_value)) {
        default_text = fmt::format("{},{},{}", (*v)(0), (*v)(1), (*v)(2));
      } else if (const auto* v = std::get_if<Eigen::Vector2d>(&input.default_value)) {
        default_text = fmt::format("{},{}", (*v)(0), (*v)(1));
      }
      std::string type_name = rule.kind() == InputKind::kVector ? "X,Y,Z" : rule.value_name();
      if (!rule.word_names().empty()) type_name += "|" + rule.word_list();
      slot.cli =
          app_.add_option(rule.flag(), slot.text)->type_name(type_name)->default_str(default_text);
      slot.cli->check(read_by(rule));
      break;
    }
    case InputKind::kChoice: {
      if (const auto* w = std::get_if<std::string>(&input.default_value)) slot.word = *w;
      slot.cli = app_.add_option(rule.flag(), slot.word)->type_name("WORD")->capture_default_str();
      slot.cli->check(CLI::IsMember(rule.choices()).description(""));
      break;
    }
    case InputKind::kFlag:
      slot.cli = app_.add_flag(rule.flag(), slot.on);
      // --project=maybe: the one reader words the refusal, as a live view's field does
      slot.cli->check(read_by(rule));
      break;
  }
  if (!rule.lab_default_text().empty()) slot.cli->default_str("");
  slot.cli->description(rule.description());
  if (!rule.old_flag().empty()) bind_old_name(slot);
}

// The same storage under the input's old name, hidden from --help.
void CommandLine::bind_old_name(Slot& slot) {
  const InputRule& rule = *slot.input->rule;
  if (rule.kind() == InputKind::kNumber) {
    slot.old = app_.add_option(rule.old_flag(), slot.number);
  } else if (rule.kind() == InputKind::kPair || rule.kind() == InputKind::kVector) {
    slot.old = app_.add_option(rule.old_flag(), slot.text);
  } else if (rule.kind() == InputKind::kChoice) {
    slot.old = app_.add_option(rule.old_flag(), slot.word);
  } else {
    slot.old = app_.add_flag(rule.old_flag(), slot.on);
  }
  slot.old->group("");
}

std::optional<int> CommandLine::parse(int argc, char** argv) {
  try {
    read_argv(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app_.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app_.exit(e);
  }
  store();
  check_renderer();
  check_pairings();
  check_output_paths();
  return std::nullopt;
}

void CommandLine::read_argv(int argc, char** argv) {
  app_.allow_extras();
  for (int i = 0; i < argc; ++i) options_.command.emplace_back(argv[i]);
  const std::vector<std::string> args(options_.command.begin() + std::min(argc, 1),
                                      options_.command.end());
  if (const std::string twice = support::repeated_option(app_, args); !twice.empty())
    throw InputError(twice, "given twice: give it once");
  try {
    app_.parse(argc, argv);
  } catch (const CLI::ArgumentMismatch& e) {
    // A wrong count of values: say it in the student's terms.
    const std::string what = e.what();
    const std::string name = what.substr(0, what.find(':'));
    const CLI::Option* option = app_.get_option_no_throw(name);
    const int count = option != nullptr ? option->get_items_expected_max() : 1;
    const std::string rule = count == 3   ? "must be three numbers X,Y,Z"
                             : count == 2 ? "must be two numbers"
                                          : "needs a value";
    throw InputError(name, rule + " (" + what.substr(what.find(':') + 2) + ")");
  } catch (const CLI::CallForHelp&) {
    throw;
  } catch (const CLI::CallForVersion&) {
    throw;
  } catch (const CLI::ParseError& e) {
    // The option's own rules speak as "--option: rule"; anything else (CLI11's
    // wording) is said as it is, under the option it names first.
    const std::string what = e.what();
    const std::size_t colon = what.find(": ");
    if (what.rfind("--", 0) == 0 && colon != std::string::npos) {
      throw InputError(what.substr(0, colon), what.substr(colon + 2));
    }
    const std::size_t dash = what.find("--");
    const std::size_t end = what.find_first_of(" ,:=", dash);
    throw InputError(dash == std::string::npos ? "--inputs" : what.substr(dash, end - dash), what);
  }
  // The first word CLI11 could not place names the mistake.
  if (const auto extras = app_.remaining(); !extras.empty()) {
    const std::string& word = extras.front();
    if (word.rfind("-", 0) == 0) throw InputError(word, "unknown option (see --help)");
    throw InputError(word, "unexpected argument (options take the form --name VALUE)");
  }
}

bool CommandLine::given(const std::string& flag) const {
  for (const Slot& slot : slots_) {
    if (slot.input->rule->flag() == flag) return given(slot);
  }
  const CLI::Option* option = app_.get_option_no_throw(flag);
  return option != nullptr && option->count() > 0;
}

// The value of a given input, as CLI11 stored it.
InputValue CommandLine::given_value(Slot& slot) const {
  const InputRule& rule = *slot.input->rule;
  switch (rule.kind()) {
    case InputKind::kNumber:
      return slot.number;
    case InputKind::kPair:
    case InputKind::kVector: {
      // checked by the option's validator, or given under the old name and read here
      const auto read = read_input(rule, slot.text);
      if (const auto* why = std::get_if<std::string>(&read)) {
        throw InputError(slot.cli->count() > 0 ? rule.flag() : rule.old_flag(), *why);
      }
      return std::get<InputValue>(read);
    }
    case InputKind::kChoice:
      return slot.word;
    case InputKind::kFlag:
      return slot.on;
  }
  return {};
}

// The values given, into the lab's inputs.
void CommandLine::store() {
  for (Slot& slot : slots_) {
    if (!given(slot)) continue;
    const InputRule& rule = *slot.input->rule;
    const InputValue value = given_value(slot);
    if (slot.old != nullptr && slot.old->count() > 0) {
      if (slot.cli->count() > 0) {
        throw InputError(rule.flag(), "give it once: " + rule.old_flag() + " is its old name");
      }
      // CLI11 checked the new name's values; the old name's are checked here
      if (const std::string why = rule.broken(value); !why.empty()) {
        throw InputError(rule.old_flag(), why);
      }
      options_.warnings.push_back(rule.old_flag() + ": renamed " + rule.flag() +
                                  "; the old name is taken until the next release");
    }
    slot.input->set(value);
  }
}

// Alternatives given together, and options given without the one they act with: the
// command's own options, then the lab's inputs, by the one check a live session's
// inputs are held to as well.
void CommandLine::check_pairings() const {
  std::vector<const InputRule*> rules;
  for (const InputRule& rule : own_) rules.push_back(&rule);
  for (const Slot& slot : slots_) rules.push_back(slot.input->rule);
  lab::check_pairings(rules, [this](const std::string& flag) { return given(flag); });
}

std::string CommandLine::message(const std::exception& e) const {
  std::vector<const InputRule*> rules;
  for (const Slot& slot : slots_) rules.push_back(slot.input->rule);
  return refusal_message(e, rules, [this](const std::string& flag) { return given(flag); });
}

// A build without the renderer refuses what would draw, before any work.
void CommandLine::check_renderer() const {
  const std::string missing = renderer_missing();
  if (missing.empty()) return;
  if (app_.count("--figures") > 0) throw InputError("--figures", missing);
  if (animation_enabled_ && app_.count("--animate") > 0) throw InputError("--animate", missing);
}

void CommandLine::check_animation_path() const {
  const CommandOptions& o = options_;
  if (!animation_enabled_ || app_.count("--animate") == 0) return;
  if (o.animation_path.empty()) throw InputError("--animate", "needs a file name");
  if (!animation_format_known(o.animation_path)) {
    throw InputError("--animate", "the file name must end in .mp4 or .webp (got '" +
                                      quoted_text(o.animation_path) + "')");
  }
  check_animation_file("--animate", o.animation_path);
  // At least one frame: 1 fps for 0.1 s would be stretched to a second of video.
  const double frames = o.animation_fps * o.animation_duration;
  if (frames < 1.0) {
    throw InputError("--duration",
                     fmt::format("holds no whole frame at --fps {:g} (fps x duration = {:g}); give "
                                 "at least {:g} s",
                                 o.animation_fps, frames, 1.0 / o.animation_fps));
  }
  // The work before it starts: every frame is drawn and encoded, so frames x pixels
  // bounds it (kMaxPixelFrames).
  const double pixel_frames = frames * o.animation_width * o.animation_height;
  if (pixel_frames > kMaxPixelFrames) {
    throw InputError("--duration",
                     fmt::format("{:g} frames of {}x{} are {:.3g} pixels to draw, beyond the "
                                 "budget of {:.3g}: shorten --duration, or lower --fps or "
                                 "--animation-size",
                                 std::round(frames), o.animation_width, o.animation_height,
                                 pixel_frames, kMaxPixelFrames));
  }
}

void CommandLine::check_output_paths() const {
  const CommandOptions& o = options_;
  check_animation_path();
  if (app_.count("--figures") > 0 && o.figures_dir.empty()) {
    throw InputError("--figures", "needs a directory name");
  }
  if (!o.figures_dir.empty()) {
    // a figure's file: PREFIX + LAB + "_" + its name (a word of at most 32 bytes) + ".png",
    // ".svg" or ".pdf", within NAME_MAX by --figure-prefix's rule
    const std::size_t longest_figure = o.figure_prefix.size() + o.lab.size() + 1 + 32 + 4;
    check_output_dir("--figures", o.figures_dir, longest_figure);
  }
  const bool csv = csv_enabled_ && app_.count("--csv") > 0;
  if (csv) {
    if (o.csv_path.empty()) throw InputError("--csv", "needs a file name");
    check_csv_file("--csv", o.csv_path);
  }
  const bool animation = animation_enabled_ && app_.count("--animate") > 0;
  check_distinct_outputs(csv ? o.csv_path : "", animation ? o.animation_path : "", o.figures_dir,
                         o.figure_prefix + o.lab + "_", o.figure_extension());
}

}  // namespace rigid::lab
