// Golden images: each lab's figures, regenerated with its textbook defaults,
// match the committed figures/ within a tolerance; every golden of the lab is
// drawn (a lab that stops drawing one fails), and the README gallery shows each
// figure with the caption the lab gives it. On a mismatch the actual, expected
// and difference PNGs are written to build/figure-diff/. To accept new goldens:
// `cmake --build build --target figures` and commit figures/ and README.md.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "lab_common.h"
#include "rigid/render/image.h"
#include "rigid/render/png.h"

namespace fs = std::filesystem;
using rigid::test::all_labs;
using rigid::test::run_lab;

namespace {
// Antialiasing and rasterisation may differ in a few edge pixels between
// llvmpipe builds; a real change moves far more than 0.1 % of the pixels.
constexpr double kMaxDifferingFraction = 0.001;
constexpr int kChannelThreshold = 16;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The committed goldens of a lab: figures/<lab>_*.png, less those of a longer lab name.
std::set<std::string> goldens_of(const std::string& lab) {
  std::set<std::string> files;
  for (const auto& entry : fs::directory_iterator(fs::path(RIGID_SOURCE_DIR) / "figures")) {
    const std::string file = entry.path().filename().string();
    if (file.rfind(lab + "_", 0) != 0 || entry.path().extension() != ".png") continue;
    bool other = false;
    for (const std::string& longer : all_labs()) {
      other = other || (longer.size() > lab.size() && file.rfind(longer + "_", 0) == 0);
    }
    if (!other) files.insert(file);
  }
  return files;
}

void check_lab_figures(const std::string& lab) {
  // Each backend (RIGID_GL_BACKEND, set by ctest for the EGL run) draws into its own
  // directory, so the two runs of a lab may go side by side.
  const char* backend = std::getenv("RIGID_GL_BACKEND");
  const fs::path actual_dir = fs::path(RIGID_BINARY_DIR) / "figure-actual" /
                              (lab + (backend != nullptr ? std::string("-") + backend : ""));
  fs::remove_all(actual_dir);
  const auto run = run_lab(lab, "--json --figures " + actual_dir.string());
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto figures = j["figures"];
  REQUIRE(!figures.empty());
  std::set<std::string> drawn;
  const std::string readme = read_text(fs::path(RIGID_SOURCE_DIR) / "README.md");
  for (const auto& name : figures) {
    const std::string file = name.get<std::string>();
    INFO(file);
    drawn.insert(file);
    // The gallery shows it with the lab's caption.
    const std::string caption = j["captions"][file];
    CHECK(readme.find("](figures/" + file + ")") != std::string::npos);
    CHECK(readme.find("`" + lab + "`: " + caption + " |") != std::string::npos);
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
  // Every committed golden of this lab is still drawn.
  CHECK(drawn == goldens_of(lab));
}
}  // namespace

TEST_CASE("figures: every lab matches its goldens") {
  for (const std::string& lab : all_labs()) {
    DYNAMIC_SECTION(lab) { check_lab_figures(lab); }
  }
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
