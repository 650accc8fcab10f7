#include "tire_balancing/tire_balancing.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "common/integrated_motion.h"
#include "rigid/units.h"

namespace rigid::lab::tire_balancing {

namespace {
constexpr const char* kName = "tire_balancing";
constexpr const char* kTitle = "dynamic balancing of a wheel on a crooked axle (sections 2.2-2.3)";

// The spin: --omega, or from the road, where a tire of rolling radius R at speed v turns
// at v / R.
double spin_of(Report& report, const Inputs& in) {
  const double tire_radius = in.tire_radius;
  if (in.road_speed) {
    if (tire_radius < report.wheel.radius) {
      throw InputError("--tire-radius", fmt::format("must be at least the disk's radius "
                                                    "--radius = {:g} m (got {:g})",
                                                    report.wheel.radius, tire_radius));
    }
    report.drop_input("omega");
    return *in.road_speed / tire_radius;
  }
  report.drop_input("tire_radius");
  return in.omega;
}

// Before balancing, L is off the axle.
struct Unbalanced {
  double tilt_L_deg;  ///< angle between L and the axle
  double torque;      ///< N m, the bearings' |N|
};

// Section 2.2: the wheel as it comes, L off the axle and the torque the bearings need.
Unbalanced report_unbalanced(Report& report) {
  const CrookedWheel& wheel = report.wheel;
  report.section("2.2 before balancing: L is off the axle");
  const Vec3 axle = axle_direction(wheel);
  const Vec3 L0 = angular_momentum_at(wheel, 0.0, report.omega, 0.0);
  const double tilt_L = rad_to_deg(angle_between(L0, axle));
  report.result("angle_L_axle_deg", "angle between L and the axle", tilt_L, "deg");
  const double torque_unbalanced = bearing_torque(wheel, 0.0, report.omega).stableNorm();
  report.result("torque_unbalanced_n_m", "bearing torque |omega x I omega|", torque_unbalanced,
                "N m");
  return {tilt_L, torque_unbalanced};
}

// Section 2.3: the two masses that put a principal axis on the axle, and what they leave.
void report_balancing(Report& report, const Inputs& in, double torque_unbalanced) {
  const CrookedWheel& wheel = report.wheel;
  report.section("2.3 balancing masses m0 at (-b, a) and (b, -a) (eqs. 57-61)");
  // The rule 4 a b > 2 (a^2 - b^2) tan 2 theta joins the tilt, the offset and the radius.
  const double m0 =
      for_inputs({"--tilt-deg", "--offset", "--radius"}, [&] { return balance_mass_exact(wheel); });
  report.m0 = m0;
  const double m0_small = balance_mass_small_angle(wheel);
  report.result("balance_mass_kg", "m0, exact from tan 2 theta (eq. 60)", m0, "kg",
                report.textbook("0.076 (76 g)"));
  report.result("balance_mass_small_angle_kg", "m0, small angle theta = 8 b m0 / (a m) (eq. 61)",
                m0_small, "kg", report.textbook("0.076 (76 g)"));
  // The exact m0 as a double misses eq. 60 by up to half an ulp, which turns the principal
  // axis by eps/2 |d phi / d ln m0| (about eps theta / 2): shown as 0 within twice that.
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  report.result_roundoff("residual_tilt_exact_deg", "principal axis to axle, exact m0",
                         rad_to_deg(principal_axis_misalignment(wheel, m0)),
                         rad_to_deg(kEps * std::abs(misalignment_per_mass(wheel, m0))), "deg");
  // Eq. 61's mass taken exactly: its own rounding would hide a miss of theta^2 (a^2 - b^2)/(a b).
  report.result("residual_tilt_small_angle_deg", "principal axis to axle, small-angle m0",
                rad_to_deg(small_angle_misalignment(wheel)), "deg");
  // The torque the double m0 leaves, in closed form: half an ulp of m0 leaves eps/2 of the
  // unbalanced torque; shown as 0 within eps of it.
  report.result_roundoff("torque_balanced_n_m", "bearing torque after balancing",
                         bearing_torque_size(wheel, m0, report.omega), kEps * torque_unbalanced,
                         "N m");
  // The old names (read "nm" as nanometres), kept one release (the schema says so).
  report.alias("torque_unbalanced_nm", "torque_unbalanced_n_m");
  report.alias("torque_balanced_nm", "torque_balanced_n_m");
  if (report.textbook_inputs()) {
    report.erratum({"section 2.3, eqs. 60-61",
                    "we find the required balancing masses to be m0 = 76 grams",
                    fmt::format("its own small-angle formula (eq. 61) gives {:.1f} g and the "
                                "exact eq. 60 gives {:.1f} g for m = {:g} kg, a = {:g} cm, "
                                "b = {:g} cm, theta = {:g} deg",
                                1e3 * m0_small, 1e3 * m0, wheel.mass, 100 * wheel.radius,
                                100 * wheel.offset, in.tilt_deg)});
  }
}

// One turn of the unbalanced wheel: L and the bearing torque sweep a cone.
TimeSeries one_turn(const CrookedWheel& wheel, double omega) {
  // both vectors in the axes the wheel had at t = 0: x its symmetry axis, the axle in
  // the x-y plane at the tilt from x, so L sweeps a cone about the axle
  const std::string axes = " (x the wheel's symmetry axis at t = 0, the axle in the x-y plane)";
  TimeSeries turn("tire_balancing: one turn of the unbalanced wheel");
  turn.add({"t_s"}, "s", "time")
      .add({"Lx", "Ly", "Lz"}, "kg m^2/s", "the wheel's angular momentum" + axes)
      .add({"Nx", "Ny", "Nz"}, "N m", "the torque the bearings exert (eqs. 74-76)" + axes);
  const int samples = 361;
  const double period = 2.0 * kPi / omega;
  for (int k = 0; k < samples; ++k) {
    const double t = period * k / (samples - 1);
    const Vec3 L = angular_momentum_at(wheel, 0.0, omega, t);
    const Vec3 N = bearing_torque_at(wheel, 0.0, omega, t);
    turn.rows.push_back({t, L(0), L(1), L(2), N(0), N(1), N(2)});
  }
  return turn;
}
}  // namespace

const InputTable<Inputs>& input_table() {
  static const InputTable<Inputs> table = [] {
    InputTable<Inputs> t;
    t.number("--mass", &Inputs::mass, "mass m of the disk").unit("kg").positive().symbol("m");
    t.number("--radius", &Inputs::radius, "radius a of the disk").unit("m").positive().symbol("a");
    t.number("--offset", &Inputs::offset, "distance b of each balancing mass from the disk")
        .unit("m")
        .positive()
        .symbol("b");
    t.angle_deg("--tilt-deg", &Inputs::tilt_deg,
                "angle theta between axle and symmetry axis (0: straight)")
        .range_from(0.0, 45.0)
        .symbol("\\theta");
    t.number("--omega", &Inputs::omega, "spin of the wheel about its axle")
        .unit("rad/s")
        .positive();
    // SI inputs carry no unit in their names (angles in degrees end in -deg)
    t.number("--road-speed", &Inputs::road_speed,
             "road speed of the car, for the spin omega = speed / tire radius (instead of "
             "--omega)")
        .unit("m/s")
        .positive()
        .lab_default("--omega's")
        .excludes("--omega", "give --omega or --road-speed, not both")
        .renamed_from("--road-speed-m-s");
    t.number("--tire-radius", &Inputs::tire_radius,
             "rolling radius of the tire (at least --radius)")
        .unit("m")
        .positive()
        .requires_input("--road-speed", "sets the spin only with --road-speed")
        .renamed_from("--tyre-radius-m");
    return t;
  }();
  return table;
}

Report compute(const Inputs& in) {
  Report report(kName, kTitle);
  report.start(input_table(), in);
  CrookedWheel& wheel = report.wheel;
  wheel.mass = in.mass;
  wheel.radius = in.radius;
  wheel.offset = in.offset;
  wheel.set_tilt_deg(in.tilt_deg);
  const double omega = report.omega = spin_of(report, in);

  if (in.road_speed) {
    report.section("the spin from the road");
    report.result("omega_rad_s", "omega = road speed / tire radius", omega, "rad/s");
    report.result("road_speed_km_h", "  the road speed in km/h", 3.6 * *in.road_speed, "km/h");
  }
  const Unbalanced before = report_unbalanced(report);
  report_balancing(report, in, before.torque);
  report.series(one_turn(wheel, omega));
  const double m0 = report.m0;
  report.answer(
      m0 == 0.0 ? std::string("balanced already: the axle is a principal axis, L lies along it "
                              "and the bearings need no torque")
                : fmt::format("unbalanced: L is {:.3g} deg off the axle and sweeps a cone, so the "
                              "bearings must supply |N| = {:.4g} N m at omega = {:.4g} rad/s; two "
                              "masses of {:.4g} g at (-b, a) and (b, -a) put a principal axis on "
                              "the axle and the torque goes to 0",
                              before.tilt_L_deg, before.torque, omega, 1e3 * m0));
  return report;
}

namespace {

// The wheel turning steadily about its axle, its axes the space axes at t = 0: omega
// along the axle, the same in the body as in space.
BodyMotion body_motion(const Report& report) {
  const Vec3 axle = axle_direction(report.wheel);
  const double omega = report.omega;
  return [axle, omega](double t) {
    if (!(t >= 0.0)) refuse_before_start(t);
    return BodyState{Eigen::Quaterniond(Eigen::AngleAxisd(omega * t, axle)), omega * axle};
  };
}

}  // namespace

LabProgram<Inputs, Report> program() {
  return {kName,
          kTitle,
          input_table(),
          compute,
          figures,
          nullptr,
          /*csv=*/"the wheel's L and the bearings' torque N against time over one turn",
          /*preview=*/nullptr,
          /*textbook_example=*/true,
          body_motion};
}

}  // namespace rigid::lab::tire_balancing
