// PNG files through libpng: 8-bit RGB, written atomically (a temporary file in
// the target's directory, renamed when complete) so a failed write never
// leaves a partial figure behind.
#pragma once

#include <string>

#include "rigid/render/image.h"

namespace rigid::render {

/// Writes img to path as 8-bit RGB PNG; on any failure removes the temporary file and throws
/// std::runtime_error.
void write_png(const Image& img, const std::string& path);

/// Reads an 8-bit RGB or RGBA PNG (alpha dropped); throws std::runtime_error if it cannot.
Image read_png(const std::string& path);

}  // namespace rigid::render
