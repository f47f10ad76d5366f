// The closed form (src/methods/closed_form.hpp) against physics and an independent reference: its six
// boundary conditions and global equilibrium, the force method (Castigliano), the free body of every
// station, and a reason where it does not apply.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <unsupported/Eigen/MatrixFunctions>

#include "methods/closed_form.hpp"
#include "ogive/solve/solve.hpp"
#include "support/reference.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

TEST_CASE("closed form: the solution meets all six boundary conditions and global equilibrium") {
  for (double eps : {0.0, 0.3, 0.5, 1.0, 3.0})
    for (double t : {0.06, 0.2})
      for (double d : {0.0, 2e-4}) {
        CAPTURE(eps);
        CAPTURE(t);
        CAPTURE(d);
        const Scene scene = paper_scene(eps, t, d);
        const Solution sol = closed_form(scene, 3);  // springing, crown, springing
        REQUIRE(sol.status == Status::success);
        CHECK(sol.diagnostics.boundary_residual <= kExact);
        CHECK(sol.diagnostics.equilibrium_residual <= kExact);
        // In SI, from the profile: the springing and crown states themselves.
        const ArchState& spring = sol.profile.front();
        const ArchState& crown = sol.profile[1];
        const double disp = sol.model->scales().displacement, rot = sol.model->scales().rotation;
        const double force = sol.model->scales().force;
        CHECK(std::abs(spring.Ux + scene.left.spread) <= kExact * disp);
        CHECK(std::abs(spring.Uy) <= kExact * disp);
        CHECK(std::abs(spring.psi) <= kExact * rot);
        CHECK(std::abs(crown.Ux) <= kExact * disp);
        CHECK(std::abs(crown.psi) <= kExact * rot);
        CHECK(std::abs(crown.Fy) <= kExact * force);
        // The vertical reaction is half the weight, w S, and H = -Fx everywhere.
        CHECK(close(sol.V, scene.weight_per_length() * scene.curve->length(), kExact));
        CHECK(close(-spring.Fy, sol.V, kExact));
        CHECK(close(-crown.Fx, sol.H, kExact));
      }
}

TEST_CASE("closed form: agrees with the force method (Castigliano) for any eccentricity - thickness - d") {
  for (double eps : {0.0, 0.25, 0.5, 1.0, 2.0, 5.0})
    for (double t : {0.01, 0.08, 0.2})
      for (double d : {0.0, 1e-4, -5e-5}) {
        CAPTURE(eps);
        CAPTURE(t);
        CAPTURE(d);
        const Scene scene = paper_scene(eps, t, d);
        const double H = reference::castigliano_pointed_H(10.0, eps, scene.thickness, scene.material,
                                                          scene.left.spread);
        const Solution sol = closed_form(scene);
        REQUIRE(sol.ok());
        // Scale by the weight: H may cross zero as d grows.
        CHECK(std::abs(sol.H - H) <= kTwoExactMethods * sol.V);
      }
  Scene strain = paper_scene(0.5);
  strain.material.plane_strain = true;
  CHECK(close(closed_form(strain).H, reference::castigliano_pointed_H(10.0, 0.5, 0.8, strain.material, 0.0),
              kTwoExactMethods));
}

TEST_CASE("closed form: every station - right half included - balances the free body from the left springing") {
  // The right half is not solved but mapped from the left (symmetry, with "beyond" and "before"
  // swapped): this checks that map against statics and the right springing's own conditions, which a
  // wrong sign of Ux, psi or Fy there would break. Free body [0, s]: the support pushes -F(0) and the
  // couple -M(0), the part beyond pushes F(s) with M(s), the weight w per length acts at the axis.
  const double d = 1e-4 * 10.0;
  const Scene scene = paper_scene(0.5, 0.08, 1e-4);
  Options o;
  o.method = Method::closed_form;
  o.stations = 41;
  const Solution sol = solve(scene, o);
  REQUIRE(sol.ok());
  const double w = scene.weight_per_length(), L = 10.0;
  const ArchState& a = sol.profile.front();
  // The integral of x over [0, s] of the whole arch by composite Simpson on each half (smooth there).
  auto first_moment = [&](double s_end) {
    const double S = scene.curve->length();
    auto simpson = [&](double lo, double hi) {
      const int n = 4000;
      const double h = (hi - lo) / n;
      double sum = 0;
      for (int k = 0; k <= n; ++k) {
        const double x = scene.curve->at_whole_arch(lo + k * h).x;
        sum += x * ((k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2));
      }
      return sum * h / 3;
    };
    return s_end <= S ? simpson(0, s_end) : simpson(0, S) + simpson(S, s_end);
  };
  for (const ArchState& st : sol.profile) {
    CAPTURE(st.s);
    CHECK(std::abs(st.Fx - a.Fx) <= kExact * w * L);
    CHECK(std::abs(st.Fy - (a.Fy + w * st.s)) <= kExact * w * L);
    const double moment = a.M + (a.x * a.Fy - a.y * a.Fx) - (st.x * st.Fy - st.y * st.Fx) + w * first_moment(st.s);
    CHECK(std::abs(st.M - moment) <= 1e-10 * w * L * L);
    // The resultant F acting at the thrust point has the moment M about the axis point.
    const double arm_x = st.thrust_x - st.x, arm_y = st.thrust_y - st.y;
    CHECK(std::abs(arm_x * st.Fy - arm_y * st.Fx - st.M) <= 1e-9 * std::abs(st.N) * 0.8);
    // e is the offset in per cent of the kern half-width t/6.
    CHECK(close(std::abs(st.e) / 100.0 * 0.8 / 6.0, std::hypot(arm_x, arm_y), 1e-9));
  }
  // Both springings: the left moves out by d (to -x), the right by d (to +x); neither settles nor turns.
  const ArchState& z = sol.profile.back();
  CHECK(close(a.Ux, -d, 1e-12));
  CHECK(close(z.Ux, d, 1e-12));
  const double U = std::abs(d);
  CHECK(std::abs(a.Uy) <= kExact * U);
  CHECK(std::abs(z.Uy) <= kExact * U);
  CHECK(std::abs(a.psi) <= kExact * U / L);
  CHECK(std::abs(z.psi) <= kExact * U / L);
  CHECK(close(z.x, L, kExact));
}

TEST_CASE("closed form on a non-circular curve is not applicable - with a reason") {
  struct Sine final : Curve {
    std::string family() const override { return "sine"; }
    double span() const override { return 10.0; }
    double length() const override { return 8.0; }
    CurvePoint at(double s) const override {
      // A made-up smooth curve: theta = pi/2 (1 - s/8)^2 is enough for this test's purpose.
      const double th = std::numbers::pi / 2 * (1 - s / 8) * (1 - s / 8);
      return {s < 8 ? 5.0 * s / 8 : 5.0, 0.0, th, -std::numbers::pi / 8 * (1 - s / 8)};
    }
  };
  Scene scene;
  scene.curve = std::make_shared<Sine>();
  scene.thickness = 0.5;
  Options o;
  o.method = Method::closed_form;
  const Solution sol = solve(scene, o);
  CHECK(sol.status == Status::not_applicable);
  CHECK(sol.message.find("piecewise-circular") != std::string::npos);
  CHECK(std::isnan(sol.H_over_V));
}

namespace {

// A8 of closed_form.cpp's arc_exponential, in any precision.
template <typename T>
Eigen::Matrix<T, 8, 8> arc_matrix(T k, T aN, T aV, T b, T h) {
  Eigen::Matrix<T, 8, 8> A = Eigen::Matrix<T, 8, 8>::Zero();
  A(0, 1) = k;  A(0, 3) = aN;                 // u'   = k v + a_N N
  A(1, 0) = -k; A(1, 2) = 1; A(1, 4) = aV;    // v'   = -k u + psi + a_V V
  A(2, 5) = 1;                                // psi' = M
  A(3, 4) = k;  A(3, 7) = b; A(3, 6) = -h;    // N'   = k V + b sn - h c
  A(4, 3) = -k; A(4, 6) = b; A(4, 7) = h;     // V'   = -k N + b c + h sn
  A(5, 4) = -1;                               // M'   = -V
  A(6, 7) = -k;                               // c'   = -k sn
  A(7, 6) = k;                                // sn'  = k c
  return A;
}

}  // namespace

TEST_CASE("closed form: the arc's analytic transfer is exp(A8 l), from a straight piece to a full turn") {
  // Against Eigen's Pade exponential in long double (64-bit mantissa: its own error near 1e-19), and in
  // double (what the closed form used before): within round-off of each column's largest entry (the
  // measure of a matrix function's accuracy: an entry may pass through zero, or be a difference of
  // physical terms that nearly cancel, such as a_V l - l^3 / 6, in either computation).
  constexpr double kRoundOff = 1e-14;
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // x = k l: exactly zero (a straight piece), tiny, small, moderate and up to a full turn, both signs,
  // across |x| = 3, where trig_phi changes from series to recurrence.
  const std::vector<double> turns = {0.0, 1e-14, 1e-9, 1e-5, 1e-3, 0.05, 0.5, 1.0, 2.0, 2.9, 3.0, 3.1, 4.0, 6.0,
                                     2 * std::numbers::pi};
  double worst_column = 0, worst_eigen = 0;
  for (int trial = 0; trial < 200; ++trial)
    for (double turn : turns) {
      const double l = std::pow(10.0, -3 + 3.5 * unit(rng));  // 1e-3 .. 3 spans
      const double x = (unit(rng) < 0.5 ? -1 : 1) * turn * (turn < 2 * std::numbers::pi ? 0.9 + 0.1 * unit(rng) : 1);
      const double k = x / l;
      const double aN = 1e-5 * std::pow(10.0, 3 * unit(rng)), aV = aN * (1 + 3 * unit(rng));
      const double b = 0.5 + unit(rng), h = unit(rng) - 0.5;
      CAPTURE(x);
      CAPTURE(l);
      const ArcMatrix E = arc_exponential(k, l, aN, aV, b, h);
      using Long = long double;
      const Eigen::Matrix<Long, 8, 8> ref = (arc_matrix<Long>(k, aN, aV, b, h) * static_cast<Long>(l)).exp();
      const ArcMatrix eigen = (arc_matrix<double>(k, aN, aV, b, h) * l).exp();
      for (int j = 0; j < 8; ++j) {
        const double column = static_cast<double>(ref.col(j).cwiseAbs().maxCoeff());
        for (int i = 0; i < 8; ++i) {
          const double r = static_cast<double>(ref(i, j));
          worst_column = std::max(worst_column, std::abs(E(i, j) - r) / column);
          worst_eigen = std::max(worst_eigen, std::abs(E(i, j) - eigen(i, j)) / column);
        }
      }
    }
  MESSAGE("largest difference of an entry in its column's largest entry: ", worst_column,
          " (against the double Pade: ", worst_eigen, ")");
  CHECK(worst_column <= kRoundOff);
  CHECK(worst_eigen <= kRoundOff);
}
