// tire_balancing: sections 2.2 and 2.3 of the chapter.
// A wheel (a uniform disk of mass m and radius a) sits on an axle tilted by
// theta from its symmetry axis. Spinning, its L is not along the axle, so L
// sweeps a cone and the bearings must supply a torque. Two masses m0 at
// (-b, a) and (b, -a) swing a principal axis onto the axle and balance it.
#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "common/lab.h"
#include "figures.h"
#include "rigid/balancing.h"
#include "rigid/units.h"

using rigid::Vec3;
using rigid::lab::Lab;
using rigid::lab::UsageError;

int main(int argc, char** argv) {
  Lab lab("tire_balancing", "dynamic balancing of a wheel on a crooked axle (sections 2.2-2.3)");
  rigid::lab::tire_balancing::Inputs in;
  rigid::CrookedWheel& wheel = in.wheel;
  lab.number("--mass", wheel.mass, "mass m of the disk").unit("kg").positive().symbol("m");
  lab.number("--radius", wheel.radius, "radius a of the disk").unit("m").positive().symbol("a");
  lab.number("--offset", wheel.offset, "distance b of each balancing mass from the disk")
      .unit("m")
      .positive()
      .symbol("b");
  lab.angle_deg("--tilt-deg", in.tilt_deg,
                "angle theta between axle and symmetry axis (0: straight)")
      .range_from(0.0, 45.0)
      .symbol("\\theta");
  lab.number("--omega", in.omega, "spin of the wheel about its axle").unit("rad/s").positive();
  lab.number("--road-speed-m-s", in.road_speed,
             "road speed of the car, for the spin omega = speed / tyre radius (instead of --omega)")
      .unit("m/s")
      .positive()
      .lab_default("--omega's");
  lab.number("--tyre-radius-m", in.tyre_radius,
             "rolling radius of the tyre, with --road-speed-m-s (at least --radius)")
      .unit("m")
      .positive();
  lab.enable_csv();

  return lab.run(argc, argv, [&](Lab& lab) {
    wheel.tilt = rigid::deg_to_rad(in.tilt_deg);
    // The spin from the road: a tyre of rolling radius R at speed v turns at v / R.
    if (lab.given("--road-speed-m-s") && lab.given("--omega")) {
      throw UsageError("--road-speed-m-s", "give --omega or --road-speed-m-s, not both");
    }
    if (lab.given("--tyre-radius-m") && !lab.given("--road-speed-m-s")) {
      throw UsageError("--tyre-radius-m", "sets the spin only with --road-speed-m-s");
    }
    if (lab.given("--road-speed-m-s")) {
      if (in.tyre_radius < wheel.radius) {
        throw UsageError("--tyre-radius-m", fmt::format("must be at least the disk's radius "
                                                        "--radius = {:g} m (got {:g})",
                                                        wheel.radius, in.tyre_radius));
      }
      in.omega = in.road_speed / in.tyre_radius;
      lab.drop_input("omega");
    } else {
      lab.drop_input("tyre_radius_m");
    }
    const double omega = in.omega;

    if (lab.given("--road-speed-m-s")) {
      lab.section("the spin from the road");
      lab.result("omega_rad_s", "omega = road speed / tyre radius", omega, "rad/s");
      lab.result("road_speed_km_h", "  the road speed in km/h", 3.6 * in.road_speed, "km/h");
    }
    lab.section("2.2 before balancing: L is off the axle");
    const Vec3 axle = rigid::axle_direction(wheel);
    const Vec3 L0 = rigid::angular_momentum_at(wheel, 0.0, omega, 0.0);
    lab.result("angle_L_axle_deg", "angle between L and the axle",
               rigid::rad_to_deg(rigid::angle_between(L0, axle)), "deg");
    lab.result("torque_unbalanced_n_m", "bearing torque |omega x I omega|",
               rigid::bearing_torque(wheel, 0.0, omega).stableNorm(), "N m");

    lab.section("2.3 balancing masses m0 at (-b, a) and (b, -a) (eqs. 57-61)");
    const double m0 =
        rigid::lab::for_option("--tilt-deg", [&] { return rigid::balance_mass_exact(wheel); });
    const double m0_small = rigid::balance_mass_small_angle(wheel);
    lab.result("balance_mass_kg", "m0, exact from tan 2 theta (eq. 60)", m0, "kg",
               lab.textbook("0.076 (76 g)"));
    lab.result("balance_mass_small_angle_kg", "m0, small angle theta = 8 b m0 / (a m) (eq. 61)",
               m0_small, "kg", lab.textbook("0.076 (76 g)"));
    // Roundoff of the exact balance: the eigen-solver's axis to ~eps |I| / gap (the
    // gap between the axle's moment and the others), the torque to ~eps omega^2 |I|;
    // 64 eps bounds both.
    const rigid::Mat3 I_balanced = rigid::wheel_body(wheel, m0).I_com;
    const rigid::Vec3 moments = rigid::principal_axes(I_balanced).moments;
    const double I_axle = rigid::moment_about_axis(I_balanced, axle);
    double gap = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      if (std::abs(moments(i) - I_axle) > 1e-9 * moments.maxCoeff()) {
        gap = std::min(gap, std::abs(moments(i) - I_axle));
      }
    }
    constexpr double kRoundoff = 64 * std::numeric_limits<double>::epsilon();
    lab.result_roundoff("residual_tilt_exact_deg", "principal axis to axle, exact m0",
                        rigid::rad_to_deg(rigid::principal_axis_misalignment(wheel, m0)),
                        rigid::rad_to_deg(kRoundoff * moments.maxCoeff() / gap), "deg");
    lab.result("residual_tilt_small_angle_deg", "principal axis to axle, small-angle m0",
               rigid::rad_to_deg(rigid::principal_axis_misalignment(wheel, m0_small)), "deg");
    lab.result_roundoff("torque_balanced_n_m", "bearing torque after balancing",
                        rigid::bearing_torque(wheel, m0, omega).stableNorm(),
                        kRoundoff * omega * omega * moments.maxCoeff(), "N m");
    // The old names (read "nm" as nanometres), kept one release (the schema says so).
    lab.alias("torque_unbalanced_nm", "torque_unbalanced_n_m");
    lab.alias("torque_balanced_nm", "torque_balanced_n_m");
    if (lab.textbook_inputs()) {
      lab.note(fmt::format(
          "errata: the text prints m0 = 76 g; its own small-angle formula (eq. 61) gives "
          "{:.1f} g and the exact eq. 60 gives {:.1f} g for m = {:g} kg, a = {:g} cm, "
          "b = {:g} cm, theta = {:g} deg",
          1e3 * m0_small, 1e3 * m0, wheel.mass, 100 * wheel.radius, 100 * wheel.offset,
          in.tilt_deg));
    }

    // One turn of the unbalanced wheel: L and the bearing torque sweep a cone.
    rigid::lab::TimeSeries turn{{"t_s", "Lx", "Ly", "Lz", "Nx", "Ny", "Nz"}, {}};
    const int samples = 361;
    const double period = 2.0 * rigid::kPi / omega;
    for (int k = 0; k < samples; ++k) {
      const double t = period * k / (samples - 1);
      const Vec3 L = rigid::angular_momentum_at(wheel, 0.0, omega, t);
      const Vec3 N = rigid::bearing_torque_at(wheel, 0.0, omega, t);
      turn.rows.push_back({t, L(0), L(1), L(2), N(0), N(1), N(2)});
    }
    lab.series(std::move(turn));

    lab.figures([&](rigid::lab::FigureSet& set) { rigid::lab::tire_balancing::draw(set, in, m0); });
  });
}
