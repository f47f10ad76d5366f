// The scene options every subcommand takes (curve, geometry, material, loads, supports, section).
// Every numeric one takes a value, a list or a range (values.hpp); a sweep's scenes are their product
// (scene_plan.hpp). The options are bound straight into SceneOptions.
#pragma once

#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ogive/geometry/curve.hpp"
#include "ogive/model/scene.hpp"

namespace CLI {
class App;
}

namespace ogive::cli {

// The largest movement of a springing the scene options take: its spread and settlement over the span,
// its rotation in rad (beyond, small-displacement theory does not hold).
inline constexpr double kLargestMovement = 0.01;

// One scene of a sweep, as its row prints it (NaN: not given, or not a parameter of the curve).
struct SceneParameters {
  std::size_t scene = 0;  // 1-based number in the sweep
  std::string curve;
  double eccentricity, rise_ratio, haunch_angle, crown_angle;
  double span, thickness_ratio, support_displacement_ratio;
  // The metre forms of the ratios above and below (m), as given or derived from the ratio; radius: the
  // pointed arch's.
  double thickness, rise, radius, fill_height, point_load_x, live_load_from_x, live_load_to_x;
  double force_unit = 1;  // N per unit of point_load and live_load, as given (--units: 1 or 1000)
  double youngs_modulus, poisson_ratio, density, gravity, shear_coefficient;
  double unit_weight;  // N/m^3, --unit-weight as given (NaN: --density gave the density)
  bool plane_strain;
  double point_load, point_load_at, live_load, live_load_from, live_load_to, fill_density, fill_height_ratio;
  double horizontal_acceleration;
  double left_spread_ratio, right_spread_ratio, left_settlement_ratio, right_settlement_ratio, left_rotation,
      right_rotation;
  // The walls (--wall-...: both; --left-wall-..., --right-wall-...: one side, over the first). The
  // left_ and right_ fields are each wall's as built (NaN height: no wall on that side).
  double wall_height, wall_thickness, wall_density, wall_top_load, wall_top_load_at;
  double left_wall_height, left_wall_thickness, left_wall_density, left_wall_top_load, left_wall_top_load_at;
  double right_wall_height, right_wall_thickness, right_wall_density, right_wall_top_load, right_wall_top_load_at;
  // The walls' lean (rad, outwards positive; wall_lean_movement): --wall-lean as given, and each wall's
  // as built (0 unless given; NaN: no wall on that side).
  double wall_lean, left_wall_lean, right_wall_lean;
  const char* left_support = "clamped";
  const char* right_support = "clamped";
  const char* section = "elastic";
  bool crown_hinge = false;
  std::string loads_file;
};

// A numeric scene option: its flag, its text as given ("" = the curve family's default), the rule
// its values must meet, and (once planned) its values.
struct Axis {
  std::string flag;
  std::string text;
  double SceneParameters::*field;
  std::function<bool(double)> allowed;
  std::string rule;
  std::vector<double> values{};
};

// Which parameters a generator curve takes, and its defaults (see ogive/geometry/curve_families.hpp).
struct CurveFamily {
  std::string_view name;
  bool eccentricity = false, rise = false, haunch = false, crown = false, file = false;
  const char* default_rise = "";
  const char* default_haunch = "";
  const char* default_crown = "";
};

std::span<const CurveFamily> curve_families();
std::string curve_family_names();  // "pointed, semicircular, ..."

// Every numeric scene option in the order of --help; the last varies fastest in the output.
std::vector<Axis> scene_axes();

struct SceneOptions {
  std::string curve = "pointed";
  std::string curve_file;
  bool plane_strain = false;
  std::shared_ptr<const Curve> points;  // read once from curve_file
  std::string supports = "clamped", left_support, right_support;
  std::string section = "elastic";
  std::string beam_model = "timoshenko";
  double model_tolerance = std::numeric_limits<double>::quiet_NaN();  // --model-tolerance; NaN: not given
  std::string dimensions = "axis";  // --dimensions: axis, or intrados (--span and --rise the intrados')
  bool crown_hinge = false;
  std::string loads_file;
  Loads file_loads;  // read once from loads_file
  std::vector<Axis> axes = scene_axes();
};

void add_scene_options(CLI::App& cmd, SceneOptions& o);

}  // namespace ogive::cli
