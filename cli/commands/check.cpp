// ogive check: every applicable method on every scene, against the reference (reference.hpp). A row is
// within tolerance when the method says success and its difference from the reference is within rtol
// plus the reference's own error (a flagged reference is not the method's failure: its status and
// error are printed).
#include <memory>
#include <ostream>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli.hpp"
#include "columns.hpp"
#include "commands.hpp"
#include "reference.hpp"
#include "ogive/solve/solve.hpp"
#include "row_writer.hpp"
#include "scene_options.hpp"
#include "scene_plan.hpp"
#include "solver_options.hpp"
#include "sweep.hpp"

namespace ogive::cli {
namespace {

struct CheckOptions {
  SceneOptions scene;
  Options solver;
  SolverText solver_text;
  ColumnText columns;
  int threads = 1;
};

Columns check_columns() {
  const std::vector<std::string> results = {
      "method", "integrator", "rtol", "segments", "status", "H_over_V", "reference_method", "reference_status",
      "reference_error", "reference_H_over_V", "relative_difference", "tolerance", "within_tolerance", "message"};
  return Columns(results, results);
}

// The rows of one scene and solver combination: one per applicable method.
bool check_rows_of(const Columns& columns, const SceneParameters& p, const Scene& scene, const Options& base,
                   std::string& text) {
  const Solution reference = reference_solution(scene, base);
  const std::string reference_method = reference.method == Method::closed_form
                                           ? "closed-form"
                                           : fmt::format("multiple-shooting rtol {}", reference_rtol(base));
  const double ref_error = reference_error(reference);
  CsvRow row(columns.keep());
  bool ok = true;
  for (Method m : {Method::closed_form, Method::quadrature, Method::shooting, Method::multiple_shooting}) {
    if (m == Method::closed_form && scene.curve->arcs().empty()) continue;  // not applicable
    if (m == Method::quadrature && !base.restart_at_breakpoints) continue;  // not applicable either
    Options o = base;
    o.method = m;
    const Solution sol = solve(scene, o);
    const double diff = thrust_difference(sol.H_over_V, reference.H_over_V);
    const bool known = reference.field && sol.field;
    const bool within = sol.ok() && known && within_tolerance(diff, o.rtol + ref_error);
    ok = ok && within;
    add_scene_columns(row, p, scene.curve.get());
    row.add(to_string(sol.method)).add(integrator_of(sol.method, o)).add(o.rtol);
    row.add(sol.diagnostics.segments).add(to_string(sol.status)).add(sol.H_over_V).add(reference_method);
    row.add(to_string(reference.status)).add(ref_error).add(reference.H_over_V).add(diff).add(o.rtol);
    if (known) row.add_bool(within);
    else row.add(std::string_view{});
    row.add(sol.message);
    text += row.take();
  }
  return ok;
}

int run_check(CheckOptions& co, const CLI::App& cmd, std::ostream& out) {
  check_threads(co.threads);
  Columns columns = check_columns();
  if (co.columns.columns == "help") {
    write_all(out, columns.help(co.columns));
    return kExitOk;
  }
  const SolverSweep sweep = solver_sweep(co.solver, co.solver_text, false);
  const ScenePlan plan(co.scene, cmd);
  columns.select(co.columns, plan.varying_inputs());
  const bool all_ok =
      write_scenes(plan, columns, out, co.threads, [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        bool ok = true;
        std::string text;
        for (const Options& base : sweep.combinations) ok = check_rows_of(columns, p, scene, base, text) && ok;
        emit(text);
        return ok;
      });
  return all_ok ? kExitOk : kExitNotConverged;
}

}  // namespace

Run add_check_options(CLI::App& cmd) {
  auto options = std::make_shared<CheckOptions>();
  add_scene_options(cmd, options->scene);
  add_solver_options(cmd, options->solver, options->solver_text, false);
  add_column_options(cmd, options->columns);
  add_threads_option(cmd, options->threads);
  return [options, &cmd](std::ostream& out) { return run_check(*options, cmd, out); };
}

}  // namespace ogive::cli
