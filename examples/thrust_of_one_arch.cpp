// An elastic scene: the thrust of the equilateral pointed arch (eccentricity 0.5, span 10 m, t = 0.08 L,
// the paper's travertine), solved by the library's default method (the closed form here).
// Prints the method, the status, H, V and H/V; exits 0 when the solve succeeded, 1 otherwise.
#include <cstdio>

#include "ogive/ogive.hpp"

int main() {
  ogive::Scene scene;
  scene.curve = ogive::make_pointed(10.0, 0.5);
  scene.thickness = 0.08 * scene.span();
  scene.validate();  // throws std::invalid_argument naming the field for a bad scene

  const ogive::Solution sol = ogive::solve(scene);
  std::printf("ogive %s: method %s, status %s\nH = %.6g N/m, V = %.6g N/m, H/V = %.10g\n", ogive::kVersion,
              ogive::to_string(sol.method), ogive::to_string(sol.status), sol.H, sol.V, sol.H_over_V);
  return sol.ok() ? 0 : 1;
}
