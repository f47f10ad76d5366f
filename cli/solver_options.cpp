#include "solver_options.hpp"

#include <map>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "option_text.hpp"
#include "values.hpp"

namespace ogive::cli {
namespace {

const std::map<std::string, Method> kMethods = {{"closed-form", Method::closed_form},
                                                {"shooting", Method::shooting},
                                                {"multiple-shooting", Method::multiple_shooting},
                                                {"quadrature", Method::quadrature},
                                                {"auto", Method::automatic}};
const std::map<std::string, Integrator> kIntegrators = {{"adams", Integrator::adams}, {"bdf", Integrator::bdf}};

}  // namespace

void add_solver_options(CLI::App& cmd, Options& o, SolverText& text, bool with_method, bool plurals) {
  if (with_method)
    cmd.add_option(plurals ? "--method,--methods" : "--method", text.method,
                   "closed-form (circular arcs only), quadrature (the force method, every curve), shooting, "
                   "multiple-shooting or auto (the closed form where it applies, else the quadrature where its estimate "
                   "meets --rtol, else shooting with 1, 2, 4 .. 64 segments until the error estimate meets --rtol); a "
                   "list a,b gives a row for each")
        ->capture_default_str();
  cmd.add_option(plurals ? "--integrator,--integrators" : "--integrator", text.integrator,
                 "CVODE's method: adams or bdf (the closed form uses none); a list a,b gives a row for each")
      ->capture_default_str();
  cmd.add_option(plurals ? "--rtol,--rtols" : "--rtol", text.rtol,
                 "relative error asked of every printed number; must lie in [1e-14, 0.1]; status success "
                 "guarantees it. CVODE itself runs at rtol/10 (adams) or rtol/1000 (bdf), and a verifying solve "
                 "at rtol/16. A value, a list a,b,c or a range start:stop:count: a row for each")
      ->capture_default_str();
  cmd.add_option("--atol", o.atol,
                 "CVODE's absolute tolerance on the scaled state; must be >= 0 (0: 1e-6 of CVODE's rtol); a "
                 "verified solve uses the smaller of atol and that default (/16 for its second solve), "
                 "--no-verify atol as given")
      ->check(finite_number())
      ->capture_default_str();
  cmd.add_option("--segments", o.segments,
                 "multiple-shooting segments over the domain (breakpoints and loads add more); must lie in [1, 10000]")
      ->check(whole_count())
      ->capture_default_str();
  cmd.add_option("--max-steps", o.max_steps, "CVODE step limit per integration span; must be >= 1")
      ->check(whole_count())
      ->capture_default_str();
  cmd.add_flag("--no-verify", text.no_verify,
               "skip the second solve at rtol/16 that estimates the error (raw methods, for benchmarks): the "
               "status is then at best unverified, never success; auto always verifies");
  cmd.add_flag("--ignore-breakpoints", text.ignore_breakpoints,
               "let CVODE step across jumps of curvature (for stability studies)");
  cmd.add_flag("--whole-arch", o.whole_arch,
               "solve a symmetric scene over the whole arch too (a check; by default the half, the smaller model)");
}

void check_options(const Options& o) {
  std::string why;
  if (!o.is_valid(&why)) throw UsageError(as_option_message(why));
}

SolverSweep solver_sweep(Options base, const SolverText& text, bool with_method) {
  base.verify = !text.no_verify;
  base.restart_at_breakpoints = !text.ignore_breakpoints;
  std::vector<Method> methods;
  for (const std::string& name : with_method ? split_names(text.method) : std::vector<std::string>{"auto"})
    methods.push_back(lookup(kMethods, name, "--method"));
  std::vector<Integrator> integrators;
  for (const std::string& name : split_names(text.integrator))
    integrators.push_back(lookup(kIntegrators, name, "--integrator"));
  const std::vector<double> rtols = parse_values(text.rtol, "--rtol");
  SolverSweep sweep;
  for (Method m : methods)
    for (Integrator i : integrators)
      for (double rtol : rtols) {
        Options o = base;
        o.method = m;
        o.integrator = i;
        o.rtol = rtol;
        check_options(o);
        sweep.combinations.push_back(o);
      }
  if (sweep.combinations.size() > kMaxValues)
    throw UsageError(fmt::format("--rtol: the solver options give more than {} combinations", kMaxValues));
  if (methods.size() > 1) sweep.varying.push_back("method");
  if (integrators.size() > 1) sweep.varying.push_back("integrator");
  if (rtols.size() > 1) sweep.varying.push_back("rtol");
  return sweep;
}

std::string_view integrator_of(Method method, const Options& o) {
  return method == Method::closed_form || method == Method::quadrature ? std::string_view{} : to_string(o.integrator);
}

}  // namespace ogive::cli
