// Tests of PNG writing: round trip, atomic rename, failure leaves nothing.
#include "rigid/render/png.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <stdexcept>

using namespace rigid::render;
namespace fs = std::filesystem;

namespace {

Image gradient(int w, int h) {
  Image img;
  img.width = w;
  img.height = h;
  img.rgb.resize(static_cast<std::size_t>(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.at(x, y);
      p[0] = static_cast<std::uint8_t>(x * 255 / (w - 1));
      p[1] = static_cast<std::uint8_t>(y * 255 / (h - 1));
      p[2] = static_cast<std::uint8_t>((x * 7 + y * 13) % 256);
    }
  return img;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("rigid_render_test_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST_CASE("png: written pixels read back identical, no temporary left", "[render][png]") {
  const fs::path dir = fresh_dir("png");
  const Image img = gradient(97, 61);  // odd sizes catch row-stride mistakes
  const fs::path file = dir / "g.png";
  write_png(img, file.string());
  const Image back = read_png(file.string());
  CHECK(back.width == img.width);
  CHECK(back.height == img.height);
  CHECK(back.rgb == img.rgb);
  // Only the target is in the directory: the temporary was renamed.
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    (void)e;
    ++files;
  }
  CHECK(files == 1);
  // Overwriting an existing file works the same way.
  write_png(gradient(10, 10), file.string());
  CHECK(read_png(file.string()).width == 10);
  fs::remove_all(dir);
}

TEST_CASE("png: an unwritable target throws and leaves nothing", "[render][png]") {
  const Image img = gradient(8, 8);
  CHECK_THROWS_AS(write_png(img, "/nonexistent-dir-rigid/x.png"), std::runtime_error);
  // /proc refuses new files even for root.
  CHECK_THROWS_AS(write_png(img, "/proc/rigid_render_test.png"), std::runtime_error);
  CHECK_FALSE(fs::exists("/proc/rigid_render_test.png"));
  // A target that is a directory: the temporary is written, rename fails, and it is removed.
  const fs::path dir = fresh_dir("png_dir_target");
  fs::create_directories(dir / "taken.png");
  CHECK_THROWS_AS(write_png(img, (dir / "taken.png").string()), std::runtime_error);
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    (void)e;
    ++files;
  }
  CHECK(files == 1);  // just the directory that was in the way
  fs::remove_all(dir);
}

TEST_CASE("png: reading a file that is not a PNG throws", "[render][png]") {
  const fs::path dir = fresh_dir("png_bad");
  {
    std::FILE* f = std::fopen((dir / "bad.png").c_str(), "wb");
    std::fputs("not a png", f);
    std::fclose(f);
  }
  CHECK_THROWS_AS(read_png((dir / "bad.png").string()), std::runtime_error);
  fs::remove_all(dir);
}
