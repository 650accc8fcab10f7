#include "common/command.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <future>
#include <iostream>
#include <list>
#include <memory>

#include "common/output_paths.h"
#include "common/writers.h"
#include "rigid/render/atomic_file.h"
#include "rigid/render/figure_format.h"
#include "rigid/render/image.h"
#include "rigid/support/cli.h"
#include "rigid/support/programs.h"
#include "rigid/support/progress.h"
#include "rigid/support/text.h"

#if RIGID_HAVE_RENDER
#include "rigid/render/context.h"
#include "rigid/render/draw.h"
#include "rigid/render/png.h"
#include "rigid/render/video.h"
#endif

namespace rigid::lab {
namespace fs = std::filesystem;
namespace {

// "1280x720" into width and height within the limits (the inputs' one reader of sizes):
// the rule broken, or "".
std::string parse_size(const std::string& text, int min_w, int min_h, int max_w, int max_h,
                       bool even, int& width, int& height) {
  const auto size = read_size(text, {min_w, min_h, max_w, max_h, even});
  if (const auto* why = std::get_if<std::string>(&size)) return *why;
  width = std::get<Size>(size).width;
  height = std::get<Size>(size).height;
  return "";
}

// The most pixels an animation may draw, frames x width x height: 3840x2160 for
// 1200 frames (10 s at 120 fps) or 1920x1080 for 4800 frames (80 s at 60 fps).
constexpr double kMaxPixelFrames = 1e10;

int frame_count(double duration, double fps) {
  return std::max(1, static_cast<int>(std::lround(duration * fps)));
}

// One lab input as a CLI11 option: where CLI11 stores what was typed.
struct OptionSlot {
  const BoundInput* input = nullptr;
  CLI::Option* cli = nullptr;
  CLI::Option* old = nullptr;  // the input's old name, still taken for one release
  double number = 0.0;
  std::string word;
  bool on = false;
  std::string text;  // a vector's or pair's text (or word) as given
};

class Command {
 public:
  Command(const std::string& name, const std::string& title, const std::vector<BoundInput>& inputs,
          bool csv, bool animation);
  int run(int argc, char** argv, const std::function<Computed()>& compute);
  int explore(int argc, char** argv, int at) const;
  /// `status`, or 1 with one line on stderr if what went to stdout did not arrive.
  int stdout_written(int status) const;

 private:
  class FigureFiles;
  void bind(const BoundInput& input);
  void parse(int argc, char** argv);
  void store();
  void check_pairings() const;
  void check_output_paths() const;
  void check_animation_path() const;
  std::string blamed_option() const;
  /// Of a joint rule's inputs, those the user gave (all of them if none was).
  std::string given_among(const std::vector<std::string>& joint) const;
  bool given(const std::string& flag) const;
  static bool given(const OptionSlot& slot) {
    return slot.cli->count() > 0 || (slot.old != nullptr && slot.old->count() > 0);
  }
  void draw_figures(const Computed& computed);
  /// ".png", ".svg" or ".pdf": the figure files' ending.
  std::string figure_extension() const {
    return "." + std::string(render::figure_format_name(figure_format_));
  }
  void animate(const Computed& computed);
  std::vector<double> animation_times(double motion_seconds) const;

  std::string name_, title_;
  CLI::App app_;
  std::list<OptionSlot> slots_;
  bool json_ = false, quiet_ = false, timing_ = false, csv_enabled_, animation_enabled_;
  bool figures_failed_ = false;
  std::vector<fs::path> created_dirs_;  ///< by --figures, deepest first
  std::string figures_dir_, figure_size_ = "1600x1200", figure_prefix_, csv_path_;
  std::string figure_format_name_ = "png";
  render::FigureFormat figure_format_ = render::FigureFormat::kPng;
  int figure_width_ = 1600, figure_height_ = 1200;
  std::string animation_path_, animation_size_ = "1280x720";
  double animation_fps_ = 30.0, animation_duration_ = 10.0;
  int animation_width_ = 1280, animation_height_ = 720;
  RunOutputs outputs_;
  std::vector<std::string> warnings_;  // the command's own (an old option name used)
  Json figure_seconds_ = Json::object(), figure_phases_ = Json::object();
};

Command::Command(const std::string& name, const std::string& title,
                 const std::vector<BoundInput>& inputs, bool csv, bool animation)
    : name_(name),
      title_(title),
      app_(title, name),
      csv_enabled_(csv),
      animation_enabled_(animation) {
  app_.add_flag("--json", json_, "print one JSON object on stdout instead of the table");
  app_.add_flag("--quiet", quiet_, "print no table (files are still written)");
  // taken before parsing (run()): the other options are the explorer's to check
  app_.add_flag("--explore",
                "open this lab live in a window with the inputs given (rigidlab-explore)");
  app_.add_flag("--timing", timing_,
                "with --json: the wall time of each figure and where it went, for bench/");
  app_.add_option("--figures", figures_dir_, "write this lab's figures into DIR")->type_name("DIR");
  app_.add_option("--figure-format", figure_format_name_,
                  "png, or svg or pdf for slides and papers (a plot's lines and text as vectors, "
                  "a 3D scene as its image at --figure-size)")
      ->type_name("FORMAT")
      ->capture_default_str()
      ->check(CLI::Validator(
          [this](std::string& text) -> std::string {
            const auto format = render::figure_format_named(text);
            if (format) figure_format_ = *format;
            return format ? "" : "must be png, svg or pdf (got '" + text + "')";
          },
          ""));
  // The figure style is laid out for 800x600 and up; 8192 bounds memory.
  app_.add_option("--figure-size", figure_size_, "figure size in pixels, 800x600 to 8192x8192")
      ->type_name("WxH")
      ->capture_default_str()
      ->check(CLI::Validator(
          [this](std::string& text) -> std::string {
            return parse_size(text, 800, 600, 8192, 8192, false, figure_width_, figure_height_);
          },
          ""));
  app_.add_option("--figure-prefix", figure_prefix_,
                  "prefix of the figure files, e.g. 'book-' for book-poinsot_omega.png (letters, "
                  "digits, '-', '_' and '.')")
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
  app_.set_version_flag("--version", name_ + " (rigidlab) " + std::string(RIGID_VERSION),
                        "print the version and exit");
  for (const BoundInput& input : inputs) bind(input);
  if (csv_enabled_) {
    app_.add_option("--csv", csv_path_, "write the lab's time series to FILE as CSV")
        ->type_name("FILE");
  }
  if (animation_enabled_) {
    app_.add_option("--animate", animation_path_,
                    "write the motion as an animation to FILE: .mp4 (H.264, for players and "
                    "slides) or .webp (animated WebP, for browsers and READMEs)")
        ->type_name("FILE");
    // a number in [lo, hi] or the rule, as the options' errors say it
    const auto in_range = [](double lo, double hi, std::string what) {
      return CLI::Validator(
          [=](std::string& text) -> std::string {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0' || !(v >= lo && v <= hi))
              return fmt::format("must be {} from {:g} to {:g} (got '{}')", what, lo, hi,
                                 quoted_text(text));
            return "";
          },
          "");
    };
    app_.add_option("--fps", animation_fps_, "frames a second of the animation, 1 to 120")
        ->type_name("NUMBER")
        ->capture_default_str()
        ->check(in_range(1.0, 120.0, "a number"));
    // The film shows the lab's whole motion: to --t-end where the lab has one.
    const bool t_end = std::any_of(inputs.begin(), inputs.end(), [](const BoundInput& in) {
      return in.rule->flag() == "--t-end";
    });
    app_.add_option("--duration", animation_duration_,
                    std::string("length of the animation in seconds, 0.1 to 600 (") +
                        (t_end ? "the motion to --t-end is shown in it)"
                               : "the lab's motion is shown in it)"))
        ->type_name("NUMBER")
        ->capture_default_str()
        ->check(in_range(0.1, 600.0, "a number of seconds"));
    // H.264's 4:2:0 chroma needs even sizes; the figure style is laid out from 320x240 up
    app_.add_option("--animation-size", animation_size_,
                    "animation size in pixels, even, 320x240 to 3840x2160")
        ->type_name("WxH")
        ->capture_default_str()
        ->check(CLI::Validator(
            [this](std::string& text) -> std::string {
              return parse_size(text, 320, 240, 3840, 2160, true, animation_width_,
                                animation_height_);
            },
            ""));
  }
}

void Command::bind(const BoundInput& input) {
  const InputRule& rule = *input.rule;
  OptionSlot& slot = slots_.emplace_back();
  slot.input = &input;
  const bool lab_default = !rule.lab_default_text().empty();
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
      slot.cli->check(CLI::Validator(
          [&rule](std::string& text) -> std::string {
            const auto read = read_input(rule, text);
            const auto* why = std::get_if<std::string>(&read);
            return why != nullptr ? *why : "";
          },
          ""));
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
      break;
  }
  if (lab_default) slot.cli->default_str("");
  slot.cli->description(rule.description());
  if (!rule.old_flag().empty()) {
    // the same storage under the old name, hidden from --help
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
}

bool Command::given(const std::string& flag) const {
  for (const OptionSlot& slot : slots_) {
    if (slot.input->rule->flag() == flag) return given(slot);
  }
  return app_.count(flag) > 0;
}

// The values given, into the lab's inputs.
void Command::store() {
  for (OptionSlot& slot : slots_) {
    if (!given(slot)) continue;
    const InputRule& rule = *slot.input->rule;
    InputValue value;
    switch (rule.kind()) {
      case InputKind::kNumber:
        value = slot.number;
        break;
      case InputKind::kPair:
      case InputKind::kVector: {
        // checked by the option's validator, or given under the old name and read here
        const auto read = read_input(rule, slot.text);
        if (const auto* why = std::get_if<std::string>(&read)) {
          throw InputError(slot.cli->count() > 0 ? rule.flag() : rule.old_flag(), *why);
        }
        value = std::get<InputValue>(read);
        break;
      }
      case InputKind::kChoice:
        value = slot.word;
        break;
      case InputKind::kFlag:
        value = slot.on;
        break;
    }
    if (slot.old != nullptr && slot.old->count() > 0) {
      if (slot.cli->count() > 0) {
        throw InputError(rule.flag(), "give it once: " + rule.old_flag() + " is its old name");
      }
      // CLI11 checked the new name's values; the old name's are checked here
      if (const std::string why = rule.broken(value); !why.empty()) {
        throw InputError(rule.old_flag(), why);
      }
      warnings_.push_back(rule.old_flag() + ": renamed " + rule.flag() +
                          "; the old name is taken until the next release");
    }
    slot.input->set(value);
  }
}

// Alternatives given together, and inputs given without the one they go with.
void Command::check_pairings() const {
  for (const OptionSlot& slot : slots_) {
    if (!given(slot)) continue;
    const InputRule& rule = *slot.input->rule;
    for (const auto& pairing : rule.exclusions()) {
      if (given(pairing.other)) throw InputError(rule.flag(), pairing.rule);
    }
    for (const auto& pairing : rule.requirements()) {
      if (!given(pairing.other)) throw InputError(rule.flag(), pairing.rule);
    }
  }
}

std::string Command::given_among(const std::vector<std::string>& joint) const {
  std::vector<std::string> named;
  for (const std::string& flag : joint) {
    for (const OptionSlot& s : slots_) {
      if (s.input->rule->flag() == flag && given(s)) named.push_back(flag);
    }
  }
  return InputError::joined(named.empty() ? joint : named);
}

std::string Command::blamed_option() const {
  for (const OptionSlot& s : slots_) {
    if (s.input->rule->physical() && given(s)) return s.input->rule->flag();
  }
  for (const OptionSlot& s : slots_) {  // then a numerical one
    if (given(s)) return s.input->rule->flag();
  }
  return "--inputs";
}

void Command::check_animation_path() const {
  if (!animation_enabled_ || app_.count("--animate") == 0) {
    for (const char* flag : {"--fps", "--duration", "--animation-size"}) {
      if (animation_enabled_ && app_.count(flag) > 0)
        throw InputError(flag, "sets the animation: give --animate FILE too");
    }
    return;
  }
  if (animation_path_.empty()) throw InputError("--animate", "needs a file name");
#if RIGID_HAVE_RENDER
  if (!render::video_format_for(animation_path_)) {
    throw InputError("--animate", "the file name must end in .mp4 or .webp (got '" +
                                      quoted_text(animation_path_) + "')");
  }
#endif
  check_animation_file("--animate", animation_path_);
  // At least one frame: 1 fps for 0.1 s would be stretched to a second of video.
  const double frames = animation_fps_ * animation_duration_;
  if (frames < 1.0) {
    throw InputError("--duration",
                     fmt::format("holds no whole frame at --fps {:g} (fps x duration = {:g}); give "
                                 "at least {:g} s",
                                 animation_fps_, frames, 1.0 / animation_fps_));
  }
  // The work before it starts: every frame is drawn and encoded, so frames x pixels
  // bounds it (kMaxPixelFrames).
  const double pixel_frames = frames * animation_width_ * animation_height_;
  if (pixel_frames > kMaxPixelFrames) {
    throw InputError("--duration",
                     fmt::format("{:g} frames of {}x{} are {:.3g} pixels to draw, beyond the "
                                 "budget of {:.3g}: shorten --duration, or lower --fps or "
                                 "--animation-size",
                                 std::round(frames), animation_width_, animation_height_,
                                 pixel_frames, kMaxPixelFrames));
  }
}

void Command::check_output_paths() const {
  check_animation_path();
  if (app_.count("--figures") > 0 && figures_dir_.empty()) {
    throw InputError("--figures", "needs a directory name");
  }
  // as the animation's options without --animate: a setting for nothing is not ignored
  if (app_.count("--figures") == 0) {
    for (const char* flag : {"--figure-format", "--figure-size", "--figure-prefix"}) {
      if (app_.count(flag) > 0) throw InputError(flag, "sets the figures: give --figures DIR too");
    }
  }
  if (!figures_dir_.empty()) {
    // a figure's file: PREFIX + LAB + "_" + its name (a word of at most 32 bytes) + ".png",
    // ".svg" or ".pdf",
    // within NAME_MAX by --figure-prefix's rule
    const std::size_t longest_figure = figure_prefix_.size() + name_.size() + 1 + 32 + 4;
    check_output_dir("--figures", figures_dir_, longest_figure);
  }
  const bool csv = csv_enabled_ && app_.count("--csv") > 0;
  if (csv) {
    if (csv_path_.empty()) throw InputError("--csv", "needs a file name");
    check_output_file("--csv", csv_path_);
  }
  const bool animation = animation_enabled_ && app_.count("--animate") > 0;
  check_distinct_outputs(csv ? csv_path_ : "", animation ? animation_path_ : "", figures_dir_,
                         figure_prefix_ + name_ + "_", figure_extension());
}

void Command::parse(int argc, char** argv) {
  app_.allow_extras();
  for (int i = 0; i < argc; ++i) outputs_.command.emplace_back(argv[i]);
  const std::vector<std::string> args(outputs_.command.begin() + std::min(argc, 1),
                                      outputs_.command.end());
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

int Command::stdout_written(int status) const {
  // Output that never arrived (stdout closed, a full disk, a closed pipe) is an error,
  // for --help and --version as for a run.
  std::cout.flush();
  if (!std::cout) {
    std::cerr << name_ << ": error: stdout: the output could not be written ("
              << std::strerror(errno) << ")\n";
    return 1;
  }
  return status;
}

// LAB --explore ...: the explorer opens the lab with the other options as its inputs.
int Command::explore(int argc, char** argv, int at) const {
  const fs::path path = support::explorer_path();
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    std::cerr << name_
              << ": error: --explore: this build has no explorer (it is built where "
                 "libglfw3-dev and libimgui-dev are installed)\n";
    return 2;
  }
  // named as the lab, so that its messages ("LAB: error: ...") read as the lab's
  std::vector<std::string> args{name_, name_};
  for (int k = 1; k < argc; ++k) {
    if (k != at) args.emplace_back(argv[k]);
  }
  const std::string why = support::exec(path, args);
  std::cerr << name_ << ": error: --explore: cannot run " << support::terminal_safe(path.string())
            << " (" << why << ")\n";
  return 1;
}

int Command::run(int argc, char** argv, const std::function<Computed()>& compute) {
  for (int k = 1; k < argc; ++k) {
    if (std::strcmp(argv[k], "--explore") == 0) return explore(argc, argv, k);
  }
  // A closed pipe is a failed write to report, not a silent death by SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  const Report* report = nullptr;
  // Unless the run's files landed, the folders it made go too (if still empty).
  bool landed = false;
  const std::shared_ptr<void> unmake(nullptr, [&](void*) {
    if (landed) return;
    std::error_code ignored;
    for (const fs::path& dir : created_dirs_) fs::remove(dir, ignored);
  });
  try {
    try {
      parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
      return stdout_written(app_.exit(e));
    } catch (const CLI::CallForVersion& e) {
      return stdout_written(app_.exit(e));
    }
    store();
    check_output_paths();
    check_pairings();
    // The run's files (figures, CSV, animation) land together or not at all.
    render::FileTransaction files;
    const Computed computed = compute();
    report = computed.report;
    if (computed.animation) animate(computed);
    if (!figures_failed_ && !figures_dir_.empty()) draw_figures(computed);
    // A figure or the animation that failed (its error line is out): nothing lands,
    // and the CSV is not written to fail a second time (a full disk) with a second line.
    if (figures_failed_) return 1;
    if (!csv_path_.empty() && !report->time_series().columns.empty()) {
      const std::string text = csv_text(report->time_series());
      try {
        render::write_file_atomically(
            csv_path_, [&](std::FILE* file) { std::fwrite(text.data(), 1, text.size(), file); });
      } catch (const std::runtime_error& e) {
        throw InputError("--csv", e.what());
      }
    }
    // The report as it will be printed, composed before any file lands: once the
    // renames are done, only writing it to stdout is left.
    outputs_.figures_dir = figures_dir_;
    outputs_.csv_path = csv_path_;
    outputs_.animation_path = animation_path_;
    if (timing_) {
      outputs_.timing = {{"figure_seconds", figure_seconds_}, {"figure_phases", figure_phases_}};
    }
    std::ostringstream text;
    if (json_) {
      write_json(text, *report, outputs_, RIGID_VERSION);
    } else if (!quiet_) {
      write_table(text, *report, outputs_);
    }
    // Printed before the files land: a report that cannot be written (a full disk,
    // a closed pipe) leaves no file behind (the transaction removes them).
    for (const std::string& warning : warnings_) {
      std::cerr << name_ << ": warning: " << support::terminal_safe(warning) << '\n';
    }
    for (const std::string& warning : report->warnings()) {
      std::cerr << name_ << ": warning: " << support::terminal_safe(warning) << '\n';
    }
    std::cout << text.str();
    if (const int status = stdout_written(0); status != 0) return status;
    try {
      files.commit();
    } catch (const render::CommitError& e) {
      // The renames themselves failed (the disk or a folder changed under the run):
      // an output error, said of the file it names, with what had landed.
      const std::string option = e.path == csv_path_         ? "--csv"
                                 : e.path == animation_path_ ? "--animate"
                                                             : "--figures";
      std::cerr << name_ << ": error: " << support::terminal_safe(option + ": " + e.what()) << '\n';
      return 1;
    }
    landed = true;
    return 0;
  } catch (const InputError& e) {
    const std::string what = e.input.empty()   ? blamed_option() + ": " + e.rule
                             : e.joint.empty() ? e.what()
                                               : given_among(e.joint) + ": " + e.rule;
    std::cerr << name_ << ": error: " << support::terminal_safe(what) << '\n';
    return 2;
  } catch (const std::exception& e) {
    // A rule of core's broken where the lab named no input (or a failure it did
    // not foresee): the inputs given are to blame, the first physical one named.
    std::cerr << name_ << ": error: " << support::terminal_safe(blamed_option() + ": " + e.what())
              << '\n';
    return 2;
  }
}

// ---- Figures ----------------------------------------------------------------

// The figures as files <prefix><lab>_<name>.<format> in the --figures directory. A PNG
// is encoded on a second thread while the next figure is drawn (the drawing needs the
// GL context, which is this thread's; the encoding only the pixels); finish() waits for
// the last and rethrows what failed.
class Command::FigureFiles : public FigureSink {
 public:
  FigureFiles(Command& command, const Report& report) : command_(command), report_(report) {}
  FigureFiles(const FigureFiles&) = delete;
  FigureFiles& operator=(const FigureFiles&) = delete;
  ~FigureFiles() override {
    // a failure elsewhere: the encoding in flight is waited for, its own error dropped
    if (encoding_.valid()) encoding_.wait();
  }
  void add(const std::string& name, const std::string& caption, render::Plot2D plot) override {
    plot.title = report_.figure_title(plot.title);
    save(name, caption, plot);
  }
  void add(const std::string& name, const std::string& caption, render::Scene3D scene) override {
    scene.title = report_.figure_title(scene.title);
    save(name, caption, scene);
  }
  /// Waits for the last PNG; its error, if any, is thrown here.
  void finish();

 private:
  // What a figure took, its encoding's share known when that is done.
  struct Drawn {
    std::string file;
    double seconds = 0;
    render::FigureTiming phases;
  };
  template <class Figure>
  void save(const std::string& name, const std::string& caption, const Figure& figure);
  void record(const Drawn& drawn);
  Command& command_;
  const Report& report_;
  std::future<double> encoding_;  ///< the seconds the PNG in flight took to encode
  Drawn in_flight_;
};

template <class Figure>
void Command::FigureFiles::save(const std::string& name, const std::string& caption,
                                const Figure& figure) {
  Command& c = command_;
  const std::string file = c.figure_prefix_ + c.name_ + "_" + name + c.figure_extension();
  const fs::path path = fs::path(c.figures_dir_) / file;
  if (fs::is_directory(path)) {
    throw InputError("--figures", "'" + path.string() + "' is a directory, not a figure");
  }
  c.outputs_.figures.push_back(file);
  c.outputs_.captions[file] = caption;
  const auto start = std::chrono::steady_clock::now();
  const auto since = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
#if RIGID_HAVE_RENDER
  // --timing: where each figure's time went (the phases wait for the GL to finish each)
  Drawn drawn{file, 0.0, {}};
  render::FigureTiming* phases = c.timing_ ? &drawn.phases : nullptr;
  if (c.figure_format_ != render::FigureFormat::kPng) {
    render::save_figure(figure, path.string(), c.figure_format_, c.figure_width_, c.figure_height_,
                        phases);
    drawn.seconds = since();
    record(drawn);
    return;
  }
  render::Image image = render::draw(figure, c.figure_width_, c.figure_height_, phases);
  drawn.seconds = since();
  finish();  // one PNG in flight at a time
  in_flight_ = std::move(drawn);
  encoding_ = std::async(std::launch::async, [image = std::move(image), path] {
    const auto t0 = std::chrono::steady_clock::now();
    render::write_png(image, path.string());
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  });
#else
  (void)figure;
  (void)since;
  throw std::runtime_error("this build has no renderer (RIGID_BUILD_RENDER=OFF)");
#endif
}

void Command::FigureFiles::finish() {
  if (!encoding_.valid()) return;
  const double encode = encoding_.get();
  in_flight_.seconds += encode;
  in_flight_.phases.encode = encode;
  record(in_flight_);
}

void Command::FigureFiles::record(const Drawn& drawn) {
  Command& c = command_;
  c.figure_seconds_[drawn.file] = drawn.seconds;
  if (c.timing_) {
    const render::FigureTiming& p = drawn.phases;
    c.figure_phases_[drawn.file] = {{"setup", p.setup},
                                    {"layout", p.layout},
                                    {"draw", p.draw},
                                    {"resolve", p.resolve},
                                    {"encode", p.encode}};
  }
  // A figure the user made very large (past 4x the default's pixels) takes seconds
  // each: say so as each is drawn, rather than sit silent.
  if (static_cast<double>(c.figure_width_) * c.figure_height_ > 4.0 * 1600 * 1200) {
    std::cerr << c.name_ << ": drew " << drawn.file << " (" << c.figure_width_ << "x"
              << c.figure_height_ << ") in " << fmt::format("{:.1f}", drawn.seconds) << " s\n";
  }
}

void Command::draw_figures(const Computed& computed) {
  std::error_code error;
  // The folders this run makes, deepest first: removed again if the run lands nothing.
  // A name that is there as anything, a dangling link included (symlink_status), is not
  // this run's to remove.
  const auto missing = [](const fs::path& p) {
    std::error_code ec;
    return fs::symlink_status(p, ec).type() == fs::file_type::not_found;
  };
  for (fs::path dir = fs::absolute(figures_dir_, error).lexically_normal();
       !error && !dir.empty() && missing(dir) && dir != dir.parent_path();
       dir = dir.parent_path()) {
    created_dirs_.push_back(dir);
  }
  fs::create_directories(figures_dir_, error);
  if (error) {
    throw InputError("--figures",
                     "cannot create directory '" + figures_dir_ + "': " + error.message());
  }
  try {
#if RIGID_HAVE_RENDER
    // The GL context is made once per process, before any figure is drawn and
    // timed (bench/ reports it on its own, like matplotlib's import).
    render::context();
#else
    throw std::runtime_error("this build has no renderer (RIGID_BUILD_RENDER=OFF)");
#endif
    FigureFiles sink(*this, *computed.report);
    computed.figures(sink);
    sink.finish();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    figures_failed_ = true;
    std::cerr << name_ << ": error: --figures: " << support::terminal_safe(e.what()) << '\n';
  }
}

// ---- Animation --------------------------------------------------------------

std::vector<double> Command::animation_times(double motion_seconds) const {
  const int frames = frame_count(animation_duration_, animation_fps_);
  std::vector<double> times;
  for (int k = 0; k < frames; ++k) times.push_back(film_time(motion_seconds, k, frames));
  for (int k = 0; k < kFitSamples; ++k) times.push_back(film_time(motion_seconds, k, kFitSamples));
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

// --animate FILE: the lab's motion as an animated WebP or an H.264 MP4 (by the
// file's extension). The frames are drawn at their own times with one camera
// fitted to the whole motion, while a second thread encodes them (render/video.h).
void Command::animate(const Computed& computed) {
  if (animation_path_.empty()) return;
  const Animation motion =
      computed.animation([this](double seconds) { return animation_times(seconds); });
  const double motion_seconds = motion.seconds;
  if (!(motion_seconds > 0.0) || !std::isfinite(motion_seconds)) {
    throw InputError("--animate", "there is no motion to show (its span is not positive)");
  }
  const Report& report = *computed.report;
#if RIGID_HAVE_RENDER
  const auto start = std::chrono::steady_clock::now();
  const int frames = frame_count(animation_duration_, animation_fps_);
  const auto motion_time = [&](int k) { return film_time(motion_seconds, k, frames); };
  const int w = animation_width_, h = animation_height_;
  // the scene above, the strip (if any) below: both even, for H.264
  const int h_strip =
      motion.strip ? 2 * static_cast<int>(std::lround(0.5 * motion.strip_share * h)) : 0;
  const int h_scene = h - h_strip;
  try {
    render::context();
    // one camera for every frame, fitted to the union of frames spread over the motion
    render::Scene3D envelope = motion_envelope(motion);
    envelope.title = report.figure_title(envelope.title);
    const render::Camera camera = render::fitted_camera(envelope, w, h_scene);
    // and one legend, of every part any frame shows
    const auto legend = std::make_shared<const render::Scene3D>(envelope.legend_only());

    render::VideoWriter writer(animation_path_, *render::video_format_for(animation_path_),
                               {w, h, animation_fps_});
    support::Progress progress(name_, "animation frames", frames, quiet_);
    // --timing: where the frames' time went (the GL phases waited for, as for figures)
    render::FigureTiming phases;
    double build = 0.0, handover = 0.0;
    const auto lap = [](std::chrono::steady_clock::time_point& t0) {
      const auto t1 = std::chrono::steady_clock::now();
      const double s = std::chrono::duration<double>(t1 - t0).count();
      t0 = t1;
      return s;
    };
    const auto add_phases = [&phases](const render::FigureTiming& f) {
      phases.setup += f.setup, phases.layout += f.layout, phases.draw += f.draw,
          phases.resolve += f.resolve;
    };
    for (int k = 0; k < frames; ++k) {
      auto t0 = std::chrono::steady_clock::now();
      render::Scene3D scene = motion.scene(motion_time(k));
      scene.title = report.figure_title(scene.title);
      scene.camera = camera;
      scene.legend_from = legend;
      build += lap(t0);
      render::FigureTiming f;
      render::Image image = render::draw(scene, w, h_scene, timing_ ? &f : nullptr);
      add_phases(f);
      if (motion.strip) {
        render::Plot2D plot = motion.strip(motion_time(k));
        plot.style_height = h;
        const render::Image below = render::draw(plot, w, h_strip, timing_ ? &f : nullptr);
        add_phases(f);
        image.height = h;
        image.rgb.insert(image.rgb.end(), below.rgb.begin(), below.rgb.end());
      }
      lap(t0);
      writer.add(std::move(image));  // waits while two frames are still being encoded
      handover += lap(t0);
      progress.update(k + 1);
    }
    auto t_finish = std::chrono::steady_clock::now();
    const std::size_t bytes = writer.finish();
    const double finishing = lap(t_finish);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::error_code ec;
    Json& animation = outputs_.animation;
    animation = {{"path", fs::absolute(animation_path_, ec).lexically_normal().string()},
                 {"caption", motion.caption},
                 {"frames", frames},
                 {"fps", animation_fps_},
                 {"duration_s", frames / animation_fps_},
                 {"motion_s", motion_seconds},
                 {"width", w},
                 {"height", h},
                 {"bytes", bytes},
                 {"seconds", seconds}};
    if (!motion.still.empty()) {
      animation["still"] = figure_prefix_ + name_ + "_" + motion.still + figure_extension();
    }
    if (timing_) {
      animation["phases"] = {
          {"scene", build},      {"setup", phases.setup},     {"layout", phases.layout},
          {"draw", phases.draw}, {"resolve", phases.resolve}, {"encoder_wait", handover},
          {"finish", finishing}};
    }
    progress.finish(fmt::format(
        "wrote {}: {} frames, {}x{} at {:g} fps ({:g} s of video for {:.3g} s of motion), "
        "{:.1f} MB, in {:.1f} s",
        support::terminal_safe(animation_path_), frames, w, h, animation_fps_,
        frames / animation_fps_, motion_seconds, bytes / 1e6, seconds));
  } catch (const InputError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw InputError("--animate", e.what());
  } catch (const std::exception& e) {
    figures_failed_ = true;
    std::cerr << name_ << ": error: --animate: " << support::terminal_safe(e.what()) << '\n';
  }
#else
  (void)report;
  figures_failed_ = true;
  std::cerr << name_ << ": error: --animate: this build has no renderer (RIGID_BUILD_RENDER=OFF)\n";
#endif
}

}  // namespace

int run_command(const std::string& name, const std::string& title,
                const std::vector<BoundInput>& inputs, bool csv, bool animation, int argc,
                char** argv, const std::function<Computed()>& compute) {
  Command command(name, title, inputs, csv, animation);
  return command.run(argc, argv, compute);
}

}  // namespace rigid::lab
