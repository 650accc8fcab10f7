#include "common/output_paths.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <utility>

#include "common/inputs.h"
#include "common/writers.h"
#include "rigid/render/atomic_file.h"
#include "rigid/support/memory.h"

namespace rigid::lab {
namespace fs = std::filesystem;

namespace {
// The longest file name the filesystem takes (NAME_MAX, 255 bytes): any of them is
// written (a temporary whose suffix would not fit is a hidden one beside it).
constexpr std::size_t kMaxFileName = NAME_MAX;
// The longest path the system opens (PATH_MAX, 4096 bytes with its end).
constexpr std::size_t kMaxPath = PATH_MAX - 1;

// A name no file can have is refused before any work: each part at most NAME_MAX
// bytes, the whole path (as the program will open it) under PATH_MAX. `longest_leaf`
// is the longest file name that will be written inside `name` (a figure's, for a
// folder).
void check_name_length(const std::string& option, const std::string& name,
                       std::size_t longest_leaf = 0) {
  std::error_code ec;
  const fs::path path = fs::absolute(name, ec);
  for (const fs::path& part : path) {
    if (part.string().size() > kMaxFileName) {
      throw InputError(option, fmt::format("'{}' holds a name longer than {} bytes, the "
                                           "filesystem's limit",
                                           quoted_text(name), kMaxFileName));
    }
  }
  if (ec || path.string().size() + (longest_leaf ? longest_leaf + 1 : 0) > kMaxPath) {
    throw InputError(option, fmt::format("'{}' is a path longer than {} bytes, the system's limit",
                                         quoted_text(name), kMaxPath));
  }
}
}  // namespace

bool can_create_in(const std::string& dir) {
  const std::string probe =
      (fs::path(dir) / fmt::format(".rigidlab-probe-{}", ::getpid())).string();
  // A signal that ends the run between the probe's creation and its removal would leave
  // it behind (the handler removes only the run's temporaries): held until it is gone.
  sigset_t all, before;
  sigfillset(&all);
  ::pthread_sigmask(SIG_BLOCK, &all, &before);
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd >= 0) {
    ::close(fd);
    ::unlink(probe.c_str());
  }
  ::pthread_sigmask(SIG_SETMASK, &before, nullptr);
  return fd >= 0;
}

void check_output_dir(const std::string& option, const std::string& dir_name,
                      std::size_t longest_file) {
  check_name_length(option, dir_name, longest_file);
  std::error_code ec;  // every filesystem question is asked without throwing
  // Nothing is created before the lab has computed its results: find the
  // nearest existing ancestor and check that it can be written.
  fs::path dir = fs::absolute(dir_name, ec);
  while (!ec && !fs::exists(dir, ec) && dir.has_parent_path() && dir != dir.parent_path()) {
    dir = dir.parent_path();
  }
  if (ec || !fs::is_directory(dir, ec) || !can_create_in(dir.string())) {
    throw InputError(option, "cannot create or write directory '" + quoted_text(dir_name) + "'");
  }
}

void check_csv_file(const std::string& option, const std::string& name) {
  check_output_file(option, name);
  const std::string metadata = csv_metadata_path(name);
  if (fs::path(metadata).filename().string().size() > kMaxFileName) {
    throw InputError(
        option, fmt::format("'{}' leaves no room for the metadata beside it: '{}' "
                            "would be a name longer than {} bytes",
                            quoted_text(name), quoted_text(fs::path(metadata).filename().string()),
                            kMaxFileName));
  }
  check_output_file(option, metadata);
}

void write_csv_files(const TimeSeries& series, const std::string& path) {
  render::write_text_atomically(path, csv_text(series));
  render::write_text_atomically(csv_metadata_path(path),
                                csv_metadata_text(series, path, RIGID_VERSION));
}

void save_csv_files(const TimeSeries& series, const std::string& path) {
  check_csv_file("", path);
  render::FileTransaction files;
  write_csv_files(series, path);
  files.commit();
}

void check_output_file(const std::string& option, const std::string& name) {
  check_name_length(option, name);
  std::error_code ec;
  const fs::path path = fs::absolute(name, ec);
  // Only a regular file is written (by rename, so a link would be replaced, not
  // followed, and a device or pipe replaced by a file): refuse anything else.
  const fs::file_status status = fs::symlink_status(path, ec);
  if (!ec && fs::exists(status)) {
    if (fs::is_symlink(status)) {
      throw InputError(option,
                       "'" + quoted_text(name) + "' is a symbolic link; give the file itself");
    }
    if (fs::is_directory(status)) {
      throw InputError(option, "'" + quoted_text(name) + "' is a directory, not a file");
    }
    if (!fs::is_regular_file(status)) {
      throw InputError(option, "'" + quoted_text(name) +
                                   "' is not a regular file (a device, pipe or "
                                   "socket); give a file name");
    }
  }
  const fs::path parent = path.parent_path();
  if (!fs::is_directory(parent, ec) || !can_create_in(parent.string())) {
    throw InputError(option, "cannot write into directory '" + quoted_text(parent.string()) + "'");
  }
}

void check_animation_file(const std::string& option, const std::string& name) {
  check_name_length(option, name);
  std::error_code ec;
  const fs::path path = fs::absolute(name, ec);
  const fs::file_status status = fs::symlink_status(path, ec);
  if (!ec && fs::exists(status) && !fs::is_regular_file(status)) {
    throw InputError(option, "'" + quoted_text(name) + "' exists and is not a regular file");
  }
  const fs::path parent = path.parent_path();
  if (!fs::is_directory(parent, ec) || !can_create_in(parent.string())) {
    throw InputError(option, "cannot write into directory '" + quoted_text(parent.string()) + "'");
  }
}

void check_drawing_memory(const std::string& option, int width, int height, std::uint64_t need) {
  std::optional<support::MemoryBudget> budget;
  try {
    budget = support::memory_budget();
  } catch (const std::invalid_argument& e) {
    throw InputError(support::kMemoryBudgetVariable, e.what());
  }
  if (!budget || need <= budget->bytes) return;
  throw InputError(option, fmt::format("{}x{} takes about {} to draw, more than the {} this run "
                                       "may use ({}); give a smaller size",
                                       width, height, support::bytes_text(need),
                                       support::bytes_text(budget->bytes), budget->source));
}

fs::path output_place(const std::string& name) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(name, ec), ec);
  if (ec) p = fs::absolute(name, ec).lexically_normal();
  // "d/x/.." is "/abs/d/" once normal: the folder, named without its trailing separator
  if (!p.has_filename() && p.has_parent_path() && p != p.root_path()) p = p.parent_path();
  return p;
}

namespace {
// `inner` is `outer` or lies below it.
bool within(const fs::path& inner, const fs::path& outer) {
  const auto [end, _] = std::mismatch(outer.begin(), outer.end(), inner.begin(), inner.end());
  return end == outer.end();
}
}  // namespace

void check_distinct_outputs(const std::string& csv, const std::string& animation,
                            const std::string& figures_dir, const std::string& figure_stem,
                            const std::string& figure_extension) {
  // --csv writes two files: FILE and its metadata beside it.
  const std::string metadata = csv.empty() ? "" : csv_metadata_path(csv);
  if (!csv.empty() && !animation.empty()) {
    for (const std::string& written : {csv, metadata}) {
      if (output_place(written) == output_place(animation)) {
        throw InputError("--animate", "'" + quoted_text(animation) +
                                          "' is a file --csv writes; give each its own");
      }
    }
  }
  if (figures_dir.empty()) return;
  const fs::path figures = output_place(figures_dir);
  for (const auto& [option, name] :
       {std::pair{"--csv", csv}, std::pair{"--csv", metadata}, std::pair{"--animate", animation}}) {
    if (name.empty()) continue;
    const fs::path file = output_place(name);
    if (within(figures, file)) {
      throw InputError("--figures", "'" + quoted_text(figures_dir) +
                                        "' would lie inside the file " + option + " writes ('" +
                                        quoted_text(name) + "')");
    }
    const std::string leaf = file.filename().string();
    const std::size_t ext = figure_extension.size();
    if (file.parent_path() == figures && leaf.rfind(figure_stem, 0) == 0 && leaf.size() >= ext &&
        leaf.compare(leaf.size() - ext, ext, figure_extension) == 0) {
      throw InputError(option, "'" + quoted_text(name) +
                                   "' is where --figures writes its figures (" +
                                   quoted_text(figure_stem) + "*" + figure_extension + " in '" +
                                   quoted_text(figures_dir) + "'); give another name");
    }
  }
}

}  // namespace rigid::lab
