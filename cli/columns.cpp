#include "columns.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "option_text.hpp"
#include "values.hpp"

namespace ogive::cli {
namespace {

struct ColumnDoc {
  std::string_view name, unit, meaning;
};

constexpr ColumnDoc kColumnDocs[] = {
    {"scene", "", "scene number in the sweep, from 1"},
    {"curve", "", "generator curve family"},
    {"eccentricity", "", "pointed arch: centres eccentricity x span beyond mid-span (0 semicircle, 0.5 equilateral)"},
    {"rise_ratio", "", "rise / span: as asked, or for curves without --rise-ratio their own (12 digits)"},
    {"haunch_angle", "deg", "three- and four-centred arches: angle turned by the haunch arc"},
    {"crown_angle", "deg", "four-centred arch: tangent's angle at the pointed crown"},
    {"radius", "m", "pointed arch: the arcs' radius R = (0.5 + eccentricity) span"},
    {"rise", "m", "rise h: the crown's height above the springing line (as asked, or the curve's own, 12 digits)"},
    {"span", "m", "span L between the springings, on the axis"},
    {"thickness_ratio", "", "thickness t / span"},
    {"thickness", "m", "thickness t"},
    {"support_displacement_ratio", "", "outward movement d of each springing / span"},
    {"youngs_modulus", "Pa", "Young's modulus E"},
    {"poisson_ratio", "", "Poisson's ratio nu"},
    {"density", "kg/m^3", "density rho"},
    {"gravity", "m/s^2", "gravitational acceleration g"},
    {"shear_coefficient", "", "Timoshenko shear coefficient k"},
    {"plane_strain", "", "true: plane strain, E / (1 - nu^2); false: plane stress"},
    {"section", "", "elastic (linear) or no-tension (cracks beyond the kern)"},
    {"left_support", "", "left springing: clamped (rotation given) or pinned (M = 0)"},
    {"right_support", "", "right springing: clamped or pinned"},
    {"crown_hinge", "", "true: a hinge at the crown (M = 0 there)"},
    {"left_spread_ratio", "", "left springing's horizontal movement, outwards positive / span"},
    {"right_spread_ratio", "", "right springing's horizontal movement, outwards positive / span"},
    {"left_settlement_ratio", "", "left springing's vertical movement, downwards positive / span"},
    {"right_settlement_ratio", "", "right springing's vertical movement, downwards positive / span"},
    {"left_rotation", "rad", "left springing's given rotation, counter-clockwise positive"},
    {"right_rotation", "rad", "right springing's given rotation, counter-clockwise positive"},
    {"point_load", "N/m", "vertical point load P on the axis, downwards, per metre of vault width"},
    {"point_load_at", "", "where P acts, x / span from the left springing"},
    {"point_load_x", "m", "where P acts, x from the left springing"},
    {"live_load", "N/m^2", "uniform load q per horizontal length, downwards, per metre of vault width"},
    {"live_load_from", "", "where the live load starts, x / span"},
    {"live_load_to", "", "where the live load ends, x / span"},
    {"live_load_from_x", "m", "where the live load starts, x from the left springing"},
    {"live_load_to_x", "m", "where the live load ends, x from the left springing"},
    {"fill_density", "kg/m^3", "fill density rho_f (load rho_f g max(0, h_f - y_extrados) per horizontal length)"},
    {"fill_height_ratio", "", "the fill's level h_f above the springing line / span"},
    {"fill_height", "m", "the fill's level h_f above the springing line"},
    {"unit_weight", "N/m^3", "the masonry's unit weight gamma = rho g as given (--unit-weight; density is then gamma / g); empty: --density gave it"},
    {"loads_file", "", "the --loads-file whose loads the scene carries too"},
    {"wall_height", "m", "--wall-height as given: both walls' height h_w from the base to the springing line"},
    {"wall_thickness", "m", "--wall-thickness as given: both walls' thickness b_w"},
    {"wall_density", "kg/m^3", "--wall-density as given: both walls' density"},
    {"wall_top_load", "N/m", "--wall-top-load as given: the load on both walls' tops, downwards"},
    {"wall_top_load_at", "", "--wall-top-load-at as given: where it acts, a fraction of b_w from the inner face"},
    {"left_wall_height", "m", "left wall's height h_w from its base to the springing line; empty: no wall"},
    {"left_wall_thickness", "m", "left wall's thickness b_w, outwards from the vertical through the springing's intrados point"},
    {"left_wall_density", "kg/m^3", "left wall's density"},
    {"left_wall_top_load", "N/m", "load on the left wall's top, downwards"},
    {"left_wall_top_load_at", "", "where it acts, a fraction of b_w from the inner face"},
    {"right_wall_height", "m", "right wall's height h_w from its base to the springing line; empty: no wall"},
    {"right_wall_thickness", "m", "right wall's thickness b_w, outwards from the vertical through the springing's intrados point"},
    {"right_wall_density", "kg/m^3", "right wall's density"},
    {"right_wall_top_load", "N/m", "load on the right wall's top, downwards"},
    {"right_wall_top_load_at", "", "where it acts, a fraction of b_w from the inner face"},
    {"wall_lean", "rad", "--wall-lean as given: both walls' lean, outwards positive (the rotation about the base's outer toe; for small rotations the top's outward displacement / h_w)"},
    {"left_wall_lean", "rad", "left wall's lean, outwards positive (counter-clockwise), about its base's outer toe; empty: no wall"},
    {"right_wall_lean", "rad", "right wall's lean, outwards positive (clockwise), about its base's outer toe; empty: no wall"},
    {"left_lean_spread_ratio", "", "thrust: the left springing's horizontal movement that the left wall's lean causes, outwards positive / span (its top's outward displacement at the springing line, lean h_w, / span); added to left_spread_ratio's"},
    {"left_lean_settlement_ratio", "", "thrust: the left springing's vertical movement that the wall's lean causes, downwards positive / span (an outward lean raises it); added to left_settlement_ratio's"},
    {"left_lean_rotation", "rad", "thrust: the left springing's rotation that the wall's lean causes, counter-clockwise positive (the lean on a clamped springing, 0 on a pinned one, which turns freely); added to left_rotation"},
    {"right_lean_spread_ratio", "", "thrust: as left_lean_spread_ratio, of the right springing and wall"},
    {"right_lean_settlement_ratio", "", "thrust: as left_lean_settlement_ratio, of the right springing and wall"},
    {"right_lean_rotation", "rad", "thrust: as left_lean_rotation, of the right springing (minus the lean on a clamped springing)"},
    {"left_wall_crossings", "", "thrust: where the resultant of the left springing's reaction, the wall's weight and its top load crosses the left wall's beds, y/L:x/L joined by ';', from the highest bed to the base in four equal parts (the wall rigid)"},
    {"left_wall_base_eccentricity", "m", "thrust: the resultant's distance from the centre of the left wall's base, outwards positive"},
    {"left_wall_stability_ratio", "", "thrust: the left wall base's half-width over the resultant's distance from its centre (> 1: the resultant inside the base)"},
    {"left_wall_geometric_factor", "", "thrust: Heyman's geometric factor of the left wall, b_w over the thickness at which the base's resultant would reach the outer toe; empty where none does"},
    {"right_wall_crossings", "", "thrust: as left_wall_crossings, down the right wall"},
    {"right_wall_base_eccentricity", "m", "thrust: as left_wall_base_eccentricity, of the right wall (outwards: +x)"},
    {"right_wall_stability_ratio", "", "thrust: as left_wall_stability_ratio, of the right wall"},
    {"right_wall_geometric_factor", "", "thrust: as left_wall_geometric_factor, of the right wall"},
    {"wall_thickness_min", "m", "least wall thickness b_min on which the arch as it is stands (every wall given that thickness); empty without walls"},
    {"horizontal_acceleration", "", "horizontal acceleration a / g, left to right positive, on the self-weight and fill"},
    {"method", "", "method that produced the numbers (closed-form, shooting, multiple-shooting)"},
    {"integrator", "", "CVODE's method (adams, bdf); empty for the closed form"},
    {"rtol", "", "relative error asked (--rtol); success guarantees it"},
    {"status", "", "success, or why not (docs/cli.md: What status promises); limit: success, inadmissible, not_converged or lp_failure; spread: the mechanism's success, inadmissible (too thin at d = 0: no curve), no_mechanism, not_collapsed, not_converged, unsettled or lp_failure (spread --path: each solve's own on the elastic and cracking rows)"},
    {"domain", "", "the model solved: half (a symmetric scene, the right half by symmetry) or whole (springing to springing)"},
    {"H", "N/m", "horizontal reaction H_left: inward push of the left support on the arch, per metre of vault (limit --thrust-line: of that state; spread --path: of the row's state, both supports' alike)"},
    {"V", "N/m", "vertical reaction V_left of the left support (half the total vertical load of a symmetric scene); limit: half the total vertical load, (V_left + V_right) / 2, the live load at factor 1; spread --path: V_left of the row's state; per metre of vault"},
    {"H_over_V", "", "normalized horizontal reaction H_left / V_left, the left support's, in every command (thrust, profile, check, bench, draw, spread --path); H over half the total vertical load when the scene is symmetric"},
    {"H_left", "N/m", "left support's horizontal reaction on the arch, positive pointing into the span (+x)"},
    {"V_left", "N/m", "left support's vertical reaction on the arch, upwards positive"},
    {"M_left", "N m/m", "left support's couple on the arch, counter-clockwise positive (0 when pinned)"},
    {"H_right", "N/m", "right support's horizontal reaction on the arch, positive pointing into the span (-x)"},
    {"V_right", "N/m", "right support's vertical reaction on the arch, upwards positive"},
    {"M_right", "N m/m", "right support's couple on the arch, counter-clockwise positive (0 when pinned)"},
    {"max_thrust_eccentricity", "%", "largest |thrust_eccentricity| along the arch; empty if N is not a compression everywhere"},
    {"max_thrust_eccentricity_at", "m", "arc length from the left springing where it occurs"},
    {"thrust_in_kern", "", "true: compression everywhere and |thrust_eccentricity| <= 100 % (no tension in the section)"},
    {"thrust_in_section", "", "true: compression everywhere and |thrust_eccentricity| <= 300 % (resultant inside the masonry)"},
    {"max_compressive_stress", "Pa", "largest compressive_stress along the arch (kPa with --units kN); empty if N is not a compression everywhere or the no-tension section's resultant leaves the section"},
    {"max_compressive_stress_at", "m", "arc length from the left springing where it occurs"},
    {"max_stress_ratio", "", "thrust: max_compressive_stress / f_c (--compressive-strength); empty without it"},
    {"steps", "", "CVODE steps, all solves of the row"},
    {"rhs_evaluations", "", "CVODE right-hand-side evaluations"},
    {"segments", "", "shooting segments (arcs for the closed form)"},
    {"newton_iterations", "", "no-tension section: Newton iterations, all solves of the row (0 for the elastic section)"},
    {"condition_estimate", "", "Skeel condition number of the boundary-value problem"},
    {"error_estimate", "", "estimated relative error of the row's numbers (thrust eccentricities in units of the kern)"},
    {"beam_model", "", "the beam theory that produced the numbers: euler-bernoulli, timoshenko or curved (--beam-model; auto: the one it picked)"},
    {"model_error_estimate", "", "estimated relative error of H_over_V that the beam model makes against the two-dimensional arch: the difference to the curved bar's plus its calibrated bound (docs/model.md); empty unless asked"},
    {"boundary_residual", "", "largest residual of the six boundary conditions (and a hinge's M = 0), scaled units"},
    {"equilibrium_residual", "", "largest residual of the domain's equilibrium (forces, moments) / its load"},
    {"message", "", "why the status is not success; empty on success"},
    {"s", "m", "arc length from the left springing (limit --thrust-line: of the joint's axis point; a wall's bed lies outside the arch's arc lengths, below 0 on the left wall, beyond the arch's length on the right one)"},
    {"x", "m", "axis point, horizontal from the left springing"},
    {"y", "m", "axis point, up from the springing line"},
    {"theta", "rad", "tangent angle to the horizontal, in the direction of increasing s"},
    {"kappa", "1/m", "curvature d theta / ds (negative: turning downwards)"},
    {"intrados_x", "m", "the section's (limit: the joint's) end on the intrados, horizontal (profile: axis point - t/2 along the normal)"},
    {"intrados_y", "m", "the section's end on the intrados, vertical"},
    {"extrados_x", "m", "the section's (limit: the joint's) end on the extrados, horizontal (profile: axis point + t/2 along the normal)"},
    {"extrados_y", "m", "the section's end on the extrados, vertical"},
    {"Ux", "m", "horizontal displacement of the axis"},
    {"Uy", "m", "vertical displacement of the axis"},
    {"psi", "rad", "rotation of the cross-section, counter-clockwise positive"},
    {"N", "N/m", "normal force, negative in compression"},
    {"shear_force", "N/m", "shear force (V of the model's equations)"},
    {"M", "N m/m", "bending moment: couple of the part beyond s on the part before s"},
    {"thrust_eccentricity", "%", "e = 600 M / (N t): offset of the compression in per cent of the kern half-width t/6; < 0 towards the extrados"},
    {"thrust_x", "m", "where the resultant crosses the section or joint (line of thrust), horizontal"},
    {"thrust_y", "m", "where the resultant crosses the section (line of thrust), vertical"},
    {"compressed_depth", "", "no-tension section: the compressed depth c over t (1 while the resultant is in the kern; 0 at a hinge); empty for the elastic section"},
    {"cracked", "", "no-tension section: true where the resultant lies beyond the kern (the section is cracked); empty for the elastic section"},
    {"stress_ratio", "", "profile: compressive_stress / f_c (--compressive-strength); empty without it"},
    {"compressive_stress", "Pa", "greatest compressive stress in the section, unit width, positive (kPa with --units kN): |N| / t + 6 |M| / t^2 (elastic section, or in the kern); cracked no-tension section 2 |N| / (3 (t/2 - |M / N|)); empty where N is not a compression or the resultant leaves the no-tension section"},
    {"warning", "", "tension, outside_section (|e| > 300 %), outside_kern (|e| > 100 %), no_normal_force, or empty"},
    {"reference_method", "", "check: what the row is compared with"},
    {"reference_status", "", "check: the reference's own status"},
    {"reference_error", "", "check and bench: the reference's own estimated error"},
    {"reference_H_over_V", "", "check: the reference's H_left / V_left"},
    {"relative_difference", "", "check: |H_over_V - reference_H_over_V| / max(|reference_H_over_V|, 0.01)"},
    {"tolerance", "", "check: the rtol the row is held to"},
    {"within_tolerance", "", "check: true when the row says success and relative_difference <= rtol + reference_error"},
    {"chosen_method", "", "bench: the method auto chose (or the method itself)"},
    {"error_H_over_V", "", "bench: true error of H_over_V (H_left / V_left) against the reference's"},
    {"error_profile", "", "bench: true error of the profile (profile_difference) against the reference"},
    {"median_seconds", "s", "bench: median time of one solve"},
    {"file", "", "draw, report: the SVG drawing or HTML page written for the scene"},
    {"joints", "", "limit, spread: joint orientation, radial (normal to the axis) or vertical"},
    {"weight", "", "limit, spread: voussoir (each voussoir's weight at its centroid) or axis (rho g t per axis length)"},
    {"joints_count", "", "limit, spread: joints springing to springing, both included"},
    {"friction", "", "limit, spread: friction coefficient of the joints; empty: no sliding check"},
    {"friction_model", "", "limit, assess: the sliding's flow rule with friction, non-associative or associative; empty: no sliding check"},
    {"compressive_strength", "Pa", "limit, spread, assess: the masonry's compressive strength f_c (kPa with --units kN, as the stresses); empty: infinite (no crushing)"},
    {"H_min", "N/m", "limit: minimum horizontal thrust of an admissible state"},
    {"H_max", "N/m", "limit: maximum horizontal thrust of an admissible state"},
    {"H_min_over_V", "", "limit: H_min / V, V half the total vertical load (the V column; with a symmetric scene, H_over_V's V_left)"},
    {"H_max_over_V", "", "limit: H_max / V, V half the total vertical load (the V column; with a symmetric scene, H_over_V's V_left)"},
    {"thickness_min_ratio", "", "limit, assess: t_min / span, the thinnest arch of the same axis that stands"},
    {"geometric_safety_factor", "", "limit, assess: t / t_min"},
    {"hinges_min", "", "limit: hinges of the minimum-thrust state, x/L:face joined by ';' (face: intrados, extrados, or axis for a pin; x from the left springing's axis point, so a hinge on a springing's outer face lies beyond [0, 1], e.g. -0.04 at t/L 0.08); on walls a hinge at a bed's edge is x/L:wall-outer@y/L or wall-inner@y/L, y from the springing line (the base at -h_w/L)"},
    {"hinges_max", "", "limit: hinges of the maximum-thrust state, x/L:face joined by ';'"},
    {"load_factor", "", "limit, assess: multiplier on the live load (every point and live load) at collapse (static LP)"},
    {"load_factor_mechanism", "", "limit: the same from the mechanism of those hinges by virtual work"},
    {"hinges_collapse", "", "limit: hinges of the collapse mechanism, x/L:face joined by ';'"},
    {"horizontal_load_factor", "",
     "limit, assess: the horizontal acceleration a_c / g (to +x) that makes the arch a mechanism, vertical loads at "
     "factor 1 and --horizontal-acceleration ignored (only when asked for)"},
    {"horizontal_load_factor_mechanism", "", "limit: the same from the mechanism of its hinges by virtual work"},
    {"hinges_horizontal", "", "limit: hinges of the mechanism of a_c, x/L:face joined by ';'"},
    {"lp_solves", "", "limit: linear programs solved for the row"},
    {"state", "", "limit --thrust-line: min, max or collapse"},
    {"joint", "", "limit --thrust-line: joint index from the left springing (on walls: from the left wall's base)"},
    {"hinge", "", "limit --thrust-line: intrados, extrados (a hinge) or axis (a pin), else empty; at a wall's bed intrados is its edge on the wall's inner face, extrados on the outer one"},
    {"moving", "", "spread: the springings that move outwards, left, right or both"},
    {"left_settlement_share", "m/m", "spread: the left springing's settlement, downwards positive, per metre of d, the outward movement of each springing that moves (--left-settlement-share)"},
    {"right_settlement_share", "m/m", "spread: the right springing's settlement, downwards positive, per metre of d (--right-settlement-share)"},
    {"path_steps", "", "spread: rows of the mechanism's path from d = 0 to collapse (--steps)"},
    {"H_elastic", "N/m", "spread: H_left of the elastic arch (the scene's elastic section) at d = 0"},
    {"V_elastic", "N/m", "spread: V_left of the elastic arch at d = 0"},
    {"H_over_V_elastic", "", "spread: H_left / V_left of the elastic arch at d = 0"},
    {"H_plateau", "N/m", "spread: the plateau the cracking arch falls to, the rigid voussoirs' minimum thrust at d = 0 (limit's H_min with spread's --weight)"},
    {"V_plateau", "N/m", "spread: V_left of that minimum-thrust state"},
    {"H_over_V_plateau", "", "spread: H_plateau / V_plateau"},
    {"spread_capacity_ratio", "", "spread, assess: the span's increase at collapse of the rigid voussoirs' mechanism (from d = 0) / span"},
    {"collapse", "", "spread: how the mechanism collapses, thrust_leaves_arch (no thrust line through its hinges fits the moved voussoirs: it would leave the arch) or snap_through (no mechanism of its hinges moves the springings apart: they are in a line, or fewer than three open; or a new hinge forms that no balance holds, message says where) or sliding (with --friction: a joint's resultant leaves the friction cone, sliding_joint; on walls also the resultant down a wall at one of its beds, the message says which wall and bed) or wall_tips (on walls: the resultant down a wall leaves one of its beds, the message says which wall and bed: the wall tips there); spread --path: on the last mechanism row"},
    {"H_collapse", "N/m", "spread: the mechanism's H at collapse (its last admissible state)"},
    {"V_collapse", "N/m", "spread: the mechanism's V_left at collapse"},
    {"H_over_V_collapse", "", "spread: H_collapse / V_collapse"},
    {"crown_drop_ratio", "", "spread: the crown's drop, downwards positive, / span (the mechanism's crown hinge; the elastic and cracking arch's axis at the crown); the summary's: at collapse"},
    {"hinges", "", "spread: the mechanism's hinges, x/L:face joined by ';' (three, or four for a pointed arch; they may move along the path), x where the hinge point is at the row's spread (the summary's: at d = 0) from the left springing's place at d = 0: a hinge at a springing that has moved outwards lies beyond [0, 1] (e.g. -0.05 or 1.05)"},
    {"sliding_joint", "", "spread --friction: with collapse sliding, the joint that slides, x/L of its axis point where it is then (beyond [0, 1] at a moved springing or a wall's bed)"},
    {"left_wall_rotation_collapse", "rad", "spread on walls: the left wall's rotation outwards (counter-clockwise, about its base's outer toe) at collapse; empty without a left wall"},
    {"right_wall_rotation_collapse", "rad", "spread on walls: the right wall's rotation outwards (clockwise, about its base's outer toe) at collapse; empty without a right wall"},
    {"left_wall_top_displacement_collapse", "m", "spread on walls: the outward horizontal displacement of the left wall's top (its outer corner) at collapse, h sin(rotation) with h its height above the toe"},
    {"right_wall_top_displacement_collapse", "m", "spread on walls: the outward horizontal displacement of the right wall's top (its outer corner) at collapse"},
    {"wall_rotation", "rad", "spread --path on walls: the rotation outwards of each moving wall at the row (the cracking rows': the small rotation that gives their span's increase)"},
    {"hinges_at_collapse", "", "spread: the mechanism's hinges at collapse, x/L:face joined by ';', where they are then (beyond [0, 1] at a moved springing)"},
    {"verdict", "", "assess: pass (every criterion asked for is met), fail (one is not: an arch that cannot stand fails) or not_assessed (none fails, but one could not be assessed: message says why)"},
    {"governing", "", "assess: the criterion that decides the verdict: the failed one of least margin, else the one not assessed, else the passed one of least margin"},
    {"margin", "", "assess: the governing criterion's value / required (required / value for max_thrust_eccentricity): >= 1 exactly where it passes"},
    {"geometric_safety_factor_required", "", "assess: the least t / t_min asked for (--require-geometric-factor); empty: not required"},
    {"geometric_safety_factor_outcome", "", "assess: pass, fail, not_assessed (required, no trustworthy value: message says why), not_required or not_applicable"},
    {"load_factor_required", "", "assess: the least collapse load factor asked for (--require-load-factor); empty: not required"},
    {"load_factor_outcome", "", "assess: as geometric_safety_factor_outcome; not_applicable without a point or live load"},
    {"horizontal_load_factor_required", "", "assess: the least a_c / g asked for (--require-acceleration); empty: not required"},
    {"horizontal_load_factor_outcome", "", "assess: as geometric_safety_factor_outcome"},
    {"spread_capacity_ratio_required", "", "assess: the least spreading capacity asked for (--require-spread); empty: not required"},
    {"spread_capacity_ratio_outcome", "", "assess: as geometric_safety_factor_outcome; not_applicable with a horizontal acceleration"},
    {"max_thrust_eccentricity_required", "%", "assess: the largest |e| allowed (--require-thrust: 300 section, 100 kern); empty: not required"},
    {"max_thrust_eccentricity_outcome", "", "assess: as geometric_safety_factor_outcome (fail also where the no-tension section is inadmissible)"},
    {"limit_status", "", "assess: the limit analysis' status (success, inadmissible, not_converged, lp_failure)"},
    {"warnings", "", "assess: what the engineer must read whatever the criteria, in words, joined by '; ': the line of thrust leaving the section, t below t_min, a load factor below 1"},
    {"part", "", "spread --path: elastic (the elastic section at d = 0), cracking (the no-tension section) or mechanism (rigid voussoirs to collapse)"},
    {"spread_ratio", "", "spread --path: the span's increase / span (cracking: the moving springings' movements; mechanism: from its own d = 0)"},
};

const ColumnDoc* find_column_doc(std::string_view name) {
  for (const ColumnDoc& d : kColumnDocs)
    if (d.name == name) return &d;
  return nullptr;
}

// Twelve significant digits: a rise derived from the geometry (exact to about 1e-15) prints as the
// number it is meant to be, 0.5 for the semicircle and not 0.4999999999999999.
double rounded(double value) {
  if (!std::isfinite(value) || value == 0) return value;
  return std::stod(fmt::format("{:.12g}", value));
}

// A force or moment unit (per metre of vault width) and the same in kN: what --units kN divides by 1000.
// A result's stress (Pa) prints in kPa, kN/m^2; an input in Pa (Young's modulus) is given in Pa whatever
// --units says, and prints so.
std::string_view in_kilonewtons(std::string_view unit, bool result) {
  if (unit == "N/m") return "kN/m";
  if (unit == "N m/m") return "kN m/m";
  if (unit == "N/m^2") return "kN/m^2";
  if (unit == "Pa" && result) return "kPa";
  return {};
}

// --digits as a number of significant digits (0: not given, the shortest round-trip decimal).
int significant_digits(const std::string& text) {
  if (text.empty()) return 0;
  int digits = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), digits);
  if (error != std::errc{} || end != text.data() + text.size() || digits < 1 || digits > 17)
    throw UsageError(fmt::format("--digits: must be a whole number in [1, 17] (significant digits; 17 reads back "
                                 "every double exactly), got '{}'",
                                 text.substr(0, 60)));
  return digits;
}

}  // namespace

const std::vector<std::string>& scene_columns() {
  static const std::vector<std::string> columns = {
      "scene", "curve", "eccentricity", "rise_ratio", "haunch_angle", "crown_angle", "span", "thickness_ratio",
      "support_displacement_ratio", "youngs_modulus", "poisson_ratio", "density", "gravity", "shear_coefficient",
      "plane_strain", "section", "left_support", "right_support", "crown_hinge", "left_spread_ratio",
      "right_spread_ratio", "left_settlement_ratio", "right_settlement_ratio", "left_rotation", "right_rotation",
      "point_load", "point_load_at", "live_load", "live_load_from", "live_load_to", "fill_density",
      "fill_height_ratio", "loads_file", "horizontal_acceleration", "thickness", "rise", "radius", "point_load_x",
      "live_load_from_x", "live_load_to_x", "fill_height", "unit_weight", "wall_height", "wall_thickness",
      "wall_density", "wall_top_load", "wall_top_load_at", "left_wall_height", "left_wall_thickness",
      "left_wall_density", "left_wall_top_load", "left_wall_top_load_at", "right_wall_height",
      "right_wall_thickness", "right_wall_density", "right_wall_top_load", "right_wall_top_load_at", "wall_lean",
      "left_wall_lean", "right_wall_lean"};
  return columns;
}

double force_unit(const std::string& units) {
  // Any case: kn and KN are kN as engineers type it.
  std::string lower = units;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower == "n") return 1.0;
  if (lower == "kn") return 1000.0;
  throw UsageError(fmt::format("--units: must be N or kN, got '{}'", units.substr(0, 60)));
}

bool ColumnText::given() const { return option && option->count() > 0; }

void add_column_options(CLI::App& cmd, ColumnText& text) {
  text.option = cmd.add_option("--columns", text.columns,
                               "columns to print, comma-separated, in the order given after scene; 'help' lists every column "
                               "with its unit (default: scene, the inputs that vary, the results)");
  cmd.add_flag("--all-columns", text.all_columns, "print every column, the inputs that do not vary included");
  cmd.add_option("--units", text.units,
                 "force unit: N or kN, of the force options (--point-load in N/m or kN/m, --live-load in N/m^2 or "
                 "kN/m^2) and of every force and moment printed (N/m or kN/m, N m/m or kN m/m per metre of vault "
                 "width; with kN a first line '# units: kN' says so); loads files stay in N")
      ->capture_default_str();
  cmd.add_option("--digits", text.digits,
                 "significant digits of every number printed, 1 to 17 (default: the shortest decimal that reads back "
                 "to the same double)");
}

Columns::Columns(const std::vector<std::string>& results, std::vector<std::string> defaults)
    : all_(scene_columns()), defaults_(std::move(defaults)) {
  all_.insert(all_.end(), results.begin(), results.end());
}

void Columns::select(const ColumnText& ct, const std::vector<std::string>& varying_inputs,
                     const std::vector<std::string>& varying_solver) {
  if (ct.given() && ct.all_columns) throw UsageError("--columns: give either --columns or --all-columns");
  selection_.digits = significant_digits(ct.digits);
  selection_.divisor.clear();
  if (force_unit(ct.units) != 1.0) {
    // The results' forces and moments; the inputs print as given (in the unit they were given in).
    selection_.divisor.assign(all_.size(), 1.0);
    for (std::size_t i = scene_columns().size(); i < all_.size(); ++i) {
      const ColumnDoc* d = find_column_doc(all_[i]);
      if (d && !in_kilonewtons(d->unit, true).empty()) selection_.divisor[i] = force_unit(ct.units);
    }
  }
  std::vector<bool>& keep = selection_.keep;
  selection_.order.clear();
  keep.assign(all_.size(), ct.all_columns);
  if (ct.all_columns) return;
  // The names to print, in the order printed: the scene's number first (it ties a row to its scene).
  std::vector<std::string> wanted{"scene"};
  if (!ct.given()) {
    wanted.insert(wanted.end(), defaults_.begin(), defaults_.end());
    wanted.insert(wanted.end(), varying_inputs.begin(), varying_inputs.end());
    wanted.insert(wanted.end(), varying_solver.begin(), varying_solver.end());
  } else {
    for (const std::string& name : split_names(ct.columns)) {
      if (std::find(all_.begin(), all_.end(), name) == all_.end())
        throw UsageError(fmt::format("--columns: no column '{}' in this command's output{} (--columns help lists them)",
                                     name.substr(0, 60), did_you_mean(name, all_)));
      if (std::find(wanted.begin(), wanted.end(), name) == wanted.end()) wanted.push_back(name);
    }
  }
  for (std::size_t i = 0; i < all_.size(); ++i)
    keep[i] = std::find(wanted.begin(), wanted.end(), all_[i]) != wanted.end();
  if (!ct.given()) return;  // the defaults print in the full order
  // Each wanted name's rank among the kept fields in the full order.
  std::vector<std::string> kept_in_full_order;
  for (std::size_t i = 0; i < all_.size(); ++i)
    if (keep[i]) kept_in_full_order.push_back(all_[i]);
  for (const std::string& name : wanted)
    selection_.order.push_back(static_cast<std::size_t>(
        std::find(kept_in_full_order.begin(), kept_in_full_order.end(), name) - kept_in_full_order.begin()));
  bool identity = true;
  for (std::size_t k = 0; k < selection_.order.size(); ++k) identity = identity && selection_.order[k] == k;
  if (identity) selection_.order.clear();
}

bool Columns::selected(std::string_view name) const {
  for (std::size_t i = 0; i < all_.size(); ++i)
    if (all_[i] == name) return selection_.keep[i];
  return false;
}

std::string Columns::header() const {
  std::vector<std::string_view> kept;
  bool stresses = false;  // a stress printed in kPa
  for (std::size_t i = 0; i < all_.size(); ++i)
    if (selection_.keep[i]) {
      kept.push_back(all_[i]);
      const ColumnDoc* d = find_column_doc(all_[i]);
      stresses = stresses || (i >= scene_columns().size() && d && d->unit == "Pa");
    }
  std::string out;
  if (!selection_.divisor.empty())
    out = fmt::format("# units: kN (forces in kN/m and moments in kN m/m per metre of vault width{})\n",
                      stresses ? "; stresses in kPa" : "");
  for (std::size_t k = 0; k < kept.size(); ++k) {
    if (k > 0) out += ',';
    out += kept[selection_.order.empty() ? k : selection_.order[k]];
  }
  return out + "\n";
}

std::string Columns::help(const ColumnText& ct) const {
  const bool kilonewtons = force_unit(ct.units) != 1.0;
  std::string out = "column,unit,meaning\n";
  CsvRow row;
  for (std::size_t i = 0; i < all_.size(); ++i) {
    const std::string& name = all_[i];
    const ColumnDoc* d = find_column_doc(name);
    const std::string_view unit = d ? d->unit : "";
    const std::string_view kilo = in_kilonewtons(unit, i >= scene_columns().size());
    row.add(name).add(kilonewtons && !kilo.empty() ? kilo : unit);
    row.add(d ? d->meaning : "");
    out += row.take();
  }
  return out;
}

void add_parameter(CsvRow& row, double value) {
  if (std::isnan(value)) row.add(std::string_view{});
  else row.add(value);
}

void add_scene_columns(CsvRow& row, const SceneParameters& p, const Curve* curve) {
  row.add(static_cast<std::int64_t>(p.scene)).add(p.curve);
  add_parameter(row, p.eccentricity);
  if (!std::isnan(p.rise_ratio)) row.add(p.rise_ratio);  // the rise asked for
  // The curve's own rise, rounded through text, only when the column is printed: it costs a twentieth
  // of a closed-form scene.
  else if (curve && row.wants_next()) row.add(rounded(curve->rise() / curve->span()));
  else row.add(std::string_view{});
  add_parameter(row, p.haunch_angle);
  add_parameter(row, p.crown_angle);
  row.add(p.span).add(p.thickness_ratio).add(p.support_displacement_ratio);
  row.add(p.youngs_modulus).add(p.poisson_ratio).add(p.density).add(p.gravity).add(p.shear_coefficient);
  row.add_bool(p.plane_strain);
  row.add(p.section).add(p.left_support).add(p.right_support).add_bool(p.crown_hinge);
  for (double v : {p.left_spread_ratio, p.right_spread_ratio, p.left_settlement_ratio, p.right_settlement_ratio,
                   p.left_rotation, p.right_rotation, p.point_load, p.point_load_at, p.live_load, p.live_load_from,
                   p.live_load_to, p.fill_density, p.fill_height_ratio})
    add_parameter(row, v);
  row.add(p.loads_file);
  row.add(p.horizontal_acceleration);
  // The metre forms, after the ratios (so that every column before them keeps its place).
  row.add(p.thickness);
  if (!std::isnan(p.rise)) row.add(p.rise);
  else if (curve && row.wants_next()) row.add(rounded(curve->rise()));
  else row.add(std::string_view{});
  for (double v : {p.radius, p.point_load_x, p.live_load_from_x, p.live_load_to_x, p.fill_height, p.unit_weight})
    add_parameter(row, v);
  for (double v : {p.wall_height, p.wall_thickness, p.wall_density, p.wall_top_load, p.wall_top_load_at,
                   p.left_wall_height, p.left_wall_thickness, p.left_wall_density, p.left_wall_top_load,
                   p.left_wall_top_load_at, p.right_wall_height, p.right_wall_thickness, p.right_wall_density,
                   p.right_wall_top_load, p.right_wall_top_load_at, p.wall_lean, p.left_wall_lean, p.right_wall_lean})
    add_parameter(row, v);
}

std::string sparse_row(const Columns& columns, const SceneParameters& p, const Curve* curve,
                       const std::vector<std::pair<std::string_view, std::string>>& fields) {
  CsvRow row(columns.keep());
  add_scene_columns(row, p, curve);
  for (std::size_t i = scene_columns().size(); i < columns.all().size(); ++i) {
    const auto it =
        std::find_if(fields.begin(), fields.end(), [&](const auto& f) { return f.first == columns.all()[i]; });
    row.add(it == fields.end() ? std::string_view{} : std::string_view(it->second));
  }
  return row.take();
}

}  // namespace ogive::cli
