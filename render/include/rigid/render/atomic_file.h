// Atomic file writing: a file appears complete under its name or not at all.
// The content goes to a temporary in the target's directory (its name holds
// the process id), is flushed and checked, and is renamed into place; a
// failure removes the temporary. PNG figures and the labs' CSV use it.
#pragma once

#include <cstdio>
#include <functional>
#include <string>

namespace rigid::render {

/// Writes a file through `write` (which fills the stream, and may throw) and renames it to `path`;
/// on any failure removes the temporary and throws std::runtime_error "cannot write 'PATH': REASON" (one line).
void write_file_atomically(const std::string& path, const std::function<void(std::FILE*)>& write);

}  // namespace rigid::render
