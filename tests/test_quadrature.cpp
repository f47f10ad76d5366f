// The quadrature (force) method, its rules, and its own error estimate: against the closed form on every
// circular family, against verified CVODE multiple shooting on the smooth curves and the surveys, and
// against the catenary's funicular limit.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "numerics/chebyshev.hpp"
#include "cli.hpp"
#include "numerics/gauss_legendre.hpp"
#include "ogive/geometry/curve_families.hpp"
#include "methods/quadrature.hpp"
#include "ogive/solve/solve.hpp"
#include "scenes.hpp"
#include "tolerances.hpp"

using namespace ogive;

namespace {

// Published to 16 significant digits (Abramowitz & Stegun, table 25.4): agreement to their last digit.
constexpr double kPublishedDigits = 2e-16;
constexpr int kStations = 41;  // as ogive bench measures profiles

// Integral of x^k over [a, b].
double monomial_integral(int k, double a, double b) { return (std::pow(b, k + 1) - std::pow(a, k + 1)) / (k + 1); }

template <int N>
void check_gauss_exact() {
  const GaussLegendreRule<N>& g = gauss_legendre<N>();
  double sum = 0;
  for (int i = 0; i < N; ++i) {
    sum += g.weight[i];
    CHECK(g.weight[i] > 0);
    CHECK(g.node[i] == -g.node[N - 1 - i]);  // symmetric to the last bit
    if (i > 0) CHECK(g.node[i] > g.node[i - 1]);
  }
  CHECK(close(sum, 2.0, kExact));
  for (int k = 0; k <= 2 * N - 1; ++k) {
    const double exact = monomial_integral(k, -0.3, 1.0);
    const double rule = gauss_legendre_integral<N>([k](double x) { return std::pow(x, k); }, -0.3, 1.0);
    CAPTURE(N);
    CAPTURE(k);
    CHECK(std::abs(rule - exact) <= kExact * std::max(1.0, std::abs(exact)));
  }
}

Scene scene_of(std::shared_ptr<const Curve> curve, double t_over_L = 0.08, double d_over_L = 0.0) {
  Scene s;
  s.curve = std::move(curve);
  s.thickness = t_over_L * s.curve->span();
  s.set_support_displacement(d_over_L * s.curve->span());
  return s;
}

Solution solve_with(const Scene& scene, Method m, double rtol, int stations = kStations) {
  Options o;
  o.method = m;
  o.rtol = rtol;
  o.stations = stations;
  return solve(scene, o);
}

// The error of everything a solution prints: H/V and the profile.
double true_error(const Solution& sol, const Solution& ref, const Scene& scene) {
  return std::max(relative_difference(sol.H_over_V, ref.H_over_V),
                  profile_difference(sol.profile, ref.profile, scene.thickness));
}

}  // namespace

TEST_CASE("Gauss-Legendre: the published 8-point rule, and exact for polynomials of degree 2N - 1") {
  const GaussLegendreRule<8>& g = gauss_legendre<8>();
  const double nodes[] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  const double weights[] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  for (int i = 0; i < 4; ++i) {
    CHECK(std::abs(g.node[4 + i] - nodes[i]) <= kPublishedDigits * 4);
    CHECK(std::abs(g.weight[4 + i] - weights[i]) <= kPublishedDigits * 4);
  }
  CHECK(gauss_legendre<1>().node[0] == 0.0);
  CHECK(gauss_legendre<5>().node[2] == 0.0);
  check_gauss_exact<1>();
  check_gauss_exact<2>();
  check_gauss_exact<5>();
  check_gauss_exact<8>();
  check_gauss_exact<16>();
}

TEST_CASE("Chebyshev-Lobatto rules: nested nodes, cumulative integrals and interpolation exact for degree N") {
  CHECK_THROWS_AS(chebyshev_rule(12), std::invalid_argument);
  CHECK_THROWS_AS(chebyshev_rule(512), std::invalid_argument);
  for (int N = kMinChebyshevDegree; N <= kMaxChebyshevDegree; N *= 2) {
    const ChebyshevRule& r = chebyshev_rule(N);
    REQUIRE(r.node.size() == N + 1);
    CHECK(r.node[0] == -1.0);
    CHECK(r.node[N] == 1.0);
    if (N < kMaxChebyshevDegree) {
      const ChebyshevRule& fine = chebyshev_rule(2 * N);
      for (int i = 0; i <= N; ++i) CHECK(fine.node[2 * i] == r.node[i]);
    }
    // Monomials up to degree N: the cumulative integral from -1 at every node, and the interpolant
    // between the nodes.
    for (int k : {0, 1, 2, N / 2, N - 1, N}) {
      Eigen::VectorXd f(N + 1);
      for (int i = 0; i <= N; ++i) f[i] = std::pow(r.node[i], k);
      const Eigen::VectorXd F = r.integration * f;
      double worst = 0;
      for (int i = 0; i <= N; ++i) worst = std::max(worst, std::abs(F[i] - monomial_integral(k, -1.0, r.node[i])));
      CAPTURE(N);
      CAPTURE(k);
      CHECK(worst <= kExact);
      for (double x : {-0.999, -0.31, 0.0123, 0.77}) {
        const double p = chebyshev_interpolate(r, f.transpose(), x)[0];
        CHECK(std::abs(p - std::pow(x, k)) <= kExact);
      }
    }
  }
}

TEST_CASE("quadrature: the closed form's H/V and profile on every circular family, rtol 1e-4 .. 1e-12") {
  std::vector<Scene> scenes;
  for (double eps : {0.0, 0.25, 0.5, 1.0, 2.0}) scenes.push_back(scene_of(make_pointed(10.0, eps)));
  scenes.push_back(scene_of(make_pointed(10.0, 0.5), 0.2, 3e-4));  // thick, supports spread
  scenes.push_back(scene_of(make_segmental(10.0, 0.1)));
  scenes.push_back(scene_of(make_segmental(10.0, 0.3)));
  scenes.push_back(scene_of(make_three_centred(10.0, 0.25, 50.0)));
  scenes.push_back(scene_of(make_four_centred(10.0, 0.42)));
  scenes.push_back(scene_of(make_four_centred(10.0, 0.5, 40.0, 10.0)));
  for (const Scene& scene : scenes) {
    const Solution ref = solve_with(scene, Method::closed_form, 1e-12);
    REQUIRE(ref.ok());
    for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
      const Solution sol = solve_with(scene, Method::quadrature, rtol);
      CAPTURE(scene.curve->family());
      CAPTURE(rtol);
      REQUIRE(sol.ok());
      CHECK(sol.method == Method::quadrature);
      const double error = true_error(sol, ref, scene);
      CHECK(error <= 10 * rtol);
      // Its own estimate bounds its true error, up to the closed form's own round-off.
      CHECK(error <= sol.diagnostics.error_estimate +
                         ref.diagnostics.condition_estimate * std::numeric_limits<double>::epsilon());
      CHECK(sol.diagnostics.error_estimate <= 10 * rtol);
    }
  }
}

TEST_CASE("quadrature: verified CVODE multiple shooting's H/V and profile on smooth curves and surveys") {
  const std::vector<Scene> scenes = {
      scene_of(make_catenary(10.0, 0.5)),        scene_of(make_catenary(10.0, 0.2), 0.02),
      scene_of(make_parabolic(10.0, 0.5)),       scene_of(make_parabolic(10.0, 0.3)),
      scene_of(make_elliptical(10.0, 0.3)),      scene_of(make_elliptical(10.0, 0.7), 0.1, 2e-4),
      scene_of(read_points_curve(OGIVE_DATA_DIR "/curves/catenary-survey.csv")),
      scene_of(read_points_curve(OGIVE_DATA_DIR "/curves/parabola-40.csv")),
      scene_of(read_points_curve(OGIVE_DATA_DIR "/curves/semicircle-24.csv")),
  };
  for (const Scene& scene : scenes) {
    Options o;
    o.method = Method::multiple_shooting;
    o.rtol = 1e-12;
    o.segments = 32;
    o.stations = kStations;
    const Solution ref = solve(scene, o);
    REQUIRE(ref.field);  // success, or ill_conditioned on the survey (condition 1e4): solved
    // The reference's own error: its verification estimate, or its conditioning, whichever is larger.
    const double ref_error = std::max(ref.diagnostics.error_estimate,
                                      ref.diagnostics.condition_estimate * std::numeric_limits<double>::epsilon());
    REQUIRE(ref_error <= 1e-11);
    for (double rtol : {1e-6, 1e-8, 1e-10}) {
      const Solution sol = solve_with(scene, Method::quadrature, rtol);
      CAPTURE(scene.curve->family());
      CAPTURE(rtol);
      REQUIRE(sol.ok());
      const double error = true_error(sol, ref, scene);
      CHECK(error <= 10 * rtol);
      CHECK(error <= sol.diagnostics.error_estimate + ref_error);
    }
  }
}

TEST_CASE("quadrature: the catenary tends to its funicular H/V = 1/sinh(L/2a) as t/L falls") {
  const double L = 10.0, rise = 0.5;
  const double funicular = 1.0 / std::sinh(L / (2.0 * catenary_parameter(L, rise)));
  // (The eccentricity falling with t/L is test_curve_solves.cpp's, where auto now runs this method.)
  double previous_gap = 0, previous_t = 0;
  for (double t : {0.08, 0.02, 0.005, 0.001, 1e-4}) {
    const Solution sol = solve_with(scene_of(make_catenary(L, rise), t), Method::quadrature, 1e-12, 0);
    REQUIRE(sol.ok());
    const double gap = relative_difference(sol.H_over_V, funicular);
    CAPTURE(t);
    if (previous_t > 0) {
      // The remainder comes from axial shortening and shear, both of order (t/L)^2.
      const double order = std::log(previous_gap / gap) / std::log(previous_t / t);
      CHECK(order > 1.9);
      CHECK(order < 2.1);
    }
    previous_gap = gap;
    previous_t = t;
  }
  CHECK(previous_gap < 1e-7);  // t/L = 1e-4: 3.5e-8
}

TEST_CASE("quadrature: misuse and what does not apply") {
  // Ignoring the breakpoints would put a jump of curvature inside a panel: refused as not applicable.
  Options o;
  o.method = Method::quadrature;
  o.restart_at_breakpoints = false;
  const Solution sol = solve(scene_of(make_four_centred(10.0, 0.42)), o);
  CHECK(sol.status == Status::not_applicable);
  CHECK(!sol.message.empty());
  CHECK(!sol.field);
  // A curve without breakpoints has none to ignore.
  CHECK(solve(scene_of(make_catenary(10.0, 0.5)), o).ok());
  CHECK(std::string(to_string(Method::quadrature)) == "quadrature");
}

TEST_CASE("curves: a parameter of their own agrees with the arc length (parabola, ellipse, surveys)") {
  const std::vector<std::shared_ptr<const Curve>> curves = {
      make_parabolic(10.0, 0.5), make_parabolic(10.0, 1.5), make_elliptical(10.0, 0.3), make_elliptical(10.0, 1.2),
      read_points_curve(OGIVE_DATA_DIR "/curves/catenary-survey.csv")};
  for (const auto& curve : curves) {
    const std::vector<double> knots = curve->parameter_knots();
    REQUIRE(knots.size() == curve->breakpoints().size() + 2);
    CAPTURE(curve->family());
    // The knots are the springing, the breakpoints and the crown.
    CHECK(curve->at_parameter(knots.front()).s == 0.0);
    CHECK(close(curve->at_parameter(knots.back()).s, curve->length(), kExact));
    for (std::size_t k = 1; k + 1 < knots.size(); ++k)
      CHECK(close(curve->at_parameter(knots[k]).s, curve->breakpoints()[k - 1], kExact));
    for (std::size_t k = 0; k + 1 < knots.size(); ++k)
      for (double f : {0.1, 0.37, 0.5, 0.93}) {
        const double t = knots[k] + f * (knots[k + 1] - knots[k]);
        const ParameterPoint p = curve->at_parameter(t);
        // The same point as at(s): the unit tangent, and t back from s.
        CHECK(std::abs(p.cos * p.cos + p.sin * p.sin - 1) <= kExact);
        CHECK(std::abs(std::atan2(p.sin, p.cos) - curve->at(p.s).theta) <= kExact);
        CHECK(std::abs(curve->parameter_at(p.s) - t) <= kExact * (knots.back() - knots.front()));
        // ds/dt against a central difference of s(t) (step 1e-5 of the piece: error ~ 1e-10 of s'').
        const double h = 1e-5 * (knots[k + 1] - knots[k]);
        const double difference = (curve->at_parameter(t + h).s - curve->at_parameter(t - h).s) / (2 * h);
        CHECK(close(p.speed, difference, 1e-8));
      }
  }
  // Curves whose arc length is their parameter have none of their own.
  for (const auto& curve : {make_catenary(10.0, 0.5), make_pointed(10.0, 0.5)}) {
    CHECK(curve->parameter_knots().empty());
    CHECK_THROWS_AS(curve->at_parameter(0.0), std::logic_error);
    CHECK_THROWS_AS(curve->parameter_at(0.0), std::logic_error);
  }
}

TEST_CASE("curves: the largest curvature they know agrees with sampling the curve (Scene::validate's rule)") {
  const std::vector<std::shared_ptr<const Curve>> curves = {
      make_pointed(10.0, 0.5),     make_four_centred(10.0, 0.42), make_catenary(10.0, 0.5),
      make_parabolic(10.0, 1.5),   make_elliptical(10.0, 0.3),    make_elliptical(10.0, 1.2),
      read_points_curve(OGIVE_DATA_DIR "/curves/catenary-survey.csv")};
  for (const auto& curve : curves) {
    double sampled = 0;
    constexpr int kSamples = 4096;
    for (int i = 0; i <= kSamples; ++i)
      sampled = std::max(sampled, std::abs(curve->at(curve->length() * i / kSamples).kappa));
    CAPTURE(curve->family());
    // Never smaller than what any sample shows (to round-off), and no more than sampling between the
    // samples can miss (the curvature varies smoothly between breakpoints).
    CHECK(curve->max_curvature() >= sampled * (1 - kExact));
    CHECK(curve->max_curvature() <= sampled * (1 + 1e-3));
  }
}

TEST_CASE("quadrature: --method quadrature in the CLI, no integrator, its estimate, not_applicable said") {
  std::ostringstream out, err;
  REQUIRE(cli::run_cli({"thrust", "--curve", "catenary", "--rise-ratio", "0.5", "--method", "quadrature",
                        "--all-columns"},
                       out, err) == 0);
  const std::string csv = out.str();
  const std::string header = csv.substr(0, csv.find('\n'));
  const std::string row = csv.substr(csv.find('\n') + 1);
  CHECK(header.find(",method,integrator,rtol,status,") != std::string::npos);
  CHECK(row.find(",quadrature,,1e-08,success,") != std::string::npos);  // no integrator: empty
  CHECK(err.str().empty());
  // Told to ignore a survey's breakpoints: not applicable, exit 3, no number where there is none.
  std::ostringstream out2, err2;
  CHECK(cli::run_cli({"thrust", "--curve", "points", "--curve-file", OGIVE_DATA_DIR "/curves/parabola-40.csv",
                      "--method", "quadrature", "--ignore-breakpoints", "--all-columns"},
                     out2, err2) == 3);
  CHECK(out2.str().find(",quadrature,,1e-08,not_applicable,half,,") != std::string::npos);
  CHECK(out2.str().find("nan") == std::string::npos);
}
