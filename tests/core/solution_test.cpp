// Sampling a solution's field (include/ogive/core/solution.hpp: sample_profile, sample_stations): the
// closed form's stations are exact wherever they fall, however many there are.
#include <doctest/doctest.h>

#include <vector>

#include "ogive/solve/solve.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

TEST_CASE("trust: the closed form's profile is exact at any number of stations - crown moment with 3 and 999 999") {
  for (double eps : {0.0, 0.5}) {
    Options o;
    o.method = Method::closed_form;
    Solution sol = solve(paper_scene(eps), o);
    REQUIRE(sol.ok());
    sample_profile(sol, 3);
    const double few = sol.profile[1].M;
    const std::vector<ArchState> crown = sample_stations(sol, 999999, 499999, 1);
    REQUIRE(crown.size() == 1);
    CAPTURE(eps);
    CHECK(close(crown[0].M, few, 1e-14));
    CHECK(close(crown[0].s, sol.profile[1].s, 1e-14));
  }
}
