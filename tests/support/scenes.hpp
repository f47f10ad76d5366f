// Scenes and measures shared by the tests.
#pragma once

#include <algorithm>
#include <cmath>

#include "ogive/solve/solve.hpp"

namespace ogive {

// The paper's scene: L = 10 m, travertine, thickness and support displacement as ratios of the span.
inline Scene paper_scene(double eps, double t_over_L = 0.08, double d_over_L = 0.0) {
  Scene s;
  s.curve = make_pointed(10.0, eps);
  s.thickness = t_over_L * 10.0;
  s.set_support_displacement(d_over_L * 10.0);
  return s;
}

// The scene in closed form, its profile at `stations` stations (0: none).
inline Solution closed_form(const Scene& scene, int stations = 0) {
  Options o;
  o.method = Method::closed_form;
  o.stations = stations;
  return solve(scene, o);
}

// The largest |e| over a solution's profile, in per cent of the kern.
inline double max_abs_e(const Solution& sol) {
  double m = 0;
  for (const ArchState& st : sol.profile) m = std::max(m, std::abs(st.e));
  return m;
}

}  // namespace ogive
