// The thrust line's summary (include/ogive/core/thrust_line.hpp) against a dense resampling of the same
// field: 10 001 stations over the whole arch, the best refined by golden-section search between its
// neighbours to 1e-12 of the arch's length. Over every kind of piece the summary meets: circular arcs,
// a pointed crown, point loads (upward ones too), pins and a hinge, a fill, a horizontal acceleration,
// the no-tension section, CVODE's and the quadrature's fields, and arches in tension in part (no bound).
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ogive/core/thrust_line.hpp"
#include "ogive/geometry/curve_families.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

// How far the summary's largest |e| may lie from the dense reference's, relative to the larger of it and
// the kern (100 %): both are values of the same field at its maximum, found to 1e-9 (the summary) and
// 1e-12 (the reference) of the arch's length, where a smooth maximum is flat and a piece's end is
// evaluated (the summary) or approached (the reference) on its own side. Measured: at most 3.7e-12 (the
// fill's field, interpolated), 7.3e-13 at an upward point load's one-sided limit (|e| 3 217 %, the
// summary's the larger), below 1e-14 on every other scene here.
constexpr double kSummaryAgreement = 1e-10;
// How far apart the two may place the maximum, relative to the arch's length (measured: at most 6.0e-8,
// the fill's).
constexpr double kPlaceAgreement = 1e-6;
// The same for the largest compressive stress, relative to it (measured: at most 7.5e-13, the summary's
// the smaller, at an upward point load's one-sided limit; round-off at the interior maxima of the pinned
// arches and the segmental one, 0 where the maximum is at a springing).
constexpr double kStressAgreement = 1e-10;

struct Reference {
  double max_abs_e = 0, at = 0;
  bool compressed = true;
};

// The largest value(state) over a dense resampling, refined between the best station's neighbours.
template <class Value>
Reference dense_reference(const Solution& sol, Value value) {
  constexpr int kStations = 10001;
  const std::vector<ArchState> profile = sample_stations(sol, kStations, 0, kStations);
  Reference r;
  std::size_t best = 0;
  for (std::size_t k = 0; k < profile.size(); ++k) {
    if (!(profile[k].N < 0)) r.compressed = false;
    if (value(profile[k]) > value(profile[best])) best = k;
  }
  r.max_abs_e = value(profile[best]);
  r.at = profile[best].s;
  auto abs_e = [&](double s) {
    const ArchState st = sol.at(s);
    if (!(st.N < 0)) r.compressed = false;
    if (value(st) > r.max_abs_e) {
      r.max_abs_e = value(st);
      r.at = st.s;
    }
    return value(st);
  };
  double lo = profile[best == 0 ? 0 : best - 1].s, hi = profile[std::min(best + 1, profile.size() - 1)].s;
  const double total = profile.back().s, golden = (std::sqrt(5.0) - 1) / 2;
  double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
  double fa = abs_e(a), fb = abs_e(b);
  while (hi - lo > 1e-12 * total) {
    if (fa > fb) {
      hi = b;
      b = a;
      fb = fa;
      a = hi - golden * (hi - lo);
      fa = abs_e(a);
    } else {
      lo = a;
      a = b;
      fa = fb;
      b = lo + golden * (hi - lo);
      fb = abs_e(b);
    }
  }
  return r;
}

struct Case {
  std::string name;
  Scene scene;
  Method method = Method::closed_form;
};

Scene with_point_load(Scene s, double P, double at) {
  s.loads.points.push_back({P, at});
  return s;
}

Scene pinned(Scene s, bool hinge) {
  s.left.kind = s.right.kind = SupportKind::pinned;
  s.crown_hinge = hinge;
  return s;
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (double eps : {0.0, 0.25, 0.5, 1.0})
    for (double t : {0.05, 0.08, 0.2}) out.push_back({"pointed", paper_scene(eps, t)});
  out.push_back({"point load", with_point_load(paper_scene(0.25), 2e4, 0.3)});
  out.push_back({"point load at the crown", with_point_load(paper_scene(0.5, 0.1), 5e4, 0.5)});
  out.push_back({"two point loads", with_point_load(with_point_load(paper_scene(0.0, 0.15), 1e4, 0.2), 3e4, 0.7)});
  out.push_back({"upward point load", with_point_load(paper_scene(0.25), -8e4, 0.3)});
  // The peak at the load's one-sided limit, away from 129 stations' best (which the old search refined).
  out.push_back({"upward point load, peak at the load", with_point_load(paper_scene(0.7), -5e4, 0.2)});
  out.push_back({"upward point load, tension before it", with_point_load(paper_scene(0.25), -1.1e5, 0.3)});
  out.push_back({"pinned", pinned(paper_scene(0.5, 0.1), false)});
  out.push_back({"three hinges", pinned(paper_scene(0.5, 0.1), true)});
  out.push_back({"three hinges, point load", with_point_load(pinned(paper_scene(0.0, 0.12), true), 1e4, 0.25)});
  Scene quake = paper_scene(0.25, 0.15);
  quake.horizontal_acceleration = 0.1;
  out.push_back({"horizontal acceleration", quake});
  Scene segmental = paper_scene(0.0, 0.06);
  segmental.curve = make_segmental(10.0, 0.25);
  out.push_back({"segmental", segmental});
  Scene four = paper_scene(0.0, 0.1);
  four.curve = make_four_centred(10.0, 0.4);
  out.push_back({"four-centred", four});
  out.push_back({"shooting", paper_scene(0.3, 0.1), Method::shooting});
  out.push_back({"multiple shooting, point load", with_point_load(paper_scene(0.0, 0.1), 2e4, 0.4),
                 Method::multiple_shooting});
  Scene fill = paper_scene(0.0, 0.1);
  fill.loads.fills.push_back({2000.0, 0.6});
  out.push_back({"fill", fill, Method::automatic});
  Scene ellipse = paper_scene(0.0, 0.1);
  ellipse.curve = make_elliptical(10.0, 0.35);
  out.push_back({"elliptical", ellipse, Method::quadrature});
  Scene cracked = paper_scene(0.0, 0.1);
  cracked.section = SectionKind::no_tension;
  out.push_back({"no-tension", cracked, Method::quadrature});
  out.push_back({"crown in tension", paper_scene(0.0, 0.08, 0.0003)});
  return out;
}

}  // namespace

TEST_CASE("thrust line: the summary's largest |e| - its place - kern and section - against a dense resampling") {
  int compressed = 0;
  for (const Case& c : cases()) {
    CAPTURE(c.name);
    Options o;
    o.method = c.method;
    const Solution sol = solve(c.scene, o);
    REQUIRE(sol.field);
    const ThrustLineSummary line = summarize_thrust_line(sol);
    const Reference ref = dense_reference(sol, [](const ArchState& st) { return std::abs(st.e); });
    REQUIRE(line.ok);
    if (!ref.compressed) {
      CHECK(std::isnan(line.max_abs_e));
      CHECK_FALSE(line.in_kern);
      CHECK_FALSE(line.in_section);
      continue;
    }
    ++compressed;
    REQUIRE(std::isfinite(line.max_abs_e));
    const double tolerance = kSummaryAgreement * std::max(ref.max_abs_e, 100.0);
    CHECK(std::abs(line.max_abs_e - ref.max_abs_e) <= tolerance);
    const double length = sol.model->half() ? 2 * sol.model->curve().length() : sol.model->curve().length();
    const double mirrored = length - ref.at;  // a symmetric whole arch has its maximum twice
    CHECK(std::min(std::abs(line.max_abs_e_at - ref.at), std::abs(line.max_abs_e_at - mirrored)) <=
          kPlaceAgreement * length);
    if (std::abs(ref.max_abs_e - 100) > tolerance) CHECK(line.in_kern == (ref.max_abs_e <= 100));
    if (std::abs(ref.max_abs_e - 300) > tolerance) CHECK(line.in_section == (ref.max_abs_e <= 300));
  }
  CHECK(compressed >= 20);
}

TEST_CASE("thrust line: the largest compressive stress and its place against a dense resampling") {
  int compressed = 0;
  for (const Case& c : cases()) {
    CAPTURE(c.name);
    Options o;
    o.method = c.method;
    const Solution sol = solve(c.scene, o);
    REQUIRE(sol.field);
    const StressSummary stress = summarize_compressive_stress(sol);
    const Reference ref = dense_reference(
        sol, [](const ArchState& st) { return std::isnan(st.compressive_stress) ? -1.0 : st.compressive_stress; });
    REQUIRE(stress.ok);
    if (!ref.compressed) {
      CHECK(std::isnan(stress.max_compressive_stress));
      continue;
    }
    ++compressed;
    REQUIRE(std::isfinite(stress.max_compressive_stress));
    // Both are values of the same field at its maximum (the summary's never above the truth).
    CHECK(std::abs(stress.max_compressive_stress - ref.max_abs_e) <= kStressAgreement * ref.max_abs_e);
    const double length = sol.model->half() ? 2 * sol.model->curve().length() : sol.model->curve().length();
    const double mirrored = length - ref.at;
    CHECK(std::min(std::abs(stress.max_compressive_stress_at - ref.at),
                   std::abs(stress.max_compressive_stress_at - mirrored)) <= kPlaceAgreement * length);
  }
  CHECK(compressed >= 20);
}

TEST_CASE("thrust line: the largest compressive stress by hand from N and M at its place") {
  Scene live = pinned(paper_scene(0.0, 0.08), false);  // an interior maximum
  live.loads.live.push_back({5000.0, 0.0, 0.5});
  Scene cracked = paper_scene(0.0, 0.06);  // the no-tension section cracked at the springings
  cracked.section = SectionKind::no_tension;
  for (const Scene& scene : {paper_scene(0.0, 0.08), live, cracked}) {
    const Solution sol = solve(scene, Options{});
    CAPTURE(sol.message);
    REQUIRE(sol.ok());
    const StressSummary stress = summarize_compressive_stress(sol);
    const ArchState st = sol.at(stress.max_compressive_stress_at);
    const double t = scene.thickness, P = -st.N, m = std::abs(st.M);
    REQUIRE(P > 0);
    const bool beyond_kern = scene.section == SectionKind::no_tension && m > P * t / 6;
    if (scene.section == SectionKind::no_tension) CHECK(beyond_kern);  // the cracked formula is exercised
    const double by_hand = beyond_kern ? 2 * P / (3 * (t / 2 - m / P)) : P / t + 6 * m / (t * t);
    CHECK(close(stress.max_compressive_stress, by_hand, kExact));
  }
}

TEST_CASE("thrust line: the closed form's estimate from the field's scan - the same status as from 129 stations") {
  // With an unprinted profile the closed form bounds its round-off from field_scan's states instead of
  // kVerificationStations stations: the field's largest force and couple, seen at fewer points.
  for (double eps : {0.0, 0.5, 1.0})
    for (double t : {0.02, 0.08, 0.2}) {
      CAPTURE(eps);
      CAPTURE(t);
      Options o;
      o.method = Method::closed_form;
      o.stations = 65;
      const Solution dense = solve(paper_scene(eps, t), o);
      o.unprinted_profile = true;
      const Solution scanned = solve(paper_scene(eps, t), o);
      CHECK(scanned.status == dense.status);
      CHECK(scanned.profile.empty());
      // The scan sees the largest couple at fewer points: a bound at least as large, and not far off.
      CHECK(scanned.diagnostics.error_estimate >= dense.diagnostics.error_estimate * (1 - 1e-12));
      CHECK(scanned.diagnostics.error_estimate <= 1.5 * dense.diagnostics.error_estimate);
    }
}
