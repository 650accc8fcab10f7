#include "rigid/splitting.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace rigid {

namespace {

// The exact flow of H_i = L_i^2 / (2 I_i) over tau: L_body turns by -w_i tau
// about axis i, the attitude by +w_i tau about body axis i (w_i = L_i / I_i).
inline void axis_flow(int i, double tau, const double* inv_I, double* L, double* q) {
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  const double angle = L[i] * inv_I[i] * tau;
  // one sine and cosine of the half angle serve both L and q
  const double ch = std::cos(0.5 * angle), sh = std::sin(0.5 * angle);
  // 1 - cos(angle) = 2 sh^2 and sin(angle) = 2 sh ch, applied as increments:
  // near the separatrix the same small angles recur step after step, and
  // rounding c = 1 - 2 sh^2 would then drift |L| linearly instead of as a random walk.
  const double one_minus_c = 2.0 * sh * sh, s = 2.0 * sh * ch;
  // L_j' = L_k w_i, L_k' = -L_j w_i
  const double Lj = L[j], Lk = L[k];
  L[j] = Lj + (s * Lk - one_minus_c * Lj);
  L[k] = Lk - (s * Lj + one_minus_c * Lk);
  // q <- q (x) (cos(angle/2), sin(angle/2) e_i); q = (w, x, y, z)
  const double w = q[0];
  double v[3] = {q[1], q[2], q[3]};
  q[0] = ch * w - sh * v[i];
  const double vi = v[i], vj = v[j], vk = v[k];
  q[1 + i] = ch * vi + sh * w;
  // v x (sh e_i): component j = v_k sh, component k = -v_j sh
  q[1 + j] = ch * vj + sh * vk;
  q[1 + k] = ch * vk - sh * vj;
}

// Strang S2(tau): 1/2, 2/2, 3, 2/2, 1/2 on axes 0, 1, 2.
inline void strang(double tau, const double* inv_I, double* L, double* q) {
  axis_flow(0, 0.5 * tau, inv_I, L, q);
  axis_flow(1, 0.5 * tau, inv_I, L, q);
  axis_flow(2, tau, inv_I, L, q);
  axis_flow(1, 0.5 * tau, inv_I, L, q);
  axis_flow(0, 0.5 * tau, inv_I, L, q);
}

}  // namespace

LiePoissonSplitting::LiePoissonSplitting(const PrincipalMoments& I, int order)
    : inv_I_{1.0 / I.I1, 1.0 / I.I2, 1.0 / I.I3}, order_(order) {
  if (order != 2 && order != 4) {
    std::ostringstream os;
    os << "splitting order must be 2 or 4, got " << order;
    throw std::invalid_argument(os.str());
  }
}

void LiePoissonSplitting::step(Eigen::Vector3d& L_body, Eigen::Quaterniond& q, double h) const {
  double L[3] = {L_body.x(), L_body.y(), L_body.z()};
  double qa[4] = {q.w(), q.x(), q.y(), q.z()};
  if (order_ == 2) {
    strang(h, inv_I_, L, qa);
  } else {
    // adjacent half-steps about axis 0 merge: S2(a) S2(b) ends and starts with axis 0
    const double p = kSuzukiP * h, r = (1.0 - 4.0 * kSuzukiP) * h;
    const double stages[5] = {p, p, r, p, p};
    axis_flow(0, 0.5 * stages[0], inv_I_, L, qa);
    for (int s = 0; s < 5; ++s) {
      axis_flow(1, 0.5 * stages[s], inv_I_, L, qa);
      axis_flow(2, stages[s], inv_I_, L, qa);
      axis_flow(1, 0.5 * stages[s], inv_I_, L, qa);
      const double next = s + 1 < 5 ? stages[s + 1] : 0.0;
      axis_flow(0, 0.5 * (stages[s] + next), inv_I_, L, qa);
    }
  }
  L_body = Eigen::Vector3d(L[0], L[1], L[2]);
  q = Eigen::Quaterniond(qa[0], qa[1], qa[2], qa[3]);
}

}  // namespace rigid
