#include "scene_options.hpp"

#include <cmath>
#include <map>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "units.hpp"

namespace ogive::cli {
namespace {

constexpr CurveFamily kFamilies[] = {
    {"pointed", true},
    {"semicircular"},
    {"segmental", false, true, false, false, false, "0.25"},
    {"three-centred", false, true, true, false, false, "0.3333333333333333", "60"},
    {"four-centred", false, true, true, true, false, "0.42", "45", "15"},
    {"elliptical", false, true, false, false, false, "0.5"},
    {"parabolic", false, true, false, false, false, "0.5"},
    {"catenary", false, true, false, false, false, "0.5"},
    {"points", false, false, false, false, true},
    {"whole-points", false, false, false, false, true},
};

bool positive(double v) { return v > 0; }
bool any_number(double) { return true; }
bool within_span(double v) { return v >= 0 && v <= 1; }
bool non_negative(double v) { return v >= 0; }
bool small_movement(double v) { return std::abs(v) <= kLargestMovement; }
constexpr const char* kSpanRule = "must lie in [0, 1] (x / L within the span)";
constexpr const char* kInSpanRule = "must lie in [0, L] (m from the left springing, within the span)";
constexpr const char* kWallFractionRule = "must lie in [0, 1] (a fraction of the wall's thickness from its inner face)";
constexpr const char* kMovementRule = "must lie in [-0.01, 0.01] (beyond, small-displacement theory does not hold)";
constexpr const char* kLeanRule = "must lie in [-0.01, 0.01] (rad; beyond, small-displacement theory does not hold)";

// What each scene option is, with its unit, for --help (the rules are scene_axes').
const std::map<std::string, std::string>& axis_meanings() {
  static std::map<std::string, std::string> meanings = {
      {"--span", "span L between the springings' axis points, m"},
      {"--youngs-modulus", "Young's modulus E, Pa"},
      {"--poisson-ratio", "Poisson's ratio nu (shear modulus G = E / (2 (1 + nu)))"},
      {"--density", "density rho, kg/m^3"},
      {"--unit-weight", "unit weight gamma = rho g of the masonry, N/m^3, instead of --density (rho = gamma / g)"},
      {"--gravity", "gravitational acceleration g, m/s^2"},
      {"--shear-coefficient", "Timoshenko shear coefficient k (5/6 for a rectangle)"},
      {"--thickness-ratio", "thickness over span t/L"},
      {"--support-displacement-ratio", "outward movement of each springing over span d/L (0.0003 = 0.03 %)"},
      {"--haunch-angle", "three- and four-centred: angle the haunch arc turns through, degrees"},
      {"--crown-angle", "four-centred: the tangent's angle above the horizontal at the crown, degrees"},
      {"--rise-ratio", "rise over span h/L (not for semicircular, points, whole-points; pointed: sets the "
                       "eccentricity, (h/L)^2 - 1/4)"},
      {"--eccentricity",
       "pointed: the centres' offset beyond mid-span over the span (0 semicircle, 0.5 equilateral)"},
      {"--point-load", "vertical point load P on the axis, downwards, per metre of vault width: N/m (kN/m with --units kN)"},
      {"--point-load-at", "where the point load acts, x / L from the left springing (default 0.5)"},
      {"--live-load", "uniform load q per horizontal length, downwards: N/m^2, N/m per metre of width (kN/m^2 with --units kN)"},
      {"--live-load-from", "where the live load starts, x / L (default 0)"},
      {"--live-load-to", "where the live load ends, x / L (default 1)"},
      {"--fill-density",
       "fill density rho_f, kg/m^3: load rho_f g max(0, h_f - y_extrados(x)) per horizontal length"},
      {"--fill-height-ratio", "the fill's level h_f above the springing line, over the span"},
      {"--fill-height",
       "the fill's level h_f above the springing line, m; crown: the height of the extrados over the crown"},
      {"--thickness", "thickness t, m"},
      {"--rise", "rise h, m: the crown's height above the springing line (not for semicircular, points, "
                 "whole-points; pointed: sets the eccentricity)"},
      {"--radius", "pointed: the arcs' radius R, m (R = (0.5 + eccentricity) L)"},
      {"--point-load-x", "where the point load acts, m from the left springing"},
      {"--live-load-from-x", "where the live load starts, m from the left springing"},
      {"--live-load-to-x", "where the live load ends, m from the left springing"},
      {"--horizontal-acceleration",
       "horizontal acceleration a, a fraction of g, left to right positive: the self-weight and the fill also "
       "carry a times their weight horizontally (point and live loads do not)"},
      {"--left-spread-ratio", "left springing's horizontal movement, outwards positive, over the span"},
      {"--right-spread-ratio", "right springing's horizontal movement, outwards positive, over the span"},
      {"--left-settlement-ratio", "left springing's vertical movement, downwards positive, over the span"},
      {"--right-settlement-ratio", "right springing's vertical movement, downwards positive, over the span"},
      {"--left-rotation", "left springing's rotation, rad, counter-clockwise positive (clamped only)"},
      {"--right-rotation", "right springing's rotation, rad, counter-clockwise positive (clamped only)"},
  };
  // The walls' options, each in three forms: both walls, the left one, the right one.
  static const bool walls_added = [] {
    const std::pair<const char*, const char*> wall[] = {
        {"height", "wall's height h_w from its base to the springing line, m (docs/model.md, Walls; limit, thrust, "
                   "spread, assess, draw, report)"},
        {"thickness", "wall's thickness b_w from the vertical through the springing's intrados point outwards, m "
                      "(needed with a height)"},
        {"density", "wall's density, kg/m^3 (default: --density)"},
        {"top-load", "vertical load on the wall's top (a wall above, a roof), downwards, N/m (kN/m with --units kN) "
                     "(default 0)"},
        {"top-load-at", "where the top load acts, a fraction of b_w from the inner face (default 0.5)"},
        {"lean", "wall's lean, rad, outwards positive: its rotation about its base's outer toe, which for small "
                 "rotations is its out-of-plumb, the top's outward displacement over h_w (also in mm/m or %); it moves "
                 "the springing (out, up and, clamped, turning with the wall), adding to the springing's given "
                 "movement (thrust, draw, report) (default 0)"},
    };
    for (const auto& [name, meaning] : wall)
      for (const char* side : {"", "left-", "right-"})
        meanings.emplace(fmt::format("--{}wall-{}", side, name),
                         std::string(*side ? (side[0] == 'l' ? "left " : "right ") : "each ") + meaning);
    return true;
  }();
  (void)walls_added;
  return meanings;
}

// What an option without a default text means when it is not given.
std::string absent_default(const std::string& flag) {
  if (flag == "--rise-ratio" || flag == "--haunch-angle" || flag == "--crown-angle") return " (default: the curve's)";
  if (flag == "--left-spread-ratio" || flag == "--right-spread-ratio") return " (default: --support-displacement-ratio)";
  if (flag == "--point-load-at" || flag == "--live-load-from" || flag == "--live-load-to") return "";
  if (flag == "--thickness") return " (default: --thickness-ratio)";
  if (flag.find("wall-") != std::string::npos) return "";
  if (flag == "--rise" || flag == "--radius") return " (default: the curve's)";
  return " (default: none)";
}

}  // namespace

std::span<const CurveFamily> curve_families() { return kFamilies; }

std::string curve_family_names() {
  std::string names;
  for (const CurveFamily& f : kFamilies) names += (names.empty() ? "" : ", ") + std::string(f.name);
  return names;
}

std::vector<Axis> scene_axes() {
  using P = SceneParameters;
  return {
      {"--point-load", "", &P::point_load, any_number, "must be a finite number"},
      {"--point-load-at", "", &P::point_load_at, within_span, kSpanRule},
      {"--point-load-x", "", &P::point_load_x, non_negative, kInSpanRule},
      {"--live-load", "", &P::live_load, any_number, "must be a finite number"},
      {"--live-load-from", "", &P::live_load_from, within_span, kSpanRule},
      {"--live-load-to", "", &P::live_load_to, within_span, kSpanRule},
      {"--live-load-from-x", "", &P::live_load_from_x, non_negative, kInSpanRule},
      {"--live-load-to-x", "", &P::live_load_to_x, non_negative, kInSpanRule},
      {"--fill-density", "", &P::fill_density, [](double v) { return v >= 0; }, "must be >= 0"},
      {"--fill-height-ratio", "", &P::fill_height_ratio, [](double v) { return v > 0 && v <= 100; },
       "must lie in (0, 100] (the fill's level above the springing line, over the span)"},
      {"--fill-height", "", &P::fill_height, positive, "must be > 0, or crown"},
      {"--horizontal-acceleration", "0", &P::horizontal_acceleration, any_number, "must be a finite number"},
      {"--left-spread-ratio", "", &P::left_spread_ratio, small_movement, kMovementRule},
      {"--right-spread-ratio", "", &P::right_spread_ratio, small_movement, kMovementRule},
      {"--left-settlement-ratio", "0", &P::left_settlement_ratio, small_movement, kMovementRule},
      {"--right-settlement-ratio", "0", &P::right_settlement_ratio, small_movement, kMovementRule},
      {"--left-rotation", "0", &P::left_rotation, small_movement, kMovementRule},
      {"--right-rotation", "0", &P::right_rotation, small_movement, kMovementRule},
      {"--span", "10", &P::span, positive, "must be > 0"},
      {"--youngs-modulus", "14.8e9", &P::youngs_modulus, positive, "must be > 0"},
      {"--poisson-ratio", "0.2", &P::poisson_ratio, [](double v) { return v > -1 && v <= 0.5; },
       "must lie in (-1, 0.5]"},
      {"--density", "2348", &P::density, [](double v) { return v >= 0; },
       "must be >= 0 (0: no self-weight, with another load)"},
      {"--unit-weight", "", &P::unit_weight, [](double v) { return v >= 0; },
       "must be >= 0 (0: no self-weight, with another load)"},
      {"--gravity", "9.81", &P::gravity, positive, "must be > 0"},
      {"--shear-coefficient", "0.8333333333333334", &P::shear_coefficient, [](double v) { return v > 0 && v <= 2; },
       "must lie in (0, 2]"},
      {"--thickness-ratio", "0.08", &P::thickness_ratio, [](double v) { return v > 0 && v < 1; },
       "must lie in (0, 1)"},
      {"--thickness", "", &P::thickness, positive, "must be > 0"},
      {"--support-displacement-ratio", "0", &P::support_displacement_ratio, small_movement,
       "must lie in [-0.01, 0.01] (d/L; beyond, small-displacement theory does not hold)"},
      {"--haunch-angle", "", &P::haunch_angle, [](double v) { return v > 0 && v < 90; }, "must lie in (0, 90)"},
      {"--crown-angle", "", &P::crown_angle, [](double v) { return v > 0 && v < 90; }, "must lie in (0, 90)"},
      {"--rise-ratio", "", &P::rise_ratio, [](double v) { return v > 0 && v <= 2; }, "must lie in (0, 2]"},
      {"--rise", "", &P::rise, positive, "must be > 0"},
      {"--eccentricity", "0", &P::eccentricity, [](double v) { return v >= 0 && v <= 100; },
       "must lie in [0, 100]"},
      {"--radius", "", &P::radius, positive, "must be > 0"},
      {"--wall-height", "", &P::wall_height, non_negative, "must be >= 0"},
      {"--left-wall-height", "", &P::left_wall_height, non_negative, "must be >= 0"},
      {"--right-wall-height", "", &P::right_wall_height, non_negative, "must be >= 0"},
      {"--wall-thickness", "", &P::wall_thickness, positive, "must be > 0"},
      {"--left-wall-thickness", "", &P::left_wall_thickness, positive, "must be > 0"},
      {"--right-wall-thickness", "", &P::right_wall_thickness, positive, "must be > 0"},
      {"--wall-density", "", &P::wall_density, non_negative, "must be >= 0"},
      {"--left-wall-density", "", &P::left_wall_density, non_negative, "must be >= 0"},
      {"--right-wall-density", "", &P::right_wall_density, non_negative, "must be >= 0"},
      {"--wall-top-load", "", &P::wall_top_load, non_negative, "must be >= 0 (downwards)"},
      {"--left-wall-top-load", "", &P::left_wall_top_load, non_negative, "must be >= 0 (downwards)"},
      {"--right-wall-top-load", "", &P::right_wall_top_load, non_negative, "must be >= 0 (downwards)"},
      {"--wall-top-load-at", "", &P::wall_top_load_at, within_span, kWallFractionRule},
      {"--left-wall-top-load-at", "", &P::left_wall_top_load_at, within_span, kWallFractionRule},
      {"--right-wall-top-load-at", "", &P::right_wall_top_load_at, within_span, kWallFractionRule},
      {"--wall-lean", "", &P::wall_lean, small_movement, kLeanRule},
      {"--left-wall-lean", "", &P::left_wall_lean, small_movement, kLeanRule},
      {"--right-wall-lean", "", &P::right_wall_lean, small_movement, kLeanRule},
  };
}

void add_scene_options(CLI::App& cmd, SceneOptions& o) {
  cmd.add_option("--curve", o.curve, "generator curve: " + curve_family_names())->capture_default_str();
  cmd.add_option("--curve-file", o.curve_file,
                 "with --curve points: CSV file with header x,y and the axis points in m, springing (y = 0) to crown; "
                 "with --curve whole-points: springing to springing (any heights); - reads it from standard input");
  for (Axis& a : o.axes) {
    const std::string units = units_taken(a.flag);
    cmd.add_option(a.flag, a.text,
                   fmt::format("{}; {}; a value, a list a,b,c or a range start:stop:count{}{}",
                               axis_meanings().at(a.flag), a.rule, units.empty() ? "" : ", each with a unit or not (" + units + ")",
                               a.text.empty() ? absent_default(a.flag) : ""))
        ->capture_default_str();
  }
  cmd.add_flag("--plane-strain", o.plane_strain, "plane strain: E / (1 - nu^2) for axial and bending stiffness");
  cmd.add_option("--supports", o.supports, "both springings: clamped or pinned")->capture_default_str();
  cmd.add_option("--left-support", o.left_support, "left springing: clamped or pinned (default: --supports)");
  cmd.add_option("--right-support", o.right_support, "right springing: clamped or pinned (default: --supports)");
  cmd.add_option("--section", o.section,
                 "elastic (linear) or no-tension (cracks where the resultant leaves the kern; Newton on explicit forces "
                 "by quadrature, or shooting; a sweep of support movements is traced in order)")
      ->capture_default_str();
  cmd.add_option("--beam-model", o.beam_model,
                 "the beam theory: euler-bernoulli (no shear strain), timoshenko (shear strain V / (k G A), the "
                 "paper's), curved (a thick curved bar: plane elasticity's section law, each slice's weight at "
                 "its centroid; the elastic section) or auto (the least of the three whose model error estimate "
                 "is within --model-tolerance)")
      ->capture_default_str();
  cmd.add_option("--model-tolerance", o.model_tolerance,
                 "the relative error of H/V the beam model may make against the two-dimensional arch, in (0, 1): "
                 "rows whose model_error_estimate exceeds it are tolerance_not_met (default: none; 0.01 with "
                 "--beam-model auto)");
  cmd.add_option("--dimensions", o.dimensions,
                 "what --span and --rise measure: axis (the axis' span and rise) or intrados (the clear span between "
                 "the intrados' springing points and the intrados' rise from them to the crown's vertical, with "
                 "--thickness in m; the rows print the axis' span and rise)")
      ->capture_default_str();
  cmd.add_flag("--crown-hinge", o.crown_hinge,
               "a hinge at the crown (M = 0): the three-hinged arch with --supports pinned");
  cmd.add_option("--loads-file", o.loads_file,
                 "CSV of loads, header kind,value,a,b: point,P,a, | live,q,a,b | fill,rho_f,h_f/L, (docs/file-formats.md)");
}

}  // namespace ogive::cli
