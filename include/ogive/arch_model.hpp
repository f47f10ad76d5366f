// The arch model of docs/model.md in non-dimensional form: state layout, right-hand side and boundary
// conditions of the six first-order equations. No solver types here: every method builds on this.
//
// Scaling (why: so that one matrix mixes numbers of order one whatever t/L and E are):
//   length       L (the span)              s~ = s / L, x~, y~, kappa~ = kappa L
//   force        w L                       Fx~, Fy~ (w = rho g t, the weight per axis length)
//   moment       w L^2                     M~
//   displacement w L^4 / (E I)             Ux~, Uy~
//   rotation     w L^3 / (E I)             psi~
// With c = cos theta, sn = sin theta, N~ = c Fx~ + sn Fy~, V~ = -sn Fx~ + c Fy~, the system reads
//   Ux~'  = a_N N~ c - (a_V V~ + psi~) sn          a_N = E I / (E A L^2) = (t/L)^2 / 12
//   Uy~'  = a_N N~ sn + (a_V V~ + psi~) c          a_V = E I / (k G A L^2)
//   psi~' = M~
//   Fx~'  = 0,   Fy~' = 1,   M~' = sn Fx~ - c Fy~
// i.e. y' = A(theta(s)) y + b with the constant load b = e_Fy. E enters only through a_V's ratio E/G,
// so with d = 0 the forces do not depend on the scale of E at all.
#pragma once

#include <memory>

#include <Eigen/Dense>

#include "ogive/scene.hpp"

namespace ogive {

// Global components, in this order, everywhere in ogive.
enum StateIndex : int { kUx = 0, kUy = 1, kPsi = 2, kFx = 3, kFy = 4, kM = 5 };
inline constexpr int kStateSize = 6;
using StateVector = Eigen::Matrix<double, kStateSize, 1>;
using SystemMatrix = Eigen::Matrix<double, kStateSize, kStateSize>;

// SI value of one scaled unit of each kind.
struct Scales {
  double length = 1, force = 1, moment = 1, displacement = 1, rotation = 1;
};

// Linear two-point conditions at_springing * y(0) + at_crown * y(S) = rhs (scaled). Rows 0-2 act at
// the springing (Ux = -d, Uy = 0, psi = 0), rows 3-5 at the crown (Ux = 0, psi = 0, Fy = 0).
struct BoundaryConditions {
  SystemMatrix at_springing = SystemMatrix::Zero();
  SystemMatrix at_crown = SystemMatrix::Zero();
  StateVector rhs = StateVector::Zero();
};

// The state at one point of the axis, in SI units, with the quantities the user reads.
struct ArchState {
  double s = 0;                  // m, arc length from the left springing (over the whole arch: 0..2S)
  double x = 0, y = 0;           // m, axis point
  double theta = 0;              // rad, tangent angle in the direction of increasing s
  double Ux = 0, Uy = 0;         // m, displacement of the axis
  double psi = 0;                // rad, rotation of the cross-section (counter-clockwise positive)
  double Fx = 0, Fy = 0;         // N/m, force of the part beyond s on the part before s
  double M = 0;                  // N m/m, couple of the part beyond s on the part before s
  double N = 0;                  // N/m, normal force, negative in compression
  double V = 0;                  // N/m, shear force
  double e = 0;                  // %, eccentricity of the compression, 600 M / (N t): 100 at the kern's
                                 // edge (t/6), 300 at the section's face; NaN where N = 0
  double thrust_x = 0, thrust_y = 0;  // m, where the resultant crosses the section (the thrust line);
                                      // NaN where N = 0
};

class ArchModel {
 public:
  // The scene must be valid (Scene::validate); the model keeps a copy of it.
  explicit ArchModel(Scene scene);

  const Scene& scene() const { return scene_; }
  const Scales& scales() const { return scales_; }
  double half_length() const { return half_length_; }  // S~ = S / L
  double a_N() const { return a_N_; }
  double a_V() const { return a_V_; }
  double support_displacement() const { return d_; }  // d~ = d / displacement scale

  double theta(double s) const;      // tangent angle at scaled arc length s
  SystemMatrix system_matrix(double theta) const;  // A(theta)
  static StateVector load() { return StateVector::Unit(kFy); }  // b
  // dy = A(theta(s)) y + load_factor * b; y and dy hold kStateSize doubles each.
  void rhs(double s, const double* y, double* dy, double load_factor = 1.0) const;
  // The same at the angle whose cosine and sine are c and sn (the one place of this arithmetic; inline:
  // the quadrature calls it at every node).
  void derivative(double c, double sn, const double* y, double* dy, double load_factor = 1.0) const;
  // Interior breakpoints of the half arch, scaled.
  std::vector<double> breakpoints() const;
  BoundaryConditions boundary_conditions() const;

  // Reactions from the springing state: H = -Fx (inwards push of the support), V = w S.
  double horizontal_reaction(const StateVector& y_springing) const { return -y_springing[kFx] * scales_.force; }
  double vertical_reaction() const { return half_length_ * scales_.force; }

  // The SI state at scaled arc length s of the half arch; mirrored = true maps it onto the right half
  // (at s_whole = 2S - s) using the scene's symmetry.
  ArchState to_physical(double s, const StateVector& y, bool mirrored = false) const;

  // |Boundary-condition residual| (max norm, scaled) and the relative residual of the half arch's
  // global equilibrium (vertical forces and moments about the springing, over the half weight).
  double boundary_residual(const StateVector& y0, const StateVector& yS) const;
  double equilibrium_residual(const StateVector& y0, const StateVector& yS) const;

 private:
  Scene scene_;
  Scales scales_;
  double half_length_, a_N_, a_V_, d_;
};

// The six equations of the header comment.
inline void ArchModel::derivative(double c, double sn, const double* y, double* dy, double load_factor) const {
  const double N = c * y[kFx] + sn * y[kFy];
  const double V = -sn * y[kFx] + c * y[kFy];
  const double rot = a_V_ * V + y[kPsi];
  dy[kUx] = a_N_ * N * c - rot * sn;
  dy[kUy] = a_N_ * N * sn + rot * c;
  dy[kPsi] = y[kM];
  dy[kFx] = 0.0;
  dy[kFy] = load_factor;
  dy[kM] = sn * y[kFx] - c * y[kFy];
}

}  // namespace ogive
