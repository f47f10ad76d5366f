// The solver options of a command, bound straight into ogive::Options; --method, --integrator and
// --rtol are bound as text, take lists (and --rtol ranges) like the scene options, and each
// combination is a row of its own, after the scene's (rtol fastest).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ogive/solve/solve.hpp"

namespace CLI {
class App;
}

namespace ogive::cli {

struct SolverText {
  std::string method = "auto";
  std::string integrator = "adams";
  std::string rtol = "1e-8";  // a value, a list or a range, like a scene option
  bool no_verify = false;
  bool ignore_breakpoints = false;
};

// with_method false: the command chooses its methods itself (check); plurals: --methods, --integrators
// and --rtols are accepted too (bench).
void add_solver_options(CLI::App& cmd, Options& o, SolverText& text, bool with_method = true, bool plurals = false);

struct SolverSweep {
  std::vector<Options> combinations;
  std::vector<std::string> varying;  // the columns among method, integrator and rtol that take several values
};

// Every combination of the listed methods, integrators and rtols, each checked (UsageError).
SolverSweep solver_sweep(Options base, const SolverText& text, bool with_method = true);

// UsageError naming the option when the options break a rule of the library's.
void check_options(const Options& o);

// The integrator column: CVODE's method, empty for the methods that use none.
std::string_view integrator_of(Method method, const Options& o);

}  // namespace ogive::cli
