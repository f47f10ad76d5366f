// ogive draw and ogive report: one file per scene, an SVG drawing (ogive/output/svg.hpp) or an HTML page
// (ogive/output/html_report.hpp), and one CSV row per file on stdout (--output -: the drawing or page instead).
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <functional>
#include <fstream>
#include <memory>
#include <optional>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli.hpp"
#include "columns.hpp"
#include "commands.hpp"
#include "criteria.hpp"
#include "interrupt.hpp"
#include "limit_text.hpp"
#include "ogive/limit/limit.hpp"
#include "ogive/limit/spreading.hpp"
#include "ogive/output/html_report.hpp"
#include "ogive/output/svg.hpp"
#include "ogive/solve/solve.hpp"
#include "option_text.hpp"
#include "row_writer.hpp"
#include "scene_options.hpp"
#include "scene_plan.hpp"
#include "solver_options.hpp"
#include "sweep.hpp"
#include "values.hpp"

namespace ogive::cli {
namespace {

// Scenes one draw may write: each is a file, and a sweep of thousands of pictures is a mistake.
constexpr std::size_t kMaxDrawings = 1000;

struct DrawTargets {
  std::string output;      // --output FILE: exactly one scene
  std::string output_dir;  // --output-dir DIR: one file per scene, named by draw_file_name
  bool limit = false;      // --limit: the limit analysis' minimum and maximum thrust lines too
  std::optional<double> spread_stage;  // --spread-stage: the spreading mechanism this far to collapse
};

struct DrawOptions {
  SceneOptions scene;
  CriteriaText criteria;  // report's verdict
  Options solver;
  SolverText solver_text;
  DrawTargets targets;
  ColumnText columns;
  std::string compressive_strength;  // the limit analysis' f_c as given (--compressive-strength)
};

Columns draw_columns() {
  const std::vector<std::string> results = {"method", "status", "H", "V", "H_over_V", "message", "file"};
  return Columns(results, results);
}

// The limit analysis (default options: radial joints, the voussoirs' own weight) drawn: the minimum and
// maximum thrust states as lines with their hinges (none where the arch cannot stand), and with a live
// load the collapse mechanism; under a horizontal acceleration also the collapse state of the
// acceleration a_c, with its four hinges.
void add_limit_drawing(const Scene& scene, double compressive_strength, DrawingOptions& drawing) {
  LimitOptions options;
  options.compressive_strength = compressive_strength;
  options.horizontal_load_factor = scene.horizontal_acceleration != 0;
  const LimitResult r = analyse_limit(scene, options);
  add_limit_analysis(drawing, scene, r);
}

// The options a spreading stage does not take: it starts from the arch at d = 0, both springings moving
// apart (on walls, the walls leaning), vertical loads only.
constexpr auto kStageMoves = springing_movements("the rigid voussoirs' springings move apart from d = 0");
constexpr Inapplicable kNotForSpreadStage[] = {
    {"--horizontal-acceleration", "the mechanism of rigid voussoirs carries vertical loads only"},
};

// The arch of rigid voussoirs on spreading springings (ogive spread's mechanism with its defaults: both
// springings moving, the weight on the axis; on walls, each wall leaning about its toe, a springing
// without one standing) at `fraction` of the way from d = 0 to collapse (of the walls' rotation on
// walls): its voussoirs, thrust line and hinges, and the leaning walls where they have turned; a legend
// line alone where there is no path (the arch too thin).
void add_spread_drawing(const Scene& scene, double fraction, DrawingOptions& drawing) {
  LimitOptions limit;
  limit.weight = WeightModel::axis;
  SpreadOptions spread = leaning_walls(scene, {});
  // No wall with anything to turn (no height under horizontal springing joints): the path says so, as
  // spread's row does.
  if (!(spread.left_share + spread.right_share > 0)) spread = {};
  SpreadResult r = analyse_spreading(scene, limit, spread);
  const double L = scene.span();
  if (r.status == SpreadStatus::success && fraction < 1) {
    spread.stop_ratio = fraction * r.span_rate * r.d_max / L;
    r = analyse_spreading(scene, limit, spread);
  }
  // The span's own increase (on walls not in proportion to d), as spread prints it.
  const double increase = r.path.empty() ? 0 : r.path.back().span_increase / L;
  if (std::optional<SpreadStageDrawing> stage = spread_stage_drawing(r, increase)) {
    const double d = r.path.back().d;  // on walls each leaning wall's rotation (its share is 1)
    add_leaning_walls(*stage, scene, spread.left_share * d, spread.right_share * d);
    drawing.spread_stages.push_back(std::move(*stage));
    return;
  }
  SpreadStageDrawing none;
  none.label = fmt::format("rigid voussoirs: {}: {}", to_string(r.status), r.message);
  drawing.spread_stages.push_back(std::move(none));
}

// Exactly one of --output FILE and --output-dir DIR (draw's and report's targets).
void check_target_choice(const DrawTargets& to, const char* command, const char* file, const char* one_scene) {
  if (to.output.empty() == to.output_dir.empty())
    throw UsageError(to.output.empty() ? fmt::format("--output: {} needs --output {} ({}) or --output-dir DIR (one "
                                                     "file per scene)",
                                                     command, file, one_scene)
                                       : fmt::format("--output-dir: give --output {} or --output-dir DIR, not both", file));
}

// One scene for --output, at most kMaxDrawings for --output-dir; `what` names one file's content.
void check_target_count(const DrawTargets& to, std::size_t scenes, const char* what) {
  if (!to.output.empty() && scenes > 1)
    throw UsageError(fmt::format("--output: the options give {} scenes and one file holds one {}; use "
                                 "--output-dir DIR for one file per scene", scenes, what));
  if (scenes > kMaxDrawings)
    throw UsageError(fmt::format("--output-dir: the options give {} scenes, more than {} {}s", scenes, kMaxDrawings, what));
}

// The drawing's caption: the curve, its shape parameters, span, t/L and d/L, as the options name them.
std::string draw_title(const SceneParameters& p) {
  std::string title = p.curve;
  for (const auto& [name, v] : {std::pair{"eccentricity", p.eccentricity}, std::pair{"rise ratio", p.rise_ratio},
                                std::pair{"haunch angle", p.haunch_angle}, std::pair{"crown angle", p.crown_angle}})
    if (!std::isnan(v)) title += fmt::format(", {} {:.6g}", name, v);
  // Six significant digits: a ratio derived from metres (0.3 m over 12 m) shows as 0.025, not as the
  // double's 0.024999999999999998.
  title += fmt::format(", span {:.6g} m, t/L {:.6g}", p.span, p.thickness_ratio);
  if (p.support_displacement_ratio != 0) title += fmt::format(", d/L {:.6g}", p.support_displacement_ratio);
  if (p.plane_strain) title += ", plane strain";
  for (auto [side, h, b, lean] : {std::tuple{"left", p.left_wall_height, p.left_wall_thickness, p.left_wall_lean},
                                  std::tuple{"right", p.right_wall_height, p.right_wall_thickness, p.right_wall_lean}}) {
    if (!std::isnan(h)) title += fmt::format(", {} wall {:g} m high, {:g} m thick", side, h, b);
    if (!std::isnan(h) && lean != 0) title += fmt::format(", leaning {:.6g} rad outwards", lean);
  }
  if (std::string(p.section) != "elastic") title += fmt::format(", {} section", p.section);
  const double kilonewtons = p.force_unit / 1000;  // the force options' unit in kN
  if (!std::isnan(p.point_load))
    title += fmt::format(", P {:g} kN/m at x/L {:g}", p.point_load * kilonewtons, p.point_load_at);
  if (!std::isnan(p.live_load))
    title += fmt::format(", q {:g} kN/m^2 over x/L {:g}..{:g}", p.live_load * kilonewtons, p.live_load_from,
                         p.live_load_to);
  if (!std::isnan(p.fill_density)) title += fmt::format(", fill {:g} kg/m^3 to {:g} L", p.fill_density, p.fill_height_ratio);
  if (p.horizontal_acceleration != 0) title += fmt::format(", horizontal acceleration {:g} g", p.horizontal_acceleration);
  if (p.crown_hinge) title += ", crown hinge";
  return title;
}

// The file of one scene in --output-dir: the curve, then each option that varies in the sweep with the
// scene's value, e.g. "pointed_thickness-ratio-0.2_eccentricity-0.5.svg" (the order of --help).
std::string draw_file_name(const SceneParameters& p, const SceneOptions& so, const char* extension) {
  std::string name = p.curve;
  for (const Axis& a : so.axes)
    if (a.values.size() > 1) name += fmt::format("_{}-{}", a.flag.substr(2), p.*(a.field));
  return name + extension;
}

// A new name beside `path` for a file written before it replaces `path`: of this process and of this
// call, so that two runs drawing one path (or two drawings of one run) never share it.
std::string temporary_beside(const std::string& path) {
  static std::atomic<unsigned> made{0};
  return fmt::format("{}.part-{}-{}", path, ::getpid(), made++);
}

// Whether `path` is the file standard output writes to (/dev/stdout, or the file it is redirected to),
// /dev/null aside (nothing written there mixes).
bool is_standard_output(const std::string& path) {
  struct stat target {}, standard {}, null {};
  const auto same = [](const struct stat& a, const struct stat& b) { return a.st_dev == b.st_dev && a.st_ino == b.st_ino; };
  return ::stat(path.c_str(), &target) == 0 && ::fstat(STDOUT_FILENO, &standard) == 0 && same(target, standard) &&
         !(::stat("/dev/null", &null) == 0 && same(target, null));
}

// Refuses, before anything is solved or printed, a target that cannot be written: a directory where a
// file should be, a missing directory, a file that cannot be opened for writing. Leaves no file behind:
// a scene that turns out invalid is not drawn, and its file must not appear.
void check_writable(const std::string& path, const char* flag) {
  if (path.find_first_of(",\r\n") != std::string::npos)
    throw UsageError(fmt::format("{}: the path must not contain a comma or a line break (it is printed in the CSV)", flag));
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw UsageError(fmt::format("{}: '{}' is a directory, not a file", flag, path));
  if (is_standard_output(path))
    throw UsageError(fmt::format("{}: '{}' is standard output, which carries the CSV rows: give --output - for the "
                                 "one scene's file alone on standard output, or another file",
                                 flag, path));
  // Appending leaves an existing file as it is until it is drawn; a new name is tried with a temporary
  // file of its own beside it, so that the probe never removes what another run drew there meanwhile.
  const WholeWrite whole;  // an interrupting signal must not leave the probe behind
  const bool existed = std::filesystem::exists(path, ec);
  const std::string probe_path = existed ? path : temporary_beside(path);
  errno = 0;
  std::ofstream probe(probe_path, std::ios::app);
  const int code = errno;
  if (!probe) throw UsageError(fmt::format("{}: cannot write '{}': {}", flag, path, std::strerror(code)));
  probe.close();
  if (!existed) std::filesystem::remove(probe_path, ec);
}

// The drawing into `path` whole or not at all: written to a temporary file beside it, named after this
// process and drawing (two runs drawing one path each write their own), which replaces `path` once complete and is
// removed when a write fails (a full disk leaves no partial picture); an interrupting signal waits until
// it is done. Anything but a plain file or a new name (a symlink, a device, a named pipe) is written in
// place: replacing it would replace the link or the device itself.
void write_drawing(const std::string& path, const std::string& svg) {
  const WholeWrite whole;
  std::error_code ec;
  const std::filesystem::file_status target = std::filesystem::symlink_status(path, ec);
  const bool in_place = std::filesystem::exists(target) && !std::filesystem::is_regular_file(target);
  const std::string part = in_place ? path : temporary_beside(path);
  // errno as the failing call left it: the stream's later calls may overwrite it.
  const auto fail = [&](int code) {
    if (!in_place) std::filesystem::remove(part, ec);
    throw OutputError(code != 0 ? fmt::format("cannot write {}: {}", path, std::strerror(code))
                                : fmt::format("cannot write {}", path));
  };
  errno = 0;
  std::ofstream file(part, std::ios::trunc);
  if (!file.is_open()) fail(errno);
  file << svg;
  file.flush();
  if (!file) fail(errno);
  file.close();
  if (!file) fail(errno);
  if (in_place) return;
  std::filesystem::rename(part, path, ec);
  if (ec) {
    const std::string reason = ec.message();
    std::filesystem::remove(part, ec);
    throw OutputError(fmt::format("cannot write {}: {}", path, reason));
  }
}

// The file each scene of the plan is drawn into, each checked writable.
std::vector<std::string> target_files(const ScenePlan& plan, const SceneOptions& so, const DrawTargets& to,
                                      const char* extension) {
  std::vector<std::string> files;
  if (!to.output.empty()) {
    files.push_back(to.output);
  } else {
    std::error_code ec;
    if (!std::filesystem::is_directory(to.output_dir, ec))
      throw UsageError(fmt::format("--output-dir: '{}' is not an existing directory", to.output_dir));
    std::set<std::string> seen;
    for (std::size_t i = 0; i < plan.size(); ++i) {
      const std::string name = draw_file_name(plan.parameters(i), so, extension);
      if (!seen.insert(name).second)
        throw UsageError(fmt::format("--output-dir: two scenes would both be drawn into {} (a value repeats)", name));
      files.push_back((std::filesystem::path(to.output_dir) / name).string());
    }
  }
  for (const std::string& f : files) check_writable(f, to.output.empty() ? "--output-dir" : "--output");
  return files;
}

// The one solver combination a picture is drawn with.
Options drawing_solver(const DrawOptions& d) {
  const SolverSweep sweep = solver_sweep(d.solver, d.solver_text);
  if (sweep.combinations.size() != 1)
    throw UsageError("--rtol: draw takes one method, integrator and rtol (a picture per scene)");
  return sweep.combinations.front();
}

// The solver options of draw and report, checked, and their file names refused when empty.
Options checked_picture_options(const DrawOptions& d, const CLI::App& cmd, const char* output_rule) {
  const Options o = drawing_solver(d);
  check_stations(o.stations);
  check_options(o);
  refuse_empty_name(cmd, "--output", d.targets.output, output_rule);
  refuse_empty_name(cmd, "--output-dir", d.targets.output_dir, "an existing directory, . for the current one");
  return o;
}

// The CSV row of one picture (a drawing or a report): the scene, its solve and the file written.
std::string picture_row(const Columns& columns, const SceneParameters& p, const Scene& scene, const Solution& sol,
                        const std::string& path) {
  CsvRow row(columns.keep());
  add_scene_columns(row, p, scene.curve.get());
  row.add(to_string(sol.method)).add(to_string(sol.status)).add(sol.H).add(sol.V).add(sol.H_over_V);
  row.add(sol.message).add(path);
  return row.take();
}

// --output -: the one scene's drawing or page alone on standard output (no CSV row), with the exit status
// that --output FILE would have; a scene that cannot be analysed is refused with one line, as there is
// no row to say so. page(p, scene, sol) makes the text and leaves its solve in sol.
using Page = std::function<std::string(const SceneParameters&, const Scene&, Solution&)>;
int page_to_standard_output(const ScenePlan& plan, std::ostream& out, const Page& page) {
  const SceneParameters p = plan.parameters(0);
  const ScenePlan::Built built = plan.build(p);
  if (!built.scene) throw UsageError(built.problem);
  Solution sol;
  std::string text;
  try {
    text = page(p, *built.scene, sol);
  } catch (const std::invalid_argument& e) {
    throw UsageError(plan.problem_words(e.what()));
  }
  write_all(out, text);
  return sol.ok() ? kExitOk : kExitNotConverged;
}

int run_draw(DrawOptions& d, const CLI::App& cmd, std::ostream& out) {
  Columns columns = draw_columns();
  if (d.columns.columns == "help") {
    write_all(out, columns.help(d.columns));
    return kExitOk;
  }
  const Options o = checked_picture_options(d, cmd, "a file name ending in .svg, or - for standard output");
  const DrawTargets& to = d.targets;
  check_target_choice(to, "draw", "FILE.svg", "one scene");
  if (to.spread_stage) {
    if (!(*to.spread_stage >= 0 && *to.spread_stage <= 1))
      throw UsageError(fmt::format("--spread-stage: must lie in [0, 1] (0: d = 0, 1: collapse), got {}", *to.spread_stage));
    refuse_inapplicable(cmd, "draw --spread-stage", kStageMoves);
    refuse_inapplicable(cmd, "draw --spread-stage", kNotForSpreadStage);
  }
  const double compressive_strength = compressive_strength_of(d.compressive_strength, cmd);
  if (std::isfinite(compressive_strength) && !to.limit)
    throw UsageError("--compressive-strength: the strength of the rigid voussoirs of --limit's analysis; give --limit");
  const ScenePlan plan(d.scene, cmd);
  check_target_count(to, plan.size(), "drawing");
  const auto drawing_of = [&](const SceneParameters& p, const Scene& scene, Solution& sol) {
    sol = solve(scene, o);
    DrawingOptions drawing;
    drawing.title = draw_title(p);
    if (to.limit) add_limit_drawing(scene, compressive_strength, drawing);
    add_wall_resultants(drawing, scene, sol);
    if (to.spread_stage) add_spread_drawing(scene, *to.spread_stage, drawing);
    return arch_svg(scene, sol, drawing);
  };
  if (to.output == "-") return page_to_standard_output(plan, out, drawing_of);
  columns.select(d.columns, plan.varying_inputs());
  const std::vector<std::string> files = target_files(plan, d.scene, to, ".svg");
  const bool all_ok = write_scenes(
      plan, columns, out, 1,  // one file at a time
      [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        Solution sol;
        const std::string svg = drawing_of(p, scene, sol);
        const std::string& path = files[p.scene - 1];
        write_drawing(path, svg);
        emit(picture_row(columns, p, scene, sol, path));
        return sol.ok();
      });
  return all_ok ? kExitOk : kExitNotConverged;
}

// The inputs as given on the command line, option by option in the order of --help.
std::vector<std::pair<std::string, std::string>> given_inputs(const CLI::App& cmd) {
  std::vector<std::pair<std::string, std::string>> inputs;
  for (const CLI::Option* o : cmd.get_options()) {
    if (o->count() == 0 || o->get_name() == "--output" || o->get_name() == "--output-dir") continue;
    std::string value;
    for (const std::string& r : o->results()) value += (value.empty() ? "" : " ") + r;
    inputs.emplace_back(o->get_name(), value);
  }
  return inputs;
}

// Today's date (UTC, YYYY-MM-DD), or SOURCE_DATE_EPOCH's where it is set (the reproducible-builds
// convention: a page made twice from the same inputs is then the same bytes).
std::string report_date() {
  std::time_t now = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) {
    char* end = nullptr;
    const long long seconds = std::strtoll(epoch, &end, 10);
    if (end != epoch && *end == '\0' && seconds >= 0) now = static_cast<std::time_t>(seconds);
  }
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[16];
  std::strftime(text, sizeof text, "%Y-%m-%d", &utc);
  return text;
}

int run_report(DrawOptions& d, const CLI::App& cmd, std::ostream& out) {
  Columns columns = draw_columns();
  if (d.columns.columns == "help") {
    write_all(out, columns.help(d.columns));
    return kExitOk;
  }
  const Options o = checked_picture_options(d, cmd, "a file name ending in .html, or - for standard output");
  const DrawTargets& to = d.targets;
  check_target_choice(to, "report", "FILE.html", "one scene; - for standard output");
  const ScenePlan plan(d.scene, cmd);
  check_target_count(to, plan.size(), "report");
  ReportOptions report;
  report.solver = o;
  report.inputs = given_inputs(cmd);
  report.require = criteria_of(d.criteria);
  report.limit.compressive_strength = compressive_strength_of(d.compressive_strength, cmd);
  report.warnings = default_warnings(cmd, d.scene.curve);
  report.date = report_date();
  if (to.output == "-")
    return page_to_standard_output(plan, out, [&](const SceneParameters& p, const Scene& scene, Solution& sol) {
      report.title = draw_title(p);
      sol = report_solution(scene, report);
      return html_report(scene, sol, report);
    });
  columns.select(d.columns, plan.varying_inputs());
  const std::vector<std::string> files = target_files(plan, d.scene, to, ".html");
  const bool all_ok = write_scenes(plan, columns, out, 1, [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
    report.title = draw_title(p);
    const std::string& path = files[p.scene - 1];
    const Solution sol = report_solution(scene, report);
    write_drawing(path, html_report(scene, sol, report));
    emit(picture_row(columns, p, scene, sol, path));
    return sol.ok();
  });
  return all_ok ? kExitOk : kExitNotConverged;
}

// The options draw and report share: the scene, the solver, the stations, the targets, the columns.
std::shared_ptr<DrawOptions> add_picture_options(CLI::App& cmd, const char* output_help) {
  auto options = std::make_shared<DrawOptions>();
  options->solver.stations = 101;
  DrawTargets& to = options->targets;
  add_scene_options(cmd, options->scene);
  add_solver_options(cmd, options->solver, options->solver_text);
  cmd.add_option("--stations", options->solver.stations,
                 "points of the thrust line, springing to springing; must lie in [2, 1000000]")
      ->check(whole_count())
      ->capture_default_str();
  add_compressive_strength_option(cmd, options->compressive_strength,
                                  "the limit analysis' joints crush (stress blocks at its hinges); omitted: infinite "
                                  "strength");
  cmd.add_option("--output", to.output, output_help);
  return options;
}

}  // namespace

Run add_draw_options(CLI::App& cmd) {
  auto options = add_picture_options(cmd, "the SVG file of the one scene (refused for a sweep); - writes the drawing to standard output");
  DrawTargets& to = options->targets;
  cmd.add_flag("--limit", to.limit,
               "also draw the limit analysis' minimum and maximum thrust lines with their hinges and, with a point "
               "or live load, the collapse mechanism (ogive limit's defaults: radial joints, the voussoirs' weight)");
  cmd.add_option("--spread-stage", to.spread_stage,
                 "also draw the arch of rigid voussoirs on spreading springings (ogive spread's mechanism, its "
                 "defaults) this far from d = 0 (0) to collapse (1), where its voussoirs have moved, with its thrust "
                 "line and hinges (on walls, the walls leaning about their toes); in [0, 1]")
      ->check(finite_number());
  cmd.add_option("--output-dir", to.output_dir,
                 "an existing directory: one SVG per scene, named after the curve and the options that vary");
  add_column_options(cmd, options->columns);
  return [options, &cmd](std::ostream& out) { return run_draw(*options, cmd, out); };
}

Run add_report_options(CLI::App& cmd) {
  auto options = add_picture_options(
      cmd, "the HTML file of the one scene (refused for a sweep); - writes the page to standard output");
  add_criteria_options(cmd, options->criteria);
  cmd.add_option("--output-dir", options->targets.output_dir,
                 "an existing directory: one HTML page per scene, named after the curve and the options that vary");
  add_column_options(cmd, options->columns);
  return [options, &cmd](std::ostream& out) { return run_report(*options, cmd, out); };
}

}  // namespace ogive::cli
