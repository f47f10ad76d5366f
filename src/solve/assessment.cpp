// The assessment (assessment.hpp): the analyses that exist, each compared with its required value.
#include "ogive/solve/assessment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "ogive/core/thrust_line.hpp"
#include "ogive/solve/solve.hpp"

namespace ogive {
namespace {

bool required(double value) { return !std::isnan(value); }

CriterionResult result(Criterion c, Outcome o, double need = std::numeric_limits<double>::quiet_NaN()) {
  CriterionResult r;
  r.criterion = c;
  r.outcome = o;
  r.required = need;
  return r;
}

// A criterion with a value to meet: at least `need` (or, for `most`, at most). Not required (need NaN):
// the value alone, for the reader.
CriterionResult judged(Criterion c, double value, double need, bool most = false) {
  CriterionResult r = result(c, Outcome::pass, need);
  r.value = value;
  if (!required(need)) {
    r.outcome = Outcome::not_required;
    return r;
  }
  r.margin = most ? need / value : value / need;
  // A value that is exactly 0 against a most (an axis-true thrust line) has infinite margin.
  if (most && value == 0) r.margin = std::numeric_limits<double>::infinity();
  if (!(r.margin >= 1)) r.outcome = Outcome::fail;
  return r;
}

CriterionResult unassessed(Criterion c, double need, std::string reason) {
  CriterionResult r = result(c, required(need) ? Outcome::not_assessed : Outcome::not_required, need);
  if (required(need)) r.reason = std::move(reason);
  return r;
}

CriterionResult not_required(Criterion c) { return result(c, Outcome::not_required); }

// Numbers of a limit result that are answers: a converged analysis, or an arch that cannot stand (whose
// t_min and load factor are still found).
bool limit_answered(const LimitResult& r) {
  return r.status == LimitStatus::success || r.status == LimitStatus::inadmissible;
}

std::string limit_reason(const LimitResult& r) {
  return fmt::format("limit analysis {}: {}", to_string(r.status), r.message);
}

CriterionResult geometric_factor(const Scene& scene, const LimitResult& lr, double need) {
  const Criterion c = Criterion::geometric_safety_factor;
  if (!limit_answered(lr)) return unassessed(c, need, limit_reason(lr));
  if (!(lr.thickness_min > 0)) {
    // Walls thinner than the least that stands: no arch thickness makes the system stand (t_min's search
    // stops at the thickest springing joint the walls carry), so its geometric factor is 0.
    if (lr.status == LimitStatus::inadmissible && scene.thinnest_wall() < lr.wall_thickness_min) {
      CriterionResult r = judged(c, 0, need);
      r.reason = lr.message;
      return r;
    }
    return unassessed(c, need, "t_min not found: " + lr.message);
  }
  return judged(c, scene.thickness / lr.thickness_min, need);
}

CriterionResult load_factor(const LimitResult& lr, double need) {
  const Criterion c = Criterion::load_factor;
  if (!lr.ring.has_live_load()) {
    CriterionResult r = result(c, required(need) ? Outcome::not_applicable : Outcome::not_required, need);
    if (required(need)) r.reason = "no point or live load to multiply";
    return r;
  }
  if (!limit_answered(lr)) return unassessed(c, need, limit_reason(lr));
  // The arch that cannot carry its dead loads alone carries no live load: a factor of 0.
  if (!lr.collapse_state.found()) return judged(c, 0, need);
  return judged(c, lr.load_factor(), need);
}

CriterionResult acceleration(const LimitResult& lr, double need) {
  const Criterion c = Criterion::horizontal_load_factor;
  if (!required(need)) return not_required(c);
  if (!limit_answered(lr)) return unassessed(c, need, limit_reason(lr));
  if (lr.status == LimitStatus::inadmissible) return judged(c, 0, need);  // it does not stand at rest
  if (!lr.horizontal_state.found())
    return unassessed(c, need, "no finite horizontal acceleration makes a mechanism: " + lr.message);
  return judged(c, lr.horizontal_load_factor(), need);
}

// The spreading path's options: the movement, and why there is no path where there can be none.
struct SpreadRun {
  SpreadOptions spread;
  std::string unassessed;  // empty: the path runs
};

CriterionResult spreading(const Scene& scene, const SpreadRun& o, const SpreadResult& sr, double need) {
  const Criterion c = Criterion::spread_capacity_ratio;
  if (!required(need)) return not_required(c);
  if (scene.horizontal_acceleration != 0) {
    CriterionResult r = result(c, Outcome::not_applicable, need);
    r.reason = "the spreading mechanism carries vertical loads only: no horizontal acceleration";
    return r;
  }
  if (!o.unassessed.empty()) return unassessed(c, need, o.unassessed);
  if (sr.status == SpreadStatus::inadmissible) return judged(c, 0, need);  // t < t_min: no path at all
  if (sr.status != SpreadStatus::success)
    return unassessed(c, need, fmt::format("spreading {}: {}", to_string(sr.status), sr.message));
  return judged(c, spread_capacity_ratio(sr, o.spread), need);
}

// The spreading path's movement for `scene`: on walls, the walls lean (each side with a wall by its
// share; a side without one stays where it is).
SpreadRun spread_run(const Scene& scene, const AssessmentOptions& options) {
  SpreadRun run{options.spread, {}};
  if (!scene.has_walls()) return run;
  run.spread = leaning_walls(scene, options.spread);
  if (!(run.spread.left_share + run.spread.right_share > 0))
    run.unassessed = "no wall with some height under a moving springing to lean";
  return run;
}

CriterionResult thrust_line(const Solution& sol, const ThrustLineSummary& line, ThrustRequirement req) {
  const Criterion c = Criterion::max_thrust_eccentricity;
  const double most = req == ThrustRequirement::kern   ? 100
                      : req == ThrustRequirement::none ? std::numeric_limits<double>::quiet_NaN()
                                                       : 300;
  if (sol.status == Status::inadmissible) {  // no state of the no-tension arch keeps it in the section
    CriterionResult r = result(c, required(most) ? Outcome::fail : Outcome::not_required, most);
    if (required(most)) r.margin = 0;
    return r;
  }
  if (!sol.ok())
    return unassessed(c, most, fmt::format("the solve's status is {}: {}", to_string(sol.status), sol.message));
  if (!line.ok || std::isnan(line.max_abs_e))
    return unassessed(c, most, "the normal force is not a compression everywhere: e is unbounded");
  return judged(c, line.max_abs_e, most, true);
}

// The governing criterion and the verdict (assessment.hpp).
void decide(Assessment& a) {
  const CriterionResult* failed = nullptr;
  const CriterionResult* open = nullptr;
  const CriterionResult* passed = nullptr;
  // An arch that cannot carry its loads fails every capacity at 0; its cause is what governs: t below
  // t_min, or a load factor below 1.
  const bool stands = a.limit.status != LimitStatus::inadmissible;
  const auto cause = [&](const CriterionResult& r) {
    return stands || r.criterion == Criterion::geometric_safety_factor || r.criterion == Criterion::load_factor;
  };
  for (const CriterionResult& r : a.criteria)
    if (r.outcome == Outcome::fail && cause(r) && (!failed || r.margin < failed->margin)) failed = &r;
  for (const CriterionResult& r : a.criteria) {
    if (r.outcome == Outcome::fail && !failed) failed = &r;
    if (r.outcome == Outcome::not_assessed && !open) open = &r;
    if (r.outcome == Outcome::pass && (!passed || r.margin < passed->margin)) passed = &r;
  }
  const CriterionResult* governing = failed ? failed : open ? open : passed;
  a.verdict = failed ? Verdict::fail : open || !passed ? Verdict::not_assessed : Verdict::pass;
  if (governing) {
    a.governing = governing->criterion;
    a.margin = governing->margin;
  }
}

void add_warnings(Assessment& a, const Scene& scene, const ThrustLineSummary& line) {
  if (a.solution.ok() && line.ok && !line.in_section && !std::isnan(line.max_abs_e))
    a.warnings.push_back(fmt::format(
        "the {} line of thrust leaves the section: |e| reaches {:.4g} % of the kern (300 % is the face) "
        "{:.4g} m along the arch from the left springing",
        scene.section == SectionKind::elastic ? "elastic" : "no-tension", line.max_abs_e, line.max_abs_e_at));
  if (a.solution.status == Status::inadmissible)
    a.warnings.push_back("no line of thrust of the no-tension section stays inside the arch");
  if (limit_answered(a.limit) && a.limit.thickness_min > scene.thickness)
    a.warnings.push_back(fmt::format("t = {:.4g} m is below t_min = {:.4g} m: the arch cannot carry its loads",
                                     scene.thickness, a.limit.thickness_min));
  const double lambda = a.limit.load_factor();
  if (limit_answered(a.limit) && a.limit.ring.has_live_load() && lambda < 1)
    a.warnings.push_back(fmt::format("the collapse load factor {:.4g} is below 1: the arch does not carry its "
                                     "point and live loads",
                                     lambda));
}

}  // namespace

const char* to_string(Criterion c) {
  switch (c) {
    case Criterion::geometric_safety_factor: return "geometric_safety_factor";
    case Criterion::load_factor: return "load_factor";
    case Criterion::horizontal_load_factor: return "horizontal_load_factor";
    case Criterion::spread_capacity_ratio: return "spread_capacity_ratio";
    case Criterion::max_thrust_eccentricity: return "max_thrust_eccentricity";
  }
  return "?";
}

const char* to_string(ThrustRequirement r) {
  switch (r) {
    case ThrustRequirement::none: return "none";
    case ThrustRequirement::section: return "section";
    case ThrustRequirement::kern: return "kern";
  }
  return "?";
}

const char* to_string(Outcome o) {
  switch (o) {
    case Outcome::pass: return "pass";
    case Outcome::fail: return "fail";
    case Outcome::not_assessed: return "not_assessed";
    case Outcome::not_required: return "not_required";
    case Outcome::not_applicable: return "not_applicable";
  }
  return "?";
}

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::pass: return "pass";
    case Verdict::fail: return "fail";
    case Verdict::not_assessed: return "not_assessed";
  }
  return "?";
}

bool AssessmentCriteria::is_valid(std::string* why) const {
  const auto bad = [&](const char* field, double v) {
    if (why) *why = fmt::format("{}: must be > 0 and finite, or NaN (not required), got {}", field, v);
    return false;
  };
  for (const auto& [field, v] : {std::pair{"geometric_safety_factor", geometric_safety_factor},
                                 std::pair{"load_factor", load_factor},
                                 std::pair{"horizontal_load_factor", horizontal_load_factor},
                                 std::pair{"spread_capacity_ratio", spread_capacity_ratio}})
    if (!std::isnan(v) && !(v > 0 && std::isfinite(v))) return bad(field, v);
  return true;
}

bool AssessmentOptions::is_valid(std::string* why) const {
  return require.is_valid(why) && elastic.is_valid(why) && limit.is_valid(why) &&
         (!required(require.spread_capacity_ratio) || spread.is_valid(why));
}

Options assessment_solve_options(const Options& elastic) {
  Options o = elastic;
  o.stations = std::max(o.stations, kSummaryStations);
  o.unprinted_profile = true;
  return o;
}

Assessment assess(const Scene& scene, const AssessmentOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(why);
  return assess(scene, options, solve(scene, assessment_solve_options(options.elastic)));
}

Assessment assess(const Scene& scene, const AssessmentOptions& options, Solution solution) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(why);
  const AssessmentCriteria& need = options.require;
  Assessment a;

  a.solution = std::move(solution);
  const ThrustLineSummary line = summarize_thrust_line(a.solution);

  LimitOptions limit = options.limit;
  limit.horizontal_load_factor = required(need.horizontal_load_factor);
  a.limit = analyse_limit(scene, limit);
  const SpreadRun spread = spread_run(scene, options);
  if (required(need.spread_capacity_ratio) && scene.horizontal_acceleration == 0 && spread.unassessed.empty())
    a.spreading = analyse_spreading(scene, options.limit, spread.spread);

  a.criteria = {geometric_factor(scene, a.limit, need.geometric_safety_factor),
                load_factor(a.limit, need.load_factor),
                acceleration(a.limit, need.horizontal_load_factor),
                spreading(scene, spread, a.spreading, need.spread_capacity_ratio),
                thrust_line(a.solution, line, need.thrust)};
  decide(a);
  add_warnings(a, scene, line);
  return a;
}

}  // namespace ogive
