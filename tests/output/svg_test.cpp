// The SVG writer (include/ogive/output/svg.hpp): its options are checked, its caption is text, and an
// unsolved scene is drawn without a thrust line, saying why.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <vector>
#include <stdexcept>
#include <string>

#include "ogive/output/svg.hpp"
#include "ogive/solve/solve.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"
#include "ogive/limit/limit.hpp"

using namespace ogive;

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

TEST_CASE("svg: a horizontal acceleration is drawn as an arrow above the arch, pointing its way") {
  Scene scene = paper_scene(0.5);
  CHECK(arch_svg(scene, solve(scene)).find("horizontal-acceleration") == std::string::npos);
  for (double a : {0.15, -0.15}) {
    scene.horizontal_acceleration = a;
    const std::string svg = arch_svg(scene, solve(scene));
    const std::size_t group = svg.find("<g id=\"horizontal-acceleration\"");
    REQUIRE(group != std::string::npos);
    CHECK(svg.find(a > 0 ? "a = 0.15 g" : "a = -0.15 g", group) != std::string::npos);
    // The arrow's head (x2) lies on the side the acceleration points to.
    const std::size_t x1 = svg.find("x1=\"", group), x2 = svg.find("x2=\"", group);
    REQUIRE(x1 != std::string::npos);
    REQUIRE(x2 != std::string::npos);
    const double from = std::stod(svg.substr(x1 + 4)), to = std::stod(svg.substr(x2 + 4));
    CHECK((to - from) * a > 0);
  }
}

TEST_CASE("svg: point-load arrows are to one scale - twice the load, twice the arrow - landing on the extrados") {
  Scene scene = paper_scene(0.5);
  scene.loads.points = {{1e4, 0.25}, {2e4, 0.75}};
  const std::string svg = arch_svg(scene, solve(scene));
  const std::size_t group = svg.find("<g id=\"loads\"");
  REQUIRE(group != std::string::npos);
  std::vector<double> lengths;
  for (std::size_t at = svg.find("<line", group); at != std::string::npos && lengths.size() < 2;
       at = svg.find("<line", at + 1)) {
    auto attribute = [&](const char* name) {
      const std::size_t v = svg.find(std::string(" ") + name + "=\"", at);
      return std::stod(svg.substr(v + std::strlen(name) + 3));
    };
    CHECK(attribute("x1") == attribute("x2"));  // vertical
    lengths.push_back(std::abs(attribute("y2") - attribute("y1")));
  }
  REQUIRE(lengths.size() == 2);
  CHECK(lengths[1] / lengths[0] == doctest::Approx(2.0).epsilon(kExact));
  CHECK(svg.find("P = 10 kN/m") != std::string::npos);
  CHECK(svg.find("P = 20 kN/m") != std::string::npos);
}

TEST_CASE("svg: the collapse mechanism is the limit analysis' collapse state - four hinges in order along the arch") {
  Scene scene = paper_scene(0.5, 0.1);
  scene.loads.points = {{5e4, 0.25}};
  const LimitResult r = analyse_limit(scene, LimitOptions{});
  const std::optional<CollapseMechanism> m = collapse_mechanism(scene, r);
  REQUIRE(m.has_value());
  REQUIRE(m->hinges.size() == 4);
  CHECK(std::is_sorted(m->hinge_s.begin(), m->hinge_s.end()));
  for (std::size_t k = 0; k < 4; ++k) CHECK(m->hinges[k].x == r.collapse_state.hinges[k].point.x());
  CHECK(m->load_x == 0.25 * scene.span());
  DrawingOptions drawing;
  drawing.mechanisms = {*m};
  const std::string svg = arch_svg(scene, solve(scene), drawing);
  CHECK(svg.find("<g id=\"mechanism\"") != std::string::npos);
  // Self-weight alone: no collapse state, no mechanism.
  const Scene bare = paper_scene(0.5, 0.1);
  CHECK_FALSE(collapse_mechanism(bare, analyse_limit(bare, LimitOptions{})).has_value());
}

TEST_CASE("svg: walls are drawn under the springings, the limit analysis' lines running down them to the base") {
  Scene scene = paper_scene(0.0, 0.1);
  const double L = scene.span();
  scene.left_wall = scene.right_wall = Wall{L, 0.2 * L, scene.material.density, 0.0, 0.5};
  const LimitResult r = analyse_limit(scene, LimitOptions{});
  DrawingOptions drawing;
  add_limit_analysis(drawing, scene, r);
  REQUIRE(!drawing.extra_lines.empty());
  // The minimum thrust line ends at the walls' bases, y = -h_w, with a point per bed.
  const ExtraThrustLine& min = drawing.extra_lines.front();
  CHECK(min.points.size() == r.ring.joints.size());
  CHECK(close(min.points.front().y, -L, kExact));
  CHECK(close(min.points.back().y, -L, kExact));
  const std::string svg = arch_svg(scene, solve(scene), drawing);
  for (const char* id : {"wall-left", "wall-right", "ground-left", "ground-right"})
    CHECK(svg.find(std::string("id=\"") + id + "\"") != std::string::npos);
  // The springings stand on the walls: no support of their own.
  CHECK(svg.find("id=\"support-left\"") == std::string::npos);
  // A mechanism that turns a wall is not drawn displaced.
  scene.left_wall->thickness = scene.right_wall->thickness = 0.19 * L;
  scene.loads.points = {{2e4, 0.3}};
  const LimitResult c = analyse_limit(scene, LimitOptions{});
  REQUIRE(c.collapse_state.found());
  CHECK_FALSE(collapse_mechanism(scene, c).has_value());
}
