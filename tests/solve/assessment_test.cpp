// The assessment (ogive/solve/assessment.hpp): each criterion against its required value, the verdict
// and the governing criterion, held against published values and the analyses' own invariants.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "ogive/solve/assessment.hpp"
#include "ogive/solve/solve.hpp"
#include "support/scenes.hpp"

using namespace ogive;

namespace {

// Milankovitch's thinnest semicircle, true voussoir weight and radial joints: t_min / R = 0.1075, given to
// four digits (half a unit of the last: 5e-4 of the value).
constexpr double kMilankovitch = 0.1075;
constexpr double kFourDigits = 5e-4;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Scene semicircle(double t_over_L) { return paper_scene(0.0, t_over_L); }

void check_margins(const Assessment& a) {
  for (const CriterionResult& r : a.criteria) {
    CAPTURE(to_string(r.criterion));
    if (r.outcome == Outcome::pass) CHECK(r.margin >= 1);
    if (r.outcome == Outcome::fail) CHECK(r.margin < 1);
  }
}

}  // namespace

TEST_CASE("assessment: the semicircle passes a geometric factor of 2 just above 2 t_min and fails just below (Milankovitch)") {
  const double t_min_over_L = kMilankovitch / 2;  // t/L = t / (2R)
  AssessmentOptions o;  // the defaults: geometric factor 2, load factor 2
  for (const double side : {-1.0, 1.0}) {
    CAPTURE(side);
    const Scene scene = semicircle(2 * t_min_over_L * (1 + side * 4 * kFourDigits));
    const Assessment a = assess(scene, o);
    const CriterionResult& g = a[Criterion::geometric_safety_factor];
    CHECK(g.outcome == (side > 0 ? Outcome::pass : Outcome::fail));
    CHECK(a.verdict == (side > 0 ? Verdict::pass : Verdict::fail));
    CHECK(a.governing == Criterion::geometric_safety_factor);
    CHECK(a.margin == g.margin);
    CHECK(g.margin == g.value / 2);
    // Without a point or live load the load factor has nothing to multiply.
    CHECK(a[Criterion::load_factor].outcome == Outcome::not_applicable);
    CHECK(!a[Criterion::load_factor].reason.empty());
    CHECK(a[Criterion::horizontal_load_factor].outcome == Outcome::not_required);
    CHECK(a[Criterion::spread_capacity_ratio].outcome == Outcome::not_required);
    CHECK(a[Criterion::max_thrust_eccentricity].outcome == Outcome::not_required);
    check_margins(a);
  }
}

TEST_CASE("assessment: an arch thinner than t_min fails, governed by its geometric factor, every capacity at 0") {
  AssessmentOptions o;
  o.require.horizontal_load_factor = 0.1;
  o.require.spread_capacity_ratio = 1e-3;
  const Assessment a = assess(semicircle(0.9 * kMilankovitch / 2), o);
  REQUIRE(a.limit.status == LimitStatus::inadmissible);
  CHECK(a.verdict == Verdict::fail);
  CHECK(a.governing == Criterion::geometric_safety_factor);
  CHECK(a[Criterion::geometric_safety_factor].value < 1);
  CHECK(a[Criterion::horizontal_load_factor].outcome == Outcome::fail);
  CHECK(a[Criterion::horizontal_load_factor].value == 0);
  CHECK(a[Criterion::spread_capacity_ratio].outcome == Outcome::fail);
  CHECK(a[Criterion::spread_capacity_ratio].value == 0);
  CHECK(!a.warnings.empty());
  check_margins(a);
}

TEST_CASE("assessment: the governing criterion is the failed one of least margin, a passing arch names its least margin") {
  // The equilateral arch at t/L 0.15 with a point load at a quarter of the span (the README's: load
  // factor 2.28): ask for a load factor above and below it, and an acceleration.
  Scene scene = paper_scene(0.5, 0.15);
  scene.loads.points.push_back({2e5, 0.25});
  AssessmentOptions o;
  o.require.geometric_safety_factor = 1.5;
  o.require.horizontal_load_factor = 0.05;
  const Assessment base = assess(scene, o);
  REQUIRE(base.limit.status == LimitStatus::success);
  const double lambda = base[Criterion::load_factor].value;
  const double g = base[Criterion::geometric_safety_factor].value;
  const double a_c = base[Criterion::horizontal_load_factor].value;
  REQUIRE(lambda == base.limit.load_factor());
  REQUIRE(a_c == base.limit.horizontal_load_factor());
  for (const double need : {0.5 * lambda, 1.5 * lambda}) {
    CAPTURE(need);
    o.require.load_factor = need;
    const Assessment a = assess(scene, o);
    check_margins(a);
    const bool load_fails = lambda < need;
    CHECK(a[Criterion::load_factor].outcome == (load_fails ? Outcome::fail : Outcome::pass));
    const CriterionResult* least = nullptr;
    for (const CriterionResult& r : a.criteria)
      if ((r.outcome == Outcome::pass || r.outcome == Outcome::fail) &&
          (!least || (r.outcome == Outcome::fail) > (least->outcome == Outcome::fail) ||
           ((r.outcome == Outcome::fail) == (least->outcome == Outcome::fail) && r.margin < least->margin)))
        least = &r;
    REQUIRE(least != nullptr);
    CHECK(a.governing == least->criterion);
    CHECK(a.verdict == (load_fails || g < 1.5 || a_c < 0.05 ? Verdict::fail : Verdict::pass));
  }
}

TEST_CASE("assessment: the line of thrust against the section and the kern") {
  // The paper's equilateral arch at t/L 0.08: its elastic thrust line stays in the section (README:
  // largest |e| 206 % of the kern), so it passes `section` and fails `kern`.
  const Scene scene = paper_scene(0.5);
  AssessmentOptions o;
  o.require.geometric_safety_factor = kNaN;
  for (const ThrustRequirement req : {ThrustRequirement::section, ThrustRequirement::kern}) {
    o.require.thrust = req;
    const Assessment a = assess(scene, o);
    const CriterionResult& e = a[Criterion::max_thrust_eccentricity];
    REQUIRE(a.solution.ok());
    CHECK(e.value > 100);
    CHECK(e.value < 300);
    CHECK(e.required == (req == ThrustRequirement::kern ? 100 : 300));
    CHECK(e.outcome == (req == ThrustRequirement::kern ? Outcome::fail : Outcome::pass));
    CHECK(a.verdict == (req == ThrustRequirement::kern ? Verdict::fail : Verdict::pass));
    CHECK(a[Criterion::geometric_safety_factor].outcome == Outcome::not_required);
    check_margins(a);
  }
}

TEST_CASE("assessment: given its own solve (a page's, with a profile sampled since) it is the assessment that solves") {
  // The no-tension section (a shooting method's field, searched by the thrust line's summary) and the
  // elastic one, every criterion required: the same values to the bit, the scene solved once.
  AssessmentOptions o;
  o.require.horizontal_load_factor = 0.1;
  o.require.thrust = ThrustRequirement::section;
  o.elastic.stations = 101;
  for (const SectionKind section : {SectionKind::elastic, SectionKind::no_tension}) {
    CAPTURE(static_cast<int>(section));
    Scene scene = paper_scene(0.5);
    scene.section = section;
    const Assessment solved = assess(scene, o);
    Solution own = solve(scene, assessment_solve_options(o.elastic));
    REQUIRE(own.field);
    sample_profile(own, o.elastic.stations);
    const Assessment given = assess(scene, o, own);
    REQUIRE(given.solution.ok());
    CHECK(given.solution.profile.size() == 101);
    CHECK(given.solution.H == solved.solution.H);
    CHECK(given.verdict == solved.verdict);
    CHECK(given.warnings == solved.warnings);
    for (const Criterion c : {Criterion::geometric_safety_factor, Criterion::load_factor,
                              Criterion::horizontal_load_factor, Criterion::max_thrust_eccentricity}) {
      CAPTURE(to_string(c));
      CHECK(given[c].outcome == solved[c].outcome);
      // Bitwise: both are the numbers of the same solve and analyses (NaN where there is none).
      CHECK((given[c].value == solved[c].value || (std::isnan(given[c].value) && std::isnan(solved[c].value))));
    }
    CHECK(given[Criterion::max_thrust_eccentricity].outcome != Outcome::not_assessed);
  }
}

TEST_CASE("assessment: a required value must be > 0 and finite, or NaN") {
  for (const double bad : {0.0, -1.0, std::numeric_limits<double>::infinity()}) {
    AssessmentOptions o;
    o.require.load_factor = bad;
    std::string why;
    CHECK(!o.is_valid(&why));
    CHECK(why.rfind("load_factor:", 0) == 0);
    CHECK_THROWS_AS(assess(semicircle(0.1), o), std::invalid_argument);
  }
}
