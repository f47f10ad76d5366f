#include "ogive/arch_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace ogive {

ArchModel::ArchModel(Scene scene) : scene_(std::move(scene)) {
  const Material& m = scene_.material;
  const double L = scene_.span();
  const double w = scene_.weight_per_length();
  const double EI = m.effective_modulus() * scene_.inertia();
  scales_.length = L;
  scales_.force = w * L;
  scales_.moment = w * L * L;
  scales_.displacement = w * L * L * L * L / EI;
  scales_.rotation = w * L * L * L / EI;
  half_length_ = scene_.curve->half_length() / L;
  // a_N = I / (A L^2) exactly: the same modulus stiffens bending and stretching.
  a_N_ = scene_.inertia() / (scene_.area() * L * L);
  a_V_ = m.effective_modulus() / (m.shear_coefficient * m.shear_modulus()) * a_N_;
  d_ = scene_.support_displacement / scales_.displacement;
}

double ArchModel::theta(double s) const { return scene_.curve->angle(s * scales_.length); }

std::vector<double> ArchModel::breakpoints() const {
  std::vector<double> out = scene_.curve->breakpoints();
  for (double& b : out) b /= scales_.length;
  return out;
}

SystemMatrix ArchModel::system_matrix(double theta) const {
  const double c = std::cos(theta), sn = std::sin(theta);
  SystemMatrix A = SystemMatrix::Zero();
  A(kUx, kPsi) = -sn;
  A(kUx, kFx) = a_N_ * c * c + a_V_ * sn * sn;
  A(kUx, kFy) = (a_N_ - a_V_) * c * sn;
  A(kUy, kPsi) = c;
  A(kUy, kFx) = (a_N_ - a_V_) * c * sn;
  A(kUy, kFy) = a_N_ * sn * sn + a_V_ * c * c;
  A(kPsi, kM) = 1.0;
  A(kM, kFx) = sn;
  A(kM, kFy) = -c;
  return A;
}

void ArchModel::rhs(double s, const double* y, double* dy, double load_factor) const {
  const double th = theta(s);
  derivative(std::cos(th), std::sin(th), y, dy, load_factor);
}

BoundaryConditions ArchModel::boundary_conditions() const {
  BoundaryConditions bc;
  bc.at_springing(0, kUx) = 1.0;
  bc.rhs(0) = -d_;
  bc.at_springing(1, kUy) = 1.0;
  bc.at_springing(2, kPsi) = 1.0;
  bc.at_crown(3, kUx) = 1.0;
  bc.at_crown(4, kPsi) = 1.0;
  bc.at_crown(5, kFy) = 1.0;
  return bc;
}

ArchState ArchModel::to_physical(double s, const StateVector& y, bool mirrored) const {
  const double L = scales_.length;
  const CurvePoint half = scene_.curve->at(s * L);
  const CurvePoint p = mirrored ? mirror(half, L) : half;
  ArchState st;
  st.s = mirrored ? 2.0 * scene_.curve->half_length() - s * L : s * L;
  st.x = p.x;
  st.y = p.y;
  st.theta = p.theta;
  st.Ux = y[kUx] * scales_.displacement;
  st.Uy = y[kUy] * scales_.displacement;
  st.psi = y[kPsi] * scales_.rotation;
  st.Fx = y[kFx] * scales_.force;
  st.Fy = y[kFy] * scales_.force;
  st.M = y[kM] * scales_.moment;
  if (mirrored) {
    // Reflection about x = L/2, with "beyond" and "before" swapped on the right half.
    st.Ux = -st.Ux;
    st.psi = -st.psi;
    st.Fy = -st.Fy;
  }
  const double c = std::cos(st.theta), sn = std::sin(st.theta);
  st.N = c * st.Fx + sn * st.Fy;
  st.V = -sn * st.Fx + c * st.Fy;
  const double t = scene_.thickness;
  // Where the normal force vanishes there is no eccentricity: NaN, never an unbounded number that reads
  // as a result. (Under tension, N > 0, e is the tensile force's eccentricity; the CLI flags it.)
  if (st.N == 0) {
    st.e = st.thrust_x = st.thrust_y = std::numeric_limits<double>::quiet_NaN();
    return st;
  }
  st.e = 600.0 * st.M / (st.N * t);
  // F acting at offset a along the extrados normal n = (-sn, c) has moment -a N about the axis point,
  // so the resultant crosses the section at a = -M / N.
  const PlanePoint thrust = along_normal(p, -st.M / st.N);
  st.thrust_x = thrust.x;
  st.thrust_y = thrust.y;
  return st;
}

double ArchModel::boundary_residual(const StateVector& y0, const StateVector& yS) const {
  const BoundaryConditions bc = boundary_conditions();
  return (bc.at_springing * y0 + bc.at_crown * yS - bc.rhs).lpNorm<Eigen::Infinity>();
}

double ArchModel::equilibrium_residual(const StateVector& y0, const StateVector& yS) const {
  const double L = scales_.length;
  const CurvePoint crown = scene_.curve->at(scene_.curve->half_length());
  const double xS = crown.x / L, yS_pos = crown.y / L;
  const double weight = half_length_;  // scaled half weight (w = 1)
  const double first_moment = scene_.curve->first_moment_x() / (L * L);
  const double vertical = yS[kFy] - y0[kFy] - weight;
  // Moments about the left springing: crown force and couple, springing couple, weight.
  const double moment = xS * yS[kFy] - yS_pos * yS[kFx] + yS[kM] - y0[kM] - first_moment;
  const double horizontal = yS[kFx] - y0[kFx];
  return std::max({std::abs(vertical), std::abs(horizontal), std::abs(moment) / std::max(xS, 1e-300)}) /
         weight;
}

}  // namespace ogive
