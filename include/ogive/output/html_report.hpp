// One self-contained HTML page about one scene (`ogive report`): no script, no network, no file beside
// it; the drawing and the chart are inline SVG, the style inline CSS. The page is the scene's
// assessment (ogive/solve/assessment.hpp): its verdict comes first. What it holds, each in a <section>
// with an id that tests and scripts can find:
//   #verdict    PASS, FAIL or NOT ASSESSED, the governing criterion with its value, required value and
//               margin, every criterion's row, and the warnings in words (#warnings: the line of thrust
//               leaving the section, t below t_min, a load factor below 1, and the caller's, e.g. the
//               defaults it used); on walls, with a spreading capacity passed or failed, each wall's
//               lean at that collapse (#walls-lean: rotation, rad, and its top's displacement, mm)
//   #drawing    the scene drawn (svg.hpp) with its elastic (or cracked-section) line of thrust, the limit
//               analysis' minimum and maximum thrust lines and, with a live or point load, the collapse
//               mechanism
//   #reactions  H, V and M of both springings, kN/m and kN m/m, with the solution's method and status
//   #thrusts    the horizontal thrust of the scene's section (elastic or no-tension), the minimum and the
//               maximum of the limit analysis, kN/m, each with H/V
//   #safety     t, t_min (the limit analysis' thinnest arch of the same shape and loads) and the
//               geometric safety factor t / t_min
//   #collapse   the collapse load factor (the multiplier of the point and live loads) and its hinges,
//               numbered as on the drawing, each with its position (x, y in m) and face; "no live load"
//               without one
//   #spreading  the no-tension section's H/V against both springings' outward spread d/L (0 and a log
//               scale 1e-6 .. 1e-2), as an SVG chart, with the limit analysis' minimum H/V as a line; a
//               spread at which the solve fails is left out and listed below the chart
//   #geometry   what follows from the inputs: the axis' span and rise, the intrados' (the clear span and
//               rise) and the extrados' rise at the crown, the thickness, the fill's level and depth
//               over the extrados' crown
//   #inputs     the inputs as given (option and value, in the order the caller lists them; ogive report
//               lists them in the order of its --help)
//   #assumptions what the analyses take and what they leave out; ogive's version and the date given
// Every number is printed to 4 significant digits, with its full value (shortest round trip, SI units)
// in the element's data-value attribute.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "ogive/core/solution.hpp"
#include "ogive/model/scene.hpp"
#include "ogive/solve/assessment.hpp"

namespace ogive {

struct ReportOptions {
  std::string title;  // the page's heading, plain text (escaped here)
  std::vector<std::pair<std::string, std::string>> inputs;  // the inputs as given: option, value
  Options solver;     // for the scene's solution and each point of the spreading chart
  int spread_points = 9;  // points of the chart (d = 0 and log-spaced 1e-6 L .. 1e-2 L), in [2, 41]
  AssessmentCriteria require;         // the verdict's criteria
  LimitOptions limit;                 // the limit analysis' options (its horizontal_load_factor is the assessment's)
  std::vector<std::string> warnings;  // the caller's, in words, shown after the assessment's
  std::string date;                   // shown beside the version; empty: none

  // false with the reason in *why (naming the field) when an option is unusable.
  bool is_valid(std::string* why) const;
};

// The page (UTF-8 HTML). The scene must be valid (Scene::validate). It is solved once (report_solution),
// analysed by the limit analysis (options.limit) and, for the chart, solved with the no-tension
// section at each spread (a no-tension scene whose springings do not spread is the chart's point at
// d = 0 itself). Throws std::invalid_argument naming the field for invalid options.
std::string html_report(const Scene& scene, const ReportOptions& options);
// The scene's solve that the page reads, for the drawing, the reactions and the verdict alike:
// solve(scene, assessment_solve_options(options.solver)) (assessment.hpp), its profile sampled at
// options.solver.stations. Throws as html_report does.
Solution report_solution(const Scene& scene, const ReportOptions& options);
// The same page with that solve given: `solution` must be report_solution(scene, options) (a caller that
// needs it too, a CSV row, solves once).
std::string html_report(const Scene& scene, const Solution& solution, const ReportOptions& options);

}  // namespace ogive
