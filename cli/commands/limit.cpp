// ogive limit: limit analysis of rigid voussoirs that resist no tension: H_min, H_max, t_min, the
// collapse load; one row per scene, or (--thrust-line) one per joint of one state.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli.hpp"
#include "columns.hpp"
#include "commands.hpp"
#include "limit_text.hpp"
#include "ogive/limit/limit.hpp"
#include "option_text.hpp"
#include "row_writer.hpp"
#include "scene_options.hpp"
#include "scene_plan.hpp"
#include "sweep.hpp"
#include "values.hpp"

namespace ogive::cli {
namespace {

enum class ThrustLine { min, max, collapse, horizontal };
const std::map<std::string, ThrustLine> kThrustLines = {{"min", ThrustLine::min},
                                                        {"max", ThrustLine::max},
                                                        {"collapse", ThrustLine::collapse},
                                                        {"horizontal", ThrustLine::horizontal}};
// The columns of the horizontal acceleration of collapse: computed only when one of them is asked for
// (or --thrust-line horizontal), and not among the defaults.
const std::vector<std::string> kHorizontalColumns = {"horizontal_load_factor", "horizontal_load_factor_mechanism",
                                                     "hinges_horizontal"};

// The joints that the loads and the refinement add to a starting ring, for the rows a scene's
// --thrust-line may print: a generous estimate (a few dozen per refinement round).
constexpr std::size_t kRefinementRows = 1024;

struct LimitText {
  std::string joints = "radial", weight = "voussoir", thrust_line;
  int joints_count = kDefaultJointsCount;
  double friction = 0;
  std::string friction_model = "non-associative";
  std::string compressive_strength;
  int repeats = 0;
  int threads = 1;
};

struct LimitCommandOptions {
  SceneOptions scene;
  LimitText text;
  ColumnText columns;
};

void add_analysis_options(CLI::App& cmd, LimitText& t) {
  cmd.add_option("--joints", t.joints,
                 "interior joints: radial (normal to the axis) or vertical; a list radial,vertical gives a row for each")
      ->capture_default_str();
  cmd.add_option("--weight", t.weight,
                 "voussoir (the ring's true weight at each centroid) or axis (rho g t per axis length); a list gives a "
                 "row for each")
      ->capture_default_str();
  cmd.add_option("--joints-count", t.joints_count, fmt::format("joints springing to springing, both included; odd, in [{}, {}]", kMinJointsCount,
                             kMaxJointsCount))
      ->check(whole_count())
      ->capture_default_str();
  cmd.add_option("--friction", t.friction, "friction coefficient of the joints (> 0): adds the sliding check")
      ->check(finite_number());
  add_friction_model_option(cmd, t.friction_model);
  add_compressive_strength_option(cmd, t.compressive_strength,
                                  "the joints crush (stress blocks at the hinges); omitted: infinite strength");
  cmd.add_option("--thrust-line", t.thrust_line, "instead of the summary, one row per joint of the min, max, collapse or horizontal (the acceleration a_c of collapse) state");
  cmd.add_option("--repeats", t.repeats,
                 "solve each scene this many times and add median_seconds (benchmark; the scenes one after another)")
      ->check(whole_count());
}

// The scene options that rigid voussoirs without tensile strength do not use, and why: refused when
// given, and left out of `limit --help`.
constexpr const char* kMovementWhy =
    "rigid voussoirs ignore the supports' movements: a spreading support brings the arch to H_min";
constexpr const char* kLeanWhy =
    "the limit analysis takes the walls rigid and plumb: a wall's lean moves its springing, which rigid voussoirs "
    "ignore";
constexpr const char* kElasticWhy =
    "rigid voussoirs have no stiffness: the material's elastic constants belong to thrust, profile and draw";
constexpr Inapplicable kNotForLimit[] = {
    {"--support-displacement-ratio", kMovementWhy},
    {"--left-spread-ratio", kMovementWhy},
    {"--right-spread-ratio", kMovementWhy},
    {"--left-settlement-ratio", kMovementWhy},
    {"--right-settlement-ratio", kMovementWhy},
    {"--left-rotation", kMovementWhy},
    {"--right-rotation", kMovementWhy},
    {"--wall-lean", kLeanWhy},
    {"--left-wall-lean", kLeanWhy},
    {"--right-wall-lean", kLeanWhy},
    {"--youngs-modulus", kElasticWhy},
    {"--poisson-ratio", kElasticWhy},
    {"--shear-coefficient", kElasticWhy},
    {"--plane-strain", kElasticWhy},
    {"--section", "the voussoirs carry no tension by construction: --section chooses the elastic analyses' model"},
};

// The options as the library's, refused with the option's name when they break a rule: one per
// combination of --joints and --weight (each a name or a list a,b), joints first, as the rows print them.
std::vector<LimitOptions> limit_options(const LimitText& t, const CLI::App& cmd) {
  LimitOptions o;
  o.joints_count = t.joints_count;
  if (given(cmd, "--friction") && !(t.friction > 0))
    throw UsageError(fmt::format("--friction: must be > 0 (omit it for no sliding check), got {}", t.friction));
  o.friction = t.friction;
  o.friction_model = friction_model_of(t.friction_model, cmd);
  o.compressive_strength = compressive_strength_of(t.compressive_strength, cmd);
  // The loads are the scene's (--point-load, --live-load, --fill-density, --loads-file) and so are the
  // pins (--supports pinned, --crown-hinge); the rest of the scene options does not enter rigid voussoirs.
  refuse_inapplicable(cmd, "limit", kNotForLimit);
  if (!t.thrust_line.empty()) lookup(kThrustLines, t.thrust_line, "--thrust-line");
  if (t.repeats < 0 || t.repeats > 100000)
    throw UsageError(fmt::format("--repeats: must lie in [0, 100000] (0: no timing), got {}", t.repeats));
  std::vector<LimitOptions> combinations;
  for (const std::string& joints : split_names(t.joints))
    for (const std::string& weight : split_names(t.weight)) {
      o.joints = lookup(joint_orientations(), joints, "--joints");
      o.weight = lookup(weight_models(), weight, "--weight");
      std::string why;
      if (!o.is_valid(&why)) throw UsageError(as_option_message(why));
      combinations.push_back(o);
    }
  return combinations;
}

// The columns among joints and weight that take several values (printed by default, as a varying input).
std::vector<std::string> varying_setup(const LimitText& t) {
  std::vector<std::string> varying;
  if (split_names(t.joints).size() > 1) varying.push_back("joints");
  if (split_names(t.weight).size() > 1) varying.push_back("weight");
  return varying;
}

void add_limit_setup(CsvRow& row, const LimitOptions& o) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  row.add(to_string(o.joints)).add(to_string(o.weight)).add(o.joints_count);
  row.add(o.friction > 0 ? o.friction : nan).add(friction_model_text(o));
  row.add(std::isfinite(o.compressive_strength) ? o.compressive_strength : nan);
}

// The columns of limit: a summary per scene, or (--thrust-line) one row per joint of one state.
Columns limit_columns(bool lines, bool timed, bool walls) {
  std::vector<std::string> results = {"joints",   "weight", "joints_count", "friction", "friction_model",
                                      "compressive_strength"},
                           defaults;
  const std::vector<std::string> summary = {
      "status", "H_min", "H_max", "V", "H_min_over_V", "H_max_over_V", "thickness_min_ratio",
      "geometric_safety_factor", "wall_thickness_min", "hinges_min", "hinges_max", "load_factor", "load_factor_mechanism",
      "hinges_collapse", "horizontal_load_factor", "horizontal_load_factor_mechanism", "hinges_horizontal",
      "lp_solves", "message", "median_seconds"};
  const std::vector<std::string> joints = {"state",      "status",     "H",          "load_factor", "joint",
                                           "s",          "intrados_x", "intrados_y", "extrados_x",  "extrados_y",
                                           "thrust_x",   "thrust_y",   "hinge"};
  const std::vector<std::string>& own = lines ? joints : summary;
  results.insert(results.end(), own.begin(), own.end());
  for (const std::string& name : own)
    if (name != "lp_solves" && (name != "median_seconds" || timed) && (name != "wall_thickness_min" || walls) &&
        std::find(kHorizontalColumns.begin(), kHorizontalColumns.end(), name) == kHorizontalColumns.end())
      defaults.push_back(name);
  return Columns(results, defaults);
}

// The analysis, `repeats` times when timed (at least once); *median_seconds the median time.
LimitResult analyse_timed(const Scene& scene, const LimitOptions& o, int repeats, double* median_seconds) {
  LimitResult r;
  std::vector<double> seconds;
  for (int k = 0; k < std::max(1, repeats); ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    r = analyse_limit(scene, o);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::nth_element(seconds.begin(), seconds.begin() + seconds.size() / 2, seconds.end());
  *median_seconds = seconds[seconds.size() / 2];
  return r;
}

std::string summary_row(const Columns& columns, const SceneParameters& p, const Scene& scene, const LimitOptions& o,
                        const LimitResult& r, bool timed, double median_seconds) {
  const double L = scene.span();
  CsvRow row(columns.keep());
  add_scene_columns(row, p, scene.curve.get());
  add_limit_setup(row, o);
  row.add(to_string(r.status)).add(r.H_min()).add(r.H_max()).add(r.V).add(r.H_min() / r.V).add(r.H_max() / r.V);
  row.add(r.thickness_min / L).add(scene.thickness / r.thickness_min);
  if (scene.has_walls()) row.add(r.wall_thickness_min);
  else row.add(std::string_view{});
  row.add(hinge_text(r.min_state.hinges, L, &r.ring)).add(hinge_text(r.max_state.hinges, L, &r.ring));
  row.add(r.load_factor()).add(r.load_factor_mechanism).add(hinge_text(r.collapse_state.hinges, L, &r.ring));
  row.add(r.horizontal_load_factor()).add(r.horizontal_load_factor_mechanism);
  row.add(hinge_text(r.horizontal_state.hinges, L, &r.horizontal_ring));
  row.add(r.lp_solves).add(r.message);
  if (timed) row.add(median_seconds);
  else row.add(std::string_view{});
  return row.take();
}

// One row per joint of the state `which` names (one row without numbers when there is no such state).
std::string joint_rows(const Columns& columns, const SceneParameters& p, const Scene& scene, const LimitOptions& o,
                       const LimitResult& r, const std::string& which) {
  const ThrustLine line = kThrustLines.at(which);
  const ThrustState& st = line == ThrustLine::min        ? r.min_state
                          : line == ThrustLine::max      ? r.max_state
                          : line == ThrustLine::collapse ? r.collapse_state
                                                         : r.horizontal_state;
  CsvRow row(columns.keep());
  add_scene_columns(row, p, scene.curve.get());
  add_limit_setup(row, o);
  row.add(which).add(to_string(r.status)).add(st.H).add(st.load_factor);
  if (!st.found()) {
    for (int k = 0; k < 9; ++k) row.add(std::string_view{});
    return row.take();
  }
  row.mark();
  const Ring& ring = line == ThrustLine::horizontal ? r.horizontal_ring : r.ring;  // the ring the state belongs to
  std::string text;
  for (std::size_t j = 0; j < ring.joints.size(); ++j) {
    const Joint& joint = ring.joints[j];
    std::string hinge;
    for (const Hinge& h : st.hinges)
      if (h.joint == static_cast<int>(j)) hinge = to_string(h.face);
    row.add(static_cast<std::int64_t>(j)).add(joint.s).add(joint.intrados.x()).add(joint.intrados.y());
    row.add(joint.extrados.x()).add(joint.extrados.y()).add(st.crossing[j].x()).add(st.crossing[j].y()).add(hinge);
    text += row.take_to_mark();
  }
  return text;
}

// Exit 0 when every scene has an answer (success, or inadmissible: an arch that cannot stand is an
// answer, not a failure), 3 when an LP failed, the joints' refinement did not converge or a scene could
// not be made.
int run_limit(LimitCommandOptions& lo, const CLI::App& cmd, std::ostream& out) {
  const LimitText& text = lo.text;
  check_threads(text.threads);
  const bool lines = !text.thrust_line.empty(), timed = text.repeats > 0;
  Columns columns = limit_columns(lines, timed, walls_given(cmd));
  if (lo.columns.columns == "help") {
    write_all(out, columns.help(lo.columns));
    return kExitOk;
  }
  std::vector<LimitOptions> combinations = limit_options(text, cmd);
  const ScenePlan plan(lo.scene, cmd);
  if (lines && kThrustLines.at(text.thrust_line) == ThrustLine::collapse && !given(cmd, "--point-load") &&
      !given(cmd, "--live-load") && lo.scene.file_loads.points.empty() && lo.scene.file_loads.live.empty())
    throw UsageError("--thrust-line collapse: a load factor needs a live load (--point-load, --live-load or a "
                     "--loads-file with point or live rows)");
  if (lines) check_rows(plan.size() * combinations.size(), text.joints_count);
  columns.select(lo.columns, plan.varying_inputs(), varying_setup(text));
  const bool horizontal = (lines && kThrustLines.at(text.thrust_line) == ThrustLine::horizontal) ||
                          std::any_of(kHorizontalColumns.begin(), kHorizontalColumns.end(),
                                      [&](const std::string& c) { return columns.selected(c); });
  for (LimitOptions& o : combinations) o.horizontal_load_factor = horizontal;
  // Each scene's analysis has its own LP model, so scenes run in parallel; timed scenes (--repeats) one
  // after another, each on a core of its own. A scene's joint rows (--thrust-line) wait in the reorder
  // window while other threads work: write_scenes bounds them by the starting ring's joints and the few
  // hundred that the loads and the refinement add (one thread beyond kChunkRows).
  const int threads = timed ? 1 : text.threads;
  const std::size_t rows_per_scene =
      combinations.size() * (lines ? static_cast<std::size_t>(text.joints_count) + kRefinementRows : 1);
  const bool all_answered = write_scenes(
      plan, columns, out, threads,
      [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        bool answered = true;
        std::string text_rows;
        for (const LimitOptions& o : combinations) {
          double median_seconds = 0;
          const LimitResult r = analyse_timed(scene, o, text.repeats, &median_seconds);
          text_rows += lines ? joint_rows(columns, p, scene, o, r, text.thrust_line)
                             : summary_row(columns, p, scene, o, r, timed, median_seconds);
          answered = answered && (r.status == LimitStatus::success || r.status == LimitStatus::inadmissible);
        }
        emit(text_rows);
        return answered;
      },
      rows_per_scene);
  return all_answered ? kExitOk : kExitNotConverged;
}

}  // namespace

Run add_limit_options(CLI::App& cmd) {
  auto options = std::make_shared<LimitCommandOptions>();
  add_scene_options(cmd, options->scene);
  hide_inapplicable(cmd, kNotForLimit);
  add_analysis_options(cmd, options->text);
  add_column_options(cmd, options->columns);
  add_threads_option(cmd, options->text.threads);
  return [options, &cmd](std::ostream& out) { return run_limit(*options, cmd, out); };
}

}  // namespace ogive::cli
