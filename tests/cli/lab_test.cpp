// Each lab's own contract: its JSON keys, the text's numbers at its defaults,
// and exit status 2 with one line naming the option for its own bad input
// (what every lab shares is in contract_test.cpp).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "lab_common.h"

using Catch::Matchers::WithinAbs;
using rigid::test::run_lab;

TEST_CASE("tire_balancing: --csv writes one turn of L and the torque") {
  const std::string path = "/tmp/rigid_tire_test_" + std::to_string(::getpid()) + ".csv";
  std::remove(path.c_str());
  REQUIRE(run_lab("tire_balancing", "--quiet --csv " + path).status == 0);
  const rigid::test::Csv csv = rigid::test::read_csv(path);
  CHECK(csv.header == "t_s,Lx,Ly,Lz,Nx,Ny,Nz");
  CHECK(csv.rows.size() == 361);
  // the columns' units and axes said in the metadata beside it
  CHECK(csv.column("Ly")["schema:unitText"] == "kg m^2/s");
  CHECK_THAT(csv.column("Ly")["dc:description"].get<std::string>(),
             Catch::Contains("the wheel's angular momentum"));
  CHECK(csv.column("Nz")["schema:unitText"] == "N m");
  std::remove(path.c_str());
  std::remove((path + "-metadata.json").c_str());
}

TEST_CASE("football and lamina_tensor: --csv writes the sweep their figure draws and says so") {
  struct Case {
    const char* lab;
    const char* header;
    std::size_t rows;
    double first, last;  // the swept angle's ends, deg
  };
  for (const Case& c :
       {Case{"football", "alpha_deg,Omega_over_omega,phi_dot_over_omega", 179, 0.5, 89.5},
        Case{"lamina_tensor", "alpha_deg,moment_kg_m2", 361, -90, 90}}) {
    INFO(c.lab);
    const std::string path =
        "/tmp/rigid_sweep_test_" + std::to_string(::getpid()) + "_" + c.lab + ".csv";
    std::remove(path.c_str());
    const auto run = run_lab(c.lab, "--quiet --csv " + path);
    INFO(run.err);
    REQUIRE(run.status == 0);
    const rigid::test::Csv csv = rigid::test::read_csv(path);
    CHECK(csv.header == c.header);
    REQUIRE(csv.rows.size() == c.rows);
    CHECK(csv.rows.front()[0] == c.first);
    CHECK(csv.rows.back()[0] == c.last);
    CHECK_THAT(csv.metadata["dc:title"].get<std::string>(),
               Catch::Contains("a sweep: the lab has no time series"));
    CHECK(csv.column("alpha_deg")["schema:unitText"] == "deg");
    std::remove(path.c_str());
    std::remove((path + "-metadata.json").c_str());
  }
  // The moment at the sweep's ends is I_yy (the axis along y): the default plate's
  // m (a^2 + ... ) is the lab's own number, here only its symmetry: -90 and 90 deg alike.
  const std::string path = "/tmp/rigid_sweep_test_" + std::to_string(::getpid()) + ".csv";
  REQUIRE(run_lab("lamina_tensor", "--quiet --csv " + path).status == 0);
  const rigid::test::Csv csv = rigid::test::read_csv(path);
  CHECK(csv.rows.front()[1] == Approx(csv.rows.back()[1]).epsilon(1e-15));
  std::remove(path.c_str());
  std::remove((path + "-metadata.json").c_str());
}

TEST_CASE("labs: help texts say only what the lab does") {
  // football has no --t-end: its --duration says the lab's motion is shown, not --t-end's
  const auto football = run_lab("football", "--help");
  CHECK_THAT(football.out, !Catch::Contains("--t-end"));
  CHECK_THAT(run_lab("poinsot", "--help").out, Catch::Contains("the motion to --t-end is shown"));
  // lamina_tensor's --examples uses the inputs given
  CHECK_THAT(run_lab("lamina_tensor", "--help").out, Catch::Contains("with these inputs"));
}

TEST_CASE("labs: bad input exits 2 with one line naming the option") {
  struct Case {
    const char* lab;
    const char* args;
    const char* option;
  };
  const Case cases[] = {
      {"lamina_tensor", "--mass -1", "--mass"},
      {"lamina_tensor", "--mass 0", "--mass"},
      {"lamina_tensor", "--mass nan", "--mass"},
      {"lamina_tensor", "--mass inf", "--mass"},
      {"lamina_tensor", "--mass abc", "--mass"},
      {"lamina_tensor", "--a 0", "--a"},
      {"lamina_tensor", "--b -2", "--b"},
      {"lamina_tensor", "--axis 0,0,0", "--axis"},
      {"lamina_tensor", "--axis 1,2", "--axis"},
      {"lamina_tensor", "--axis 1,x,2", "--axis"},
      {"lamina_tensor", "--origin middle", "--origin"},
      {"lamina_tensor", "--omega nan", "--omega"},
      {"tire_balancing", "--mass -10", "--mass"},
      {"tire_balancing", "--radius 0", "--radius"},
      {"tire_balancing", "--offset nan", "--offset"},
      {"tire_balancing", "--offset inf", "--offset"},
      {"tire_balancing", "--tilt-deg -1e-9", "--tilt-deg"},
      {"tire_balancing", "--road-speed 30 --omega 90", "--road-speed"},
      {"tire_balancing", "--tire-radius 0.3", "--tire-radius"},
      {"tire_balancing", "--road-speed 30 --tire-radius 0.1", "--tire-radius"},
      {"tire_balancing", "--road-speed 0", "--road-speed"},
      // the old names, taken one release, by the same rules
      {"tire_balancing", "--road-speed-m-s 0", "--road-speed-m-s"},
      {"tire_balancing", "--road-speed-m-s 3 --road-speed 4", "--road-speed"},
      {"lamina_tensor", "--axis diag", "--axis"},
      {"lamina_tensor", "--axis 1,2", "--axis"},
      {"lamina_tensor", "--axis diagonal,1,2", "--axis"},
      {"lamina_tensor", "--axis diagonal --axis-deg 30", "--axis-deg"},
      {"lamina_tensor", "--axis-deg nan", "--axis-deg"},
      {"tire_balancing", "--tilt-deg 45", "--tilt-deg"},
      {"tire_balancing", "--tilt-deg -3", "--tilt-deg"},
      {"tire_balancing", "--tilt-deg 40 --offset 0.001", "--tilt-deg"},
      {"tire_balancing", "--csv /proc/nope/x.csv", "--csv"},
      {"tire_balancing", "--csv /tmp", "--csv"},
      {"tire_balancing", "--mass 1e308", "--mass"},
      {"tire_balancing", "--radius 1e-300", "--radius"},
      {"tire_balancing", "--offset 1e300", "--offset"},
      {"lamina_tensor", "--omega 1e200", "--omega"},
      {"lamina_tensor", "--axis 1e-300,0,0", "--axis"},
  };
  for (const auto& c : cases) {
    INFO(c.lab << " " << c.args);
    const auto run = run_lab(c.lab, c.args);
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.rfind(std::string(c.lab) + ": error: " + c.option, 0) == 0);
    CHECK(run.out.empty());
  }
}

TEST_CASE("poinsot: --csv writes t, omega, the quaternion, energy and |L|") {
  const std::string path = "/tmp/rigid_poinsot_test_" + std::to_string(::getpid()) + ".csv";
  std::remove(path.c_str());
  REQUIRE(run_lab("poinsot", "--quiet --method splitting --csv " + path).status == 0);
  const rigid::test::Csv csv = rigid::test::read_csv(path);
  CHECK(csv.header == "t_s,omega1,omega2,omega3,qw,qx,qy,qz,energy_J,L_kg_m2_s");
  // the quaternion's order and frame said of each of its columns beside it
  for (const char* q : {"qw", "qx", "qy", "qz"}) {
    CHECK_THAT(csv.column(q)["dc:description"].get<std::string>(),
               Catch::StartsWith("the attitude, the unit quaternion that turns body axes into "
                                 "space axes"));
    CHECK(csv.column(q)["schema:unitText"] == "1");
  }
  std::remove(path.c_str());
  std::remove((path + "-metadata.json").c_str());
}

TEST_CASE("poinsot: bad input exits 2 with one line naming the option") {
  const std::pair<const char*, const char*> cases[] = {
      {"--inertia 1,1,3", "--inertia"},
      {"--inertia -1,1,1", "--inertia"},
      {"--inertia 1,2", "--inertia"},
      {"--inertia 0,1,1", "--inertia"},
      {"--ellipsoid 0,1,1", "--ellipsoid"},
      {"--mass -1", "--mass"},
      {"--omega nan,1,1", "--omega"},
      {"--omega 0,0,0", "--omega"},
      {"--t-end -1", "--t-end"},
      {"--method euler", "--method"},
      {"--tolerance 0", "--tolerance"},
      {"--tolerance 1", "--tolerance"},
      {"--step -1", "--step"},
      {"--inertia 1,2,2 --ellipsoid 1,2,3", "--inertia"},
      {"--method rk4 --step 1e-9 --t-end 100", "--step"},
      {"--method dopri5 --project", "--project"},
      {"--step 0", "--step"},
      {"--t-end 0", "--t-end"},
      {"--t-end 1e300", "--t-end"},
      {"--t-end 1e59", "--t-end"},
      {"--omega 1e200,1,1", "--omega"},
      {"--method rk4 --step 10", "--step"},
      // below double precision's reach no step meets a tolerance
      {"--method dopri5 --tolerance 1e-17", "--tolerance"},
      {"--tolerance 1e-300", "--tolerance"},
      {"--periods 2 --t-end 3", "--periods"},
      {"--periods 0", "--periods"},
      // too few numbers before the next option: named as such, not as a bad component
      {"--omega , --json", "--omega: each component must be a number (got '')"},
  };
  rigid::test::check_bad_inputs("poinsot", cases);
}

TEST_CASE("football: bad input exits 2 with one line naming the option") {
  const std::pair<const char*, const char*> cases[] = {
      {"--alpha-deg -0.001", "--alpha-deg"},
      {"--alpha-deg 90", "--alpha-deg"},
      {"--alpha-deg nan", "--alpha-deg"},
      {"--inertia 1,3", "--inertia"},
      {"--inertia -1,1", "--inertia"},
      {"--inertia 1", "--inertia"},
      {"--preset moon", "--preset"},
      {"--omega 0", "--omega"},
      {"--preset earth --inertia 1,1", "--inertia"},
  };
  rigid::test::check_bad_inputs("football", cases);
}

namespace {
// The text's racquet, written out from eqs. 83-85 (independent of core's primitives).
struct TextRacquet {
  double ma = 0.15, a = 0.13, ml = 0.18, l = 0.38;
  double R = ml * (a + l / 2) / (ma + ml);
  double I1 = ma * a * a / 2;
  double I2 =
      ma * a * a / 2 + ma * R * R + ml * l * l / 12 + ml * (a + l / 2 - R) * (a + l / 2 - R);
  double I3 = I1 + I2;
};
}  // namespace

TEST_CASE("tennis_racquet: --csv holds the exact motion and the integrator's omega beside it") {
  const std::string path = "/tmp/rigid_racquet_test_" + std::to_string(::getpid()) + ".csv";
  std::remove(path.c_str());
  const auto run =
      run_lab("tennis_racquet", "--json --method rkf78 --tolerance 1e-12 --csv " + path);
  INFO(run.err);
  REQUIRE(run.status == 0);
  const double t_end = run.json()["results"]["t_end_s"];
  const rigid::test::Csv csv = rigid::test::read_csv(path);
  CHECK(csv.header ==
        "t_s,omega1,omega2,omega3,qw,qx,qy,qz,omega1_integrated,omega2_integrated,"
        "omega3_integrated");
  // The file holds the lab's time series to 17 digits; what the numbers say (the
  // integrated omega beside the exact one) is tested on the series itself, in-process
  // (tests/labs/tennis_racquet_test.cpp).
  std::size_t rows = 0;
  double last_t = -1, worst_norm = 0;
  for (const std::vector<double>& v : csv.rows) {
    REQUIRE(v.size() == 11);
    ++rows;
    last_t = v[0];
    worst_norm = std::max(worst_norm,
                          std::abs(std::hypot(std::hypot(v[4], v[5]), std::hypot(v[6], v[7])) - 1));
  }
  CHECK(rows > 100);
  CHECK(last_t == t_end);
  CHECK(worst_norm < 1e-14);
  std::remove(path.c_str());
}

TEST_CASE("tennis_racquet: bad input exits 2 with one line naming the option") {
  const std::pair<const char*, const char*> cases[] = {
      {"--spin-axis 4", "--spin-axis"},
      {"--spin-axis 0", "--spin-axis"},
      {"--perturbation 1e-61", "--perturbation"},
      {"--perturbation 0.5", "--perturbation"},
      {"--perturbation nan", "--perturbation"},
      {"--perturbation -0.1", "--perturbation"},
      {"--head-mass -1", "--head-mass"},
      {"--head-radius 0", "--head-radius"},
      {"--handle-mass inf", "--handle-mass"},
      {"--handle-length x", "--handle-length"},
      {"--omega 0", "--omega"},
      {"--t-end -1", "--t-end"},
      {"--method dopri5 --project", "--project"},
      {"--method rk4 --step 1e-9", "--step"},
  };
  rigid::test::check_bad_inputs("tennis_racquet", cases);
}

TEST_CASE("top_nutation: bad input exits 2 with one line naming the option") {
  const std::pair<const char*, const char*> cases[] = {
      {"--mass 0", "--mass"},
      {"--arm -1", "--arm"},
      {"--disk-radius nan", "--disk-radius"},
      {"--g inf", "--g"},
      {"--inertia 1,-1", "--inertia"},
      {"--inertia 0.00445,0.01", "--inertia"},  // I - m l^2 < Is/2: no body has these
      {"--inertia 0.00445,0.0025 --disk-radius 0.05", "--inertia"},
      {"--spin 50 --spin-rpm 500", "--spin"},
      {"--theta0-deg 180", "--theta0-deg"},
      {"--theta0-deg -1", "--theta0-deg"},
      {"--theta0-deg 0 --spin 0", "--theta0-deg"},
      {"--method rk4 --step 1e-12", "--step"},
      {"--method euler", "--method"},
  };
  rigid::test::check_bad_inputs("top_nutation", cases);
  // The text's thin disk sits exactly on I - m l^2 = Is / 2 and is accepted.
  CHECK(run_lab("top_nutation", "--json --inertia 0.00445,0.0025").status == 0);
}

TEST_CASE("top_nutation: --csv holds theta beside the exact theta, and a unit quaternion") {
  const std::string path = "/tmp/rigid_top_test_" + std::to_string(::getpid()) + ".csv";
  std::remove(path.c_str());
  const auto run = run_lab("top_nutation", "--json --method rkf78 --tolerance 1e-12 --csv " + path);
  INFO(run.err);
  REQUIRE(run.status == 0);
  const double t_end = run.json()["results"]["t_end_s"];
  const rigid::test::Csv csv = rigid::test::read_csv(path);
  CHECK(csv.header ==
        "t_s,theta_rad,theta_exact_rad,omega1,omega2,omega3,qw,qx,qy,qz,energy_error_rel,phi_rad,"
        "psi_rad,theta_dot_rad_s,phi_dot_rad_s,psi_dot_rad_s");
  // The file holds the lab's time series to 17 digits; what the numbers say (theta
  // beside the exact theta, its nod) is tested on the series itself, in-process
  // (tests/labs/top_nutation_test.cpp).
  std::size_t rows = 0;
  double last_t = -1, worst_norm = 0;
  for (const std::vector<double>& v : csv.rows) {
    REQUIRE(v.size() == 16);
    ++rows;
    last_t = v[0];
    worst_norm = std::max(worst_norm,
                          std::abs(std::hypot(std::hypot(v[6], v[7]), std::hypot(v[8], v[9])) - 1));
  }
  CHECK(rows > 100);
  CHECK(last_t == t_end);
  CHECK(worst_norm < 1e-14);
  std::remove(path.c_str());
}

TEST_CASE("labs: extreme but legal inputs end with finite numbers or one line, never a crash") {
  // Each was a crash or a message naming no option: odeint's dense-output steppers
  // failed for runs shorter than 1e-14 s (now run in scaled time), and the heavy
  // top's turning circles within roundoff of a pole (no spin, huge g) overflowed.
  const std::pair<const char*, const char*> cases[] = {
      {"poinsot", "--t-end 1e-60"},
      {"poinsot", "--t-end 1e-20 --method dopri5"},
      {"poinsot", "--t-end 1e-20 --method bulirsch-stoer"},
      {"poinsot", "--inertia 1,2,3 --omega 1e20,1e20,1e20"},
      {"tennis_racquet", "--t-end 1e-60"},
      {"tennis_racquet", "--omega 1e30"},
      // moments equal to double precision: no flip, no growth to measure
      {"tennis_racquet", "--head-mass 1e-60"},
      {"tennis_racquet", "--handle-length 1e60"},
      {"tennis_racquet", "--head-mass 1e60 --handle-mass 1e-60"},
      {"top_nutation", "--g 1e60"},
      {"top_nutation", "--spin 0"},
      {"top_nutation", "--spin 1e-60"},
      {"top_nutation", "--spin 1e60"},
      {"top_nutation", "--thetadot0 1e60"},
      {"top_nutation", "--t-end 1e-60"},
      {"top_nutation", "--spin 0 --theta0-deg 1e-10"},
      {"top_nutation", "--theta0-deg 0 --thetadot0 1"},
      {"top_nutation", "--theta0-deg 179.9999999"},
  };
  for (const auto& [lab, args] : cases) {
    INFO(lab << " " << args);
    const auto run = run_lab(lab, std::string("--json ") + args);
    CHECK((run.status == 0 || run.status == 2));
    if (run.status == 2) {
      CHECK(run.one_error_line());
      CHECK(run.err.find(": error: --") != std::string::npos);
    } else {
      CHECK(run.out.find("NaN") == std::string::npos);
      CHECK(run.json()["results"].is_object());
    }
  }
}

// Every lab at inputs none of its defaults share, against the
// chapter's formulas typed here (or a quadrature / another library's elliptic
// integral), never against the lab's own output. Tolerances: the formulas are a
// few operations each, so a few ulps; 1e-13 relative leaves room for libm.
namespace {
constexpr double kDeg = M_PI / 180;
double value(const nlohmann::json& r, const char* key) {
  return r.at(key).get<double>();
}
}  // namespace

TEST_CASE("labs: which method to use, in the table and --help of each lab that integrates") {
  // What the ranking holds is tested in-process (tests/labs/); here, that a student sees it.
  for (const char* lab : {"poinsot", "top_nutation"}) {
    INFO(lab);
    const auto table = run_lab(lab, "--periods 5");
    INFO(table.err);
    REQUIRE(table.status == 0);
    CHECK_THAT(table.out, Catch::Contains("[which method to use: every method at 1000 evaluations "
                                          "a period over the run's 5 periods"));
    CHECK_THAT(table.out, Catch::Contains("\nuse  "));
    const auto help = run_lab(lab, "--help");
    CHECK_THAT(help.out, Catch::Contains("symplectic splitting, order 2"));
    CHECK_THAT(help.out, Catch::Contains("to use: vern9 or vern8"));
  }
}

TEST_CASE("labs: an option the method does not use is said so, once the run succeeds") {
  const auto run = run_lab("tennis_racquet", "--json --method rk4 --tolerance 1e-6");
  INFO(run.err);
  REQUIRE(run.status == 0);
  CHECK(run.err ==
        "tennis_racquet: warning: --tolerance: rk4 takes a fixed step; it is not used "
        "(--step sets it)\n");
  bool noted = false;
  const auto j = run.json();
  for (const auto& note : j["notes"]) noted |= note.get<std::string>().rfind("warning:", 0) == 0;
  CHECK(noted);
  // a fixed step that does not divide t_end: the shortened last step is reported
  const auto fixed = run_lab("poinsot", "--json --method rk4 --step 0.3 --t-end 10");
  REQUIRE(fixed.status == 0);
  CHECK(value(fixed.json()["results"], "last_step_s") == Approx(10 - 33 * 0.3).epsilon(1e-12));
  CHECK(fixed.err.empty());
  // --project with the closed form is refused, not ignored
  CHECK(run_lab("poinsot", "--project").status == 2);
}

TEST_CASE("poinsot: a solid box (a phone) beside the ellipsoid, its moments by eq. 40") {
  const double m = 0.2, A = 0.16, B = 0.08, C = 0.008;
  const auto run = run_lab("poinsot", "--json --box 0.16,0.08,0.008 --mass 0.2 --omega 0,5,0.01");
  INFO(run.err);
  REQUIRE(run.status == 0);
  const auto j = run.json();
  const auto& I = j["results"]["principal_moments"];
  CHECK(double(I[0]) == Approx(m * (B * B + C * C) / 12).epsilon(1e-15));
  CHECK(double(I[1]) == Approx(m * (A * A + C * C) / 12).epsilon(1e-15));
  CHECK(double(I[2]) == Approx(m * (A * A + B * B) / 12).epsilon(1e-15));
  // spun about its middle axis, nudged: the tennis racquet theorem for a phone
  CHECK(j["results"]["motion_stability"] == "unstable");
  CHECK(!j["inputs"].contains("ellipsoid"));
  CHECK(run_lab("poinsot", "--box 1,1,1 --ellipsoid 1,2,3").status == 2);
  CHECK(run_lab("poinsot", "--box 1,1,1 --inertia 1,2,3").status == 2);
  CHECK(run_lab("poinsot", "--box 1,0,1").status == 2);
}

TEST_CASE("poinsot: --animate writes the motion as an MP4 or a WebP, and says so in the JSON",
          "[draws]") {
  const std::string dir = "/tmp/rigid_anim_test_" + std::to_string(::getpid());
  std::filesystem::create_directories(dir);
  for (const std::string ext : {"mp4", "webp"}) {
    const std::string path = dir + "/poinsot." + ext;
    const rigid::test::Run run = rigid::test::run_lab(
        "poinsot", "--json --animate " + path + " --duration 0.5 --fps 8 --animation-size 480x270");
    INFO(run.err);
    INFO(run.err);
    REQUIRE(run.status == 0);
    const nlohmann::json a = run.json()["animation"];
    // 0.5 s at 8 fps: 4 frames over three polhode periods (the default --t-end)
    CHECK(a["frames"] == 4);
    CHECK(a["width"] == 480);
    CHECK(a["height"] == 270);
    CHECK(a["duration_s"] == Approx(0.5));
    CHECK(a["motion_s"] == Approx(3 * run.json()["results"]["polhode_period_s"].get<double>()));
    CHECK(std::filesystem::file_size(path) == a["bytes"].get<std::size_t>());
    const auto outputs = run.json()["outputs"];
    CHECK(std::find(outputs.begin(), outputs.end(), std::filesystem::absolute(path).string()) !=
          outputs.end());
    // one final line on stderr (not a terminal: no progress line)
    CHECK(run.err.find("wrote " + path) != std::string::npos);
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  }
  // --quiet says nothing
  const rigid::test::Run quiet =
      rigid::test::run_lab("poinsot", "--quiet --animate " + dir + "/q.mp4 --duration 0.2 --fps 5");
  CHECK(quiet.status == 0);
  CHECK(quiet.err.empty());
  std::filesystem::remove_all(dir);
}

TEST_CASE("poinsot: bad animation options exit 2 with one line naming the option", "[draws]") {
  const std::string dir = "/tmp/rigid_anim_bad_" + std::to_string(::getpid());
  std::filesystem::create_directories(dir);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--animate " + dir + "/a.gif", "--animate"},
      {"--animate " + dir + "/no/such/dir/a.mp4", "--animate"},
      {"--animate " + dir, "--animate"},
      {"--animate " + dir + "/a.mp4 --fps 0", "--fps"},
      {"--animate " + dir + "/a.mp4 --fps nan", "--fps"},
      {"--animate " + dir + "/a.mp4 --duration 1e9", "--duration"},
      {"--animate " + dir + "/a.mp4 --animation-size 641x360", "--animation-size"},
      {"--fps 10", "--fps"},
      {"--duration 2", "--duration"},
      // where permission bits say yes and no file can be made: checked before any work,
      // so the CSV and figures asked beside it are not written either
      {"--csv " + dir + "/x.csv --figures " + dir + "/f --animate /proc/a.mp4", "--animate"},
      {"--animate " + dir + "/a.mp4 --figures /proc/f", "--figures"},
      {"--figures " + dir + "/f --csv /proc/x.csv", "--csv"},
  };
  for (const auto& [args, option] : cases) {
    const rigid::test::Run run = rigid::test::run_lab("poinsot", args);
    INFO(args << " -> " << run.err);
    CHECK(run.status == 2);
    CHECK(run.one_error_line());
    CHECK(run.err.find(option) != std::string::npos);
  }
  // nothing was written
  CHECK(std::filesystem::is_empty(dir));
  std::filesystem::remove_all(dir);
}

TEST_CASE("labs with motion: --animate writes a short animation of each", "[draws]") {
  const std::string dir = "/tmp/rigid_anim_labs_" + std::to_string(::getpid());
  std::filesystem::create_directories(dir);
  for (const std::string lab :
       {"poinsot", "tennis_racquet", "football", "top_nutation", "euler_angles"}) {
    const std::string path = dir + "/" + lab + ".mp4";
    const rigid::test::Run run =
        rigid::test::run_lab(lab, "--json --animate " + path + " --duration 0.2 --fps 10");
    INFO(lab << ": " << run.err);
    INFO(run.err);
    REQUIRE(run.status == 0);
    CHECK(run.json()["animation"]["frames"] == 2);
    CHECK(std::filesystem::file_size(path) > 0);
  }
  // frames from an integrator, sampled at the frame times: a fixed step off their grid,
  // and an adaptive method with dense output
  for (const auto& [lab, method] :
       {std::pair<std::string, std::string>{"poinsot", "--method rk4 --step 0.37"},
        {"poinsot", "--method vern7"},
        {"top_nutation", "--method splitting4"},
        {"tennis_racquet", "--method rk4 --step 0.01"},
        {"top_nutation", "--method vern8"}}) {
    const rigid::test::Run run = rigid::test::run_lab(
        lab, method + " --json --animate " + dir + "/i.mp4 --duration 0.5 --fps 10");
    INFO(lab << " " << method << ": " << run.err);
    INFO(run.err);
    CHECK(run.status == 0);
    CHECK(run.json()["animation"]["frames"] == 5);
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("figures of extreme valid input are drawn, not an error", "[draws]") {
  // top_nutation at S = 1e20: theta flat at 30 deg, its axis range lo + 1 == lo (the
  // ticks threw); lamina_tensor at 1e60: |I n|^2 overflowed and L's arrow had no length
  const std::string dir = "/tmp/rigid_extreme_figures_" + std::to_string(::getpid());
  for (const auto& [lab, args] :
       {std::pair<std::string, std::string>{"top_nutation", "--spin 1e20"},
        {"lamina_tensor", "--a 1e60 --b 1e60 --mass 1e60"},
        {"lamina_tensor", "--a 1e-60 --b 1e-60 --mass 1e-60"}}) {
    const auto run = rigid::test::run_lab(lab, "--quiet " + args + " --figures " + dir);
    INFO(lab << " " << args << ": " << run.err);
    INFO(run.err);
    CHECK(run.status == 0);
    CHECK(run.err.empty());
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("tire_balancing: an input's old name is taken one release, with a warning") {
  const auto old_names =
      run_lab("tire_balancing", "--json --road-speed-m-s 30 --tyre-radius-m 0.33");
  const auto new_names = run_lab("tire_balancing", "--json --road-speed 30 --tire-radius 0.33");
  REQUIRE(old_names.status == 0);
  REQUIRE(new_names.status == 0);
  CHECK(old_names.json()["results"] == new_names.json()["results"]);
  CHECK(old_names.json()["inputs"] == new_names.json()["inputs"]);
  CHECK(new_names.err.empty());
  CHECK_THAT(old_names.err, Catch::Contains("warning: --road-speed-m-s: renamed --road-speed"));
  CHECK_THAT(old_names.err, Catch::Contains("warning: --tyre-radius-m: renamed --tire-radius"));
  // --help lists the new names only
  const auto help = run_lab("tire_balancing", "--help");
  CHECK_THAT(help.out, Catch::Contains("--road-speed NUMBER"));
  CHECK(help.out.find("--road-speed-m-s") == std::string::npos);
}
