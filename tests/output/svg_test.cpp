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
