// poinsot's figures and motion in-process: the figures handed over, the animation's
// span, the motion the same in any order of its times, the notes' numbers, the phase
// plot, the flip of any body spun near its middle axis, and Poinsot's construction
// (the invariable plane, the herpolhode's turn) as values.
#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "lab_library.h"
#include "poinsot/poinsot.h"
#include "poinsot_inputs.h"

using rigid::lab::poinsot::compute;
using rigid::lab::poinsot::Inputs;
using rigid::lab::poinsot::Motion;
using rigid::lab::poinsot::Report;
using rigid::test::check_same_scene;
using rigid::test::given;
using rigid::test::kRoundoff;
using rigid::test::value;

namespace {

// The figures handed over, by name.
struct NamingSink : rigid::lab::FigureSink {
  std::vector<std::string> names;
  void add(const std::string& name, const std::string&, rigid::render::Plot2D) override {
    names.push_back(name);
  }
  void add(const std::string& name, const std::string&, rigid::render::Scene3D) override {
    names.push_back(name);
  }
};

}  // namespace

TEST_CASE("poinsot: the figures handed over, the herpolhode only with a polhode period") {
  NamingSink periodic;
  rigid::lab::poinsot::figures(compute(given("--method rk4")), periodic);
  CHECK(periodic.names ==
        std::vector<std::string>{"ellipsoids", "polhodes", "omega", "integrators", "herpolhode"});
  NamingSink steady;
  rigid::lab::poinsot::figures(compute(given("--omega 0,1,0")), steady);
  CHECK(steady.names == std::vector<std::string>{"ellipsoids", "polhodes", "omega", "integrators"});
}

TEST_CASE("poinsot: the animation spans t_end, three polhode periods by default") {
  const Report report = compute(Inputs{});
  bool asked = false;
  const auto frame_times = [&asked](double seconds) {
    asked = true;
    return std::vector<double>{0.0, seconds / 2};
  };
  const auto animation = rigid::lab::poinsot::animation(report, frame_times);
  CHECK(animation.seconds ==
        Approx(3 * value(report.results(), "polhode_period_s")).epsilon(kRoundoff));
  CHECK(!asked);  // the closed form needs no samples ahead
  CHECK(animation.scene(0.0).title.find("t = 0.00 s") != std::string::npos);
  const Report integrated = compute(given("--method rk4 --step 0.37"));
  const auto frames = rigid::lab::poinsot::animation(integrated, frame_times);
  CHECK(asked);
  CHECK(frames.seconds == value(integrated.results(), "t_end_s"));
}

TEST_CASE("poinsot: the motion is the same whatever the order of its times") {
  for (const char* args : {"", "--method rk4", "--method dopri5 --box 0.07,0.15,0.008"}) {
    INFO(args);
    const Report report = compute(given(args));
    // the animation's times (as --animate asks them) ahead, and times between them
    // and past the run's samples, which an integrated motion integrates to
    std::vector<double> ahead, times;
    for (int k = 0; k < 24; ++k) ahead.push_back(report.t_end * k / 24);
    for (int k = 0; k <= 60; ++k) times.push_back(report.t_end * k / 60);
    times.insert(times.end(), ahead.begin(), ahead.end());
    for (int k = 0; k < 24; ++k) times.push_back(report.t_end * (k + 0.37) / 24);
    const Motion in_order(report, ahead);
    std::vector<rigid::render::Scene3D> scenes;
    for (const double t : times) scenes.push_back(in_order.scene(t));
    // a second motion of the same report, asked in another order (twice for some)
    const Motion shuffled(report, ahead);
    std::vector<std::size_t> order(times.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::shuffle(order.begin(), order.end(), std::mt19937(20240611));
    order.insert(order.end(), order.begin(), order.begin() + 10);
    for (const std::size_t k : order) {
      INFO("t = " << times[k]);
      check_same_scene(shuffled.scene(times[k]), scenes[k]);
    }
    CHECK(shuffled.seconds() == report.t_end);
  }
}

TEST_CASE("poinsot: the notes carry their own numbers, the herpolhode's folded to 180 deg") {
  using rigid::test::contains;
  using rigid::test::notes_starting;
  // Section 4.1 for I1 : I2 : I3 = 5 : 4 : 3: touching the energy ellipsoid (1/sqrt(I_j))
  // on axis i scales the momentum one (1/I_j) to sqrt(I_i)/I_j.
  const double I[] = {5, 4, 3};
  const auto touching = [&](int i) {
    return fmt::format("({:.3f} : {:.3f} : {:.3f})", std::sqrt(I[i]) / I[0], std::sqrt(I[i]) / I[1],
                       std::sqrt(I[i]) / I[2]);
  };
  const std::string herpolhode = "the herpolhode closes only if";
  int folded = 0;  // runs whose contact point ends more than 180 deg round
  for (const Eigen::Vector3d& omega0 :
       {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 0.2, 0.5), Eigen::Vector3d(0.3, 1, 0.1),
        Eigen::Vector3d(0.1, 0.4, 1)}) {
    INFO("omega0 " << omega0.transpose());
    Inputs in;
    in.omega0 = omega0;
    const auto report = compute(in);
    REQUIRE(report.errata().size() == 2);
    const auto& ratios = report.errata()[1];
    CHECK(ratios.where == "section 4.1, the momentum ratios touching on axes 1 and 2");
    CHECK(ratios.printed ==
          "resulting is (0.44:0.55:0.73) ... However for the 2-axis, intermediate moment, the "
          "ratio becomes (0.40:0.50:0.66)");
    CHECK(ratios.correction ==
          "the text rescales ratios it has already rounded; exactly, touching on axis 1 gives " +
              touching(0) + " and on axis 2 " + touching(1));
    const auto& root5 = report.errata()[0];
    CHECK(root5.where == "section 4.1, the energy ellipsoid's ratios");
    CHECK(root5.printed == "the ratio from kinetic energy is (0.44:0.50:0.58)");
    CHECK(root5.correction ==
          fmt::format("1/sqrt(5) = {:.4f} rounds to {:.2f}, which the text truncates to 0.44: "
                      "({:.2f} : {:.2f} : {:.2f})",
                      1 / std::sqrt(5.0), 1 / std::sqrt(5.0), 1 / std::sqrt(5.0),
                      1 / std::sqrt(4.0), 1 / std::sqrt(3.0)));
    for (const auto& e : report.errata()) {
      CHECK(notes_starting(report, "errata: " + e.where + ": the text prints \"" + e.printed +
                                       "\"; " + e.correction)
                .size() == 1);
    }
    // After kHerpolhodePeriods periods the contact point has turned N x turn; its
    // distance from the start is that angle folded into [0, 180] deg.
    const double turn = value(report.results(), "herpolhode_turn_per_period_deg");
    const double round = std::fmod(rigid::lab::poinsot::kHerpolhodePeriods * turn, 360.0);
    const double from_start = std::min(std::abs(round), 360.0 - std::abs(round));
    folded += std::abs(round) > 180.0;
    const auto said = notes_starting(report, herpolhode);
    REQUIRE(said.size() == 1);
    CHECK(contains(said[0], fmt::format("a polhode period, {:.4f} deg, is", turn)));
    CHECK(contains(said[0], fmt::format("after {:g} periods the contact point is {:.2f} deg from",
                                        rigid::lab::poinsot::kHerpolhodePeriods, from_start)));
  }
  CHECK(folded > 0);
  CHECK(folded < 4);
  // No polhode period (about an axis, steady): no herpolhode note.
  Inputs steady;
  steady.omega0 = Eigen::Vector3d(0, 0, 2);
  CHECK(notes_starting(compute(steady), herpolhode).empty());
}

TEST_CASE("poinsot: the phase plot starts each curve at its own t = 0 point") {
  // omega0 with three different components: (omega1, omega2) and (omega1, omega3) at
  // t = 0 are the marked points, each the first point of its curve.
  Inputs in;
  in.omega0 = Eigen::Vector3d(1.0, 0.2, 0.5);
  const auto report = compute(in);
  rigid::test::KeptFigures kept;
  rigid::lab::poinsot::figures(report, kept);
  REQUIRE(kept.plots.count("omega") == 1);
  const rigid::render::Panel& phase = kept.plots.at("omega").panel(0, 1);
  const rigid::render::Series* start = nullptr;
  for (const auto& s : phase.series) {
    if (s.label == "t = 0") start = &s;
  }
  REQUIRE(start != nullptr);
  REQUIRE(start->x.size() == 2);
  REQUIRE(phase.series.size() >= 2);
  for (int j = 0; j < 2; ++j) {
    INFO("omega_" << j + 2 << " against omega_1");
    CHECK(start->x[j] == in.omega0(0));
    CHECK(start->y[j] == in.omega0(j + 1));
    CHECK(phase.series[j].x.front() == Approx(start->x[j]).epsilon(kRoundoff));
    CHECK(phase.series[j].y.front() == Approx(start->y[j]).epsilon(kRoundoff));
  }
}

TEST_CASE("poinsot: any body spun near its middle axis - growth rate, first flip, flips") {
  // The book of the issue: 24 x 16 x 4 cm, 0.8 kg, spun at 6 rad/s about its middle
  // axis with 0.06 rad/s on each of the others.
  const double m = 0.8, a = 0.24, b = 0.16, c = 0.04;
  const double I1 = m * (b * b + c * c) / 12, I2 = m * (a * a + c * c) / 12,
               I3 = m * (a * a + b * b) / 12;
  const Report book = compute(given("--box 0.24,0.16,0.04 --mass 0.8 --omega 0.06,6,0.06"));
  const auto& r = book.results();
  // eqs. 86-88 about axis 2, at the spin's own component omega_2(0) = 6 rad/s
  CHECK(value(r, "growth_rate_per_s") ==
        Approx(6 * std::sqrt((I2 - I1) * (I3 - I2) / (I1 * I3))).epsilon(kRoundoff));
  // fitted to the exact motion up to a share of 0.1: the linear rate to ~share^2
  CHECK(value(r, "growth_rate_measured_per_s") ==
        Approx(value(r, "growth_rate_per_s")).epsilon(0.01));
  CHECK(value(r, "flip_interval_s") ==
        Approx(0.5 * value(r, "polhode_period_s")).epsilon(kRoundoff));
  // The first flip against a second method: an integration at tolerance 1e-13, whose
  // omega_2 changes sign between two of its samples that bracket the closed form's time.
  const Report run = compute(given(
      "--box 0.24,0.16,0.04 --mass 0.8 --omega 0.06,6,0.06 --method vern9 --tolerance 1e-13"));
  const double flip = value(r, "first_flip_s");
  bool bracketed = false;
  const auto& samples = run.run.samples;
  for (std::size_t k = 1; k < samples.size() && !bracketed; ++k) {
    if (samples[k - 1].x[1] > 0 && samples[k].x[1] <= 0) {
      bracketed = samples[k - 1].t < flip && flip <= samples[k].t;
      INFO("omega_2 changes sign between " << samples[k - 1].t << " and " << samples[k].t
                                           << " s; the closed form says " << flip << " s");
      CHECK(bracketed);
    }
  }
  CHECK(bracketed);
  // the headline says at once that the body flips, not only "polhode about the largest axis"
  bool headline = false;
  for (const auto& row : book.rows()) {
    headline = headline ||
               (row.label == "motion" && row.remark.find("the body flips") != std::string::npos);
  }
  CHECK(headline);
  // the answer in short says so, with the numbers
  CHECK_THAT(r["answer"].get<std::string>(),
             Catch::StartsWith(fmt::format("it flips: spun near its intermediate axis, the body "
                                           "turns over first at {:.4g} s, then every {:.4g} s",
                                           flip, value(r, "flip_interval_s"))));
  CHECK_THAT(compute(Inputs{}).results()["answer"].get<std::string>(), Catch::Contains("stable"));
  // No flips: a stable spin (the text's ellipsoid), a spin exactly on the axis, two
  // equal moments; each says why.
  for (const auto& [args, why] :
       {std::pair{"", "not spun near axis 2"},
        std::pair{"--box 0.24,0.16,0.04 --mass 0.8 --omega 0,6,0", "exactly on the axis"},
        std::pair{"--inertia 1,1,2 --omega 0.1,1,0.1", "two equal moments"}}) {
    INFO(args);
    const Report none = compute(given(args));
    CHECK(none.results().at("first_flip_s").is_null());
    bool said = false;
    for (const auto& row : none.rows()) {
      said = said ||
             (row.label.rfind("first flip", 0) == 0 && row.textbook.find(why) != std::string::npos);
    }
    CHECK(said);
  }
}

namespace {

using Shape = rigid::render::Scene3D::Shape;

// The construction in the motion's scene at t, drawn at `scale` (the body's largest
// half-extent over the energy ellipsoid's largest semi-axis sqrt(2T / I_min)), L
// pointing down: the plane `plane` = 2T/|L| (scaled) below its fixed point, the energy
// ellipsoid resting on it at the contact point, and the herpolhode drawn so far on it.
void check_construction_at(const Motion& motion, double t, double scale, double plane) {
  INFO("t = " << t << " s");
  const auto scene = motion.scene(t);
  const rigid::render::Scene3D::Object *plane_disk = nullptr, *ellipsoid = nullptr,
                                       *contact = nullptr, *herpolhode = nullptr;
  for (const auto& o : scene.objects()) {
    if (o.label == "invariable plane") plane_disk = &o;
    if (o.label == "energy ellipsoid") ellipsoid = &o;
    if (o.label == "herpolhode") herpolhode = &o;
    if (o.marker) contact = &o;
  }
  REQUIRE(plane_disk != nullptr);
  REQUIRE(ellipsoid != nullptr);
  REQUIRE(contact != nullptr);
  CHECK(plane_disk->shape == Shape::kDisk);
  // the plane lies 2T/|L| (scaled) below the fixed point of the construction, facing L
  const Eigen::Vector3d centre = ellipsoid->transform.translation();
  const double plane_z = plane_disk->transform.translation().z();
  CHECK(centre.z() - plane_z == Approx(scale * plane).epsilon(8 * DBL_EPSILON));
  CHECK(std::abs(plane_disk->transform.linear().col(2).normalized().z()) ==
        Approx(1.0).epsilon(kRoundoff));
  // and the energy ellipsoid rests on it: its lowest point, centre.z - |A^T z| for the
  // unit sphere's map A, is the plane's height (the attitude's roundoff: 1e-13)
  const Eigen::Matrix3d A = ellipsoid->transform.linear();
  CHECK(centre.z() - (A.transpose() * Eigen::Vector3d::UnitZ()).norm() ==
        Approx(plane_z).margin(1e-13 * scale * plane));
  // touching it at the contact point, omega, and the herpolhode drawn so far lies on it
  CHECK(contact->transform.translation().z() == Approx(plane_z).margin(1e-13 * scale * plane));
  if (herpolhode != nullptr) {
    for (const Eigen::Vector3d& p : herpolhode->path) {
      CHECK(p.z() == Approx(plane_z).margin(1e-13 * scale * plane));
    }
  }
}

// Seen from above: the contact point at t = 0, T, 2T, .. turns about the foot of L by the
// herpolhode's turn each period, `turn_deg` (modulo whole turns), on the same plane. L
// points down (-z): a turn about L is the negative of one about z.
void check_herpolhode_turn(const Motion& motion, double scale, double plane, double turn_deg) {
  const auto above = motion.herpolhode_scene(rigid::lab::poinsot::kHerpolhodePeriods);
  std::vector<Eigen::Vector3d> points;
  Eigen::Vector3d foot = Eigen::Vector3d::Zero();
  for (const auto& o : above.objects()) {
    if (o.marker) points.push_back(o.transform.translation());
    if (o.label == "invariable plane") foot = o.transform.translation();
  }
  REQUIRE(points.size() == 7);
  for (std::size_t k = 0; k < points.size(); ++k) {
    CHECK(points[k].z() == Approx(foot.z()).margin(1e-13 * scale * plane));
    if (k == 0) continue;
    const auto azimuth = [&](const Eigen::Vector3d& p) {
      return -std::atan2(p.y() - foot.y(), p.x() - foot.x()) * 180 / M_PI;
    };
    // the attitude at k T from the closed form, to ~1e-13 rad of a contact point ~1 from
    // the foot: 1e-9 deg
    CHECK(std::remainder(azimuth(points[k]) - azimuth(points[k - 1]) - turn_deg, 360.0) ==
          Approx(0.0).margin(1e-9));
  }
}

}  // namespace

TEST_CASE("poinsot: the invariable plane at 2T/|L| and the herpolhode's turn, as values") {
  // tests/labs/references/poinsot/make_reference.py: 2T/|L|, the polhode period and the turn about
  // L a period (Euler's equations and the contact point's azimuth rate integrated by mpmath), 30
  // digits.
  struct Row {
    double I1, I2, I3, w1, w2, w3, plane, period, turn_deg;
  };
  const Row rows[] = {
#include "references/poinsot/reference_construction.inc"
  };
  for (const Row& row : rows) {
    const Eigen::Vector3d I(row.I1, row.I2, row.I3), w0(row.w1, row.w2, row.w3);
    INFO("I = " << I.transpose() << ", omega0 = " << w0.transpose());
    Inputs in;
    in.inertia = I;
    in.omega0 = w0;
    const Report report = compute(in);
    const auto& r = report.results();
    // 2T/|L|: sums of three products and a square root, a few roundings
    CHECK(value(r, "invariable_plane_distance") == Approx(row.plane).epsilon(kRoundoff));
    // the elliptic closed form's period, and its turn by a periodic mean of the rate: both
    // measured within 2e-15 of mpmath; 1e-13 leaves room for another machine's libm
    CHECK(value(r, "polhode_period_s") == Approx(row.period).epsilon(1e-13));
    CHECK(value(r, "herpolhode_turn_per_period_deg") == Approx(row.turn_deg).epsilon(1e-13));

    // The scene: the construction drawn to scale, L pointing down.
    const double two_T = I.dot(w0.cwiseProduct(w0));
    const double scale = report.extents.maxCoeff() / std::sqrt(two_T / I.minCoeff());
    const Motion motion(report);
    for (const double share : {0.0, 0.3, 1.7}) {
      check_construction_at(motion, share * row.period, scale, row.plane);
    }
    check_herpolhode_turn(motion, scale, row.plane, row.turn_deg);
  }
}
