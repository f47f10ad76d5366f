#include <doctest/doctest.h>

#include <cstdio>

#include "ogive/closed_form.hpp"
#include "ogive/solve.hpp"
#include "tolerances.hpp"

using namespace ogive;

namespace {
Scene paper_scene(double eps, double t_over_L = 0.08, double d_over_L = 0.0) {
  Scene s;
  s.curve = make_pointed(10.0, eps);
  s.thickness = t_over_L * 10.0;
  s.support_displacement = d_over_L * 10.0;
  return s;
}
}  // namespace

TEST_CASE("smoke") {
  for (double eps : {0.0, 0.5, 1.0}) {
    Options o;
    o.method = Method::closed_form;
    const Solution sol = solve(paper_scene(eps), o);
    std::printf("eps %g H/V %.12g status %s cond %g bres %g eres %g\n", eps, sol.H_over_V, to_string(sol.status),
                sol.diagnostics.condition_estimate, sol.diagnostics.boundary_residual,
                sol.diagnostics.equilibrium_residual);
    for (Method m : {Method::shooting, Method::multiple_shooting}) {
      o.method = m;
      const Solution s2 = solve(paper_scene(eps), o);
      std::printf("   %s H/V %.12g status %s %s steps %ld cond %g\n", to_string(m), s2.H_over_V, to_string(s2.status),
                  s2.message.c_str(), (long)s2.diagnostics.steps, s2.diagnostics.condition_estimate);
    }
  }
}
