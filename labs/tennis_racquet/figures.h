// tennis_racquet's inputs and figures: omega against t for a spin about each
// principal axis, the growth of the disturbance on a log scale, the racquet
// turning over during one flip, and its polhodes with the separatrix.
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "common/figures.h"
#include "common/free_body_run.h"
#include "rigid/free_body_exact.h"
#include "rigid/racquet.h"

namespace rigid::lab::tennis_racquet {

/// The lab's inputs, with the text's model racquet (section 4.1, Figure 5).
struct Inputs {
  double head_mass = 0.15;      ///< m_a, kg
  double head_radius = 0.13;    ///< a, m
  double handle_mass = 0.18;    ///< m_l, kg
  double handle_length = 0.38;  ///< l, m
  std::string spin_axis = "2";  ///< the axis the run spins about
  double omega = 10.0;          ///< the spin, rad/s
  double perturbation = 0.01;   ///< transverse share of omega at launch
  double t_end = 0.0;           ///< 0: one polhode period of the spin about axis 2 (two flips)
  double periods = 0.0;         ///< --periods: t_end as a number of polhode periods
  IntegrationInputs integration{"dopri5"};  ///< the cross-check
};

/// What the figures show.
struct Figures {
  const Racquet& racquet;
  /// The exact motion launched about axes 1, 2 and 3 with the same disturbance.
  const std::array<FreeBodyExact, 3>& launches;
  std::array<SpinStability, 3> predicted;  ///< the linear prediction for each axis (eqs. 86-88)
  double textbook_rate = 0.0;              ///< eq. 92's rate for every axis: the spin
  const GrowthFit* growth;                 ///< the growth measured about axis 2; null: no flip
  double t_end = 0.0;                      ///< the span of the omega panels, s
  int spin_axis = 1;                       ///< the run's axis (0, 1, 2): its polhode is drawn
};

/// Hands the lab's figures to the set.
void draw(FigureSet& set, const Figures& f);

/// The racquet at time t of `motion` in space, L fixed and drawn up, with body axis 2:
/// spun about axis 2 it turns over and back (the animation's scene).
/// States (omega_body, attitude) from `state_at` when given (an integrator's), else exact.
render::Scene3D spin_scene(const Racquet& racquet, const FreeBodyExact& motion, int axis, double t,
                           const std::function<FreeBodyState(double)>& state_at = {});
/// omega_1, omega_2, omega_3 of `motion` over [0, t_end] with a line at t (the strip under it).
render::Plot2D omega_strip(const FreeBodyExact& motion, double t_end, double t);

}  // namespace rigid::lab::tennis_racquet
