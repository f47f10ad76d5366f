// ogive bench: time per solve (median over repeats) and true error against the reference
// (reference.hpp), one row per method, integrator and rtol. Failed runs stay in the table with their
// status.
#include <algorithm>
#include <chrono>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli.hpp"
#include "columns.hpp"
#include "commands.hpp"
#include "reference.hpp"
#include "ogive/core/thrust_line.hpp"
#include "ogive/solve/solve.hpp"
#include "option_text.hpp"
#include "row_writer.hpp"
#include "scene_options.hpp"
#include "scene_plan.hpp"
#include "solver_options.hpp"
#include "sweep.hpp"
#include "values.hpp"

namespace ogive::cli {
namespace {

struct BenchOptions {
  SceneOptions scene;
  Options solver;
  // The same options as every other command's, with a benchmark's defaults.
  SolverText solver_text{"closed-form,shooting,multiple-shooting", "adams", "1e-6,1e-8,1e-10"};
  int repeats = 21;
  ColumnText columns;
};

Columns bench_columns() {
  const std::vector<std::string> results = {
      "method", "integrator", "rtol", "segments", "status", "chosen_method", "H_over_V", "error_H_over_V",
      "error_profile", "error_estimate", "reference_error", "median_seconds", "steps", "rhs_evaluations",
      "condition_estimate", "message"};
  return Columns(results, results);
}

constexpr int kBenchProfileStations = 41;

struct BenchRow {
  std::string text;
  bool ok;  // status success
};

// One combination's row: the median time of `repeats` solves, then the profile's error from the same
// solve with stations, outside the timing.
BenchRow bench_row(const Columns& columns, const SceneParameters& p, const Scene& scene, const Options& o,
                   bool exact, const Solution& reference, int repeats) {
  std::vector<double> seconds;
  Solution sol;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    sol = solve(scene, o);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::nth_element(seconds.begin(), seconds.begin() + repeats / 2, seconds.end());
  Options profiled = o;
  profiled.stations = kBenchProfileStations;
  const Solution with_profile = solve(scene, profiled);
  // The row's status is the worse of the two solves: a profile that missed its tolerance says so.
  const Solution& judged = sol.ok() ? with_profile : sol;
  const double estimate = std::max(sol.diagnostics.error_estimate, with_profile.diagnostics.error_estimate);
  CsvRow row(columns.keep());
  add_scene_columns(row, p, scene.curve.get());
  row.add(to_string(o.method)).add(exact ? std::string_view{} : integrator_of(o.method, o));
  if (exact) row.add(std::string_view{});
  else row.add(o.rtol);
  row.add(sol.diagnostics.segments).add(to_string(judged.status));
  row.add(to_string(sol.method));
  row.add(sol.H_over_V).add(thrust_difference(sol.H_over_V, reference.H_over_V));
  row.add(profile_difference(with_profile.profile, reference.profile, scene.thickness)).add(estimate);
  row.add(reference_error(reference));
  row.add(seconds[repeats / 2]).add(sol.diagnostics.steps).add(sol.diagnostics.rhs_evaluations);
  row.add(sol.diagnostics.condition_estimate).add(judged.message);
  return {row.take(), judged.ok()};
}

int run_bench(BenchOptions& bo, const CLI::App& cmd, std::ostream& out) {
  Columns columns = bench_columns();
  if (bo.columns.columns == "help") {
    write_all(out, columns.help(bo.columns));
    return kExitOk;
  }
  const SolverSweep sweep = solver_sweep(bo.solver, bo.solver_text);
  const int repeats = bo.repeats;
  if (repeats < 1 || repeats > 100000) throw UsageError(fmt::format("--repeats: must lie in [1, 100000], got {}", repeats));
  const Options& first = sweep.combinations.front();
  const ScenePlan plan(bo.scene, cmd);
  if (plan.size() * sweep.combinations.size() > kMaxValues)
    throw UsageError(fmt::format("--rtol: {} scenes x {} solver combinations exceed {} rows", plan.size(),
                                 sweep.combinations.size(), kMaxValues));
  // The reference is tighter than the tightest rtol benchmarked.
  Options ref_options = first;
  for (const Options& o : sweep.combinations) ref_options.rtol = std::min(ref_options.rtol, o.rtol);
  ref_options.stations = kBenchProfileStations;
  columns.select(bo.columns, plan.varying_inputs());
  // Exit status 3 when a row failed, as every other command: a script must not take a failed method's
  // row for a timing.
  const bool all_ok = write_scenes(
      plan, columns, out, 1,  // one thread: the timings are the point
      [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        const Solution reference = reference_solution(scene, ref_options);
        // The reference is the closed form exactly where it applies (a piecewise-circular curve,
        // the elastic section, no live load or fill).
        const bool closed_form_applies = reference.method == Method::closed_form;
        bool rows_ok = true;
        for (const Options& o : sweep.combinations) {
          const Method m = o.method;
          if (m == Method::closed_form && !closed_form_applies) continue;  // not applicable
          // The closed form has neither integrator nor tolerance; auto where it applies is the
          // closed form: one row, not one per integrator and rtol.
          const bool exact = m == Method::closed_form || (m == Method::automatic && closed_form_applies);
          if (exact && (o.integrator != first.integrator || o.rtol != first.rtol)) continue;
          if (m == Method::quadrature && o.integrator != first.integrator) continue;  // no integrator
          const BenchRow row = bench_row(columns, p, scene, o, exact, reference, repeats);
          emit(row.text);
          rows_ok = row.ok && rows_ok;
        }
        return rows_ok;
      });
  return all_ok ? kExitOk : kExitNotConverged;
}

}  // namespace

Run add_bench_options(CLI::App& cmd) {
  auto options = std::make_shared<BenchOptions>();
  add_scene_options(cmd, options->scene);
  add_solver_options(cmd, options->solver, options->solver_text, true, true);  // and the plural spellings
  cmd.add_option("--repeats", options->repeats, "solves per row, the median time is printed; must lie in [1, 100000]")
      ->check(whole_count())
      ->capture_default_str();
  add_column_options(cmd, options->columns);
  return [options, &cmd](std::ostream& out) { return run_bench(*options, cmd, out); };
}

}  // namespace ogive::cli
