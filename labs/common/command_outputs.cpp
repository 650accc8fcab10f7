#include "common/command_outputs.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <vector>

#include "common/command_render.h"
#include "common/output_paths.h"
#include "common/writers.h"
#include "rigid/render/atomic_file.h"
#include "rigid/render/memory.h"
#include "rigid/support/text.h"

namespace rigid::lab {
namespace fs = std::filesystem;
namespace {

// The folders a run makes for --figures, deepest first: removed again (if still empty)
// unless the run's files landed.
class MadeFolders {
 public:
  MadeFolders() = default;
  MadeFolders(const MadeFolders&) = delete;
  MadeFolders& operator=(const MadeFolders&) = delete;
  ~MadeFolders() {
    if (kept_) return;
    std::error_code ignored;
    for (const fs::path& dir : dirs_) fs::remove(dir, ignored);
  }
  /// Makes `dir` (at its place: output_paths.h) and its missing parents, noting them;
  /// throws InputError for --figures.
  void make(const std::string& name) {
    const fs::path dir = output_place(name);
    std::error_code error;
    // A name that is there as anything, a dangling link included (symlink_status), is
    // not this run's to remove.
    const auto missing = [](const fs::path& p) {
      std::error_code ec;
      return fs::symlink_status(p, ec).type() == fs::file_type::not_found;
    };
    for (fs::path d = dir; !d.empty() && missing(d) && d != d.parent_path(); d = d.parent_path()) {
      dirs_.push_back(d);
    }
    fs::create_directories(dir, error);
    if (error) {
      throw InputError("--figures",
                       "cannot create directory '" + quoted_text(name) + "': " + error.message());
    }
  }
  void keep() { kept_ = true; }

 private:
  std::vector<fs::path> dirs_;
  bool kept_ = false;
};

// The times, sorted, at which a film of `motion_seconds` asks for its scene: its
// frames and the camera's fit (figures.h: FrameTimes).
std::vector<double> film_times(const CommandOptions& options, double motion_seconds) {
  const int frames = options.animation_frames();
  std::vector<double> times;
  for (int k = 0; k < frames; ++k) times.push_back(film_time(motion_seconds, k, frames));
  for (int k = 0; k < kFitSamples; ++k) times.push_back(film_time(motion_seconds, k, kFitSamples));
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

// A drawing the run could not have the memory for is refused before any work, naming
// its size, rather than killed by the system midway (render/memory.h: the model of
// the peak; support/memory.h: what the run may use).
void check_memory(const CommandOptions& options) {
  if (!options.figures_dir.empty()) {
    check_drawing_memory("--figure-size", options.figure_width, options.figure_height,
                         render::figure_peak_bytes(options.figure_width, options.figure_height));
  }
  if (!options.animation_path.empty()) {
    check_drawing_memory(
        "--animation-size", options.animation_width, options.animation_height,
        render::film_peak_bytes(options.animation_width, options.animation_height));
  }
}

class OutputRun {
 public:
  explicit OutputRun(const CommandOptions& options) : options_(options) {
    outputs_.command = options.command;
  }
  int write(const std::function<Computed()>& compute);

 private:
  void animate(const Computed& computed);
  void draw(const Computed& computed);
  void write_csv(const Report& report);
  std::string report_text(const Report& report);
  void warn(const Report& report) const;
  int land(render::FileTransaction& files) const;
  /// An output's failed write, said once: nothing lands, and the exit status is 1.
  void failed(const char* option, const std::exception& e) {
    failed_ = true;
    std::cerr << options_.lab << ": error: " << option << ": " << support::terminal_safe(e.what())
              << '\n';
  }

  const CommandOptions& options_;
  MadeFolders folders_;
  RunOutputs outputs_;
  FigureLog log_;
  bool failed_ = false;
};

int OutputRun::write(const std::function<Computed()>& compute) {
  check_memory(options_);
  // The run's files (figures, CSV, animation) land together or not at all.
  render::FileTransaction files;
  const Computed computed = compute();
  const Report& report = *computed.report;
  if (computed.animation) animate(computed);
  if (!failed_ && !options_.figures_dir.empty()) draw(computed);
  // A figure or the animation that failed (its error line is out): nothing lands,
  // and the CSV is not written to fail a second time (a full disk) with a second line.
  if (failed_) return 1;
  write_csv(report);
  if (failed_) return 1;
  const std::string text = report_text(report);
  // Printed before the files land: a report that cannot be written (a full disk,
  // a closed pipe) leaves no file behind (the transaction removes them).
  warn(report);
  std::cout << text;
  if (const int status = stdout_written(options_.lab, 0); status != 0) return status;
  if (const int status = land(files); status != 0) return status;
  folders_.keep();
  return 0;
}

// --animate FILE: the lab's motion as an animated WebP or an H.264 MP4 (by the
// file's extension), sampled at the film's own times.
void OutputRun::animate(const Computed& computed) {
  if (options_.animation_path.empty()) return;
  const Animation motion =
      computed.animation([this](double seconds) { return film_times(options_, seconds); });
  if (!(motion.seconds > 0.0) || !std::isfinite(motion.seconds)) {
    throw InputError("--animate", "there is no motion to show (its span is not positive)");
  }
  try {
    outputs_.animation = encode_animation(options_, motion, *computed.report);
  } catch (const InputError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw InputError("--animate", e.what());
  } catch (const std::exception& e) {
    failed("--animate", e);
  }
}

void OutputRun::draw(const Computed& computed) {
  folders_.make(options_.figures_dir);
  try {
    draw_figures(options_, computed, outputs_, log_);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    failed("--figures", e);
  }
}

// The CSV and its metadata beside it land together. A CSV that cannot be written (a
// full disk, EFBIG past ulimit -f) is a failed write, exit 1 as for a figure: its path
// passed the checks made before any work.
void OutputRun::write_csv(const Report& report) {
  if (options_.csv_path.empty() || report.time_series().columns.empty()) return;
  try {
    write_csv_files(report.time_series(), options_.csv_path);
  } catch (const std::runtime_error& e) {
    failed("--csv", e);
  }
}

// The report as it will be printed, composed before any file lands: once the
// renames are done, only writing it to stdout is left.
std::string OutputRun::report_text(const Report& report) {
  outputs_.figures_dir = options_.figures_dir;
  outputs_.csv_path = options_.csv_path;
  outputs_.animation_path = options_.animation_path;
  if (options_.timing) {
    outputs_.timing = {{"figure_seconds", log_.seconds}, {"figure_phases", log_.phases}};
  }
  std::ostringstream text;
  if (options_.json) {
    write_json(text, report, outputs_, RIGID_VERSION);
  } else if (!options_.quiet) {
    write_table(text, report, outputs_);
  }
  return text.str();
}

void OutputRun::warn(const Report& report) const {
  for (const auto* warnings : {&options_.warnings, &report.warnings()}) {
    for (const std::string& warning : *warnings) {
      std::cerr << options_.lab << ": warning: " << support::terminal_safe(warning) << '\n';
    }
  }
}

int OutputRun::land(render::FileTransaction& files) const {
  try {
    files.commit();
  } catch (const render::CommitError& e) {
    // The renames themselves failed (the disk or a folder changed under the run):
    // an output error, said of the file it names, with what had landed.
    const std::string option = e.path == options_.csv_path         ? "--csv"
                               : e.path == options_.animation_path ? "--animate"
                                                                   : "--figures";
    std::cerr << options_.lab << ": error: " << support::terminal_safe(option + ": " + e.what())
              << '\n';
    return 1;
  }
  return 0;
}

}  // namespace

int write_outputs(const CommandOptions& options, const std::function<Computed()>& compute) {
  OutputRun run(options);
  return run.write(compute);
}

int stdout_written(const std::string& lab, int status) {
  // Output that never arrived (stdout closed, a full disk, a closed pipe) is an error,
  // for --help and --version as for a run.
  std::cout.flush();
  if (!std::cout) {
    std::cerr << lab << ": error: stdout: the output could not be written (" << std::strerror(errno)
              << ")\n";
    return 1;
  }
  return status;
}

}  // namespace rigid::lab
