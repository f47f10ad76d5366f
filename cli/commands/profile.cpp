// ogive profile: N, V, M, the thrust eccentricity and the thrust line at stations along the arch.
#include <algorithm>
#include <cmath>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli.hpp"
#include "columns.hpp"
#include "commands.hpp"
#include "limit_text.hpp"
#include "ogive/core/thrust_line.hpp"
#include "ogive/solve/solve.hpp"
#include "option_text.hpp"
#include "row_writer.hpp"
#include "scene_options.hpp"
#include "scene_plan.hpp"
#include "solver_options.hpp"
#include "sweep.hpp"

namespace ogive::cli {
namespace {

struct ProfileOptions {
  SceneOptions scene;
  Options solver;
  SolverText solver_text;
  ColumnText columns;
  std::string compressive_strength;  // --compressive-strength as given (stress_ratio)
  int threads = 1;
};

Columns profile_columns() {
  return Columns({"method", "integrator", "rtol", "status", "H_over_V", "error_estimate", "message", "s", "x", "y",
                  "theta", "intrados_x", "intrados_y", "extrados_x", "extrados_y", "Ux", "Uy", "psi", "N",
                  "shear_force", "M", "thrust_eccentricity", "thrust_x", "thrust_y", "compressed_depth", "cracked",
                  "compressive_stress", "stress_ratio", "warning"},
                 {"status", "message", "s", "x", "y", "theta", "intrados_x", "intrados_y", "extrados_x", "extrados_y",
                  "Ux", "Uy", "psi", "N", "shear_force", "M", "thrust_eccentricity", "thrust_x", "thrust_y",
                  "compressed_depth", "cracked", "warning"});
}

constexpr int kProfilePiece = 4096;  // stations sampled and written at a time

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

// One station's fields, after the scene's (the row's mark).
void add_station(CsvRow& row, const ArchState& st, double thickness, double compressive_strength) {
  // The section's two ends, so that a plot shows the thrust line against the masonry.
  const SectionFaces faces = section_faces(CurvePoint{st.x, st.y, st.theta, 0.0}, thickness);
  row.add(st.s).add(st.x).add(st.y).add(st.theta);
  row.add(faces.intrados.x).add(faces.intrados.y).add(faces.extrados.x).add(faces.extrados.y);
  row.add(st.Ux).add(st.Uy).add(st.psi);
  row.add(st.N).add(st.V).add(st.M).add(st.e).add(st.thrust_x).add(st.thrust_y);
  add_parameter(row, st.compressed_depth);
  if (std::isnan(st.compressed_depth)) row.add(std::string_view{});
  else row.add_bool(st.cracked);
  row.add(st.compressive_stress);
  row.add(stress_ratio(st.compressive_stress, compressive_strength));
  row.add(section_warning(st));
}

// A solved scene's rows, one per station. The solve verified the profile at o.stations; longer profiles
// are sampled piece by piece from the verified field, so that memory does not grow with the stations.
void emit_stations(const Columns& columns, const SceneParameters& p, const Scene& scene, const Options& o,
                   const Solution& sol, int stations, double compressive_strength, const Emit& emit) {
  // The scene's fields are formatted once, then each station's after them.
  CsvRow row(columns.keep());
  add_scene_columns(row, p, scene.curve.get());
  row.add(to_string(sol.method)).add(integrator_of(sol.method, o)).add(o.rtol).add(to_string(sol.status));
  row.add(sol.H_over_V).add(sol.diagnostics.error_estimate).add(sol.message);
  row.mark();
  for (int first = 0; first < stations; first += kProfilePiece) {
    const int count = std::min(kProfilePiece, stations - first);
    const std::vector<ArchState> piece =
        stations == o.stations ? std::vector<ArchState>(sol.profile.begin() + first, sol.profile.begin() + first + count)
                               : sample_stations(sol, stations, first, count);
    std::string text;
    for (const ArchState& st : piece) {
      add_station(row, st, scene.thickness, compressive_strength);
      text += row.take_to_mark();
    }
    emit(text);
  }
}

// An unsolved combination: one row that says so, no numbers.
std::string unsolved_row(const Columns& columns, const SceneParameters& p, const Scene& scene, const Options& o,
                         const Solution& sol) {
  return sparse_row(columns, p, scene.curve.get(),
                    {{"method", to_string(sol.method)}, {"integrator", std::string(integrator_of(sol.method, o))},
                     {"rtol", fmt::format("{}", o.rtol)}, {"status", to_string(sol.status)}, {"message", sol.message}});
}

int run_profile(ProfileOptions& po, const CLI::App& cmd, std::ostream& out) {
  check_threads(po.threads);
  Columns columns = profile_columns();
  if (po.columns.columns == "help") {
    write_all(out, columns.help(po.columns));
    return kExitOk;
  }
  SolverSweep sweep = solver_sweep(po.solver, po.solver_text);
  const int stations = po.solver.stations;
  const double compressive_strength = compressive_strength_of(po.compressive_strength, cmd);
  check_stations(stations);
  const ScenePlan plan(po.scene, cmd);
  check_rows(plan.size() * sweep.combinations.size(), stations);
  columns.select(po.columns, plan.varying_inputs(), sweep.varying);
  // The solve verifies the profile at kVerificationStations at most (emit_stations samples the rest).
  for (Options& o : sweep.combinations) o.stations = std::min(stations, kVerificationStations);
  // A scene's rows wait in the reorder window while other threads work: write_scenes bounds them by the
  // rows a scene has (one thread beyond kChunkRows). No-tension scenes are traced in order, each from the
  // previous one (continuation): one thread.
  const bool continued = plan.no_tension();
  const int threads = continued ? 1 : po.threads;
  const std::size_t rows_per_scene = static_cast<std::size_t>(stations) * sweep.combinations.size();
  std::vector<Solution> previous(sweep.combinations.size());
  const bool all_ok =
      write_scenes(plan, columns, out, threads, [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        bool ok = true;
        for (std::size_t c = 0; c < sweep.combinations.size(); ++c) {
          const Options& o = sweep.combinations[c];
          const Solution sol = solve(scene, o, continued ? &previous[c] : nullptr);
          if (continued && sol.field) previous[c] = sol;
          if (!sol.field) {
            emit(unsolved_row(columns, p, scene, o, sol));
            ok = false;
            continue;
          }
          ok = ok && sol.ok();
          emit_stations(columns, p, scene, o, sol, stations, compressive_strength, emit);
        }
        return ok;
      },
      rows_per_scene);
  return all_ok ? kExitOk : kExitNotConverged;
}

}  // namespace

Run add_profile_options(CLI::App& cmd) {
  auto options = std::make_shared<ProfileOptions>();
  options->solver.stations = 101;
  add_scene_options(cmd, options->scene);
  add_solver_options(cmd, options->solver, options->solver_text);
  cmd.add_option("--stations", options->solver.stations,
                 "stations, equally spaced in arc length, springing to springing; must lie in [2, 1000000]")
      ->check(whole_count())
      ->capture_default_str();
  add_compressive_strength_option(cmd, options->compressive_strength,
                                  "adds stress_ratio, each station's compressive stress over f_c");
  add_column_options(cmd, options->columns);
  add_threads_option(cmd, options->threads);
  return [options, &cmd](std::ostream& out) { return run_profile(*options, cmd, out); };
}

}  // namespace ogive::cli
