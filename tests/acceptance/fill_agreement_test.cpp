// The same fill weighs the same in the elastic model (thrust) and in limit analysis (limit): both load
// the arch with rho_f g max(0, h_f - y_e(x)) per horizontal length over the span, y_e the true extrados.
// Checked against each other on the semicircle, a pointed and a segmental arch for fills below, at and
// above the crown, and against closed forms where the extrados is a circle.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "ogive/geometry/curve_families.hpp"
#include "ogive/limit/limit.hpp"
#include "ogive/solve/solve.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

// The elastic solve's reactions hold to the rtol asked of them; the fill's integral is one quadrature
// (the model's 16-point rule between its breakpoints, the ring's 8-point rule voussoir by voussoir) of a
// function smooth between the knots both place: V agrees to the solve's rtol and a little more.
constexpr double kRtol = 1e-10;
constexpr double kSameLoad = 1e-9;
// The self-weight of the true ring (voussoir weights) is rho g t S exactly where the two faces are
// offsets of one smooth axis; at a pointed crown the vertical crown joint adds the extrados' sliver
// beyond the crown and takes off the intrados' short of it, which do not cancel: 5e-5 of the total load
// of the equilateral arch at t = 0.08 L, the same with or without fill (the fill agrees to kSameLoad).
constexpr double kPointedCrownSliver = 1e-4;

constexpr double kRhoFill = 1800.0, kGravity = 9.81;

// int_{-L/2}^{L/2} rho_f g max(0, h - y_e(u)) du for the circular extrados y_e = y_c + sqrt(r^2 - u^2)
// (r > L/2, the centre y_c on or below the springing line): the fill's exact weight.
double circle_fill(double L, double r, double y_c, double h) {
  auto F = [&](double u) { return 0.5 * (u * std::sqrt(r * r - u * u) + r * r * std::asin(u / r)); };
  const double depth = h - y_c;  // the level above the centre
  if (depth <= std::sqrt(r * r - 0.25 * L * L)) return 0.0;
  if (depth >= r) return kRhoFill * kGravity * (depth * L - (F(L / 2) - F(-L / 2)));
  const double u_star = std::sqrt(r * r - depth * depth);  // y_e = h there; the fill lies beyond |u| > u_star
  return kRhoFill * kGravity * 2.0 * (depth * (L / 2 - u_star) - (F(L / 2) - F(u_star)));
}

struct Case {
  const char* name;
  Scene scene;
  bool pointed;
};

Scene with_curve(std::shared_ptr<const Curve> curve, double t_over_L) {
  Scene s;
  s.curve = std::move(curve);
  s.thickness = t_over_L * s.curve->span();
  return s;
}

// The elastic total vertical load, V_left + V_right, and the elastic self-weight rho g t S.
struct Elastic {
  double V_total = 0, self_weight = 0;
};
Elastic elastic(const Scene& scene, bool whole_arch) {
  Options o;
  o.rtol = kRtol;
  o.whole_arch = whole_arch;
  const Solution sol = solve(scene, o);
  REQUIRE(sol.status == Status::success);
  return {sol.reactions.V_left + sol.reactions.V_right, scene.weight_per_length() * scene.curve->whole_length()};
}

}  // namespace

TEST_CASE("fill: thrust's V_left + V_right equals limit's 2 V (the total dead load) on the semicircle, a pointed and a segmental arch, below, at and above the crown") {
  const double L = 10.0, t_over_L = 0.08, t = t_over_L * L;
  const Case cases[] = {{"semicircle", with_curve(make_pointed(L, 0.0), t_over_L), false},
                        {"pointed eps 0.5", with_curve(make_pointed(L, 0.5), t_over_L), true},
                        {"segmental rise 0.25", with_curve(make_segmental(L, 0.25), t_over_L), false}};
  for (const Case& c : cases) {
    const double crown_extrados = c.scene.curve->rise() + 0.5 * t;  // above a smooth crown; below a pointed one's
    for (double h : {0.5 * c.scene.curve->rise(), crown_extrados, crown_extrados + 0.2 * L}) {
      CAPTURE(c.name);
      CAPTURE(h);
      Scene scene = c.scene;
      scene.loads.fills.push_back({kRhoFill, h / L});
      // Limit's default weights (the true ring) and its axis weights (rho g t per axis length, as the
      // elastic model weighs the arch): the same fill in both.
      const LimitResult voussoir = analyse_limit(scene, {});
      LimitOptions axis_weights;
      axis_weights.weight = WeightModel::axis;
      const LimitResult axis = analyse_limit(scene, axis_weights);
      REQUIRE(voussoir.status == LimitStatus::success);
      REQUIRE(axis.status == LimitStatus::success);
      const Ring ring = make_ring(scene, {});
      for (bool whole : {false, true}) {
        CAPTURE(whole);
        const Elastic e = elastic(scene, whole);
        CHECK(close(e.V_total, 2.0 * axis.V, kSameLoad));
        CHECK(close(e.V_total - e.self_weight, ring.total_fill(), kSameLoad));
        CHECK(close(e.V_total, 2.0 * voussoir.V, c.pointed ? kPointedCrownSliver : kSameLoad));
      }
    }
  }
}

TEST_CASE("fill: thrust's total fill is the closed form of a circular extrados (semicircle, segmental arch)") {
  const double L = 10.0, t_over_L = 0.1, t = t_over_L * L;
  // The semicircle: the extrados a circle of radius L/2 + t/2 about mid-span on the springing line.
  // The segmental arch of rise f: radius R = (L^2/4 + f^2) / (2 f), the centre R - f below the springing.
  const double f = 0.3 * L, R_seg = (0.25 * L * L + f * f) / (2.0 * f);
  struct Circle {
    Scene scene;
    double r, y_c;
  };
  const Circle circles[] = {{with_curve(make_pointed(L, 0.0), t_over_L), 0.5 * L + 0.5 * t, 0.0},
                            {with_curve(make_segmental(L, 0.3), t_over_L), R_seg + 0.5 * t, f - R_seg}};
  for (const Circle& c : circles)
    for (double h_over_L : {0.1, 0.3, 0.45, 0.7}) {
      CAPTURE(c.r);
      CAPTURE(h_over_L);
      Scene scene = c.scene;
      scene.loads.fills.push_back({kRhoFill, h_over_L});
      const double exact = circle_fill(L, c.r, c.y_c, h_over_L * L);
      for (bool whole : {false, true}) {
        const Elastic e = elastic(scene, whole);
        if (exact == 0.0) CHECK(close(e.V_total, e.self_weight, kSameLoad));
        else CHECK(close(e.V_total - e.self_weight, exact, kSameLoad));
      }
    }
}
