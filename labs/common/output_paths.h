// Checks of the paths a lab will write, made before any work: a bad path is an
// InputError naming the option, never a failure after the results are computed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "common/report.h"

namespace rigid::lab {

/// True if a file can be created in directory `dir`: tried (a probe file made with
/// O_EXCL and removed), since permission bits do not tell (root may write anywhere by
/// them, yet not into /proc or a read-only mount).
bool can_create_in(const std::string& dir);

/// The directory `dir` (--figures) exists and can be written, or can be created, and a
/// file name of `longest_file` bytes inside it is a path the system can open.
void check_output_dir(const std::string& option, const std::string& dir, std::size_t longest_file);
/// `path` (--csv) can be written as a regular file by rename.
void check_output_file(const std::string& option, const std::string& path);
/// `path` and its metadata's path can both be written as regular files by rename.
void check_csv_file(const std::string& option, const std::string& path);
/// Writes `series` to `path` as CSV and its metadata beside it, each atomically (within
/// the live FileTransaction, if one is); throws std::runtime_error for a failed write.
void write_csv_files(const TimeSeries& series, const std::string& path);
/// The same, checked first as --csv is (check_csv_file: an InputError naming no option),
/// the two files landing together or neither: an export's, outside a command's run.
void save_csv_files(const TimeSeries& series, const std::string& path);
/// `path` (--animate) is not something other than a regular file, and its directory
/// can be written.
void check_animation_file(const std::string& option, const std::string& path);

/// A drawing of `width` x `height` that takes `need` bytes at its peak (render/memory.h)
/// fits in what the run may use (support/memory.h); else an InputError naming `option`
/// ("--figure-size: 8192x8192 takes about 3.4 GB to draw, more than ..."), or naming
/// RIGIDLAB_MEMORY_MB for a setting of it that breaks its rule. Nothing is checked where
/// the system does not say what is available.
void check_drawing_memory(const std::string& option, int width, int height, std::uint64_t need);

/// Where an output name points, as one spelling: absolute, the links and dots of its
/// existing part resolved, the rest's dots removed, no trailing separator. Two names of
/// one file (d/x/../f, d/./f, a link to d) have one place; a folder a run makes for
/// --figures is made here, so `d/x/..` does not make `d/x`.
std::filesystem::path output_place(const std::string& name);

/// The run's outputs are different places (each "" if not asked for): --csv (and the
/// metadata beside it) and --animate not the same file, neither where --figures writes a
/// figure (a name `figure_stem`*`figure_extension`, e.g. "poinsot_*.png", in that
/// directory), and the directory not inside either file.
void check_distinct_outputs(const std::string& csv, const std::string& animation,
                            const std::string& figures_dir, const std::string& figure_stem,
                            const std::string& figure_extension);

}  // namespace rigid::lab
