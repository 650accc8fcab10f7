// `rigidlab figures` as one transaction (docs/guide.md, "Installing"): every lab's figures land
// together or none does, in a staging folder of the run's own making; a signal that
// ends rigidlab ends its labs and removes that folder; a line that cannot be written
// lands nothing; and its options follow the labs' rules.
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "lab_common.h"

using rigid::test::all_labs;
using rigid::test::run_lab;

namespace {
namespace fs = std::filesystem;

// A folder of this test's own under /tmp, made empty.
fs::path fresh(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}
// The names of the files under `dir` (a run's staging folder among them: the labs draw
// there first).
std::vector<std::string> staged(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    names.push_back(it->path().filename().string());
  return names;
}

// The labs of `labs` for which `is_lab` holds that have a figure under `dir`: landed, or
// (`landed` false) still at its temporary name too.
template <class IsLab>
std::set<std::string> drawn_by(const fs::path& dir, IsLab is_lab, bool landed = false) {
  std::set<std::string> drawn;
  for (const std::string& name : staged(dir)) {
    for (const std::string& lab : rigid::test::all_labs()) {
      if (is_lab(lab) && name.rfind(lab + "_", 0) == 0 &&
          (!landed || name.find(".rigidlab-tmp-") == std::string::npos)) {
        drawn.insert(lab);
      }
    }
  }
  return drawn;
}

rigid::test::Background figures_into(const fs::path& dir) {
  return rigid::test::Background({std::string(RIGID_LAB_DIR) + "/rigidlab", "figures",
                                  "--figure-size", "2048x2048", "--out", dir.string()});
}

}  // namespace

TEST_CASE("contract: a signal to rigidlab figures reaches its labs, which leave no temporaries",
          "[draws]") {
  const fs::path dir = fs::temp_directory_path() / ("rigid_term_" + std::to_string(::getpid()));
  const std::string first_lab = rigid::test::all_labs().front();
  // During the first lab alone (once a figure of it shows), and during the others
  // (once a figure of another lab shows).
  const auto first = [&](const std::string& lab) { return lab == first_lab; };
  const auto others = [&](const std::string& lab) { return lab != first_lab; };
  // SIGTERM at both moments; SIGHUP (a closed terminal), as every signal that would end
  // rigidlab, while the labs run side by side.
  for (const auto& [sig, during_others] :
       {std::pair{SIGTERM, false}, std::pair{SIGTERM, true}, std::pair{SIGHUP, true}}) {
    INFO("signal " << sig
                   << (during_others ? " during the other labs" : " during the first lab alone"));
    // To rigidlab alone (not its process group, as a terminal's Ctrl-C or timeout would).
    rigid::test::Background rigidlab = figures_into(dir);
    const bool ready = during_others
                           ? rigidlab.wait_until([&] { return !drawn_by(dir, others).empty(); })
                           : rigidlab.wait_until([&] { return !drawn_by(dir, first).empty(); });
    REQUIRE(ready);
    ::kill(rigidlab.pid(), sig);
    const int status = rigidlab.wait();
    // rigidlab died of the signal, after its labs
    CHECK((WIFSIGNALED(status) && WTERMSIG(status) == sig));
    // Every lab it ran has stopped (none still writes into the folder) and left no temporary.
    const std::string still = "pgrep -f -- '[-]-figures " + dir.string() + "' > /dev/null 2>&1";
    CHECK(std::system(still.c_str()) != 0);  // (the bracket keeps pgrep's own shell out)
    // Nothing landed (the labs drew into a staging folder), and the folder it made is gone.
    CHECK(!fs::exists(dir));
    fs::remove_all(dir);
  }
}

TEST_CASE("contract: rigidlab figures killed by SIGKILL ends its labs, which draw no more",
          "[draws]") {
  // No handler sees SIGKILL: its labs were started asked to end with it (SIGTERM), and end
  // without landing a figure more or leaving a temporary. The labs are stopped first
  // (SIGSTOP), so that none can finish between the look at what they drew and the kill:
  // continued, a lab that was told to end dies before it draws again.
  const fs::path dir = fs::temp_directory_path() / ("rigid_kill_" + std::to_string(::getpid()));
  const std::string first_lab = rigid::test::all_labs().front();
  const auto any = [](const std::string&) { return true; };
  const auto others = [&](const std::string& lab) { return lab != first_lab; };
  const std::string labs_of_run = "-f -- '[-]-figures " + dir.string() + "' > /dev/null 2>&1";
  rigid::test::Background rigidlab = figures_into(dir);
  REQUIRE(rigidlab.wait_until([&] { return !drawn_by(dir, others).empty(); }));
  CHECK(std::system(("pkill -STOP " + labs_of_run).c_str()) == 0);
  const std::set<std::string> before = drawn_by(dir, any, true);
  ::kill(rigidlab.pid(), SIGKILL);
  const int status = rigidlab.wait();
  CHECK((WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL));
  CHECK(std::system(("pkill -CONT " + labs_of_run).c_str()) == 0);
  const auto labs_ended = [&] { return std::system(("pgrep " + labs_of_run).c_str()) != 0; };
  // each lab ends within its own SIGTERM handling: a bounded count of looks, not a clock
  bool ended = labs_ended();
  for (int look = 0; look < 6000 && !ended; ++look) {
    ::usleep(10000);
    ended = labs_ended();
  }
  CHECK(ended);
  CHECK(drawn_by(dir, any, true) == before);  // no lab drew on after rigidlab died
  // in --out only the staging folder, and no temporary anywhere
  for (const std::string& name : names_in(dir)) CHECK(name.rfind(".rigidlab-stage-", 0) == 0);
  for (const std::string& name : staged(dir))
    CHECK(name.find(".rigidlab-tmp-") == std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("contract: rigidlab figures says a killed run's staging folder is left and keeps it",
          "[draws]") {
  // kill -9 leaves OUT/.rigidlab-stage-PID-XXXXXX (no handler runs); the next run names
  // it for the user to remove, and leaves it: it did not make it
  const fs::path out = fs::temp_directory_path() / ("rigid_left_" + std::to_string(::getpid()));
  const fs::path left = out / ".rigidlab-stage-2147483646";  // a pid no process has
  fs::create_directories(left);
  const std::string err = (out.string() + ".err");
  const std::string command = std::string(RIGID_LAB_DIR) +
                              "/rigidlab figures --figure-size 800x600 --out '" + out.string() +
                              "' 2> '" + err + "'";
  CHECK(std::system(command.c_str()) == 0);
  std::ifstream in(err);
  const std::string said((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(said.find("rigidlab: warning: figures: " + left.string() +
                  " was left by a run that was killed") != std::string::npos);
  CHECK(fs::is_directory(left));
  fs::remove_all(out);
  fs::remove(err);
}

TEST_CASE("contract: rigidlab figures lands every lab's figures or none", "[draws]") {
  const fs::path base = fs::temp_directory_path() / ("rigid_all_" + std::to_string(::getpid()));
  fs::create_directories(base);
  const fs::path out = base / "figs";
  const std::string rigidlab = std::string(RIGID_LAB_DIR) + "/rigidlab figures --out '";
  REQUIRE(std::system((rigidlab + out.string() + "' >/dev/null 2>&1").c_str()) == 0);
  std::size_t pngs = 0;
  for (const auto& entry : fs::directory_iterator(out)) {
    CHECK(entry.path().extension() == ".png");  // no staging folder or temporary left
    ++pngs;
  }
  CHECK(pngs >= all_labs().size());
  fs::remove_all(out);
  // A full disk (a 200 kB tmpfs, where this user may mount one): every lab fails, none
  // of their figures lands, the folder rigidlab made goes, a file of the user's stays.
  const fs::path disk = base / "disk";
  fs::create_directories(disk);
  const std::string mount = "mount -t tmpfs -o size=200k tmpfs '" + disk.string() + "' 2>/dev/null";
  if (std::system(mount.c_str()) == 0) {
    std::ofstream(disk / "mine.txt") << "keep\n";
    const int status =
        std::system((rigidlab + (disk / "figs").string() + "' >/dev/null 2>&1").c_str());
    CHECK(WEXITSTATUS(status) == 1);
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(disk)) left.push_back(entry.path().filename());
    CHECK(left == std::vector<std::string>{"mine.txt"});
    CHECK(std::system(("umount '" + disk.string() + "'").c_str()) == 0);
  } else {
    WARN("cannot mount a tmpfs here: the full-disk half is not run");
  }
  // A directory where one figure goes: refused whole (exit 2, one line), nothing lands,
  // the user's files stay as they were.
  const fs::path taken = base / "taken";
  fs::create_directories(taken / "poinsot_omega.png");
  std::ofstream(taken / "tire_balancing_mass.png") << "mine\n";
  const int blocked = std::system((rigidlab + taken.string() + "' >/dev/null 2>&1").c_str());
  CHECK(WEXITSTATUS(blocked) == 2);
  std::vector<std::string> kept;
  for (const auto& entry : fs::directory_iterator(taken)) kept.push_back(entry.path().filename());
  std::sort(kept.begin(), kept.end());
  CHECK(kept == std::vector<std::string>{"poinsot_omega.png", "tire_balancing_mass.png"});
  fs::remove_all(base);
}

TEST_CASE("contract: rigidlab figures never fills or removes a staging folder it did not make",
          "[draws]") {
  // A killed run's folder named with the PID this run is given (PIDs come round again):
  // the shell makes it, then becomes rigidlab under the same PID.
  const fs::path base = fresh("rigid_stage");
  const fs::path out = base / "figs", err = base / "err";
  const std::string command =
      "sh -c 'left=\"$1/.rigidlab-stage-$$\"; mkdir -p \"$left\" && printf mine > \"$left/keep\" "
      "&& exec \"$0\" figures --figure-size 800x600 --out \"$1\"' '" +
      std::string(RIGID_LAB_DIR) + "/rigidlab' '" + out.string() + "' >/dev/null 2>'" +
      err.string() + "'";
  REQUIRE(std::system(command.c_str()) == 0);
  std::vector<std::string> left;
  std::size_t pngs = 0;
  for (const std::string& name : names_in(out)) {
    if (name.rfind(".rigidlab-stage-", 0) == 0) left.push_back(name);
    pngs += fs::path(name).extension() == ".png" ? 1 : 0;
  }
  CHECK(pngs >= all_labs().size());
  CHECK(!fs::exists(out / "keep"));  // not landed with the figures
  REQUIRE(left.size() == 1);         // this run's own is gone
  CHECK(names_in(out / left[0]) == std::vector<std::string>{"keep"});
  CHECK(text_of(out / left[0] / "keep") == "mine");
  // and said, for the user to remove: this run's PID, yet not this run's
  CHECK(text_of(err).find("rigidlab: warning: figures: " + (out / left[0]).string() +
                          " was left by a run that was killed") != std::string::npos);
  fs::remove_all(base);
}

TEST_CASE("contract: rigidlab figures whose last line cannot be written lands nothing", "[draws]") {
  // As a lab with a full or closed stdout: exit 1, one line that says so, no figure, and
  // the folder it made is gone.
  const fs::path base = fresh("rigid_stdout");
  for (const char* redirect : {" > /dev/full", " >&-"}) {
    INFO(redirect);
    const auto run = run_lab("rigidlab", "figures --figure-size 800x600 --out '" +
                                             (base / "figs").string() + "'" + redirect);
    CHECK(run.status == 1);
    const std::string last = run.err.substr(run.err.rfind('\n', run.err.size() - 2) + 1);
    CHECK(last.rfind("rigidlab: error: stdout: the output could not be written (", 0) == 0);
    CHECK(fs::is_empty(base));
  }
  // A folder of the user's keeps only what it had.
  std::ofstream(base / "mine.txt") << "keep\n";
  const auto run = run_lab(
      "rigidlab", "figures --figure-size 800x600 --out '" + base.string() + "' > /dev/full");
  CHECK(run.status == 1);
  CHECK(names_in(base) == std::vector<std::string>{"mine.txt"});
  fs::remove_all(base);
}

TEST_CASE("contract: rigidlab figures --out '' is refused before any work") {
  // not the working folder, by the labs' rule for --figures ''
  const fs::path here = fresh("rigid_out_empty");
  const auto run = run_lab("rigidlab", "figures --out ''", "cd '" + here.string() + "' &&");
  CHECK(run.status == 2);
  CHECK(run.err == "rigidlab: error: figures: --out: needs a directory name\n");
  CHECK(run.out.empty());
  CHECK(fs::is_empty(here));
  fs::remove_all(here);
}

TEST_CASE("contract: rigidlab figures --figure-prefix follows the labs' rule", "[draws]") {
  // '' is given, and refused as a lab refuses it, in the lab's words
  const fs::path base = fresh("rigid_prefix");
  const auto lab =
      run_lab("poinsot", "--figures '" + (base / "p").string() + "' --figure-prefix ''");
  REQUIRE(lab.status == 2);
  const std::string rule = lab.err.substr(lab.err.find("--figure-prefix: "));
  const auto run =
      run_lab("rigidlab", "figures --figure-prefix '' --out '" + (base / "f").string() + "'");
  CHECK(run.status == 2);
  CHECK(run.err == "rigidlab: error: figures: " + rule);
  CHECK(run.out.empty());
  CHECK(fs::is_empty(base));
  fs::remove_all(base);
}
