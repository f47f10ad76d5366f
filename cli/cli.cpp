#include "cli.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "ogive/closed_form.hpp"
#include "ogive/curve_families.hpp"
#include "ogive/csv.hpp"
#include "ogive/solve.hpp"
#include "values.hpp"

namespace ogive::cli {
namespace {

// ---------------------------------------------------------------------------------------------
// Scene options: every numeric one takes a value, a list or a range; the scenes are their product.

struct SceneParameters {
  std::string curve;
  double eccentricity, rise_ratio, haunch_angle, crown_angle;
  double span, thickness_ratio, support_displacement_ratio;
  double youngs_modulus, poisson_ratio, density, gravity, shear_coefficient;
  bool plane_strain;
};

// A numeric scene option: its flag, its text as given ("" = the curve family's default), the rule
// its values must meet.
struct Axis {
  std::string flag;
  std::string text;
  double SceneParameters::*field;
  std::function<bool(double)> allowed;
  std::string rule;
  std::vector<double> values{};
};

bool positive(double v) { return v > 0; }

// Which parameters each generator curve takes, and its defaults (see include/ogive/curve_families.hpp).
struct CurveFamily {
  std::string name;
  bool eccentricity = false, rise = false, haunch = false, crown = false, file = false;
  const char* default_rise = "";
  const char* default_haunch = "";
  const char* default_crown = "";
};

const std::vector<CurveFamily> kFamilies = {
    {"pointed", true},
    {"semicircular"},
    {"segmental", false, true, false, false, false, "0.25"},
    {"three-centred", false, true, true, false, false, "0.3333333333333333", "60"},
    {"four-centred", false, true, true, true, false, "0.42", "45", "15"},
    {"elliptical", false, true, false, false, false, "0.5"},
    {"parabolic", false, true, false, false, false, "0.5"},
    {"catenary", false, true, false, false, false, "0.5"},
    {"points", false, false, false, false, true},
};

struct SceneOptions {
  std::string curve = "pointed";
  std::string curve_file;
  bool plane_strain = false;
  std::shared_ptr<const Curve> points;  // read once from curve_file
  std::vector<Axis> axes{
      // Order: the last axis varies fastest in the output.
      {"--span", "10", &SceneParameters::span, positive, "must be > 0 (m)"},
      {"--youngs-modulus", "14.8e9", &SceneParameters::youngs_modulus, positive, "must be > 0 (Pa)"},
      {"--poisson-ratio", "0.2", &SceneParameters::poisson_ratio,
       [](double v) { return v > -1 && v <= 0.5; }, "must lie in (-1, 0.5]"},
      {"--density", "2348", &SceneParameters::density, positive, "must be > 0 (kg/m^3)"},
      {"--gravity", "9.81", &SceneParameters::gravity, positive, "must be > 0 (m/s^2)"},
      {"--shear-coefficient", "0.8333333333333334", &SceneParameters::shear_coefficient,
       [](double v) { return v > 0 && v <= 2; }, "must lie in (0, 2]"},
      {"--thickness-ratio", "0.08", &SceneParameters::thickness_ratio,
       [](double v) { return v > 0 && v < 1; }, "must lie in (0, 1) (t/L)"},
      {"--support-displacement-ratio", "0", &SceneParameters::support_displacement_ratio,
       [](double v) { return std::abs(v) <= 0.01; },
       "must lie in [-0.01, 0.01] (d/L; beyond, small-displacement theory does not hold)"},
      {"--haunch-angle", "", &SceneParameters::haunch_angle, [](double v) { return v > 0 && v < 90; },
       "must lie in (0, 90) degrees"},
      {"--crown-angle", "", &SceneParameters::crown_angle, [](double v) { return v > 0 && v < 90; },
       "must lie in (0, 90) degrees"},
      {"--rise-ratio", "", &SceneParameters::rise_ratio, [](double v) { return v > 0 && v <= 2; },
       "must lie in (0, 2] (h/L)"},
      {"--eccentricity", "0", &SceneParameters::eccentricity, [](double v) { return v >= 0 && v <= 100; },
       "must lie in [0, 100]"},
  };
};

void add_scene_options(CLI::App& cmd, SceneOptions& o) {
  std::string names;
  for (const CurveFamily& f : kFamilies) names += (names.empty() ? "" : ", ") + f.name;
  cmd.add_option("--curve", o.curve, "generator curve: " + names)->capture_default_str();
  cmd.add_option("--curve-file", o.curve_file, "with --curve points: CSV of axis points x,y, springing to crown");
  for (Axis& a : o.axes)
    cmd.add_option(a.flag, a.text, "value, list a,b,c or range start:stop:count" +
                                       std::string(a.text.empty() ? " (default: the curve's)" : ""))
        ->capture_default_str();
  cmd.add_flag("--plane-strain", o.plane_strain, "plane strain: E / (1 - nu^2) for axial and bending stiffness");
}

// "rise_ratio: rule" from the library becomes "--rise-ratio: rule".
std::string as_option_message(const std::string& what) {
  const std::size_t colon = what.find(':');
  if (colon == std::string::npos || what.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") < colon) return what;
  std::string flag = "--" + what.substr(0, colon);
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag + what.substr(colon);
}

std::vector<SceneParameters> scene_grid(SceneOptions& o, const CLI::App& cmd) {
  const auto family = std::find_if(kFamilies.begin(), kFamilies.end(), [&](const CurveFamily& f) { return f.name == o.curve; });
  if (family == kFamilies.end()) {
    std::string names;
    for (const CurveFamily& f : kFamilies) names += (names.empty() ? "" : ", ") + f.name;
    throw UsageError(fmt::format("--curve: unknown curve '{}' (known: {})", o.curve, names));
  }
  auto refuse_unless = [&](bool applies, const char* flag) {
    if (!applies && cmd.count(flag) > 0) throw UsageError(fmt::format("{}: does not apply to --curve {}", flag, o.curve));
  };
  refuse_unless(family->eccentricity, "--eccentricity");
  refuse_unless(family->rise, "--rise-ratio");
  refuse_unless(family->haunch, "--haunch-angle");
  refuse_unless(family->crown, "--crown-angle");
  refuse_unless(family->file, "--curve-file");
  refuse_unless(!family->file, "--span");  // a points file sets its own span
  if (family->file) {
    if (o.curve_file.empty()) throw UsageError("--curve-file: --curve points needs a file of axis points");
    try {
      o.points = read_points_curve(o.curve_file);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
  }
  std::size_t total = 1;
  for (Axis& a : o.axes) {
    std::string text = a.text;
    const bool given = cmd.count(a.flag) > 0;  // given text is parsed as it stands, even if empty
    if (!given && text.empty()) {
      if (a.flag == "--rise-ratio") text = family->default_rise;
      if (a.flag == "--haunch-angle") text = family->default_haunch;
      if (a.flag == "--crown-angle") text = family->default_crown;
    }
    if (family->file && a.flag == "--span") text = fmt::format("{}", o.points->span());
    // Not a parameter of this curve: one NaN, printed as an empty field.
    const bool absent = !given && text.empty();
    a.values = absent ? std::vector<double>{std::numeric_limits<double>::quiet_NaN()} : parse_values(text, a.flag);
    for (double v : a.values)
      if (!std::isnan(v) && !a.allowed(v)) throw UsageError(fmt::format("{}: {}, got {}", a.flag, a.rule, v));
    total *= a.values.size();
    if (total > kMaxValues)
      throw UsageError(fmt::format("{}: the options give more than {} scenes", a.flag, kMaxValues));
  }
  std::vector<SceneParameters> grid;
  grid.reserve(total);
  std::vector<std::size_t> index(o.axes.size(), 0);
  for (std::size_t n = 0; n < total; ++n) {
    SceneParameters p{o.curve, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, o.plane_strain};
    for (std::size_t i = 0; i < o.axes.size(); ++i) p.*(o.axes[i].field) = o.axes[i].values[index[i]];
    if (!family->eccentricity) p.eccentricity = std::numeric_limits<double>::quiet_NaN();
    grid.push_back(p);
    for (std::size_t i = o.axes.size(); i-- > 0;) {  // odometer: the last axis turns fastest
      if (++index[i] < o.axes[i].values.size()) break;
      index[i] = 0;
    }
  }
  return grid;
}

std::shared_ptr<const Curve> make_curve(const SceneParameters& p, const SceneOptions& o) {
  const std::string& c = p.curve;
  if (c == "pointed") return make_pointed(p.span, p.eccentricity);
  if (c == "semicircular") return make_pointed(p.span, 0.0);
  if (c == "segmental") return make_segmental(p.span, p.rise_ratio);
  if (c == "three-centred") return make_three_centred(p.span, p.rise_ratio, p.haunch_angle);
  if (c == "four-centred") return make_four_centred(p.span, p.rise_ratio, p.haunch_angle, p.crown_angle);
  if (c == "elliptical") return make_elliptical(p.span, p.rise_ratio);
  if (c == "parabolic") return make_parabolic(p.span, p.rise_ratio);
  if (c == "catenary") return make_catenary(p.span, p.rise_ratio);
  return o.points;
}

// Builds and validates every scene before anything is solved or printed.
std::vector<Scene> make_scenes(const std::vector<SceneParameters>& grid, const SceneOptions& o) {
  std::vector<Scene> scenes;
  scenes.reserve(grid.size());
  for (const SceneParameters& p : grid) {
    Scene scene;
    try {
      scene.curve = make_curve(p, o);
    } catch (const std::invalid_argument& e) {
      throw UsageError(as_option_message(e.what()));
    }
    scene.thickness = p.thickness_ratio * p.span;
    scene.support_displacement = p.support_displacement_ratio * p.span;
    scene.material = {p.youngs_modulus, p.poisson_ratio, p.density, p.gravity, p.shear_coefficient, p.plane_strain};
    try {
      scene.validate();
    } catch (const std::invalid_argument& e) {
      throw UsageError(fmt::format("--thickness-ratio {} with --curve {}: {}", p.thickness_ratio, p.curve, e.what()));
    }
    scenes.push_back(std::move(scene));
  }
  return scenes;
}

const char* kSceneHeader =
    "curve,eccentricity,rise_ratio,haunch_angle,crown_angle,span,thickness_ratio,support_displacement_ratio,"
    "youngs_modulus,poisson_ratio,density,gravity,shear_coefficient,plane_strain";

// A parameter that does not apply to the scene's curve is an empty field, never "nan".
void add_parameter(CsvRow& row, double value) {
  if (std::isnan(value)) row.add(std::string_view{});
  else row.add(value);
}

void add_scene_columns(CsvRow& row, const SceneParameters& p, const Scene& scene) {
  row.add(p.curve);
  add_parameter(row, p.eccentricity);
  row.add(scene.curve->rise() / scene.span());  // the actual rise of every curve
  add_parameter(row, p.haunch_angle);
  add_parameter(row, p.crown_angle);
  row.add(p.span).add(p.thickness_ratio).add(p.support_displacement_ratio);
  row.add(p.youngs_modulus).add(p.poisson_ratio).add(p.density).add(p.gravity).add(p.shear_coefficient);
  row.add(p.plane_strain ? "1" : "0");
}

// ---------------------------------------------------------------------------------------------
// Solver options, bound straight into ogive::Options.

const std::map<std::string, Method> kMethods = {{"closed-form", Method::closed_form},
                                                {"shooting", Method::shooting},
                                                {"multiple-shooting", Method::multiple_shooting},
                                                {"quadrature", Method::quadrature},
                                                {"auto", Method::automatic}};
const std::map<std::string, Integrator> kIntegrators = {{"adams", Integrator::adams}, {"bdf", Integrator::bdf}};

// Method and integrator are bound as text and mapped here, so that only their names are accepted.
struct SolverText {
  std::string method = "auto";
  std::string integrator = "adams";
  bool no_verify = false;
  bool ignore_breakpoints = false;
};

// CLI11 would read "" as 0 and saturate huge integers; numeric options must be what parse_number
// accepts (the whole text, finite), and counts whole numbers within what an int holds.
// What is wrong with an option's text as a number (empty if nothing): not what parse_number accepts,
// or, for counts, not a whole number up to 1e9.
std::string number_problem(const std::string& text, bool count) {
  double v = 0;
  try {
    v = parse_number(text, "");
  } catch (const UsageError&) {
    return "'" + text.substr(0, 60) + "' is not a finite number";
  }
  if (count && (v != std::floor(v) || std::abs(v) > 1e9))
    return "'" + text.substr(0, 60) + "' is not a whole number up to 1e9";
  return {};
}
const CLI::Validator kFiniteNumber([](std::string& text) { return number_problem(text, false); }, "NUMBER");
const CLI::Validator kCount([](std::string& text) { return number_problem(text, true); }, "COUNT");

// bench takes lists of methods and integrators instead (--methods, --integrators).
void add_solver_options(CLI::App& cmd, Options& o, SolverText& text, bool with_method = true,
                        bool with_integrator = true) {
  if (with_method)
    cmd.add_option("--method", text.method, "closed-form, quadrature, shooting, multiple-shooting or auto")->capture_default_str();
  if (with_integrator)
    cmd.add_option("--integrator", text.integrator, "CVODE's method: adams or bdf")->capture_default_str();
  cmd.add_option("--rtol", o.rtol, "accuracy asked of the result, 1e-14 .. 0.1")->check(kFiniteNumber)->capture_default_str();
  cmd.add_option("--atol", o.atol, "CVODE's absolute tolerance on the scaled state (0: 1e-6 of CVODE's rtol)")
      ->check(kFiniteNumber)->capture_default_str();
  cmd.add_option("--segments", o.segments, "multiple-shooting segments over the half arch")->check(kCount)->capture_default_str();
  cmd.add_option("--max-steps", o.max_steps, "CVODE step limit per integration span")->check(kCount)->capture_default_str();
  cmd.add_flag("--no-verify", text.no_verify,
               "skip the second solve at rtol/16 that estimates the error (raw methods, for benchmarks)");
  cmd.add_flag("--ignore-breakpoints", text.ignore_breakpoints,
               "let CVODE step across jumps of curvature (for stability studies)");
}

template <class Enum>
Enum lookup(const std::map<std::string, Enum>& names, const std::string& text, const char* flag) {
  const auto it = names.find(text);
  if (it != names.end()) return it->second;
  std::string known;
  for (const auto& [name, value] : names) known += (known.empty() ? "" : ", ") + name;
  throw UsageError(fmt::format("{}: unknown value '{}' (known: {})", flag, text, known));
}

void apply_solver_text(Options& o, const SolverText& text) {
  o.method = lookup(kMethods, text.method, "--method");
  o.integrator = lookup(kIntegrators, text.integrator, "--integrator");
  o.verify = !text.no_verify;
  o.restart_at_breakpoints = !text.ignore_breakpoints;
}

void check_options(const Options& o) {
  std::string why;
  if (!o.is_valid(&why)) throw UsageError(as_option_message(why));
}

const char* kSolutionHeader =
    "method,integrator,rtol,status,H,V,H_over_V,steps,rhs_evaluations,segments,condition_estimate,"
    "error_estimate,boundary_residual,equilibrium_residual";

void add_solution_columns(CsvRow& row, const Solution& sol, const Options& o) {
  const bool numeric = sol.method != Method::closed_form && sol.method != Method::quadrature;  // no integrator
  row.add(to_string(sol.method)).add(numeric ? to_string(o.integrator) : "none").add(o.rtol);
  row.add(to_string(sol.status)).add(sol.H).add(sol.V).add(sol.H_over_V);
  const Diagnostics& d = sol.diagnostics;
  row.add(d.steps).add(d.rhs_evaluations).add(d.segments).add(d.condition_estimate).add(d.error_estimate);
  row.add(d.boundary_residual).add(d.equilibrium_residual);
}

// ---------------------------------------------------------------------------------------------
// Subcommands.

// Commands that print rows along the arch: at least two stations, at most 10^7 rows in all.
void check_stations(int stations) {
  if (stations < 2 || stations > 1000000)
    throw UsageError(fmt::format("--stations: must lie in [2, 1000000], got {}", stations));
}

void check_rows(std::size_t scenes, int stations) {
  if (scenes * static_cast<std::size_t>(stations) > 10 * kMaxValues)
    throw UsageError(fmt::format("--stations: {} scenes x {} stations exceed {} rows", scenes, stations, 10 * kMaxValues));
}

int run_thrust(SceneOptions& so, const CLI::App& cmd, const Options& o, std::ostream& out) {
  check_options(o);
  const std::vector<SceneParameters> grid = scene_grid(so, cmd);
  const std::vector<Scene> scenes = make_scenes(grid, so);
  std::string text = std::string(kSceneHeader) + "," + kSolutionHeader + "\n";
  CsvRow row;
  bool all_ok = true;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const Solution sol = solve(scenes[i], o);
    all_ok = all_ok && sol.ok();
    add_scene_columns(row, grid[i], scenes[i]);
    add_solution_columns(row, sol, o);
    text += row.take();
  }
  out << text;
  return all_ok ? kExitOk : kExitNotConverged;
}

// What the station's numbers mean for masonry, which resists no tension: the normal force is tensile
// (or zero, and e undefined), or the compression's resultant lies outside the section (|e| > 300 %: a
// hinge would form, beyond the linear model) or outside the kern (|e| > 100 %: the elastic section is
// partly in tension).
std::string_view section_warning(const ArchState& st) {
  if (st.N == 0) return "no_normal_force";
  if (st.N > 0) return "tension";
  if (std::abs(st.e) > 300) return "outside_section";
  if (std::abs(st.e) > 100) return "outside_kern";
  return "";
}

int run_profile(SceneOptions& so, const CLI::App& cmd, Options o, std::ostream& out) {
  check_stations(o.stations);
  check_options(o);
  const std::vector<SceneParameters> grid = scene_grid(so, cmd);
  check_rows(grid.size(), o.stations);
  const std::vector<Scene> scenes = make_scenes(grid, so);
  std::string text = std::string(kSceneHeader) +
                     ",method,status,H_over_V,error_estimate,s,x,y,theta,Ux,Uy,psi,N,V,M,e,thrust_x,thrust_y,"
                     "warning\n";
  CsvRow row;
  bool all_ok = true;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const Solution sol = solve(scenes[i], o);
    all_ok = all_ok && sol.ok();
    if (sol.profile.empty()) {  // unsolved: one row that says so, no numbers
      add_scene_columns(row, grid[i], scenes[i]);
      row.add(to_string(sol.method)).add(to_string(sol.status)).add(sol.H_over_V).add(sol.diagnostics.error_estimate);
      for (int k = 0; k < 14; ++k) row.add(std::numeric_limits<double>::quiet_NaN());
      text += row.take();
      continue;
    }
    for (const ArchState& st : sol.profile) {
      add_scene_columns(row, grid[i], scenes[i]);
      row.add(to_string(sol.method)).add(to_string(sol.status)).add(sol.H_over_V).add(sol.diagnostics.error_estimate);
      row.add(st.s).add(st.x).add(st.y).add(st.theta).add(st.Ux).add(st.Uy).add(st.psi);
      row.add(st.N).add(st.V).add(st.M).add(st.e).add(st.thrust_x).add(st.thrust_y).add(section_warning(st));
      text += row.take();
    }
  }
  out << text;
  return all_ok ? kExitOk : kExitNotConverged;
}

// The reference a scene's H/V is checked against: the closed form where it applies; otherwise
// multiple shooting far tighter than anything checked against it (rtol 1e-12, 32 segments), whose
// own error the tests bound by comparing it with the closed form on circular arcs.
Solution reference_solution(const Scene& scene, Options o) {
  if (!scene.curve->arcs().empty()) {
    o.method = Method::closed_form;
  } else {
    o.method = Method::multiple_shooting;
    o.integrator = Integrator::adams;
    o.rtol = 1e-12;
    o.segments = 32;
    o.verify = true;
    o.restart_at_breakpoints = true;
  }
  return solve(scene, o);
}

// The reference's own error: its verification estimate (CVODE) or, for either method, the condition
// estimate times round-off, whichever is larger. A reference that is not even ill-conditioned but
// failed has no error to state: NaN.
double reference_error(const Solution& ref) {
  if (!ref.field) return std::numeric_limits<double>::quiet_NaN();
  const double conditioning = ref.diagnostics.condition_estimate * std::numeric_limits<double>::epsilon();
  const double estimate = ref.diagnostics.error_estimate;
  return std::isnan(estimate) ? conditioning : std::max(estimate, conditioning);
}

// Every applicable method on every scene, against the reference.
int run_check(SceneOptions& so, const CLI::App& cmd, const Options& base, std::ostream& out) {
  check_options(base);
  const std::vector<SceneParameters> grid = scene_grid(so, cmd);
  const std::vector<Scene> scenes = make_scenes(grid, so);
  std::string text = std::string(kSceneHeader) +
                     ",method,integrator,rtol,segments,status,H_over_V,reference_method,reference_H_over_V,"
                     "relative_difference,tolerance,within_tolerance\n";
  CsvRow row;
  bool all_ok = true;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const Solution reference = reference_solution(scenes[i], base);
    const std::string reference_method = reference.method == Method::closed_form
                                             ? "closed-form"
                                             : "multiple-shooting rtol 1e-12";
    for (Method m : {Method::closed_form, Method::shooting, Method::multiple_shooting}) {
      if (m == Method::closed_form && scenes[i].curve->arcs().empty()) continue;  // not applicable
      Options o = base;
      o.method = m;
      const Solution sol = solve(scenes[i], o);
      const double diff = std::abs(sol.H_over_V - reference.H_over_V) / std::abs(reference.H_over_V);
      const double tolerance = 10.0 * o.rtol;
      const bool within = sol.ok() && reference.ok() && diff <= tolerance;
      all_ok = all_ok && within;
      add_scene_columns(row, grid[i], scenes[i]);
      row.add(to_string(sol.method)).add(m == Method::closed_form ? "none" : to_string(o.integrator)).add(o.rtol);
      row.add(sol.diagnostics.segments).add(to_string(sol.status)).add(sol.H_over_V).add(reference_method);
      row.add(reference.H_over_V).add(diff).add(tolerance).add(within ? "yes" : "no");
      text += row.take();
    }
  }
  out << text;
  return all_ok ? kExitOk : kExitNotConverged;
}

// The geometry: s, x, y, theta, kappa at equally spaced stations over the whole arch.
int run_curve(SceneOptions& so, const CLI::App& cmd, int stations, std::ostream& out) {
  check_stations(stations);
  const std::vector<SceneParameters> grid = scene_grid(so, cmd);
  check_rows(grid.size(), stations);
  const std::vector<Scene> scenes = make_scenes(grid, so);
  std::string text = std::string(kSceneHeader) + ",s,x,y,theta,kappa\n";
  CsvRow row;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const Curve& curve = *scenes[i].curve;
    const double S = curve.half_length();
    for (int k = 0; k < stations; ++k) {
      const double s = 2.0 * S * k / (stations - 1);
      const CurvePoint p = curve.at_whole_arch(s);
      add_scene_columns(row, grid[i], scenes[i]);
      row.add(s).add(p.x).add(p.y).add(p.theta).add(p.kappa);
      text += row.take();
    }
  }
  out << text;
  return kExitOk;
}

constexpr int kProfileStations = 41;

// Time per solve (median over repeats) and true error against the reference, one row per method,
// integrator and rtol. Failed runs stay in the table with their status.
int run_bench(SceneOptions& so, const CLI::App& cmd, const Options& base, const std::string& methods_text,
              const std::string& integrators_text, const std::string& rtols_text, int repeats, std::ostream& out) {
  check_options(base);
  if (repeats < 1 || repeats > 100000) throw UsageError(fmt::format("--repeats: must lie in [1, 100000], got {}", repeats));
  auto split = [](const std::string& text) {
    std::vector<std::string> names;
    for (std::size_t pos = 0; pos <= text.size();) {
      const std::size_t comma = std::min(text.find(',', pos), text.size());
      names.push_back(text.substr(pos, comma - pos));
      pos = comma + 1;
    }
    return names;
  };
  std::vector<Method> methods;
  for (const std::string& name : split(methods_text)) methods.push_back(lookup(kMethods, name, "--methods"));
  std::vector<Integrator> integrators;
  for (const std::string& name : split(integrators_text))
    integrators.push_back(lookup(kIntegrators, name, "--integrators"));
  const std::vector<double> rtols = parse_values(rtols_text, "--rtols");
  for (double r : rtols)
    if (!(r >= 1e-14 && r <= 0.1)) throw UsageError(fmt::format("--rtols: must lie in [1e-14, 0.1], got {}", r));
  const std::vector<SceneParameters> grid = scene_grid(so, cmd);
  if (grid.size() * methods.size() * integrators.size() * rtols.size() > kMaxValues)
    throw UsageError(fmt::format("--rtols: {} scenes x {} methods x {} integrators x {} tolerances exceed {} rows",
                                 grid.size(), methods.size(), integrators.size(), rtols.size(), kMaxValues));
  const std::vector<Scene> scenes = make_scenes(grid, so);
  std::string text = std::string(kSceneHeader) +
                     ",method,integrator,rtol,segments,status,chosen_method,H_over_V,error_H_over_V,error_profile,"
                     "error_estimate,reference_error,median_seconds,steps,rhs_evaluations,condition_estimate\n";
  CsvRow row;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    Options ref_options = base;
    ref_options.stations = kProfileStations;
    const Solution reference = reference_solution(scenes[i], ref_options);
    for (Method m : methods) {
      const bool circular = !scenes[i].curve->arcs().empty();
      if (m == Method::closed_form && !circular) continue;  // not applicable
      // The closed form has neither integrator nor tolerance; auto on a circular arc is the closed form.
      const bool exact = m == Method::closed_form || (m == Method::automatic && circular);
      for (Integrator integrator : integrators) {
        if (exact && integrator != integrators.front()) continue;
        for (double rtol : rtols) {
          if (exact && rtol != rtols.front()) continue;
          Options o = base;
          o.method = m;
          o.integrator = integrator;
          o.rtol = rtol;
          std::vector<double> seconds;
          Solution sol;
          for (int r = 0; r < repeats; ++r) {
            const auto t0 = std::chrono::steady_clock::now();
            sol = solve(scenes[i], o);
            seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
          }
          std::nth_element(seconds.begin(), seconds.begin() + repeats / 2, seconds.end());
          // The profile's error, outside the timing, from the same solve with stations.
          Options profiled = o;
          profiled.stations = kProfileStations;
          const Solution with_profile = solve(scenes[i], profiled);
          // The row's status is the worse of the two solves: a profile that missed its tolerance says so.
          const Status status = sol.ok() ? with_profile.status : sol.status;
          const double estimate = std::max(sol.diagnostics.error_estimate, with_profile.diagnostics.error_estimate);
          add_scene_columns(row, grid[i], scenes[i]);
          row.add(to_string(m)).add(exact ? "none" : to_string(o.integrator));
          row.add(exact ? 0.0 : rtol).add(sol.diagnostics.segments).add(to_string(status));
          row.add(to_string(sol.method));
          row.add(sol.H_over_V).add(std::abs(sol.H_over_V - reference.H_over_V) / std::abs(reference.H_over_V));
          row.add(profile_difference(with_profile.profile, reference.profile, scenes[i].thickness)).add(estimate);
          row.add(reference_error(reference));
          row.add(seconds[repeats / 2]).add(sol.diagnostics.steps).add(sol.diagnostics.rhs_evaluations);
          row.add(sol.diagnostics.condition_estimate);
          text += row.take();
        }
      }
    }
  }
  out << text;
  return kExitOk;
}

}  // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"ogive: thrust and line of thrust of arches and barrel vaults (CSV on stdout)", "ogive"};
  app.require_subcommand(1);
  SceneOptions thrust_scene, profile_scene, check_scene, bench_scene;
  Options thrust_options, profile_options, check_options_, bench_options;
  SolverText thrust_text, profile_text, check_text, bench_text;
  profile_options.stations = 101;

  CLI::App* thrust = app.add_subcommand("thrust", "reactions H, V and H/V: one row per scene");
  add_scene_options(*thrust, thrust_scene);
  add_solver_options(*thrust, thrust_options, thrust_text);

  CLI::App* profile = app.add_subcommand("profile", "N, V, M, e and the thrust line along the arch");
  add_scene_options(*profile, profile_scene);
  add_solver_options(*profile, profile_options, profile_text);
  profile->add_option("--stations", profile_options.stations, "stations, springing to springing (>= 2)")
      ->check(kCount)
      ->capture_default_str();

  CLI::App* check = app.add_subcommand("check", "every method's H/V against the closed form");
  add_scene_options(*check, check_scene);
  add_solver_options(*check, check_options_, check_text, false);

  SceneOptions curve_scene;
  int curve_stations = 101;
  CLI::App* curve = app.add_subcommand("curve", "the generator curve: s, x, y, theta, kappa");
  add_scene_options(*curve, curve_scene);
  curve->add_option("--stations", curve_stations, "stations, springing to springing (>= 2)")->check(kCount)->capture_default_str();

  CLI::App* bench = app.add_subcommand("bench", "median time per solve and true error, per method and rtol");
  add_scene_options(*bench, bench_scene);
  add_solver_options(*bench, bench_options, bench_text, false, false);
  std::string bench_methods = "closed-form,shooting,multiple-shooting", bench_rtols = "1e-6,1e-8,1e-10";
  std::string bench_integrators = "adams";
  int repeats = 21;
  bench->add_option("--methods", bench_methods, "comma-separated methods (auto included)")->capture_default_str();
  bench->add_option("--integrators", bench_integrators, "comma-separated: adams, bdf")->capture_default_str();
  bench->add_option("--rtols", bench_rtols, "tolerances: list or range")->capture_default_str();
  bench->add_option("--repeats", repeats, "solves per row; the median time is printed")->check(kCount)->capture_default_str();

  std::vector<const char*> argv{"ogive"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e, out, err);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e, out, err);
  } catch (const CLI::ParseError& e) {
    std::string what = e.what();
    std::replace(what.begin(), what.end(), '\n', ' ');
    err << "ogive: " << what << "\n";
    return kExitUsage;
  }
  try {
    apply_solver_text(thrust_options, thrust_text);
    apply_solver_text(profile_options, profile_text);
    apply_solver_text(check_options_, check_text);
    apply_solver_text(bench_options, bench_text);
    if (thrust->parsed()) return run_thrust(thrust_scene, *thrust, thrust_options, out);
    if (profile->parsed()) return run_profile(profile_scene, *profile, profile_options, out);
    if (check->parsed()) return run_check(check_scene, *check, check_options_, out);
    if (curve->parsed()) return run_curve(curve_scene, *curve, curve_stations, out);
    if (bench->parsed()) return run_bench(bench_scene, *bench, bench_options, bench_methods, bench_integrators, bench_rtols,
                                            repeats, out);
  } catch (const UsageError& e) {
    err << "ogive: " << e.what() << "\n";
    return kExitUsage;
  } catch (const std::invalid_argument& e) {
    err << "ogive: " << e.what() << "\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    err << "ogive: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return kExitUsage;
}

}  // namespace ogive::cli
