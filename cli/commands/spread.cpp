// ogive spread: the arch on spreading walls, to collapse. One row per scene: the elastic thrust at
// d = 0, the plateau (the limit analysis' minimum thrust, which the cracking arch falls to), the rigid
// voussoirs' spreading capacity and their state at collapse; or (--path) the whole curve: the elastic
// arch at d = 0, the cracking arch (no-tension section) at small spreads, the three-hinge mechanism of
// rigid voussoirs (analyse_spreading) from d = 0 to collapse. docs/spreading.md tells how they join.
#include <algorithm>
#include <cmath>
#include <cstddef>
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
#include "ogive/limit/spreading.hpp"
#include "ogive/solve/solve.hpp"
#include "option_text.hpp"
#include "row_writer.hpp"
#include "scene_options.hpp"
#include "scene_plan.hpp"
#include "sweep.hpp"
#include "values.hpp"

namespace ogive::cli {
namespace {

enum class MovingSprings { left, right, both };
const std::map<std::string, MovingSprings> kMovingSprings = {
    {"left", MovingSprings::left}, {"right", MovingSprings::right}, {"both", MovingSprings::both}};

// Each moving springing's movement over the span along the cracking part: d = 0, then two a decade up
// to 1e-2, the largest movement the small-displacement theory of the elastic arch takes (the rule of
// --support-displacement-ratio), where the cracking arch's H/V lies within about 1 % of the plateau.
constexpr double kCrackingMoves[] = {0, 1e-6, 3e-6, 1e-5, 3e-5, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2};
// A springing's settlement per unit of its outward movement, at most: the cracking part's movements are
// scaled down so that no component exceeds 1e-2 of the span.
constexpr double kMostSettlementShare = 10;

struct SpreadText {
  std::string weight = "axis", moving = "both", joints = "radial";
  int joints_count = kDefaultJointsCount;
  int steps = SpreadOptions{}.steps;
  double increment_ratio = SpreadOptions{}.increment_ratio;
  double left_settlement_share = 0, right_settlement_share = 0;
  std::string compressive_strength;  // as given (--compressive-strength)
  double friction = 0;
  bool path = false;
  int threads = 1;
};

struct SpreadCommandOptions {
  SceneOptions scene;
  SpreadText text;
  ColumnText columns;
};

// The scene options whose values spread sets itself, and those it cannot take: refused when given, and
// left out of its --help.
constexpr auto kSpreadMoves = springing_movements("spread moves the springings itself: --moving chooses which");
constexpr Inapplicable kNotForSpread[] = {
    {"--section", "spread solves the elastic section at d = 0 and the no-tension section along the spread"},
    {"--horizontal-acceleration", "the mechanism of rigid voussoirs carries vertical loads only"},
};

void add_spread_analysis_options(CLI::App& cmd, SpreadText& t) {
  cmd.add_option("--moving", t.moving,
                 "the springings that move outwards: left, right or both (on walls: the walls that lean outwards, "
                 "turning about their bases' outer toes, both by the same rotation)")
      ->capture_default_str();
  cmd.add_option("--left-settlement-share", t.left_settlement_share,
                 "the left springing's settlement (downwards positive) per unit of d, the outward movement of each "
                 "springing --moving moves: it moves along a sloping line (or settles only, without --moving left or "
                 "both); in [-10, 10]")
      ->check(finite_number())
      ->capture_default_str();
  cmd.add_option("--right-settlement-share", t.right_settlement_share,
                 "the right springing's settlement per unit of d, as --left-settlement-share; in [-10, 10]")
      ->check(finite_number())
      ->capture_default_str();
  cmd.add_option("--weight", t.weight,
                 "rigid voussoirs' weight: axis (rho g t per axis length, the elastic arch's, so that the cracking "
                 "arch's plateau is the mechanism's start) or voussoir (the true weight at each centroid)")
      ->capture_default_str();
  cmd.add_option("--joints", t.joints, "rigid voussoirs' interior joints: radial (normal to the axis) or vertical")
      ->capture_default_str();
  cmd.add_option("--joints-count", t.joints_count, fmt::format("rigid voussoirs' joints springing to springing, both included; odd, in [{}, {}]",
                             kMinJointsCount, kMaxJointsCount))
      ->check(whole_count())
      ->capture_default_str();
  cmd.add_option("--steps", t.steps, "rows of the mechanism's path from d = 0 to collapse (with --path), in [1, 100000]")
      ->check(whole_count())
      ->capture_default_str();
  cmd.add_option("--increment-ratio", t.increment_ratio,
                 "the span's increase over L between two solutions of the mechanism's minimum-thrust state (where "
                 "its hinges may roll to other joints), in [1e-4, 0.1]")
      ->check(finite_number())
      ->capture_default_str();
  add_compressive_strength_option(cmd, t.compressive_strength,
                                  "the rigid voussoirs' joints crush: each hinge's resultant crosses its stress block's "
                                  "centre, N / (2 f_c) inside its face, and its blocks turn about the block's inner "
                                  "edge, N / f_c inside; on walls each wall's resultant must also cross its beds "
                                  "N / (2 f_c) inside their faces; omitted: infinite strength");
  cmd.add_option("--friction", t.friction,
                 "friction coefficient of the joints (> 0): the path ends where a joint's resultant leaves the "
                 "friction cone (collapse sliding; on walls also a wall's resultant at one of its beds)")
      ->check(finite_number());
  cmd.add_flag("--path", t.path,
               "instead of the summary, the whole curve: the elastic arch at d = 0, the cracking arch, the mechanism "
               "to collapse, one row per point");
}

struct SpreadSetup {
  LimitOptions limit;
  SpreadOptions spread;
  bool left_moves = true, right_moves = true;
  bool walls = false;  // the springings stand on walls, which lean (the movement d is their rotation, rad)
};

// On walls the walls' rotation moves the springings: no settlement share, and a moving side needs its
// wall.
void check_on_walls(const CLI::App& cmd, const SpreadSetup& s) {
  for (const char* flag : {"--left-settlement-share", "--right-settlement-share"})
    if (given(cmd, flag))
      throw UsageError(fmt::format("{}: does not apply to spread on walls (the walls' rotation about their toes moves "
                                   "the springings)",
                                   flag));
  const bool both = given(cmd, "--wall-height");
  if (s.left_moves && !both && !given(cmd, "--left-wall-height"))
    throw UsageError("--moving: the left springing moves, but it stands on no wall (give --left-wall-height or --moving right)");
  if (s.right_moves && !both && !given(cmd, "--right-wall-height"))
    throw UsageError("--moving: the right springing moves, but it stands on no wall (give --right-wall-height or --moving left)");
}

SpreadSetup spread_setup(const SpreadText& t, const CLI::App& cmd) {
  refuse_inapplicable(cmd, "spread", kSpreadMoves);
  refuse_inapplicable(cmd, "spread", kNotForSpread);
  SpreadSetup s;
  s.limit.weight = lookup(weight_models(), t.weight, "--weight");
  s.limit.joints = lookup(joint_orientations(), t.joints, "--joints");
  s.limit.joints_count = t.joints_count;
  s.limit.compressive_strength = compressive_strength_of(t.compressive_strength, cmd);
  if (given(cmd, "--friction") && !(t.friction > 0))
    throw UsageError(fmt::format("--friction: must be > 0 (omit it for no sliding check), got {}", t.friction));
  s.limit.friction = t.friction;
  const MovingSprings moving = lookup(kMovingSprings, t.moving, "--moving");
  s.left_moves = moving != MovingSprings::right;
  s.right_moves = moving != MovingSprings::left;
  s.spread.left_share = s.left_moves ? 1 : 0;
  s.spread.right_share = s.right_moves ? 1 : 0;
  for (const auto& [share, name] : {std::pair{t.left_settlement_share, "--left-settlement-share"},
                                    std::pair{t.right_settlement_share, "--right-settlement-share"}})
    if (!(share >= -kMostSettlementShare && share <= kMostSettlementShare))
      throw UsageError(fmt::format("{}: must lie in [-{}, {}], got {}", name, kMostSettlementShare,
                                   kMostSettlementShare, share));
  s.spread.left_settlement_share = t.left_settlement_share;
  s.spread.right_settlement_share = t.right_settlement_share;
  if (t.steps < 1 || t.steps > 100000)
    throw UsageError(fmt::format("--steps: must lie in [1, 100000], got {}", t.steps));
  std::string why;
  s.spread.steps = t.steps;
  s.spread.increment_ratio = t.increment_ratio;
  s.spread.whole_path = t.path;  // the summary needs the state at d = 0 and the last one only
  if (!(t.increment_ratio >= kLeastIncrementRatio && t.increment_ratio <= 0.1))
    throw UsageError(fmt::format("--increment-ratio: must lie in [1e-4, 0.1] (finer increments take longer "
                                 "without moving the capacity: docs/spreading.md), got {}",
                                 t.increment_ratio));
  if (!s.limit.is_valid(&why)) throw UsageError(as_option_message(why));
  s.walls = walls_given(cmd);
  if (s.walls) check_on_walls(cmd, s);
  return s;
}

Columns spread_columns(bool path, bool walls) {
  std::vector<std::string> results = {"moving", "left_settlement_share", "right_settlement_share", "joints", "weight",
                                      "joints_count", "compressive_strength", "path_steps", "friction"};
  // The summary: the elastic arch at d = 0, the plateau, the capacity and the state at collapse.
  std::vector<std::string> summary = {
      "status", "H_elastic", "V_elastic", "H_over_V_elastic", "H_plateau", "V_plateau", "H_over_V_plateau",
      "spread_capacity_ratio", "collapse", "H_collapse", "V_collapse", "H_over_V_collapse", "crown_drop_ratio",
      "hinges", "hinges_at_collapse", "message"};
  // --path: one row per point of the curve.
  std::vector<std::string> points = {"part", "spread_ratio", "status", "H", "V", "V_right", "H_over_V",
                                     "crown_drop_ratio", "hinges", "collapse", "message"};
  // On walls: their lean (shown by default only there).
  const std::vector<std::string> lean = {"left_wall_rotation_collapse", "right_wall_rotation_collapse",
                                         "left_wall_top_displacement_collapse", "right_wall_top_displacement_collapse"};
  std::vector<std::string> own = path ? points : summary;
  results.insert(results.end(), own.begin(), own.end());
  if (!path) results.push_back("sliding_joint");
  if (path) results.push_back("wall_rotation");
  else results.insert(results.end(), lean.begin(), lean.end());
  if (walls && path) own.push_back("wall_rotation");
  if (walls && !path) own.insert(own.end(), lean.begin(), lean.end());
  return Columns(results, own);
}

void add_setup(CsvRow& row, const SpreadText& t, const SpreadSetup& s) {
  row.add(t.moving).add(s.spread.left_settlement_share).add(s.spread.right_settlement_share);
  row.add(to_string(s.limit.joints)).add(to_string(s.limit.weight)).add(s.limit.joints_count);
  row.add(std::isfinite(s.limit.compressive_strength) ? s.limit.compressive_strength
                                                      : std::numeric_limits<double>::quiet_NaN());
  row.add(s.spread.steps);
  row.add(s.limit.friction > 0 ? s.limit.friction : std::numeric_limits<double>::quiet_NaN());
}

// The crown's drop (m, downwards positive) of a solved elastic or cracking arch; NaN without a field.
double crown_drop(const Scene& scene, const Solution& sol) {
  if (!sol.field || !(sol.status == Status::success || sol.status == Status::ill_conditioned))
    return std::numeric_limits<double>::quiet_NaN();
  return -sol.at(scene.curve->crown()).Uy;
}

// A solve's answer: success, or an arch that cannot stand as a no-tension arch.
bool answered(const Solution& sol) { return sol.ok() || sol.status == Status::inadmissible; }

// Whether a row gives the path's numbers: a success, or a path whose capacity is not within the
// tolerance (the finest ring's, as limit gives its not_converged collapse), the status and message saying so.
bool has_numbers(const SpreadResult& r) {
  return r.status == SpreadStatus::success || r.status == SpreadStatus::not_converged;
}

std::string summary_row(const Columns& columns, const SceneParameters& p, const Scene& scene, const SpreadText& t,
                        const SpreadSetup& s, const Solution& elastic, const SpreadResult& r) {
  const double L = scene.span();
  CsvRow row(columns.keep());
  add_scene_columns(row, p, scene.curve.get());
  add_setup(row, t, s);
  row.add(to_string(r.status)).add(elastic.H).add(elastic.V).add(elastic.H_over_V);
  const auto no_lean = [&row] {
    for (int k = 0; k < 4; ++k) row.add(std::string_view{});
  };
  if (r.path.empty()) {
    for (int k = 0; k < 11; ++k) row.add(std::string_view{});
    row.add(r.message).add(std::string_view{});
    no_lean();
    return row.take();
  }
  const SpreadStep& first = r.path.front();
  const SpreadStep& last = r.path.back();
  row.add(first.H).add(first.V_left).add(first.H / first.V_left);  // the plateau, whenever d = 0 stands
  if (!has_numbers(r)) {
    for (int k = 0; k < 8; ++k) row.add(std::string_view{});
    row.add(r.message).add(std::string_view{});
    no_lean();
    return row.take();
  }
  row.add(spread_capacity_ratio(r, s.spread));
  row.add(to_string(r.collapse));
  row.add(last.H).add(last.V_left).add(last.H / last.V_left).add(last.crown_drop / L);
  row.add(hinge_text(first.hinges, L)).add(hinge_text(last.hinges, L));
  row.add(r.message);
  if (r.collapse == SpreadCollapse::sliding && std::isfinite(r.sliding_point.x())) row.add(r.sliding_point.x() / L);
  else row.add(std::string_view{});
  for (const double lean : {r.left_wall_rotation, r.right_wall_rotation, r.left_wall_top_displacement,
                            r.right_wall_top_displacement})
    if (std::isfinite(lean)) row.add(lean);
    else row.add(std::string_view{});
  return row.take();
}

// One row of the elastic or cracking part: a solve of the continuous arch.
std::string solve_row(const Columns& columns, const SceneParameters& p, const Scene& scene, const SpreadText& t,
                      const SpreadSetup& s, std::string_view part, double spread_ratio, const Solution& sol,
                      double wall_rotation = std::numeric_limits<double>::quiet_NaN()) {
  CsvRow row(columns.keep());
  add_scene_columns(row, p, scene.curve.get());
  add_setup(row, t, s);
  row.add(part).add(spread_ratio).add(to_string(sol.status)).add(sol.H).add(sol.V);
  row.add(sol.field ? sol.reactions.V_right : std::numeric_limits<double>::quiet_NaN()).add(sol.H_over_V);
  row.add(crown_drop(scene, sol) / scene.span()).add(std::string_view{}).add(std::string_view{}).add(sol.message);
  if (std::isfinite(wall_rotation)) row.add(wall_rotation);
  else row.add(std::string_view{});
  return row.take();
}

// A moving wall's arm: its springing's axis point less its base's outer toe (m).
Eigen::Vector2d wall_arm(const Scene& scene, bool right) {
  const WallOutline o = wall_outline(*scene.curve, scene.thickness, right ? *scene.right_wall : *scene.left_wall, right);
  return o.joint.axis - Eigen::Vector2d(o.outer_x, o.base_y);
}

// On walls, a cracking row: the moving walls turned outwards by theta (rad), to first order (the
// elastic arch's small displacements): each springing's axis point moves by theta times its arm from
// the toe turned a quarter (outwards by theta h_w, up by theta times the arm's width) and the springing
// turns with its wall (a pinned springing turns freely). Returns theta: the largest arm moves by `move`
// of the span.
double cracking_lean(Scene& cracking, const SpreadSetup& s, double move) {
  double arm = 0;
  for (const bool right : {false, true})
    if (right ? s.right_moves : s.left_moves) arm = std::max(arm, wall_arm(cracking, right).norm());
  const double theta = move * cracking.span() / arm;
  for (const bool right : {false, true}) {
    if (!(right ? s.right_moves : s.left_moves)) continue;
    Support& support = right ? cracking.right : cracking.left;
    const Wall& wall = right ? *cracking.right_wall : *cracking.left_wall;
    support = wall_lean_movement(wall_outline(*cracking.curve, cracking.thickness, wall, right), theta, support.kind);
  }
  return theta;
}

// The whole curve of one scene: the elastic arch at d = 0, the cracking arch (each solve continuing
// from the previous one, as a sweep of thrust --section no-tension does), the mechanism to collapse.
std::string path_rows(const Columns& columns, const SceneParameters& p, const Scene& scene, const SpreadText& t,
                      const SpreadSetup& s, const Solution& elastic, const SpreadResult& r, bool* ok) {
  const double L = scene.span();
  const double sides = (s.left_moves ? 1 : 0) + (s.right_moves ? 1 : 0);
  const SpreadOptions& o = s.spread;
  const double most = std::max({1.0, std::abs(o.left_settlement_share), std::abs(o.right_settlement_share)});
  std::string text = solve_row(columns, p, scene, t, s, "elastic", 0, elastic, s.walls ? 0.0 : std::numeric_limits<double>::quiet_NaN());
  *ok = answered(elastic);
  Solution previous;
  for (const double each : kCrackingMoves) {
    const double move = each / most;  // no springing moves more than 1e-2 L either way
    Scene cracking = scene;
    cracking.section = SectionKind::no_tension;
    // The no-tension section is a straight beam's (the curved bar takes the elastic section only).
    if (cracking.beam_model != BeamModel::euler_bernoulli) cracking.beam_model = BeamModel::timoshenko;
    cracking.model_tolerance = 0;
    double theta = std::numeric_limits<double>::quiet_NaN(), spread_ratio = sides * move;
    if (s.walls) {
      theta = cracking_lean(cracking, s, move);
      spread_ratio = (cracking.left.spread + cracking.right.spread) / p.span;
    } else {
      cracking.left.spread = s.left_moves ? move * p.span : 0;
      cracking.right.spread = s.right_moves ? move * p.span : 0;
      cracking.left.settlement = o.left_settlement_share * move * p.span;
      cracking.right.settlement = o.right_settlement_share * move * p.span;
    }
    const Solution sol = solve(cracking, Options{}, &previous);
    if (sol.field) previous = sol;
    text += solve_row(columns, p, scene, t, s, "cracking", spread_ratio, sol, theta);
    *ok = *ok && answered(sol);
  }
  CsvRow row(columns.keep());
  add_scene_columns(row, p, scene.curve.get());
  add_setup(row, t, s);
  row.add(std::string_view("mechanism"));
  row.mark();
  for (std::size_t i = 0; i < r.path.size(); ++i) {
    const SpreadStep& step = r.path[i];
    row.add(s.walls ? step.span_increase / L : (s.spread.left_share + s.spread.right_share) * step.d / L);
    row.add(to_string(r.status)).add(step.H);
    row.add(step.V_left).add(step.V_right).add(step.H / step.V_left).add(step.crown_drop / L);
    row.add(hinge_text(step.hinges, L));
    row.add(i + 1 == r.path.size() ? std::string_view(to_string(r.collapse)) : std::string_view{});
    row.add(r.status == SpreadStatus::success ? std::string_view{} : std::string_view(r.message));
    if (s.walls) row.add(step.d);  // each moving wall's rotation: d itself (their shares are 1)
    else row.add(std::string_view{});
    text += row.take_to_mark();
  }
  *ok = *ok && r.status == SpreadStatus::success;
  return text;
}

// Exit 0 when every scene has an answer (an arch too thin to stand at d = 0 is one: a row of status
// inadmissible, without a curve), 3 when a program or a solve stopped without one or the capacity is
// not_converged (its row gives the numbers and says by how much the capacity moved).
int run_spread(SpreadCommandOptions& so, const CLI::App& cmd, std::ostream& out) {
  const SpreadText& text = so.text;
  check_threads(text.threads);
  Columns columns = spread_columns(text.path, walls_given(cmd));
  if (so.columns.columns == "help") {
    write_all(out, columns.help(so.columns));
    return kExitOk;
  }
  const SpreadSetup setup = spread_setup(text, cmd);
  const ScenePlan plan(so.scene, cmd);
  columns.select(so.columns, plan.varying_inputs());
  const std::size_t rows_per_scene = text.path ? 2 + std::size(kCrackingMoves) + static_cast<std::size_t>(text.steps) : 1;
  const bool all_answered = write_scenes(
      plan, columns, out, text.threads,
      [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        const SpreadResult r = analyse_spreading(scene, setup.limit, setup.spread);
        const bool spread_answered = r.status == SpreadStatus::success || r.status == SpreadStatus::inadmissible;
        const Solution elastic = solve(scene);
        if (!text.path) {
          emit(summary_row(columns, p, scene, text, setup, elastic, r));
          return spread_answered && answered(elastic);
        }
        if (!has_numbers(r)) {
          emit(sparse_row(columns, p, scene.curve.get(),
                          {{"moving", text.moving},
                           {"left_settlement_share", fmt::format("{}", setup.spread.left_settlement_share)},
                           {"right_settlement_share", fmt::format("{}", setup.spread.right_settlement_share)},
                           {"joints", to_string(setup.limit.joints)},
                           {"weight", to_string(setup.limit.weight)},
                           {"joints_count", std::to_string(setup.limit.joints_count)},
                           {"compressive_strength", std::isfinite(setup.limit.compressive_strength)
                                                        ? fmt::format("{}", setup.limit.compressive_strength)
                                                        : ""},
                           {"path_steps", std::to_string(setup.spread.steps)},
                           {"friction", setup.limit.friction > 0 ? fmt::format("{}", setup.limit.friction) : ""},
                           {"status", to_string(r.status)},
                           {"message", r.message}}));
          return spread_answered;
        }
        bool ok = true;
        emit(path_rows(columns, p, scene, text, setup, elastic, r, &ok));
        return ok;
      },
      rows_per_scene);
  return all_answered ? kExitOk : kExitNotConverged;
}

}  // namespace

Run add_spread_options(CLI::App& cmd) {
  auto options = std::make_shared<SpreadCommandOptions>();
  add_scene_options(cmd, options->scene);
  hide_inapplicable(cmd, kSpreadMoves);
  hide_inapplicable(cmd, kNotForSpread);
  add_spread_analysis_options(cmd, options->text);
  add_column_options(cmd, options->columns);
  add_threads_option(cmd, options->text.threads);
  return [options, &cmd](std::ostream& out) { return run_spread(*options, cmd, out); };
}

}  // namespace ogive::cli
