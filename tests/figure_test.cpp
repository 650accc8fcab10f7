// Golden images: each lab's figures, regenerated with its textbook defaults,
// match the committed figures/ within a tolerance. On a mismatch the actual,
// expected and difference PNGs are written to build/figure-diff/. To accept new
// goldens: `cmake --build build --target figures` and commit figures/.
#include <catch2/catch.hpp>
#include <filesystem>

#include "lab_common.h"
#include "rigid/render/image.h"
#include "rigid/render/png.h"

namespace fs = std::filesystem;
using rigid::test::run_lab;

namespace {
// Antialiasing and rasterisation may differ in a few edge pixels between
// llvmpipe builds; a real change moves far more than 0.1 % of the pixels.
constexpr double kMaxDifferingFraction = 0.001;
constexpr int kChannelThreshold = 16;

void check_lab_figures(const std::string& lab) {
  const fs::path actual_dir = fs::path(RIGID_BINARY_DIR) / "figure-actual" / lab;
  fs::remove_all(actual_dir);
  const auto run = run_lab(lab, "--json --figures " + actual_dir.string());
  REQUIRE(run.status == 0);
  const auto figures = run.json()["figures"];
  REQUIRE(!figures.empty());
  for (const auto& name : figures) {
    const std::string file = name.get<std::string>();
    INFO(file);
    const fs::path golden = fs::path(RIGID_SOURCE_DIR) / "figures" / file;
    REQUIRE(fs::exists(golden));
    const auto expected = rigid::render::read_png(golden.string());
    const auto actual = rigid::render::read_png((actual_dir / file).string());
    REQUIRE(actual.width == expected.width);
    REQUIRE(actual.height == expected.height);
    const auto diff = rigid::render::compare_images(actual, expected, kChannelThreshold);
    if (diff.differing_fraction > kMaxDifferingFraction) {
      const fs::path out = fs::path(RIGID_BINARY_DIR) / "figure-diff";
      fs::create_directories(out);
      const std::string stem = fs::path(file).stem().string();
      rigid::render::write_png(actual, (out / (stem + ".actual.png")).string());
      rigid::render::write_png(expected, (out / (stem + ".expected.png")).string());
      rigid::render::write_png(rigid::render::difference_image(actual, expected, kChannelThreshold),
                               (out / (stem + ".diff.png")).string());
    }
    CHECK(diff.differing_fraction <= kMaxDifferingFraction);
  }
}
}  // namespace

TEST_CASE("figures: lamina_tensor matches its goldens") {
  check_lab_figures("lamina_tensor");
}
TEST_CASE("figures: tire_balancing matches its goldens") {
  check_lab_figures("tire_balancing");
}
TEST_CASE("figures: poinsot matches its goldens") {
  check_lab_figures("poinsot");
}

TEST_CASE("figures: without a GL context the numbers still print, with one error line") {
  const fs::path dir = fs::path(RIGID_BINARY_DIR) / "figure-actual" / "no-context";
  fs::remove_all(dir);
  const auto run = run_lab("tire_balancing", "--json --figures " + dir.string(),
                           "RIGID_GL_BACKEND=none");
  CHECK(run.status == 1);
  CHECK(run.one_error_line());
  CHECK(run.err.rfind("tire_balancing: error: --figures:", 0) == 0);
  const auto j = run.json();
  CHECK(j["results"].contains("balance_mass_kg"));
  CHECK(j["figures"].empty());
  // No figure, and no partial file, is left behind.
  CHECK(fs::is_empty(dir));
}
