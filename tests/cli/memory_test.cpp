// A run's memory (render/memory.h, support/memory.h): the model of the drawing's peak
// bounds what a lab takes, a lab refuses a size it could not have the memory for before
// any work, and `rigidlab figures` runs no more labs at once than the budget holds.
#include "rigid/render/memory.h"

#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lab_common.h"
#include "rigid/support/subprocess.h"

using rigid::test::run_lab;
namespace fs = std::filesystem;

namespace {

fs::path fresh(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// The peak resident memory of a lab run with `args`, in bytes, and its exit status.
[[maybe_unused]] std::uint64_t peak_of(const std::string& lab, std::vector<std::string> args,
                                       int& status) {
  const std::string program = std::string(RIGID_LAB_DIR) + "/" + lab;
  args.insert(args.begin(), program);
  using rigid::support::Redirect;
  rigid::support::Subprocess child(program, args, {Redirect::null(), Redirect::null(), nullptr});
  status = child.wait();
  return child.peak_bytes();
}

}  // namespace

TEST_CASE("memory: the drawing model bounds what a lab takes at its peak", "[draws]") {
#if defined(__SANITIZE_ADDRESS__)
  // the sanitizers' shadow memory and quarantine are not the program's: no bound to hold
  SUCCEED("not measured under the sanitizers");
#else
  const fs::path dir = fresh("rigid_memory_peak");
  const struct {
    std::string lab;
    int width, height;
  } figures[] = {{"poinsot", 2048, 2048}, {"top_nutation", 1600, 1200}, {"football", 800, 600}};
  for (const auto& f : figures) {
    const std::string size = std::to_string(f.width) + "x" + std::to_string(f.height);
    INFO(f.lab << " --figure-size " << size);
    int status = -1;
    const std::uint64_t peak = peak_of(
        f.lab, {"--quiet", "--figures", (dir / f.lab).string(), "--figure-size", size}, status);
    REQUIRE(status == 0);
    const std::uint64_t model = rigid::render::figure_peak_bytes(f.width, f.height);
    CHECK(peak <= model);
    // and not so far above it that a size the machine could draw is refused
    CHECK(peak >= model / 2);
  }
  int status = -1;
  const std::uint64_t film =
      peak_of("poinsot",
              {"--quiet", "--animate", (dir / "a.mp4").string(), "--animation-size", "1280x720",
               "--duration", "0.5", "--fps", "10"},
              status);
  REQUIRE(status == 0);
  CHECK(film <= rigid::render::film_peak_bytes(1280, 720));
  CHECK(film >= rigid::render::film_peak_bytes(1280, 720) / 3);
  fs::remove_all(dir);
#endif
}

TEST_CASE("memory: a size past the budget is refused before any work, in one line", "[draws]") {
  const fs::path dir = fresh("rigid_memory_refused");
  const std::string out = (dir / "f").string();
  // 100 MiB is less than any drawing's base (render/memory.h)
  const auto lab = run_lab("poinsot", "--figures '" + out + "' --figure-size 1024x768",
                           "RIGIDLAB_MEMORY_MB=100");
  CHECK(lab.status == 2);
  CHECK(lab.err ==
        "poinsot: error: --figure-size: 1024x768 takes about 172 MB to draw, more than the 105 MB "
        "this run may use (RIGIDLAB_MEMORY_MB=100); give a smaller size\n");
  const auto film =
      run_lab("poinsot", "--animate '" + (dir / "a.webp").string() + "'", "RIGIDLAB_MEMORY_MB=200");
  CHECK(film.status == 2);
  CHECK(film.err.rfind("poinsot: error: --animation-size: 1280x720 takes about 252 MB", 0) == 0);
  // rigidlab figures says what its first lab says, and lands nothing
  const auto all = run_lab("rigidlab", "figures --out '" + out + "' --figure-size 1024x768",
                           "RIGIDLAB_MEMORY_MB=100");
  CHECK(all.status == 2);
  CHECK(all.err.rfind("rigidlab: error: figures: --figure-size: 1024x768 takes about", 0) == 0);
  CHECK(fs::is_empty(dir));
  // a setting that is not a whole number of MiB is refused where it is read (a run that
  // draws), before any work
  for (const char* bad : {"''", "x", "0", "-5", "1e3", "1.5", "99999999999999999999", "' 5'"}) {
    INFO(bad);
    const auto run = run_lab("poinsot", "--quiet --figures '" + out + "'",
                             std::string("RIGIDLAB_MEMORY_MB=") + bad);
    CHECK(run.status == 2);
    CHECK(run.err ==
          "poinsot: error: RIGIDLAB_MEMORY_MB: must be a whole number of MiB from 1 to "
          "1099511627776\n");
    CHECK(fs::is_empty(dir));
  }
  // and not read by a run that draws nothing
  CHECK(run_lab("poinsot", "--quiet", "RIGIDLAB_MEMORY_MB=x").status == 0);
  fs::remove_all(dir);
}

TEST_CASE("memory: rigidlab figures runs as many labs at once as the budget holds", "[draws]") {
  const fs::path dir = fresh("rigid_memory_schedule");
  // Room for one lab at 800x600 (its model, 157 MB; a lab takes about 120 MB) but not two
  // with the quarter spared: every lab draws, one at a time, and all 24 figures land.
  const auto run =
      run_lab("rigidlab", "figures --out '" + (dir / "f").string() + "' --figure-size 800x600",
              "RIGIDLAB_MEMORY_MB=200");
  CHECK(run.status == 0);
  CHECK(run.err.find("rigidlab: figures: 1 lab at a time, as memory allows (a lab took ") !=
        std::string::npos);
  std::size_t figures = 0;
  for (const auto& entry : fs::directory_iterator(dir / "f")) figures += entry.is_regular_file();
  CHECK(figures == 24);
  fs::remove_all(dir);
}

TEST_CASE("memory: a drawing run starts again once with malloc's huge pages, the user's kept",
          "[draws]") {
  // The restart is a drawing run's first act: the environment the kernel shows for the
  // lab's process is then the restarted program's. Each case: the user's GLIBC_TUNABLES
  // (none, another tunable, huge pages refused) and what the drawing run holds.
  const fs::path dir = fresh("huge_pages");
  const auto tunables_of = [&](const char* given) {
    if (given != nullptr)
      ::setenv("GLIBC_TUNABLES", given, 1);
    else
      ::unsetenv("GLIBC_TUNABLES");
    rigid::support::Subprocess lab(
        fs::path(RIGID_LAB_DIR) / "poinsot",
        {"poinsot", "--animate", (dir / "film.webp").string(), "--duration", "30"},
        {rigid::support::Redirect::null(), rigid::support::Redirect::null()});
    ::unsetenv("GLIBC_TUNABLES");
    // glibc, reading its tunables, ends each in the process's first copy of the
    // environment (what the kernel shows): the ones after the first follow as entries
    const auto read = [&] {
      std::ifstream environ("/proc/" + std::to_string(lab.pid()) + "/environ", std::ios::binary);
      std::string entry, tunables;
      bool in_tunables = false;
      while (std::getline(environ, entry, '\0')) {
        if (entry.rfind("GLIBC_TUNABLES=", 0) == 0) {
          tunables = entry.substr(15);
          in_tunables = true;
        } else if (in_tunables && entry.rfind("glibc.", 0) == 0) {
          tunables += ":" + entry;
        } else {
          in_tunables = false;
        }
      }
      return tunables;
    };
    // polled until the program shows huge pages named (at most 10 s: a loaded machine),
    // then once more a while later: a restart is its first act, and its last
    std::string seen;
    for (int k = 0; k < 1000 && seen.find("glibc.malloc.hugetlb") == std::string::npos; ++k) {
      seen = read();
      if (lab.poll()) break;
      ::usleep(10000);
    }
    ::usleep(300000);
    if (!lab.poll()) seen = read();
    lab.terminate();
    return seen;
  };
  CHECK(tunables_of(nullptr) == "glibc.malloc.hugetlb=1");
  CHECK(tunables_of("glibc.malloc.check=0") == "glibc.malloc.check=0:glibc.malloc.hugetlb=1");
  CHECK(tunables_of("glibc.malloc.hugetlb=0") == "glibc.malloc.hugetlb=0");  // the user's word
  // the film stopped half-way is no file
  CHECK(fs::is_empty(dir));
}
