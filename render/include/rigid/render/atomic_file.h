// Atomic file writing: a file appears complete under its name or not at all.
// The content goes to a temporary in the target's directory
// (TARGET.rigidlab-tmp-PID-RANDOM: a marker, the process id and 16 random hex
// digits, within the file system's name limit), is flushed and checked, and is
// renamed into place; a failure removes the temporary. PNG figures, the labs'
// CSV and animations use it, and every text file a program writes (write_text_atomically).
//
// A FileTransaction makes a run's files land together or not at all: while one
// lives, each file stays at its temporary name until commit() renames them all;
// without a commit they are removed. A signal that ends the process (SIGINT, SIGTERM,
// SIGHUP, SIGQUIT, SIGALRM and the others whose default is death, but not a fault's)
// removes every temporary the process holds before it dies by that signal; SIGXFSZ is
// ignored, so that a file past the size limit (ulimit -f) is a failed write (EFBIG)
// like a full disk. A writer removes the temporaries that dead processes left beside
// its target: names of exactly that pattern, regular files of this user, whose process
// is gone. Nothing else is touched.
#pragma once

#include <cstddef>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace rigid::render {

/// Writes a file through `write` (which fills the stream, and may throw) and renames it to `path`;
/// on any failure removes the temporary and throws std::runtime_error "cannot write 'PATH': REASON"
/// (one line).
void write_file_atomically(const std::string& path, const std::function<void(std::FILE*)>& write);

/// Writes `text` as the whole file `path`, atomically as above (a short write, say on a
/// full disk, is the stream's error and throws).
inline void write_text_atomically(const std::string& path, std::string_view text) {
  write_file_atomically(
      path, [text](std::FILE* file) { std::fwrite(text.data(), 1, text.size(), file); });
}

/// What FileTransaction::commit() throws when a rename fails: the file it could not
/// put in place, and how many of the transaction's files had landed before it.
struct CommitError : std::runtime_error {
  CommitError(const std::string& what, std::string failed_path, std::size_t landed_files,
              std::size_t total_files)
      : std::runtime_error(what),
        path(std::move(failed_path)),
        landed(landed_files),
        total(total_files) {}
  std::string path;
  std::size_t landed, total;
};

/// Holds back the renames of write_file_atomically until commit() (one at a time).
class FileTransaction {
 public:
  FileTransaction();
  ~FileTransaction();  ///< without commit(): removes every file written under it
  FileTransaction(const FileTransaction&) = delete;
  FileTransaction& operator=(const FileTransaction&) = delete;
  /// Renames every file written under the transaction into place; throws CommitError
  /// (one line, saying how many had landed) if one cannot be, after removing the rest.
  void commit();
};

}  // namespace rigid::render
