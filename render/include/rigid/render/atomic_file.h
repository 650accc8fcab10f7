// Placeholder until the render-overlay branch lands its writer.
#pragma once
#include <cstdio>
#include <functional>
#include <string>
namespace rigid::render {
/// Writes a file through a temporary in the same directory renamed into place.
void write_file_atomically(const std::string& path, const std::function<void(std::FILE*)>& write);
}  // namespace rigid::render
