// Golden images: each lab's figures, regenerated with its textbook defaults,
// match the committed figures/ within a tolerance; every golden of the lab is
// drawn (a lab that stops drawing one fails), and the gallery (docs/gallery.md) shows each
// figure with the caption the lab gives it. On a mismatch the actual, expected
// and difference PNGs are written to build/figure-diff/. To accept new goldens:
// `cmake --build build --target figures` and commit figures/ and docs/.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <vector>

#include "lab_common.h"
#include "rigid/render/image.h"
#include "rigid/render/image_match.h"
#include "rigid/render/png.h"

namespace fs = std::filesystem;
using rigid::test::all_labs;
using rigid::test::run_lab;

namespace {
using rigid::render::kChannelThreshold;
using rigid::render::mismatch;

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
  auto run = run_lab(lab, "--json --figures " + actual_dir.string());
  // This test compares images. A run whose figures could not be drawn at all (the
  // lab's one "--figures:" line, as when a GL context cannot be had) is the machine's
  // hiccup, not an image that differs: said on stderr, it is run once more. A
  // sanitizer's report is never retried.
  const bool sanitizer = run.err.find("Sanitizer") != std::string::npos ||
                         run.err.find("runtime error:") != std::string::npos;
  if (run.status == 1 && !sanitizer && run.err.find(": error: --figures: ") != std::string::npos) {
    std::cerr << "figure_test: " << lab << " failed to draw, run again; it said: " << run.err;
    fs::remove_all(actual_dir);
    run = run_lab(lab, "--json --figures " + actual_dir.string());
  }
  INFO(run.err);
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto figures = j["figures"];
  REQUIRE(!figures.empty());
  std::set<std::string> drawn;
  const std::string gallery = read_text(fs::path(RIGID_SOURCE_DIR) / "docs" / "gallery.md");
  for (const auto& name : figures) {
    const std::string file = name.get<std::string>();
    INFO(file);
    drawn.insert(file);
    // The gallery shows it with the lab's caption.
    const std::string caption = j["captions"][file];
    CHECK(gallery.find("](../figures/" + file + ")") != std::string::npos);
    CHECK(gallery.find("`" + lab + "`: " + caption + " |") != std::string::npos);
    const fs::path golden = fs::path(RIGID_SOURCE_DIR) / "figures" / file;
    REQUIRE(fs::exists(golden));
    const auto expected = rigid::render::read_png(golden.string());
    const auto actual = rigid::render::read_png((actual_dir / file).string());
    REQUIRE(actual.width == expected.width);
    REQUIRE(actual.height == expected.height);
    // A figure a run's environment says follows its last bits (RIGID_FIGURE_ORDERED_BY_ROUNDOFF:
    // the integrators listed as the table ranks them, two of them below roundoff) is drawn
    // and shown, not held to the pixels.
    const char* roundoff = std::getenv("RIGID_FIGURE_ORDERED_BY_ROUNDOFF");
    if (roundoff != nullptr && std::string(roundoff) == file) {
      WARN(file << ": its legend's order is the table's, which these last bits change");
      continue;
    }
    const std::string why = mismatch(actual, expected);
    // build/figure-diff/ holds the images of the comparisons that failed in this run,
    // one folder per lab and backend like figure-actual/ (CI keeps them as artifacts):
    // an earlier run's, for a figure that now matches, go.
    const fs::path out = fs::path(RIGID_BINARY_DIR) / "figure-diff" / actual_dir.filename();
    const std::string stem = fs::path(file).stem().string();
    for (const char* kind : {".actual.png", ".expected.png", ".diff.png"})
      fs::remove(out / (stem + kind));
    if (!why.empty()) {
      fs::create_directories(out);
      rigid::render::write_png(actual, (out / (stem + ".actual.png")).string());
      rigid::render::write_png(expected, (out / (stem + ".expected.png")).string());
      rigid::render::write_png(rigid::render::difference_image(actual, expected, kChannelThreshold),
                               (out / (stem + ".diff.png")).string());
    }
    INFO(why);
    CHECK(why.empty());
  }
  // Every committed golden of this lab is still drawn.
  CHECK(drawn == goldens_of(lab));
}
}  // namespace

TEST_CASE("figures: every lab matches its goldens") {
  for (const std::string& lab : all_labs()) {
    DYNAMIC_SECTION(lab) {
      check_lab_figures(lab);
    }
  }
}

namespace {

// Runs a command line (paths quoted by the caller); its exit status.
int shell(const std::string& command) {
  return std::system((command + " >/dev/null 2>&1").c_str());
}

std::string quoted(const fs::path& p) {
  return "'" + p.string() + "'";
}

// What pdftotext reads of a PDF: its text, if its text is text.
std::string pdf_text(const fs::path& pdf) {
  const fs::path txt = fs::path(pdf).replace_extension(".txt");
  REQUIRE(shell(std::string(RIGID_PDFTOTEXT) + " -enc UTF-8 " + quoted(pdf) + " " + quoted(txt)) ==
          0);
  return read_text(txt);
}

// A lab's figures as SVG and as PDF (--figure-format, the lab's own process), rendered back
// to pixels by librsvg and by poppler, draw what its committed PNGs do: the same layout,
// text, colours and curves, by the rule for another rasteriser (image_match.h). A plot is
// vectors with its text as text; a 3D scene one image of its geometry's pixels, its text
// as text over it.
void check_lab_vectors(const std::string& lab) {
  const fs::path root = fs::path(RIGID_BINARY_DIR) / "figure-actual" / (lab + "-vector");
  fs::remove_all(root);
  for (const char* format : {"svg", "pdf"}) {
    INFO(format);
    const fs::path dir = root / format;
    const auto run = run_lab(
        lab, std::string("--json --figure-format ") + format + " --figures " + dir.string());
    INFO(run.err);
    REQUIRE(run.status == 0);
    const auto j = run.json();
    std::set<std::string> drawn;
    for (const auto& name : j["figures"]) {
      const fs::path file = dir / name.get<std::string>();
      INFO(file.filename().string());
      REQUIRE(file.extension() == std::string(".") + format);
      drawn.insert(file.stem().string() + ".png");
      const fs::path pixels = fs::path(file).replace_extension(".png");
      const std::string render =
          std::string(format) == "svg"
              ? std::string(RIGID_RSVG_CONVERT) + " " + quoted(file) + " -o " + quoted(pixels)
              : std::string(RIGID_PDFTOCAIRO) + " -png -r 96 -singlefile " + quoted(file) + " " +
                    quoted(fs::path(pixels).replace_extension(""));
      REQUIRE(shell(render) == 0);
      const auto expected = rigid::render::read_png(
          (fs::path(RIGID_SOURCE_DIR) / "figures" / pixels.filename()).string());
      const auto actual = rigid::render::read_png(pixels.string());
      REQUIRE(actual.width == expected.width);
      REQUIRE(actual.height == expected.height);
      const std::string why = mismatch(actual, expected, rigid::render::kAcrossRasterisers);
      if (!why.empty()) {
        rigid::render::write_png(
            rigid::render::difference_image(actual, expected, kChannelThreshold),
            (fs::path(pixels).replace_extension(".diff.png")).string());
      }
      INFO(why);
      CHECK(why.empty());
      // Vectors, and text a reader can select and search: a scene's geometry is one image
      // under its title, legend and labels, a plot no image at all; the lab's name (the
      // title's first word) is text in either.
      const std::string bytes = read_text(file);
      if (std::string(format) == "svg") {
        CHECK(bytes.find("<text") != std::string::npos);
        CHECK(bytes.find(">" + std::string(1, lab[0]) + "</tspan>") != std::string::npos);
      } else {
        CHECK(pdf_text(file).find(lab + ":") != std::string::npos);
      }
    }
    // every golden has its vector twin
    CHECK(drawn == goldens_of(lab));
  }
}

}  // namespace

TEST_CASE("figures: the SVG and PDF figures of every lab draw what its PNGs show") {
  for (const std::string& lab : all_labs()) {
    DYNAMIC_SECTION(lab) {
      check_lab_vectors(lab);
    }
  }
}

TEST_CASE("figures: without a GL context the run fails in one line and lands nothing") {
  // A figure that cannot be drawn is a failed output: exit 1, its one line, and none of
  // the run's outputs, the report on stdout among them (a report would list figures that
  // are not there); the same run without --figures prints the numbers.
  const fs::path dir = fs::path(RIGID_BINARY_DIR) / "figure-actual" / "no-context";
  fs::remove_all(dir);
  const auto run =
      run_lab("tire_balancing", "--json --figures " + dir.string(), "RIGID_GL_BACKEND=none");
  CHECK(run.status == 1);
  CHECK(run.one_error_line());
  CHECK(run.err.rfind("tire_balancing: error: --figures:", 0) == 0);
  CHECK(run.out.empty());
  CHECK_FALSE(fs::exists(dir));  // not even the folder the run made
  const auto numbers = run_lab("tire_balancing", "--json", "RIGID_GL_BACKEND=none");
  CHECK(numbers.status == 0);
  CHECK(numbers.json()["results"].contains("balance_mass_kg"));
}

TEST_CASE(
    "figures: --timing says where each figure's time went, every phase, within its wall time") {
  const fs::path dir = fs::path(RIGID_BINARY_DIR) / "figure-actual" / "timing";
  fs::remove_all(dir);
  const auto run = run_lab("poinsot", "--json --timing --figures " + dir.string());
  INFO(run.err);
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& seconds = j["timing"]["figure_seconds"];
  const auto& phases = j["timing"]["figure_phases"];
  REQUIRE(j["figures"].size() >= 2);
  CHECK(phases.size() == j["figures"].size());
  for (const auto& name : j["figures"]) {
    const std::string file = name.get<std::string>();
    INFO(file);
    double sum = 0;
    for (const char* phase : {"setup", "layout", "draw", "resolve", "encode"}) {
      const double s = phases[file][phase].get<double>();
      CHECK(s > 0);  // every phase does work: a phase never timed would read 0
      sum += s;
    }
    // The phases are laps of one clock inside the figure's own span: they cannot add up
    // to more than it. (How close they come, and that a first figure's setup costs more
    // than a later one's, are times a busy machine moves; the bench reports them.)
    const double wall = seconds[file].get<double>();
    CHECK(sum <= wall);
  }
}

TEST_CASE("figures: the comparison itself fails on what a reader would see changed") {
  using rigid::render::Image;
  const Image golden = rigid::render::read_png(
      (fs::path(RIGID_SOURCE_DIR) / "figures" / "tire_balancing_mass.png").string());
  const int W = golden.width, H = golden.height;
  CHECK(mismatch(golden, golden).empty());
  // A copy with a block of pixels taken from elsewhere (text replaced: "83.4 g" by
  // other glyphs), recoloured (a swatch), moved (a label 20 px off), whitened (a
  // marker or a stretch of dashed curve erased), or the background made faint grey.
  const auto copy_block = [&](Image img, int sx, int sy, int dx, int dy, int w, int h) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c) img.at(dx + x, dy + y)[c] = golden.at(sx + x, sy + y)[c];
    return img;
  };
  // Find a dark text pixel in the title (top 8 %): glyphs are there.
  int tx = -1, ty = -1;
  for (int y = 0; y < H / 12 && tx < 0; ++y)
    for (int x = W / 4; x < 3 * W / 4 && tx < 0; ++x)
      if (golden.at(x, y)[0] < 80) tx = x, ty = y;
  REQUIRE(tx > 0);
  const struct {
    const char* what;
    Image image;
  } altered[] = {
      {"text replaced",
       copy_block(golden, tx, std::max(ty - 10, 0), tx + 60, std::max(ty - 10, 0), 30, 30)},
      {"label moved 20 px",
       copy_block(golden, tx - 40, std::max(ty - 8, 0), tx - 20, std::max(ty - 8, 0), 120, 40)},
      {"swatch recoloured",
       [&] {
         Image img = golden;
         for (int y = 0; y < 20; ++y)
           for (int x = 0; x < 30; ++x) img.at(W / 2 + x, H / 2 + y)[1] = 0;
         return img;
       }()},
      {"marker erased",
       [&] {
         Image img = golden;
         for (int y = 0; y < 11; ++y)
           for (int x = 0; x < 11; ++x)
             for (int c = 0; c < 3; ++c) img.at(tx + x, ty + y)[c] = 255;
         return img;
       }()},
      {"background faint grey",
       [&] {
         Image img = golden;
         for (auto& v : img.rgb) v = static_cast<std::uint8_t>(v > 245 ? 235 : v);
         return img;
       }()},
  };
  for (const auto& a : altered) {
    INFO(a.what);
    CHECK_FALSE(mismatch(a.image, golden).empty());
    // and another rasteriser's looser rule (vector figures) still sees each
    CHECK_FALSE(mismatch(a.image, golden, rigid::render::kAcrossRasterisers).empty());
  }
  // A band of the plot (curves and all) moved by 2 px, as another CPU's rounding of
  // roundoff-level data could move a curve, is no change a reader sees.
  const Image shifted = copy_block(golden, W / 4, H / 3, W / 4 + 2, H / 3 + 1, W / 2, H / 4);
  CHECK(mismatch(shifted, golden).empty());
  // The renderer's own variation between backends is nothing: EGL draws it alike.
  const fs::path dir = fs::path(RIGID_BINARY_DIR) / "figure-actual" / "comparison-egl";
  fs::remove_all(dir);
  const auto run =
      run_lab("tire_balancing", "--json --figures " + dir.string(), "RIGID_GL_BACKEND=egl");
  INFO(run.err);
  REQUIRE(run.status == 0);
  CHECK(mismatch(rigid::render::read_png((dir / "tire_balancing_mass.png").string()), golden)
            .empty());
}
