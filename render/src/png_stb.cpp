// PNG output and input through stb_image_write and stb_image (Debian's libstb-dev):
// the WebAssembly page's, where libpng is not to be had. Written atomically as
// png.cpp's are (atomic_file.h).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb_image_write.h>
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#include <stb_image.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include "rigid/render/atomic_file.h"
#include "rigid/render/png.h"

namespace rigid::render {

void write_png(const Image& img, const std::string& path) {
  if (img.width <= 0 || img.height <= 0 ||
      img.rgb.size() != static_cast<std::size_t>(img.width) * img.height * 3)
    throw std::invalid_argument("write_png: image buffer does not match its size");
  write_file_atomically(path, [&](std::FILE* f) {
    const auto put = [](void* file, void* data, int size) {
      std::fwrite(data, 1, static_cast<std::size_t>(size), static_cast<std::FILE*>(file));
    };
    if (stbi_write_png_to_func(put, f, img.width, img.height, 3, img.rgb.data(), img.width * 3) ==
        0)
      throw std::runtime_error("PNG encoding failed");
  });
}

Image read_png(const std::string& path) {
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(path.c_str(), &width, &height, &channels, 3);
  if (pixels == nullptr)
    throw std::runtime_error("cannot read " + path + ": " + stbi_failure_reason());
  Image img;
  img.width = width;
  img.height = height;
  img.rgb.assign(pixels, pixels + static_cast<std::size_t>(width) * height * 3);
  stbi_image_free(pixels);
  return img;
}

}  // namespace rigid::render
