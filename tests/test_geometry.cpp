// The section's faces and the thrust line's point: one formula (along_normal), checked against
// geometry that does not use it; the drawing's options refuse nonsense.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "ogive/geometry/curve_families.hpp"
#include "ogive/solve/solve.hpp"
#include "ogive/output/svg.hpp"
#include "scenes.hpp"
#include "tolerances.hpp"

using namespace ogive;

TEST_CASE("geometry: the faces are t/2 either side of the axis, across the tangent, extrados outside") {
  const double t = 0.8;
  for (const auto& curve : {make_pointed(10, 0.5), make_catenary(10, 0.4), make_four_centred(10, 0.42, 45, 15)}) {
    CAPTURE(curve->family());
    const double S = curve->length();
    for (int k = 0; k <= 20; ++k) {
      const CurvePoint p = curve->at_whole_arch(2 * S * k / 20);
      const SectionFaces f = section_faces(p, t);
      CHECK(std::abs(std::hypot(f.extrados.x - f.intrados.x, f.extrados.y - f.intrados.y) - t) <= kExact * t);
      CHECK(std::abs((f.extrados.x + f.intrados.x) / 2 - p.x) <= kExact * 10);
      CHECK(std::abs((f.extrados.y + f.intrados.y) / 2 - p.y) <= kExact * 10);
      // Perpendicular to the tangent (cos theta, sin theta).
      const double dot = (f.extrados.x - f.intrados.x) * std::cos(p.theta) + (f.extrados.y - f.intrados.y) * std::sin(p.theta);
      CHECK(std::abs(dot) <= kExact * t);
      // The extrados is the face farther from the arch's inside: from a point below the crown on the
      // mid-span line, every extrados point is farther than its intrados point.
      const double below_crown = 0.5 * curve->rise();
      CHECK(std::hypot(f.extrados.x - 5, f.extrados.y - below_crown) > std::hypot(f.intrados.x - 5, f.intrados.y - below_crown));
    }
  }
  // On the semicircle: the faces are the circles of radii R -+ t/2 about the centre (L/2, 0).
  const auto circle = make_pointed(10, 0);
  for (int k = 0; k <= 10; ++k) {
    const SectionFaces f = section_faces(circle->at(circle->length() * k / 10), t);
    CHECK(std::abs(std::hypot(f.intrados.x - 5, f.intrados.y) - (5 - t / 2)) <= kExact * 10);
    CHECK(std::abs(std::hypot(f.extrados.x - 5, f.extrados.y) - (5 + t / 2)) <= kExact * 10);
  }
}

TEST_CASE("geometry: the thrust point lies on the section at e t / 600 towards the intrados") {
  // e = 600 M / (N t) > 0 puts the resultant on the intrados side (README, docs/model.md); the point's
  // distance from the axis, signed towards the extrados, is -e t / 600.
  Options o;
  o.stations = 21;
  for (double eps : {0.0, 0.5, 1.0}) {
    const Scene scene = paper_scene(eps, 0.08, 1e-4);
    const Solution sol = solve(scene, o);
    REQUIRE(sol.ok());
    for (const ArchState& st : sol.profile) {
      const double n_x = -std::sin(st.theta), n_y = std::cos(st.theta);
      const double offset = (st.thrust_x - st.x) * n_x + (st.thrust_y - st.y) * n_y;
      const double along = (st.thrust_x - st.x) * n_y - (st.thrust_y - st.y) * n_x;
      CHECK(std::abs(offset + st.e * scene.thickness / 600) <= kExact * std::max(std::abs(offset), scene.thickness));
      CHECK(std::abs(along) <= kExact * std::max(std::abs(offset), scene.thickness));
    }
  }
}

TEST_CASE("svg: drawing options are checked - misuse throws naming the field") {
  const Scene scene = paper_scene(0.5);
  const Solution sol = solve(scene);
  DrawingOptions bad;
  bad.samples = 1;
  CHECK_THROWS_WITH_AS(arch_svg(scene, sol, bad), doctest::Contains("samples"), std::invalid_argument);
  bad = {};
  bad.width_px = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH_AS(arch_svg(scene, sol, bad), doctest::Contains("width_px"), std::invalid_argument);
  // The caption is text, never markup.
  DrawingOptions titled;
  titled.title = "a < b & \"c\"";
  const std::string svg = arch_svg(scene, sol, titled);
  CHECK(svg.find("a &lt; b &amp; &quot;c&quot;") != std::string::npos);
  // Without a solution there is no thrust line, and the title says why.
  Solution unsolved;
  unsolved.status = Status::integrator_failure;
  unsolved.message = "flag -4 at s = 1 m";
  const std::string bare = arch_svg(scene, unsolved);
  CHECK(bare.find("thrust-line") == std::string::npos);
  CHECK(bare.find("no solution: integrator_failure: flag -4 at s = 1 m") != std::string::npos);
}
