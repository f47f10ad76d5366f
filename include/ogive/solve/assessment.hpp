// An assessment of one scene: the analyses that apply, each compared with a required value, and one
// verdict. It runs no analysis of its own: the elastic (or cracking) arch is solve()'s, the thickness
// factor, the load factor and the collapse acceleration are analyse_limit()'s, the spreading capacity is
// analyse_spreading()'s, each with the options given here.
//
// The criteria (each off unless required; AssessmentCriteria's defaults switch on the first two):
//   geometric_safety_factor  t / t_min >= required (Heyman's geometric factor of safety, 2 to 3 in his
//                            work: the arch is `required` times as thick as the thinnest arch of the same
//                            shape that carries the same loads);
//   load_factor              the collapse load factor of the point and live loads >= required (only
//                            where the scene has a point or live load: otherwise not_applicable);
//   horizontal_load_factor   the horizontal acceleration of collapse a_c (a fraction of g) >= required;
//   spread_capacity_ratio    the span's increase at collapse on spreading springings, over the span (both
//                            springings moving outwards; on walls, the walls leaning outwards about their
//                            toes, a side without a wall standing still, and the increase the springings'
//                            own: spread_capacity_ratio() of spreading.hpp), >= required (not assessed on
//                            walls with a finite compressive strength);
//   max_thrust_eccentricity  the largest |e| of the scene's own line of thrust (elastic or no-tension
//                            section, solve()'s), in per cent of the kern, <= 300 (inside the section) or
//                            <= 100 (inside the kern).
// A criterion's margin is value / required (required / value for the eccentricity, which is a most):
// >= 1 exactly where it passes.
//
// The verdict: fail when any criterion fails (its numbers are answers: an arch too thin to stand has
// t / t_min below 1 and fails, it is not "not assessed"); else not_assessed when any required
// criterion could not be assessed (an LP or a solve stopped without an answer, a number that did not
// converge); else pass. The governing criterion: the failed one of least margin, else the unassessed
// one, else the passed one of least margin.
//
// Units: SI (m, N per metre of vault width); accelerations in g.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "ogive/core/solution.hpp"
#include "ogive/limit/limit.hpp"
#include "ogive/limit/spreading.hpp"
#include "ogive/model/scene.hpp"

namespace ogive {

enum class Criterion {
  geometric_safety_factor,
  load_factor,
  horizontal_load_factor,
  spread_capacity_ratio,
  max_thrust_eccentricity,
};
const char* to_string(Criterion c);

// Where the line of thrust must stay: no requirement, inside the section (|e| <= 300 % of the kern) or
// inside the kern (|e| <= 100 %: no tension in an elastic section).
enum class ThrustRequirement { none, section, kern };
const char* to_string(ThrustRequirement r);

enum class Outcome {
  pass,            // value meets required
  fail,            // value misses required
  not_assessed,    // required, but the analysis gave no trustworthy value (the reason says why)
  not_required,    // not asked for
  not_applicable,  // asked for, but meaningless for this scene (a load factor without a live load)
};
const char* to_string(Outcome o);

enum class Verdict { pass, fail, not_assessed };
const char* to_string(Verdict v);

struct AssessmentCriteria {
  // Each required value is > 0, or NaN: not required. Finite where given.
  double geometric_safety_factor = 2;
  double load_factor = 2;
  double horizontal_load_factor = std::numeric_limits<double>::quiet_NaN();  // g
  double spread_capacity_ratio = std::numeric_limits<double>::quiet_NaN();
  ThrustRequirement thrust = ThrustRequirement::none;
  bool is_valid(std::string* why) const;
};

struct AssessmentOptions {
  AssessmentCriteria require;
  Options elastic;     // the scene's own solve (its section: Scene::section)
  LimitOptions limit;  // the rigid-block analyses (its horizontal_load_factor is set here as required)
  // The spreading path (both springings outwards unless said): its limit options are `limit`'s.
  SpreadOptions spread;
  bool is_valid(std::string* why) const;
};

struct CriterionResult {
  Criterion criterion = Criterion::geometric_safety_factor;
  Outcome outcome = Outcome::not_required;
  double value = std::numeric_limits<double>::quiet_NaN();     // NaN where not assessed
  double required = std::numeric_limits<double>::quiet_NaN();  // NaN where not required
  double margin = std::numeric_limits<double>::quiet_NaN();    // >= 1 where it passes
  std::string reason;  // why it is not assessed or not applicable; empty otherwise
};

struct Assessment {
  Verdict verdict = Verdict::not_assessed;
  Criterion governing = Criterion::geometric_safety_factor;
  double margin = std::numeric_limits<double>::quiet_NaN();  // the governing criterion's
  // One per Criterion, in the enum's order (criteria[static_cast<int>(c)] is c's).
  std::vector<CriterionResult> criteria;
  // What an engineer must read even where no criterion asks for it, in words: the line of thrust leaving
  // the section, t below t_min, a load factor below 1.
  std::vector<std::string> warnings;
  Solution solution;      // the scene's own solve
  LimitResult limit;      // its rigid-block analysis
  SpreadResult spreading; // its spreading path (status lp_failure and an empty path where not required)
  const CriterionResult& operator[](Criterion c) const { return criteria[static_cast<int>(c)]; }
};

// Throws std::invalid_argument naming the field for an invalid scene or options (as solve and
// analyse_limit do).
Assessment assess(const Scene& scene, const AssessmentOptions& options);

// The options of assess's own solve of the scene: `elastic` with the field kept for the thrust line's
// summary (Options::unprinted_profile, at least kSummaryStations stations for the error estimate).
Options assessment_solve_options(const Options& elastic);
// The same with that solve given: `solution` must be solve(scene, assessment_solve_options(options.elastic))
// (a caller that reads it too, a page that draws it, solves once; it may have sampled a profile since,
// sample_profile). The scene is not solved again.
Assessment assess(const Scene& scene, const AssessmentOptions& options, Solution solution);

}  // namespace ogive
