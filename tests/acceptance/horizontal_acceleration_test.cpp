// The arch under a horizontal acceleration (pseudo-static earthquake): every mass (self-weight, fill) also
// carries a times its weight to +x. Checked against the statics of the three-hinged semicircle, the
// balance of reactions and loads, the mirror image of -a, linearity in a, the methods against one another,
// and a = 0 against the scene without the option.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "ogive/geometry/curve_families.hpp"
#include "ogive/solve/solve.hpp"
#include "support/cli_run.hpp"
#include "support/reference.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

namespace ogive {
namespace {

constexpr double kSpan = 10.0;
constexpr double kRtol = 1e-8;  // asked of the CVODE methods (a whole arch: single shooting confirms 1e-8)

Options with(Method m) {
  Options o;
  o.method = m;
  o.rtol = kRtol;
  return o;
}

Scene shaken(double eps, double a, SupportKind kind = SupportKind::clamped, bool hinge = false) {
  Scene s = paper_scene(eps, 0.08);
  s.horizontal_acceleration = a;
  s.left.kind = s.right.kind = kind;
  s.crown_hinge = hinge;
  return s;
}

double tolerance(Method m) { return m == Method::closed_form ? kTwoExactMethods : 10 * kRtol; }

// Both thrusts and the left vertical reaction of a verified solve agree with a reference's within 10 rtol.
void check_reactions_agree(const Scene& scene, Method m, const Solution& reference) {
  const Solution sol = solve(scene, with(m));
  CAPTURE(std::string(to_string(m)));
  REQUIRE(sol.ok());
  CHECK(close(sol.reactions.H_left, reference.reactions.H_left, 10 * kRtol));
  CHECK(close(sol.reactions.H_right, reference.reactions.H_right, 10 * kRtol));
  CHECK(close(sol.reactions.V_left, reference.reactions.V_left, 10 * kRtol));
}

}  // namespace

TEST_CASE("horizontal acceleration: the three-hinged semicircle's reactions equal statics") {
  // Semicircle of radius R (L = 2R, crown hinge at height R), self-weight w per axis length, horizontal
  // load a w per axis length. With phi the angle from the left springing, x = R (1 - cos phi),
  // y = R sin phi, ds = R dphi: the whole arch's int x ds = pi R^2, int y ds = 2 R^2, weight W = pi R w;
  // over the left half int (R - x) ds = R^2 and int (R - y) ds = R^2 (pi/2 - 1). Moments about the right
  // springing give V_right L = w pi R^2 + a w 2 R^2, about the crown hinge (left half)
  // R H_left = R V_left - w R^2 - a w R^2 (pi/2 - 1), and the horizontal balance H_right = H_left + a W:
  //   V_left = w R (pi/2 - a),  V_right = w R (pi/2 + a),
  //   H_left = w R (pi/2 - 1 - a pi/2),  H_right = w R (pi/2 - 1 + a pi/2).
  const double pi = std::numbers::pi, R = kSpan / 2;
  for (double a : {-0.3, 0.1, 0.25}) {
    const Scene s = shaken(0.0, a, SupportKind::pinned, true);
    const double w = s.weight_per_length();
    const double H_left = w * R * (pi / 2 - 1 - a * pi / 2), H_right = w * R * (pi / 2 - 1 + a * pi / 2);
    const double V_left = w * R * (pi / 2 - a), V_right = w * R * (pi / 2 + a);
    for (Method m : {Method::closed_form, Method::shooting, Method::multiple_shooting}) {
      const Solution sol = solve(s, with(m));
      CAPTURE(a);
      CAPTURE(std::string(to_string(m)));
      REQUIRE(sol.ok());
      CHECK_FALSE(sol.model->half());
      const double W = w * pi * R, tol = tolerance(m);
      CHECK(std::abs(sol.reactions.H_left - H_left) <= tol * W);
      CHECK(std::abs(sol.reactions.H_right - H_right) <= tol * W);
      CHECK(std::abs(sol.reactions.V_left - V_left) <= tol * W);
      CHECK(std::abs(sol.reactions.V_right - V_right) <= tol * W);
      CHECK(sol.reactions.M_left == 0.0);  // the pinned springing's condition, exactly
      CHECK(std::abs(sol.reactions.M_right) <= tol * W * kSpan);
      // The columns H and H_over_V are the left springing's.
      CHECK(sol.H == sol.reactions.H_left);
    }
  }
}

TEST_CASE("horizontal acceleration: the two-hinged semicircle's thrust equals an independent force method") {
  // Statically indeterminate: Castigliano's theorem with bending, stretching and shear compliance
  // (tests/support/reference.hpp), against the closed form and both shooting methods.
  for (double t_over_L : {0.02, 0.08, 0.2})
    for (double a : {-0.2, 0.1, 0.3}) {
      Scene s = shaken(0.0, a, SupportKind::pinned);
      s.thickness = t_over_L * kSpan;
      const double reference = reference::castigliano_two_hinged_semicircle_H(kSpan, s.thickness, s.material, a);
      const double W = s.weight_per_length() * s.curve->whole_length();
      for (Method m : {Method::closed_form, Method::shooting, Method::multiple_shooting}) {
        const Solution sol = solve(s, with(m));
        CAPTURE(t_over_L);
        CAPTURE(a);
        CAPTURE(std::string(to_string(m)));
        REQUIRE(sol.ok());
        CHECK(std::abs(sol.reactions.H_left - reference) <= tolerance(m) * W);
        CHECK(std::abs(sol.reactions.H_right - (reference + a * W)) <= tolerance(m) * W);
      }
    }
}

TEST_CASE("horizontal acceleration: the quadrature method over the whole arch") {
  // The symmetric clamped arch shaken: the quadrature integrates the whole arch (the crown, pointed or
  // not, a panel's end) and agrees with the closed form to both methods' round-off on circular arcs,
  // the pointed arch's kink included; on a catenary and a survey with verified shooting to its rtol.
  for (double eps : {0.0, 0.5, 1.0})
    for (double a : {-0.3, 0.1}) {
      const Scene s = shaken(eps, a);
      const Solution quadrature = solve(s, with(Method::quadrature));
      const Solution exact = solve(s, with(Method::closed_form));
      CAPTURE(eps);
      CAPTURE(a);
      REQUIRE(quadrature.ok());
      REQUIRE(exact.ok());
      CHECK_FALSE(quadrature.model->half());
      const Reactions &q = quadrature.reactions, &c = exact.reactions;
      const double W = s.weight_per_length() * s.curve->whole_length();
      for (const auto& [got, want] : {std::pair{q.H_left, c.H_left}, {q.H_right, c.H_right}, {q.V_left, c.V_left},
                                      {q.V_right, c.V_right}})
        CHECK(std::abs(got - want) <= kTwoExactMethods * W);
      CHECK(std::abs(q.M_left - c.M_left) <= kTwoExactMethods * W * kSpan);
      CHECK(std::abs(q.M_right - c.M_right) <= kTwoExactMethods * W * kSpan);
      CHECK(std::abs(q.H_right - q.H_left - a * W) <= kExact * W);
    }
  Scene catenary = shaken(0.0, 0.15);
  catenary.curve = make_catenary(kSpan, 0.5);
  Scene survey = shaken(0.0, 0.15);
  survey.curve = read_points_curve(std::string(OGIVE_DATA_DIR) + "/curves/catenary-survey.csv");
  for (const Scene& s : {catenary, survey}) {
    const Solution shooting = solve(s, with(Method::shooting));
    REQUIRE(shooting.ok());
    check_reactions_agree(s, Method::quadrature, shooting);
  }
  // A crown hinge divides the whole arch: the quadrature's columns do not carry its jump of rotation.
  CHECK(solve(shaken(0.0, 0.1, SupportKind::clamped, true), with(Method::quadrature)).status == Status::not_applicable);
}

TEST_CASE("horizontal acceleration: the reactions balance the self-weight and its horizontal load to 1e-12") {
  // Independent of the model's load sums: the weight of the whole arch is w times its length, and its
  // horizontal load a times that, so H_right - H_left = a W and V_left + V_right = W.
  for (double eps : {0.0, 0.5, 1.0})
    for (const std::pair<SupportKind, bool>& held : {std::pair{SupportKind::clamped, false}, std::pair{SupportKind::pinned, false},
                                                     std::pair{SupportKind::pinned, true}, std::pair{SupportKind::clamped, true}}) {
      const double a = 0.15;
      const bool hinge = held.second;
      const Scene s = shaken(eps, a, held.first, hinge);
      const double W = s.weight_per_length() * s.curve->whole_length();
      const Solution sol = solve(s, with(Method::closed_form));
      CAPTURE(eps);
      CAPTURE(hinge);
      REQUIRE(sol.ok());
      CHECK(std::abs(sol.reactions.H_right - sol.reactions.H_left - a * W) <= kExact * W);
      CHECK(std::abs(sol.reactions.V_left + sol.reactions.V_right - W) <= kExact * W);
      CHECK(sol.diagnostics.equilibrium_residual <= kExact);
      // The pushing side is the leeward one: the acceleration to +x loads the right springing more.
      CHECK(sol.reactions.H_right > sol.reactions.H_left);
      CHECK(sol.reactions.V_right > sol.reactions.V_left);
    }
}

TEST_CASE("horizontal acceleration: -a is the mirror image of a, and the reactions are linear in a") {
  for (double eps : {0.0, 0.5}) {
    const Solution plus = solve(shaken(eps, 0.2), with(Method::closed_form));
    const Solution minus = solve(shaken(eps, -0.2), with(Method::closed_form));
    const Solution half = solve(shaken(eps, 0.1), with(Method::closed_form));
    const Solution still = solve(shaken(eps, 0.0), with(Method::closed_form));
    REQUIRE(plus.ok());
    REQUIRE(minus.ok());
    const Reactions &p = plus.reactions, &m = minus.reactions;
    const double F = p.V_left + p.V_right;
    CAPTURE(eps);
    CHECK(std::abs(p.H_left - m.H_right) <= kTwoExactMethods * F);
    CHECK(std::abs(p.V_left - m.V_right) <= kTwoExactMethods * F);
    CHECK(std::abs(p.M_left + m.M_right) <= kTwoExactMethods * F * kSpan);
    // Linear: the change from 0 to 0.2 is twice the change from 0 to 0.1.
    CHECK(std::abs((p.H_left - still.H) - 2 * (half.reactions.H_left - still.H)) <= kTwoExactMethods * F);
    CHECK(std::abs((p.M_right - still.reactions.M_right) - 2 * (half.reactions.M_right - still.reactions.M_right)) <=
          kTwoExactMethods * F * kSpan);
  }
}

TEST_CASE("horizontal acceleration: the methods agree, with point loads, pins and fill") {
  // The closed form (self-weight and point loads on circular arcs) against shooting and multiple
  // shooting; with a fill (not constant on an arc) shooting against multiple shooting.
  Scene loaded = shaken(0.5, 0.2, SupportKind::pinned);
  loaded.loads.points.push_back({2e4, 0.3});
  const Solution exact = solve(loaded, with(Method::closed_form));
  REQUIRE(exact.ok());
  for (Method m : {Method::shooting, Method::multiple_shooting}) check_reactions_agree(loaded, m, exact);
  Scene filled = shaken(0.0, 0.1);
  filled.loads.fills.push_back({1800, 0.45});
  const Solution single = solve(filled, with(Method::shooting));
  const Solution multiple = solve(filled, with(Method::multiple_shooting));
  REQUIRE(single.ok());
  REQUIRE(multiple.ok());
  CHECK(close(single.reactions.H_left, multiple.reactions.H_left, 10 * kRtol));
  CHECK(close(single.reactions.H_right, multiple.reactions.H_right, 10 * kRtol));
  CHECK(single.diagnostics.equilibrium_residual <= kRtol);
  // The fill's mass is shaken too: every vertical load has mass here, so H_right - H_left is a times the
  // whole vertical load, V_left + V_right, more than a times the arch's own weight.
  const Reactions& r = single.reactions;
  const double arch_weight = filled.weight_per_length() * filled.curve->whole_length();
  CHECK(std::abs(r.H_right - r.H_left - 0.1 * (r.V_left + r.V_right)) <= 10 * kRtol * (r.V_left + r.V_right));
  CHECK(r.V_left + r.V_right > 1.2 * arch_weight);
  // A closed form cannot take the fill: it says so.
  CHECK(solve(filled, with(Method::closed_form)).status == Status::not_applicable);
}

TEST_CASE("horizontal acceleration: the no-tension section equals the elastic one in the kern, and its solvers agree") {
  // A thick pinned catenary lightly shaken stays in the kern: no section cracks, and the no-tension arch
  // is the linear one.
  Scene thick = shaken(0.0, 0.02, SupportKind::pinned);
  thick.curve = make_catenary(kSpan, 0.5);
  thick.thickness = 0.2 * kSpan;
  Options elastic = with(Method::multiple_shooting);
  elastic.rtol = kRtol / 10;
  elastic.stations = 201;
  const Solution linear = solve(thick, elastic);
  REQUIRE(linear.ok());
  REQUIRE(max_abs_e(linear) < 90);
  thick.section = SectionKind::no_tension;
  for (Method m : {Method::quadrature, Method::shooting}) check_reactions_agree(thick, m, linear);
  // Thinner and shaken harder it cracks: the explicit forces by quadrature and Newton shooting agree, and
  // the reactions balance the loads (the quadrature's forces are exact sums of the loads). Single
  // shooting's residual over this whole no-tension arch misses 1e-8 (tolerance_not_met, a = 0 too):
  // multiple shooting is the Newton reference.
  Scene thin = shaken(0.5, 0.1);
  thin.section = SectionKind::no_tension;
  Options fine = with(Method::quadrature);
  fine.stations = 201;
  const Solution quadrature = solve(thin, fine);
  const Solution shooting = solve(thin, with(Method::multiple_shooting));
  REQUIRE(quadrature.ok());
  REQUIRE(shooting.ok());
  bool cracked = false;
  for (const ArchState& st : quadrature.profile) cracked = cracked || st.cracked;
  CHECK(cracked);
  CHECK(close(quadrature.reactions.H_left, shooting.reactions.H_left, 10 * kRtol));
  CHECK(close(quadrature.reactions.H_right, shooting.reactions.H_right, 10 * kRtol));
  const double W = thin.weight_per_length() * thin.curve->whole_length();
  CHECK(std::abs(quadrature.reactions.H_right - quadrature.reactions.H_left - 0.1 * W) <= kExact * W);
  CHECK(std::abs(quadrature.reactions.V_left + quadrature.reactions.V_right - W) <= kExact * W);
}

TEST_CASE("cli: --horizontal-acceleration 0 prints what the scene without it prints, byte for byte") {
  using test::run_command;
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"thrust", "--eccentricity", "0,0.5,1"},
        std::vector<std::string>{"thrust", "--point-load", "2e4", "--point-load-at", "0.25", "--columns",
                                 "method,domain,H_left,V_left,M_left,H_right,V_right,M_right"},
        std::vector<std::string>{"profile", "--eccentricity", "0.5", "--stations", "7"},
        std::vector<std::string>{"thrust", "--section", "no-tension", "--thickness-ratio", "0.06",
                                 "--support-displacement-ratio", "0,1e-4"}}) {
    std::vector<std::string> zero = args;
    zero.insert(zero.end(), {"--horizontal-acceleration", "0"});
    const test::Run without = run_command(args), with_zero = run_command(zero);
    CHECK(without.status == 0);
    CHECK(with_zero.status == without.status);
    CHECK(with_zero.out == without.out);
  }
}

TEST_CASE("cli: a horizontal acceleration that is not finite, or beyond the range of the scales, is refused") {
  using test::check_refused;
  check_refused({"thrust", "--horizontal-acceleration", "nan"});
  check_refused({"thrust", "--horizontal-acceleration", "inf"});
  check_refused({"thrust", "--horizontal-acceleration", "1e300"});  // a times the weight overflows the scales
  check_refused({"limit", "--horizontal-acceleration", "nan"});
  // A sweep: the acceleration varies, H_left and H_right are printed and differ by a W.
  const test::Run r = test::run_command({"thrust", "--horizontal-acceleration", "0,0.1", "--columns",
                                         "horizontal_acceleration,status,H,H_left,H_right,H_over_V"});
  CHECK(r.status == 0);
  CHECK(test::column(r.out, "horizontal_acceleration", 2) == "0.1");
  CHECK(test::column(r.out, "H", 2) == test::column(r.out, "H_left", 2));
  CHECK(std::stod(test::column(r.out, "H_right", 2)) > std::stod(test::column(r.out, "H_left", 2)));
  CHECK(test::column(r.out, "H_left", 1) == test::column(r.out, "H_right", 1));
}

}  // namespace ogive
