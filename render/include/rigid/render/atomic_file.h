// Atomic file writing: a file appears complete under its name or not at all.
// The content goes to a temporary in the target's directory
// (TARGET.rigidlab-tmp-PID-RANDOM: a marker, the process id and 16 random hex
// digits, within the file system's name limit), is flushed and checked, and is
// renamed into place; a failure removes the temporary. PNG figures, the labs'
// CSV and animations use it.
//
// A FileTransaction makes a run's files land together or not at all: while one
// lives, each file stays at its temporary name until commit() renames them all;
// without a commit they are removed. SIGINT and SIGTERM remove every temporary
// the process holds before it dies, and a writer removes the temporaries that
// dead processes left beside its target: names of exactly that pattern, regular
// files of this user, whose process is gone. Nothing else is touched.
#pragma once

#include <cstdio>
#include <functional>
#include <string>

namespace rigid::render {

/// Writes a file through `write` (which fills the stream, and may throw) and renames it to `path`;
/// on any failure removes the temporary and throws std::runtime_error "cannot write 'PATH': REASON"
/// (one line).
void write_file_atomically(const std::string& path, const std::function<void(std::FILE*)>& write);

/// Holds back the renames of write_file_atomically until commit() (one at a time).
class FileTransaction {
 public:
  FileTransaction();
  ~FileTransaction();  ///< without commit(): removes every file written under it
  FileTransaction(const FileTransaction&) = delete;
  FileTransaction& operator=(const FileTransaction&) = delete;
  /// Renames every file written under the transaction into place; throws
  /// std::runtime_error (one line) if one cannot be, after removing the rest.
  void commit();
};

}  // namespace rigid::render
