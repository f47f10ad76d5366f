// ogive curve: the generator curve's geometry, s, x, y, theta, kappa at equally spaced stations over
// the whole arch.
#include <memory>
#include <ostream>
#include <string>

#include <CLI/CLI.hpp>

#include "cli.hpp"
#include "columns.hpp"
#include "commands.hpp"
#include "option_text.hpp"
#include "row_writer.hpp"
#include "scene_options.hpp"
#include "scene_plan.hpp"
#include "sweep.hpp"

namespace ogive::cli {
namespace {

struct CurveOptions {
  SceneOptions scene;
  int stations = 101;
  ColumnText columns;
  int threads = 1;
};

// The scene options that do not shape the axis, and why: refused when given, left out of --help.
constexpr const char* kLoadWhy = "it draws the axis alone: loads enter thrust, profile, limit, draw and report";
constexpr const char* kSupportWhy = "it draws the axis alone: supports and their movements enter the analyses";
constexpr const char* kMaterialWhy = "it draws the axis alone: the material and section enter the analyses";
constexpr Inapplicable kNotForCurve[] = {
    {"--point-load", kLoadWhy},
    {"--point-load-at", kLoadWhy},
    {"--point-load-x", kLoadWhy},
    {"--live-load", kLoadWhy},
    {"--live-load-from", kLoadWhy},
    {"--live-load-to", kLoadWhy},
    {"--live-load-from-x", kLoadWhy},
    {"--live-load-to-x", kLoadWhy},
    {"--fill-density", kLoadWhy},
    {"--fill-height-ratio", kLoadWhy},
    {"--fill-height", kLoadWhy},
    {"--loads-file", kLoadWhy},
    {"--horizontal-acceleration", kLoadWhy},
    {"--supports", kSupportWhy},
    {"--left-support", kSupportWhy},
    {"--right-support", kSupportWhy},
    {"--crown-hinge", kSupportWhy},
    {"--support-displacement-ratio", kSupportWhy},
    {"--left-spread-ratio", kSupportWhy},
    {"--right-spread-ratio", kSupportWhy},
    {"--left-settlement-ratio", kSupportWhy},
    {"--right-settlement-ratio", kSupportWhy},
    {"--left-rotation", kSupportWhy},
    {"--right-rotation", kSupportWhy},
    {"--youngs-modulus", kMaterialWhy},
    {"--poisson-ratio", kMaterialWhy},
    {"--density", kMaterialWhy},
    {"--unit-weight", kMaterialWhy},
    {"--gravity", kMaterialWhy},
    {"--shear-coefficient", kMaterialWhy},
    {"--plane-strain", kMaterialWhy},
    {"--section", kMaterialWhy},
    {"--units", "it prints lengths and angles, no force"},
};

Columns curve_columns() {
  const std::vector<std::string> results = {"status", "message", "s", "x", "y", "theta", "kappa"};
  return Columns(results, results);
}

int run_curve(CurveOptions& co, const CLI::App& cmd, std::ostream& out) {
  check_threads(co.threads);
  Columns columns = curve_columns();
  if (co.columns.columns == "help") {
    write_all(out, columns.help(co.columns));
    return kExitOk;
  }
  refuse_inapplicable(cmd, "curve", kNotForCurve);
  const int stations = co.stations;
  check_stations(stations);
  const ScenePlan plan(co.scene, cmd);
  check_rows(plan.size(), stations);
  columns.select(co.columns, plan.varying_inputs());
  const bool all_ok =
      write_scenes(plan, columns, out, co.threads, [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        CsvRow row(columns.keep());
        const Curve& curve = *scene.curve;
        add_scene_columns(row, p, &curve);
        row.add("success").add(std::string_view{});
        row.mark();
        const double S = curve.length();
        std::string text;
        for (int k = 0; k < stations; ++k) {
          const double s = 2.0 * S * k / (stations - 1);
          const CurvePoint pt = curve.at_whole_arch(s);
          row.add(s).add(pt.x).add(pt.y).add(pt.theta).add(pt.kappa);
          text += row.take_to_mark();
          if (text.size() >= (1u << 16)) {
            emit(text);
            text.clear();
          }
        }
        emit(text);
        return true;
      },
      static_cast<std::size_t>(stations));
  return all_ok ? kExitOk : kExitNotConverged;
}

}  // namespace

Run add_curve_options(CLI::App& cmd) {
  auto options = std::make_shared<CurveOptions>();
  add_scene_options(cmd, options->scene);
  cmd.add_option("--stations", options->stations,
                 "stations, equally spaced in arc length, springing to springing; must lie in [2, 1000000]")
      ->check(whole_count())
      ->capture_default_str();
  add_column_options(cmd, options->columns);
  hide_inapplicable(cmd, kNotForCurve);
  add_threads_option(cmd, options->threads);
  return [options, &cmd](std::ostream& out) { return run_curve(*options, cmd, out); };
}

}  // namespace ogive::cli
