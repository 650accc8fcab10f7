#include "common/output_paths.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <filesystem>

#include "common/inputs.h"

namespace rigid::lab {
namespace fs = std::filesystem;

namespace {
// The longest file name written, leaving room for the temporary's suffix (NAME_MAX 255).
constexpr std::size_t kMaxFileName = 224;
}  // namespace

bool can_create_in(const std::string& dir) {
  const std::string probe =
      (fs::path(dir) / fmt::format(".rigidlab-probe-{}", ::getpid())).string();
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) return false;
  ::close(fd);
  ::unlink(probe.c_str());
  return true;
}

void check_output_dir(const std::string& option, const std::string& dir_name) {
  std::error_code ec;  // every filesystem question is asked without throwing
  // Nothing is created before the lab has computed its results: find the
  // nearest existing ancestor and check that it can be written.
  fs::path dir = fs::absolute(dir_name, ec);
  while (!ec && !fs::exists(dir, ec) && dir.has_parent_path() && dir != dir.parent_path()) {
    dir = dir.parent_path();
  }
  if (ec || !fs::is_directory(dir, ec) || !can_create_in(dir.string())) {
    throw InputError(option, "cannot create or write directory '" + dir_name + "'");
  }
}

void check_output_file(const std::string& option, const std::string& name) {
  std::error_code ec;
  const fs::path path = fs::absolute(name, ec);
  if (ec || path.filename().string().size() > kMaxFileName) {
    throw InputError(option, fmt::format("file name longer than {} characters", kMaxFileName));
  }
  // Only a regular file is written (by rename, so a link would be replaced, not
  // followed, and a device or pipe replaced by a file): refuse anything else.
  const fs::file_status status = fs::symlink_status(path, ec);
  if (!ec && fs::exists(status)) {
    if (fs::is_symlink(status)) {
      throw InputError(option, "'" + name + "' is a symbolic link; give the file itself");
    }
    if (fs::is_directory(status)) {
      throw InputError(option, "'" + name + "' is a directory, not a file");
    }
    if (!fs::is_regular_file(status)) {
      throw InputError(option, "'" + name +
                                   "' is not a regular file (a device, pipe or "
                                   "socket); give a file name");
    }
  }
  const fs::path parent = path.parent_path();
  if (!fs::is_directory(parent, ec) || !can_create_in(parent.string())) {
    throw InputError(option, "cannot write into directory '" + parent.string() + "'");
  }
}

void check_animation_file(const std::string& option, const std::string& name) {
  std::error_code ec;
  const fs::path path = fs::absolute(name, ec);
  const fs::file_status status = fs::symlink_status(path, ec);
  if (!ec && fs::exists(status) && !fs::is_regular_file(status)) {
    throw InputError(option, "'" + name + "' exists and is not a regular file");
  }
  const fs::path parent = path.parent_path();
  if (!fs::is_directory(parent, ec) || !can_create_in(parent.string())) {
    throw InputError(option, "cannot write into directory '" + parent.string() + "'");
  }
}

}  // namespace rigid::lab
