// The subcommands. Each add_<name>_options adds the subcommand's options to `cmd`, bound straight into
// an options object that the returned Run owns; once the command line is parsed, the Run runs the
// subcommand (CSV on `out`) and returns its exit status (cli.hpp). Bad input throws UsageError
// (values.hpp), a failed write OutputError (row_writer.hpp).
#pragma once

#include <functional>
#include <iosfwd>

namespace CLI {
class App;
}

namespace ogive::cli {

using Run = std::function<int(std::ostream& out)>;

Run add_thrust_options(CLI::App& cmd);   // reactions, one row per scene
Run add_profile_options(CLI::App& cmd);  // the fields along the arch, one row per station
Run add_check_options(CLI::App& cmd);    // every method against a reference
Run add_curve_options(CLI::App& cmd);    // the generator curve's geometry
Run add_bench_options(CLI::App& cmd);    // time and true error per method and rtol
Run add_draw_options(CLI::App& cmd);     // an SVG file per scene
Run add_limit_options(CLI::App& cmd);    // limit analysis of rigid voussoirs
Run add_report_options(CLI::App& cmd);   // an HTML page per scene
Run add_spread_options(CLI::App& cmd);   // the arch on spreading supports to collapse
Run add_assess_options(CLI::App& cmd);   // criteria and a verdict per scene

}  // namespace ogive::cli
