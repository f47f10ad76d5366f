// ogive thrust: the reactions H, V and H/V, one row per scene and solver combination.
#include <cmath>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli.hpp"
#include "columns.hpp"
#include "ogive/core/wall_resultant.hpp"
#include "option_text.hpp"
#include "commands.hpp"
#include "limit_text.hpp"
#include "ogive/core/thrust_line.hpp"
#include "ogive/solve/solve.hpp"
#include "row_writer.hpp"
#include "scene_options.hpp"
#include "scene_plan.hpp"
#include "solver_options.hpp"
#include "sweep.hpp"

namespace ogive::cli {
namespace {

struct ThrustOptions {
  SceneOptions scene;
  Options solver;
  SolverText solver_text;
  ColumnText columns;
  std::string compressive_strength;  // --compressive-strength as given (max_stress_ratio)
  int threads = 1;
};

// The walls' columns (wall_resultant.hpp), each side's: printed by default when walls are given.
const std::vector<std::string> kWallColumns = {
    "left_wall_crossings",  "left_wall_base_eccentricity",  "left_wall_stability_ratio",  "left_wall_geometric_factor",
    "right_wall_crossings", "right_wall_base_eccentricity", "right_wall_stability_ratio", "right_wall_geometric_factor"};
// The springing movements the walls' leans cause (wall_lean_movement): printed by default when a lean is
// given.
const std::vector<std::string> kLeanColumns = {"left_lean_spread_ratio",  "left_lean_settlement_ratio",
                                               "left_lean_rotation",      "right_lean_spread_ratio",
                                               "right_lean_settlement_ratio", "right_lean_rotation"};
// The beds at which the crossings column gives the resultant: this many equal parts of the wall.
constexpr int kWallCrossingParts = 4;

bool leans_given(const CLI::App& cmd) {
  return given(cmd, "--wall-lean") || given(cmd, "--left-wall-lean") || given(cmd, "--right-wall-lean");
}

Columns thrust_columns(bool walls, bool leans) {
  std::vector<std::string> all = {
      "method", "integrator", "rtol", "status", "domain", "H", "V", "H_over_V", "H_left", "V_left", "M_left",
      "H_right", "V_right", "M_right", "max_thrust_eccentricity", "max_thrust_eccentricity_at", "thrust_in_kern",
      "thrust_in_section", "max_compressive_stress", "max_compressive_stress_at", "max_stress_ratio", "steps", "rhs_evaluations", "segments", "newton_iterations", "condition_estimate",
      "error_estimate", "boundary_residual", "equilibrium_residual", "message", "beam_model", "model_error_estimate"};
  // The thrust line's and the stress's summaries are asked for by name (or --all-columns): each scans
  // the whole field, a few times the cost of the reactions in closed form, which a sweep of 10^6 scenes
  // would feel.
  std::vector<std::string> defaults = {"method", "status", "domain", "H", "V", "H_over_V", "H_left", "V_left", "M_left",
                                       "H_right", "V_right", "M_right", "error_estimate", "message"};
  all.insert(all.end(), kWallColumns.begin(), kWallColumns.end());
  if (walls) defaults.insert(defaults.end(), kWallColumns.begin(), kWallColumns.end());
  all.insert(all.end(), kLeanColumns.begin(), kLeanColumns.end());
  if (leans) defaults.insert(defaults.end(), kLeanColumns.begin(), kLeanColumns.end());
  return Columns(all, defaults);
}

// One springing's movement that its wall's lean causes, over the span (the rotation in rad): empty
// without a wall on that side.
void add_lean_columns(CsvRow& row, const SceneParameters& p, const Scene& scene, bool right) {
  const std::optional<Wall>& wall = right ? scene.right_wall : scene.left_wall;
  const double lean = right ? p.right_wall_lean : p.left_wall_lean;
  if (!wall || std::isnan(lean)) {
    for (int k = 0; k < 3; ++k) row.add(std::string_view{});
    return;
  }
  const Support& support = right ? scene.right : scene.left;
  const Support m = lean == 0 ? Support{support.kind, 0.0, 0.0, 0.0}
                              : wall_lean_movement(wall_outline(*scene.curve, scene.thickness, *wall, right), lean,
                                                   support.kind);
  row.add(m.spread / p.span).add(m.settlement / p.span).add(m.rotation);
}

// One wall's columns: its resultant's crossings as y/L:x/L at the beds, its base's eccentricity, its
// stability ratio and geometric factor (empty without that wall or without reactions).
void add_wall_columns(CsvRow& row, const Scene& scene, const Solution& sol, bool right) {
  if (!(right ? scene.right_wall : scene.left_wall) || !sol.field) {
    for (int k = 0; k < 4; ++k) row.add(std::string_view{});
    return;
  }
  const WallResultant w = wall_resultant(scene, sol.reactions, right, kWallCrossingParts);
  const double L = scene.span();
  std::string text;
  // Six digits, so a bed's height at the springing line is 0 however the round-off of its joint fell.
  auto shown = [&](double v) { return std::abs(v) < 1e-12 * L ? 0.0 : v / L; };
  for (const WallBedCrossing& b : w.beds)
    text += fmt::format("{}{:.6g}:{:.6g}", text.empty() ? "" : ";", shown(b.y), shown(b.x));
  row.add(text).add(w.base_eccentricity).add(w.stability_ratio).add(w.geometric_factor);
}

// "half" or "whole": the model a solution used (empty without one).
std::string_view domain_of(const Solution& sol) {
  if (!sol.model) return "";
  return sol.model->half() ? "half" : "whole";
}

// One scene's row for one solver combination.
std::string thrust_row(const Columns& columns, const SceneParameters& p, const Scene& scene, const Options& o,
                       const Solution& sol, bool summary, bool stresses, double compressive_strength) {
  const ThrustLineSummary line = summary ? summarize_thrust_line(sol) : ThrustLineSummary{};
  const StressSummary stress = stresses ? summarize_compressive_stress(sol) : StressSummary{};
  CsvRow row(columns.keep());
  add_scene_columns(row, p, scene.curve.get());
  row.add(to_string(sol.method)).add(integrator_of(sol.method, o)).add(o.rtol);
  row.add(to_string(sol.status)).add(domain_of(sol)).add(sol.H).add(sol.V).add(sol.H_over_V);
  const Reactions& r = sol.reactions;
  if (sol.field) row.add(r.H_left).add(r.V_left).add(r.M_left).add(r.H_right).add(r.V_right).add(r.M_right);
  else for (int k = 0; k < 6; ++k) row.add(std::string_view{});
  row.add(line.max_abs_e).add(line.max_abs_e_at);
  if (line.ok) row.add_bool(line.in_kern).add_bool(line.in_section);
  else row.add(std::string_view{}).add(std::string_view{});
  row.add(stress.max_compressive_stress).add(stress.max_compressive_stress_at);
  row.add(stress_ratio(stress.max_compressive_stress, compressive_strength));
  const Diagnostics& d = sol.diagnostics;
  row.add(d.steps).add(d.rhs_evaluations).add(d.segments).add(d.newton_iterations);
  row.add(d.condition_estimate).add(d.error_estimate);
  row.add(d.boundary_residual).add(d.equilibrium_residual).add(sol.message);
  row.add(sol.model ? to_string(sol.model->beam_model()) : "").add(d.model_error_estimate);
  add_wall_columns(row, scene, sol, false);
  add_wall_columns(row, scene, sol, true);
  add_lean_columns(row, p, scene, false);
  add_lean_columns(row, p, scene, true);
  return row.take();
}

int run_thrust(ThrustOptions& to, const CLI::App& cmd, std::ostream& out) {
  check_threads(to.threads);
  Columns columns = thrust_columns(walls_given(cmd), leans_given(cmd));
  if (to.columns.columns == "help") {
    write_all(out, columns.help(to.columns));
    return kExitOk;
  }
  SolverSweep sweep = solver_sweep(to.solver, to.solver_text);
  const ScenePlan plan(to.scene, cmd);
  std::vector<std::string> varying = plan.varying_inputs();
  if (plan.asks_model_error()) varying.insert(varying.end(), {"beam_model", "model_error_estimate"});
  columns.select(to.columns, varying, sweep.varying);
  for (Options& o : sweep.combinations) o.estimate_model_error = columns.selected("model_error_estimate");
  const bool summary = columns.selected("max_thrust_eccentricity") || columns.selected("max_thrust_eccentricity_at") ||
                       columns.selected("thrust_in_kern") || columns.selected("thrust_in_section");
  const bool stresses = columns.selected("max_compressive_stress") || columns.selected("max_compressive_stress_at") ||
                        columns.selected("max_stress_ratio");
  const double compressive_strength = compressive_strength_of(to.compressive_strength, cmd);
  // The summaries print eccentricities and stresses: their accuracy must be part of the error estimate
  // (the profile itself is not printed).
  if (summary || stresses)
    for (Options& o : sweep.combinations) {
      o.stations = kSummaryStations;
      o.unprinted_profile = true;
    }
  // No-tension scenes are traced in order, each from the previous one (continuation): one thread.
  const bool continued = plan.no_tension();
  std::vector<Solution> previous(sweep.combinations.size());
  const int threads = continued ? 1 : to.threads;
  const bool all_ok =
      write_scenes(plan, columns, out, threads, [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        bool ok = true;
        std::string text;
        for (std::size_t c = 0; c < sweep.combinations.size(); ++c) {
          const Options& o = sweep.combinations[c];
          const Solution sol = solve(scene, o, continued ? &previous[c] : nullptr);
          if (continued && sol.field) previous[c] = sol;
          text += thrust_row(columns, p, scene, o, sol, summary, stresses, compressive_strength);
          ok = ok && sol.ok();
        }
        emit(text);
        return ok;
      });
  return all_ok ? kExitOk : kExitNotConverged;
}

}  // namespace

Run add_thrust_options(CLI::App& cmd) {
  auto options = std::make_shared<ThrustOptions>();
  add_scene_options(cmd, options->scene);
  add_solver_options(cmd, options->solver, options->solver_text);
  add_compressive_strength_option(cmd, options->compressive_strength,
                                  "adds max_stress_ratio, the greatest compressive stress over f_c");
  add_column_options(cmd, options->columns);
  add_threads_option(cmd, options->threads);
  return [options, &cmd](std::ostream& out) { return run_thrust(*options, cmd, out); };
}

}  // namespace ogive::cli
