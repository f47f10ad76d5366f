#include "help.hpp"

#include <string>
#include <string_view>
#include <utility>

#include <CLI/CLI.hpp>

namespace ogive::cli {

void add_help_texts(CLI::App& app) {
  app.footer(
      "Units are SI: m, Pa, kg/m^3, m/s^2; forces per metre of vault length (N/m). Every numeric scene option\n"
      "takes a value, a list a,b,c or a range start:stop:count; several give their cartesian product.\n"
      "Output: CSV on stdout, an empty field for no number; exit 0 every row solved (status success),\n"
      "3 some row not, 2 bad input (one line on stderr), 4 the output could not be written, 1 internal error.\n"
      "Options, statuses and every output column: docs/cli.md; the model and its sign conventions:\n"
      "docs/model.md. `ogive SUBCOMMAND --help` lists a subcommand's options.");
  // A table rather than a map: only the subcommands registered (one, once named) look theirs up.
  static constexpr std::pair<std::string_view, std::string_view> kExamples[] = {
      {"thrust",
       "  ogive thrust --eccentricity 0:1:11                      # the paper's Figure 8, H/V against eccentricity\n"
       "  ogive thrust --curve segmental --rise-ratio 0.1:0.4:4 --thickness-ratio 0.1"},
      {"profile",
       "  ogive profile --eccentricity 0.5 --stations 41          # the equilateral arch's thrust line\n"
       "  ogive profile --support-displacement-ratio 0,0.0003     # the semicircle with spreading supports"},
      {"check",
       "  ogive check --eccentricity 0:2:5\n"
       "  ogive check --curve three-centred --rise-ratio 0.25 --rtol 1e-10"},
      {"curve",
       "  ogive curve --curve four-centred --stations 21\n"
       "  ogive curve --curve points --curve-file data/curves/parabola-40.csv"},
      {"bench",
       "  ogive bench --eccentricity 0.5 --repeats 11\n"
       "  ogive bench --curve catenary --methods shooting,auto --rtols 1e-6,1e-8,1e-10 --integrators adams,bdf"},
      {"limit",
       "  ogive limit --eccentricity 0:1:5 --thickness-ratio 0.15      # thrust range, t_min, hinges\n"
       "  ogive limit --point-load 2e5 --point-load-at 0.25 --thrust-line collapse"},
      {"draw",
       "  ogive draw --eccentricity 0.5 --output equilateral.svg\n"
       "  ogive draw --eccentricity 0,0.5,1 --support-displacement-ratio 0.0001 --output-dir pictures"},
      {"report",
       "  ogive report --eccentricity 0.5 --thickness-ratio 0.1 --output equilateral.html\n"
       "  ogive report --section no-tension --support-displacement-ratio 0.0001 --output -"},
      {"spread",
       "  ogive spread --curve semicircular --thickness-ratio 0.06:0.1:5   # spreading capacity against t\n"
       "  ogive spread --curve semicircular --thickness-ratio 0.075 --path --moving left"},
  };
  for (CLI::App* sub : app.get_subcommands({}))
    for (const auto& [name, examples] : kExamples)
      if (name == sub->get_name())
        sub->footer("Examples:\n" + std::string(examples) +
                    "\nUnits and output columns: docs/cli.md; signs: docs/model.md.");
}

}  // namespace ogive::cli
