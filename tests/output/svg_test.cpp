// The SVG writer (include/ogive/output/svg.hpp): its options are checked, its caption is text, and an
// unsolved scene is drawn without a thrust line, saying why.
#include <doctest/doctest.h>

#include <limits>
#include <stdexcept>
#include <string>

#include "ogive/output/svg.hpp"
#include "ogive/solve/solve.hpp"
#include "support/scenes.hpp"

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
