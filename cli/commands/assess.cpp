// ogive assess: one row per scene with each criterion's value, what it must reach and whether it does,
// and a verdict (pass, fail, not_assessed) that names the governing criterion. The analyses are the
// library's (ogive/solve/assessment.hpp): this command binds the criteria and prints the row.
#include <cmath>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli.hpp"
#include "columns.hpp"
#include "commands.hpp"
#include "criteria.hpp"
#include "limit_text.hpp"
#include "ogive/solve/assessment.hpp"
#include "option_text.hpp"
#include "row_writer.hpp"
#include "scene_options.hpp"
#include "scene_plan.hpp"
#include "sweep.hpp"
#include "values.hpp"

namespace ogive::cli {
namespace {

struct AssessText {
  CriteriaText criteria;
  std::string joints = "radial", weight = "voussoir";
  int joints_count = kDefaultJointsCount;
  double friction = 0;
  std::string friction_model = "non-associative";
  std::string compressive_strength;
  int threads = 1;
};

struct AssessCommandOptions {
  SceneOptions scene;
  AssessText text;
  ColumnText columns;
};

constexpr auto kAssessMoves = springing_movements(
    "the assessment is of the arch on its springings as built: --require-spread asks for its spreading capacity");

void add_rigid_block_options(CLI::App& cmd, AssessText& t) {
  add_criteria_options(cmd, t.criteria);
  cmd.add_option("--joints", t.joints, "rigid voussoirs' interior joints: radial (normal to the axis) or vertical")
      ->capture_default_str();
  cmd.add_option("--weight", t.weight,
                 "rigid voussoirs' weight: voussoir (the ring's true weight at each centroid) or axis (rho g t per "
                 "axis length)")
      ->capture_default_str();
  cmd.add_option("--joints-count", t.joints_count,
                 fmt::format("rigid voussoirs' joints springing to springing, both included; odd, in [{}, {}]",
                             kMinJointsCount, kMaxJointsCount))
      ->check(whole_count())
      ->capture_default_str();
  cmd.add_option("--friction", t.friction, "friction coefficient of the joints (> 0): adds the sliding check")
      ->check(finite_number());
  add_friction_model_option(cmd, t.friction_model);
  add_compressive_strength_option(cmd, t.compressive_strength,
                                  "the rigid voussoirs' joints crush (the geometric and load factors, a_c); omitted: "
                                  "infinite strength");
}

AssessmentOptions assessment_options(const AssessText& t, const CLI::App& cmd) {
  refuse_inapplicable(cmd, "assess", kAssessMoves);
  AssessmentOptions o;
  o.require = criteria_of(t.criteria);
  o.limit.joints = lookup(joint_orientations(), t.joints, "--joints");
  o.limit.weight = lookup(weight_models(), t.weight, "--weight");
  o.limit.joints_count = t.joints_count;
  if (given(cmd, "--friction") && !(t.friction > 0))
    throw UsageError(fmt::format("--friction: must be > 0 (omit it for no sliding check), got {}", t.friction));
  o.limit.friction = t.friction;
  o.limit.friction_model = friction_model_of(t.friction_model, cmd);
  o.limit.compressive_strength = compressive_strength_of(t.compressive_strength, cmd);
  std::string why;
  if (!o.is_valid(&why)) throw UsageError(as_option_message(why));
  return o;
}

// Each criterion's three columns, in Criterion's order: its value, required value and outcome.
constexpr const char* kCriterionColumns[] = {"geometric_safety_factor", "load_factor", "horizontal_load_factor",
                                             "spread_capacity_ratio", "max_thrust_eccentricity"};

Columns assess_columns() {
  std::vector<std::string> results = {"joints",  "weight",    "joints_count", "friction", "friction_model",
                                      "compressive_strength", "verdict", "governing", "margin"};
  std::vector<std::string> defaults = {"verdict", "governing", "margin"};
  for (const char* c : kCriterionColumns)
    for (const std::string& name : {std::string(c), std::string(c) + "_required", std::string(c) + "_outcome"}) {
      results.push_back(name);
      defaults.push_back(name);
    }
  for (const char* name : {"thickness_min_ratio", "status", "limit_status", "warnings", "message"}) {
    results.emplace_back(name);
    defaults.emplace_back(name);
  }
  return Columns(results, defaults);
}

// The reasons of the criteria that were not assessed or do not apply, "criterion: reason" joined by "; ".
std::string reasons(const Assessment& a) {
  std::string text;
  for (const CriterionResult& r : a.criteria)
    if (!r.reason.empty()) text += fmt::format("{}{}: {}", text.empty() ? "" : "; ", to_string(r.criterion), r.reason);
  return text;
}

std::string assessment_row(const Columns& columns, const SceneParameters& p, const Scene& scene,
                           const AssessmentOptions& o, const Assessment& a) {
  CsvRow row(columns.keep());
  add_scene_columns(row, p, scene.curve.get());
  row.add(to_string(o.limit.joints)).add(to_string(o.limit.weight)).add(o.limit.joints_count);
  row.add(o.limit.friction > 0 ? o.limit.friction : std::numeric_limits<double>::quiet_NaN());
  row.add(friction_model_text(o.limit));
  row.add(std::isfinite(o.limit.compressive_strength) ? o.limit.compressive_strength
                                                      : std::numeric_limits<double>::quiet_NaN());
  row.add(to_string(a.verdict)).add(to_string(a.governing)).add(a.margin);
  for (const CriterionResult& r : a.criteria) row.add(r.value).add(r.required).add(to_string(r.outcome));
  row.add(a.limit.thickness_min / scene.span());
  row.add(to_string(a.solution.status)).add(to_string(a.limit.status));
  std::string warnings;
  for (const std::string& w : a.warnings) warnings += (warnings.empty() ? "" : "; ") + w;
  row.add(warnings).add(reasons(a));
  return row.take();
}

// Exit 0 whatever the verdicts (a failing arch is an answer), 3 where a scene could not be assessed.
int run_assess(AssessCommandOptions& ao, const CLI::App& cmd, std::ostream& out) {
  const AssessText& text = ao.text;
  check_threads(text.threads);
  Columns columns = assess_columns();
  if (ao.columns.columns == "help") {
    write_all(out, columns.help(ao.columns));
    return kExitOk;
  }
  const AssessmentOptions o = assessment_options(text, cmd);
  const ScenePlan plan(ao.scene, cmd);
  columns.select(ao.columns, plan.varying_inputs());
  // A no-tension scene's solve starts from scratch here (no continuation between scenes), so scenes
  // run in parallel like limit's.
  const bool all_assessed =
      write_scenes(plan, columns, out, text.threads, [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        const Assessment a = assess(scene, o);
        emit(assessment_row(columns, p, scene, o, a));
        return a.verdict != Verdict::not_assessed;
      });
  return all_assessed ? kExitOk : kExitNotConverged;
}

}  // namespace

Run add_assess_options(CLI::App& cmd) {
  auto options = std::make_shared<AssessCommandOptions>();
  add_scene_options(cmd, options->scene);
  hide_inapplicable(cmd, kAssessMoves);
  add_rigid_block_options(cmd, options->text);
  add_column_options(cmd, options->columns);
  add_threads_option(cmd, options->text.threads);
  return [options, &cmd](std::ostream& out) { return run_assess(*options, cmd, out); };
}

}  // namespace ogive::cli
