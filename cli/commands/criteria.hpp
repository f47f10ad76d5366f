// What assess and report share: the criteria of an assessment as options (--require-*), and the
// warnings about inputs that were left at their defaults.
#pragma once

#include <string>
#include <vector>

#include "ogive/solve/assessment.hpp"

namespace CLI {
class App;
}

namespace ogive::cli {

// The --require-* options as given: a number > 0, or none (not required); --require-thrust a word.
struct CriteriaText {
  std::string geometric_factor = "2", load_factor = "2", acceleration = "none", spread = "none";
  std::string thrust = "none";
};

void add_criteria_options(CLI::App& cmd, CriteriaText& text);

// The criteria, or UsageError naming the option and its rule.
AssessmentCriteria criteria_of(const CriteriaText& text);

// The scene options an assessment depends on that were left at their defaults, each as a warning in
// words ("--span not given: the default span of 10 m is used"): the span (unless a points file gives
// it), the thickness and the density.
std::vector<std::string> default_warnings(const CLI::App& cmd, const std::string& curve);

}  // namespace ogive::cli
