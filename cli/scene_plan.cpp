#include "scene_plan.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string_view>
#include <tuple>
#include <utility>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "ogive/geometry/curve_families.hpp"
#include "ogive/model/loads_file.hpp"
#include "columns.hpp"
#include "option_text.hpp"
#include "units.hpp"
#include "values.hpp"
#include "warnings.hpp"

namespace ogive::cli {
namespace {

// --fill-height crown (0) or crown+D, crown-D: the fill's level D m above (below) the extrados' crown.
double crown_offset(const std::string& text) {
  if (text == "crown") return 0;
  const std::string rest = text.substr(5);
  if (rest.size() > 1 && (rest.front() == '+' || rest.front() == '-')) {
    const double d = parse_number(with_units_resolved(rest.substr(1), "--fill-height", 0), "--fill-height");
    return rest.front() == '-' ? -d : d;
  }
  throw UsageError(fmt::format("--fill-height: crown, or crown+D for D m above the extrados' crown (e.g. crown+0.5), "
                               "got '{}'",
                               shown(text)));
}

const std::map<std::string, SupportKind> kSupportKinds = {{"clamped", SupportKind::clamped},
                                                          {"pinned", SupportKind::pinned}};
const std::map<std::string, SectionKind> kSectionKinds = {{"elastic", SectionKind::elastic},
                                                          {"no-tension", SectionKind::no_tension}};
const std::map<std::string, BeamModel> kBeamModels = {{"euler-bernoulli", BeamModel::euler_bernoulli},
                                                      {"timoshenko", BeamModel::timoshenko},
                                                      {"curved", BeamModel::curved},
                                                      {"auto", BeamModel::automatic}};

const CurveFamily& find_family(const std::string& curve) {
  for (const CurveFamily& f : curve_families())
    if (f.name == curve) return f;
  throw UsageError(fmt::format("--curve: unknown curve '{}' (known: {})", curve, curve_family_names()));
}

// Options that do not apply to the curve are refused when given.
void refuse_inapplicable(const CurveFamily& family, const std::string& curve, const CLI::App& cmd) {
  auto refuse_unless = [&](bool applies, const char* flag) {
    if (!applies && given(cmd, flag)) throw UsageError(fmt::format("{}: does not apply to --curve {}", flag, curve));
  };
  refuse_unless(family.eccentricity, "--eccentricity");
  refuse_unless(family.rise || family.eccentricity, "--rise-ratio");  // pointed: sets the eccentricity
  refuse_unless(family.rise || family.eccentricity, "--rise");
  refuse_unless(family.eccentricity, "--radius");
  refuse_unless(family.haunch, "--haunch-angle");
  refuse_unless(family.crown, "--crown-angle");
  refuse_unless(family.file, "--curve-file");
}

// The options that give one quantity in two ways (over the span and in metres; the pointed arch's
// shape four ways): at most one of each group.
constexpr std::initializer_list<const char*> kSameQuantity[] = {
    {"--thickness-ratio", "--thickness"},
    {"--density", "--unit-weight"},
    {"--eccentricity", "--rise-ratio", "--rise", "--radius"},
    {"--fill-height-ratio", "--fill-height"},
    {"--point-load-at", "--point-load-x"},
    {"--live-load-from", "--live-load-from-x"},
    {"--live-load-to", "--live-load-to-x"},
};

// The flag of `group` that was given, or nullptr.
const char* given_of(const CLI::App& cmd, std::initializer_list<const char*> group) {
  for (const char* flag : group)
    if (given(cmd, flag)) return flag;
  return nullptr;
}

// The axis points of --curve points or whole-points; "-": they come on standard input (a survey piped
// from another program).
std::shared_ptr<const Curve> read_points(const SceneOptions& o) {
  if (o.curve_file.empty())
    throw UsageError(fmt::format("--curve-file: --curve {} needs a file of axis points", o.curve));
  try {
    const bool whole = o.curve == "whole-points";
    if (o.curve_file == "-")
      return whole ? parse_whole_points_curve(std::cin, "<stdin>") : parse_points_curve(std::cin, "<stdin>");
    return whole ? read_whole_points_curve(o.curve_file) : read_points_curve(o.curve_file);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

// The commands whose analyses take walls: the others refuse them.
void refuse_walls(const CLI::App& cmd) {
  const std::string name = cmd.get_name();
  if (!walls_given(cmd) || name == "limit" || name == "draw" || name == "thrust" || name == "report" ||
      name == "assess" || name == "spread")
    return;
  const char* flag = given(cmd, "--wall-height") ? "--wall-height" : given(cmd, "--left-wall-height") ? "--left-wall-height" : "--right-wall-height";
  throw UsageError(fmt::format("{}: does not apply to {} (walls are taken by ogive limit, thrust, draw, report, assess and spread)", flag,
                               cmd.get_name()));
}

// A wall's options need its height, and a height needs a thickness: each side's own option or the
// one of both walls.
void check_wall_options(const CLI::App& cmd) {
  const bool any_height = given_of(cmd, {"--wall-height", "--left-wall-height", "--right-wall-height"}) != nullptr;
  for (const char* name : {"thickness", "density", "top-load", "top-load-at", "lean"}) {
    const std::string both = fmt::format("--wall-{}", name);
    if (given(cmd, both) && !any_height)
      throw UsageError(fmt::format("{}: needs --wall-height (or --left-wall-height, --right-wall-height)", both));
  }
  for (const char* side : {"left", "right"}) {
    const std::string height = fmt::format("--{}-wall-height", side);
    const bool has_height = given(cmd, "--wall-height") || given(cmd, height);
    for (const char* name : {"thickness", "density", "top-load", "top-load-at", "lean"}) {
      const std::string flag = fmt::format("--{}-wall-{}", side, name);
      if (given(cmd, flag) && !has_height)
        throw UsageError(fmt::format("{}: needs --wall-height or {}", flag, height));
    }
    const std::string thickness = fmt::format("--{}-wall-thickness", side);
    if (has_height && !given(cmd, "--wall-thickness") && !given(cmd, thickness))
      throw UsageError(fmt::format("{}: needs --wall-thickness or {} (the wall's b_w)",
                                   given(cmd, height) ? height : std::string("--wall-height"), thickness));
  }
}

// Load and movement options that need another, or exclude one.
void check_option_pairs(const CLI::App& cmd) {
  auto needs = [&](const char* flag, const char* other) {
    if (given(cmd, flag) && !given(cmd, other)) throw UsageError(fmt::format("{}: needs {}", flag, other));
  };
  for (std::initializer_list<const char*> group : kSameQuantity) {
    const char* first = nullptr;
    for (const char* flag : group) {
      if (!given(cmd, flag)) continue;
      if (first)
        throw UsageError(fmt::format("{}: cannot be combined with {} (both give the same quantity): give one", flag,
                                     first));
      first = flag;
    }
  }
  needs("--point-load-at", "--point-load");
  needs("--point-load-x", "--point-load");
  needs("--live-load-from", "--live-load");
  needs("--live-load-to", "--live-load");
  needs("--live-load-from-x", "--live-load");
  needs("--live-load-to-x", "--live-load");
  needs("--fill-height-ratio", "--fill-density");
  needs("--fill-height", "--fill-density");
  if (given(cmd, "--fill-density") && !given_of(cmd, {"--fill-height-ratio", "--fill-height"}))
    throw UsageError("--fill-density: needs --fill-height-ratio or --fill-height");
  check_wall_options(cmd);
  for (const char* side : {"--left-spread-ratio", "--right-spread-ratio"})
    if (given(cmd, side) && given(cmd, "--support-displacement-ratio"))
      throw UsageError(fmt::format("{}: cannot be combined with --support-displacement-ratio (both springings "
                                   "spreading alike): give each side's spread instead",
                                   side));
}

Loads read_loads(const SceneOptions& o) {
  if (o.loads_file == "-" && o.curve_file == "-")
    throw UsageError("--loads-file: standard input already holds the curve's points (--curve-file -)");
  try {
    return o.loads_file == "-" ? parse_loads(std::cin, "<stdin>") : read_loads_file(o.loads_file);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

}  // namespace

ScenePlan::ScenePlan(SceneOptions& o, const CLI::App& cmd) : options_(o) {
  // In this order, so that the problem reported is the same one when several are.
  refuse_empty_name(cmd, "--curve-file", o.curve_file, "a file, or - for standard input");
  refuse_empty_name(cmd, "--loads-file", o.loads_file, "a file, or - for standard input");
  family_ = &find_family(o.curve);
  refuse_inapplicable(*family_, o.curve, cmd);
  if (family_->file) o.points = read_points(o);
  check_option_pairs(cmd);
  refuse_walls(cmd);
  choose_supports(o, cmd);
  choose_dimensions(o, cmd);
  if (!o.loads_file.empty()) o.file_loads = read_loads(o);
  plan_axes(o, cmd);
  // Lengths in metres with the span left at its default are most likely a forgotten --span.
  if (!family_->file && !given(cmd, "--span") && !given(cmd, "--radius"))
    if (const char* metres = given_of(cmd, {"--thickness", "--rise", "--fill-height", "--point-load-x",
                                            "--live-load-from-x", "--live-load-to-x"}))
      warn("--span", fmt::format("{} is in metres but --span was not given: the default span of {} m is used",
                                 metres, cmd.get_option("--span")->get_default_str()));
  require_some_scene();
}

// --dimensions intrados: the span and rise given are the intrados', which the ring's thickness in metres
// turns into the axis' (to_axis_dimensions); the ratio forms would be ratios of a span not yet known.
void ScenePlan::choose_dimensions(const SceneOptions& o, const CLI::App& cmd) {
  static const std::map<std::string, bool> kDimensions = {{"axis", false}, {"intrados", true}};
  intrados_ = lookup(kDimensions, o.dimensions, "--dimensions");
  if (!intrados_) return;
  if (family_->file)
    throw UsageError(fmt::format("--dimensions intrados: a --curve {} file gives the axis' points", o.curve));
  for (const char* flag : {"--thickness-ratio", "--rise-ratio", "--eccentricity", "--radius"})
    if (given(cmd, flag))
      throw UsageError(fmt::format("--dimensions intrados: give the intrados' --span and --rise in m, not {}", flag));
  if (!given(cmd, "--thickness"))
    throw UsageError("--dimensions intrados: give --thickness in m (the ring's thickness sets the intrados)");
  if ((family_->rise || family_->eccentricity) && !given(cmd, "--rise"))
    throw UsageError(fmt::format("--dimensions intrados: give the intrados' --rise in m (the {} arch's rise)", o.curve));
}

// The axis' span and rise whose intrados has the span and rise given (p.span, p.rise), for the ring of
// thickness p.thickness: the corrections clear - clear(L, h) and rise - rise(L, h) added to L and h until
// they vanish to round-off (each is nearly 1 : 1, the rest of order t / R: a few iterations). NaN span
// where no such arch exists (build() refuses it).
void ScenePlan::to_axis_dimensions(SceneParameters& p) const {
  constexpr double kRoundOff = 4 * std::numeric_limits<double>::epsilon();
  constexpr int kMaxIterations = 100;
  const double clear = p.span, rise = p.rise, t = p.thickness;
  double L = clear + t, h = rise + 0.5 * t;  // the semicircle's, and a smooth crown's
  for (int k = 0; k < kMaxIterations; ++k) {
    SceneParameters q = p;
    q.span = L;
    q.rise = h;
    q.thickness_ratio = q.rise_ratio = std::numeric_limits<double>::quiet_NaN();
    try {
      derive_metres(q);
      const IntradosDimensions d = intrados_dimensions(*make_curve(q), t);
      const double dL = clear - d.clear_span, dh = std::isnan(rise) ? 0.0 : rise - d.rise;
      if (std::abs(dL) <= kRoundOff * clear && (std::isnan(rise) || std::abs(dh) <= kRoundOff * rise)) {
        p.span = L;
        p.rise = std::isnan(rise) ? rise : h;
        return;
      }
      L += dL;
      h += dh;
    } catch (const std::invalid_argument&) {
      break;
    }
  }
  p.span = std::numeric_limits<double>::quiet_NaN();
}

void ScenePlan::choose_supports(const SceneOptions& o, const CLI::App& cmd) {
  left_kind_ = o.left_support.empty() ? lookup(kSupportKinds, o.supports, "--supports")
                                      : lookup(kSupportKinds, o.left_support, "--left-support");
  right_kind_ = o.right_support.empty() ? lookup(kSupportKinds, o.supports, "--supports")
                                        : lookup(kSupportKinds, o.right_support, "--right-support");
  if (!o.left_support.empty() || !o.right_support.empty()) lookup(kSupportKinds, o.supports, "--supports");
  section_ = lookup(kSectionKinds, o.section, "--section");
  beam_model_ = lookup(kBeamModels, o.beam_model, "--beam-model");
  if (given(cmd, "--model-tolerance") && !(o.model_tolerance > 0 && o.model_tolerance < 1))
    throw UsageError(fmt::format("--model-tolerance: must lie in (0, 1) (a relative error of H/V), got {}",
                                 o.model_tolerance));
  model_tolerance_ = given(cmd, "--model-tolerance") ? o.model_tolerance
                     : beam_model_ == BeamModel::automatic ? 0.01 : 0.0;
  if (model_tolerance_ > 0 && section_ != SectionKind::elastic)
    throw UsageError(fmt::format("{}: the model's error is estimated for --section elastic only",
                                 beam_model_ == BeamModel::automatic ? "--beam-model auto" : "--model-tolerance"));
  for (const auto& [flag, kind] : {std::pair{"--left-rotation", left_kind_}, {"--right-rotation", right_kind_}})
    if (kind == SupportKind::pinned && given(cmd, flag))
      throw UsageError(fmt::format("{}: does not apply to a pinned springing (it turns freely: its rotation is a "
                                   "result, not a given movement)",
                                   flag));
}

// Each axis' values: as given, else the curve family's default; a points file sets the span.
void ScenePlan::plan_axes(SceneOptions& o, const CLI::App& cmd) {
  // --units (columns.hpp): the unit of the force options.
  if (const CLI::Option* units = cmd.get_option_no_throw("--units"); units && units->count() > 0)
    force_unit_ = force_unit(units->as<std::string>());
  thickness_flag_ = given(cmd, "--thickness") ? "--thickness" : "--thickness-ratio";
  for (const char* side : {"left", "right"}) {
    const std::string own = fmt::format("--{}-spread-ratio", side);
    spread_flags_[side[0] == 'r' ? 1 : 0] = given(cmd, own) ? own : "--support-displacement-ratio";
  }
  const auto given_here = [&](const std::string& flag) {
    const CLI::Option* o = cmd.get_option_no_throw(flag);
    return o && o->count() > 0;
  };
  for (const char* what : {"height", "thickness", "density", "top-load", "top-load-at", "lean"})
    for (const char* side : {"left", "right"})
      if (given_here(fmt::format("--wall-{}", what)) && !given_here(fmt::format("--{}-wall-{}", side, what)))
        walls_by_shared_flag_.push_back(fmt::format("--{}-wall-{}", side, what));
  const char* shape = given_of(cmd, {"--rise-ratio", "--rise", "--radius"});
  shape_flag_ = shape ? shape : "--eccentricity";
  live_from_flag_ = given(cmd, "--live-load-from-x") ? "--live-load-from-x" : "--live-load-from";
  live_to_flag_ = given(cmd, "--live-load-to-x") ? "--live-load-to-x" : "--live-load-to";
  for (Axis& a : o.axes) {
    std::string text = a.text;
    const bool is_given = given(cmd, a.flag);  // given text is parsed as it stands, even if empty
    if (!is_given && text.empty()) {
      if (a.flag == "--rise-ratio") text = family_->default_rise;
      if (a.flag == "--haunch-angle") text = family_->default_haunch;
      if (a.flag == "--crown-angle") text = family_->default_crown;
    }
    // A quantity given in its other form: this one's default does not apply.
    if (!is_given && a.flag == "--thickness-ratio" && thickness_flag_ == "--thickness") text.clear();
    if (!is_given && a.flag == "--density" && given(cmd, "--unit-weight")) text.clear();
    if (!is_given && a.flag == "--eccentricity" && shape) text.clear();
    if (is_given && a.flag == "--fill-height") fill_in_metres_ = true;
    if (is_given && a.flag == "--fill-height" && text.rfind("crown", 0) == 0) {
      fill_to_crown_ = true;
      fill_over_crown_ = crown_offset(text);
      text.clear();
    }
    const std::string resolved = with_units_resolved(text, a.flag, force_unit_ == 1 ? 0 : 3);
    if (is_given && resolved == text && force_unit_ == 1) {
      if (a.flag == "--point-load") bare_newton_point_ = true;
      if (a.flag == "--live-load") bare_newton_live_ = true;
    }
    text = resolved;
    if (family_->file && a.flag == "--span") {
      // A points file sets the span: --span may only repeat it.
      const double own = o.points->span();
      if (is_given)
        for (double v : parse_values(text, a.flag))
          if (!(std::abs(v - own) <= 1e-9 * own))
            throw UsageError(fmt::format("--span: the points file sets the span ({} m in {}), got {}: omit --span, "
                                         "or give the file's points at the span wanted",
                                         own, o.curve_file == "-" ? "<stdin>" : o.curve_file, v));
      text = fmt::format("{}", own);
    }
    // Not a parameter of this curve: one NaN, printed as an empty field.
    const bool absent = (!is_given || (a.flag == "--fill-height" && fill_to_crown_)) && text.empty();
    try {
      a.values = absent ? std::vector<double>{std::numeric_limits<double>::quiet_NaN()} : parse_values(text, a.flag);
    } catch (const UsageError& e) {
      if (a.flag != "--fill-height") throw;
      throw UsageError(std::string(e.what()) + " (give metres, or crown for the height of the extrados over the crown)");
    }
    for (double v : a.values)
      if (!std::isnan(v) && !a.allowed(v)) throw UsageError(fmt::format("{}: {}, got {}", a.flag, a.rule, v));
    size_ *= a.values.size();
    if (size_ > kMaxValues)
      throw UsageError(fmt::format("{}: the options give more than {} scenes", a.flag, kMaxValues));
  }
}

std::vector<std::string> ScenePlan::varying_inputs() const {
  std::vector<std::string> out;
  for (const Axis& a : options_.axes) {
    if (a.values.size() < 2) continue;
    std::string name = a.flag.substr(2);
    std::replace(name.begin(), name.end(), '-', '_');
    out.push_back(name);
  }
  return out;
}

SceneParameters ScenePlan::parameters(std::size_t index) const {
  SceneParameters p{};
  p.scene = index + 1;
  p.curve = options_.curve;
  p.plane_strain = options_.plane_strain;
  p.force_unit = force_unit_;
  for (std::size_t i = options_.axes.size(); i-- > 0;) {
    const Axis& a = options_.axes[i];
    p.*(a.field) = a.values[index % a.values.size()];
    index /= a.values.size();
  }
  if (!family_->eccentricity) p.eccentricity = std::numeric_limits<double>::quiet_NaN();
  if (intrados_) to_axis_dimensions(p);
  derive_metres(p);
  // The defaults of the load and movement options, as the row prints them.
  if (!std::isnan(p.point_load) && std::isnan(p.point_load_at)) p.point_load_at = 0.5;
  if (!std::isnan(p.live_load) && std::isnan(p.live_load_from)) p.live_load_from = 0;
  if (!std::isnan(p.live_load) && std::isnan(p.live_load_to)) p.live_load_to = 1;
  for (auto [x, ratio] : {std::pair{&p.point_load_x, p.point_load_at}, {&p.live_load_from_x, p.live_load_from},
                          {&p.live_load_to_x, p.live_load_to}})
    if (std::isnan(*x) && !std::isnan(ratio)) *x = decimal_product(ratio, p.span);
  if (std::isnan(p.left_spread_ratio)) p.left_spread_ratio = p.support_displacement_ratio;
  if (std::isnan(p.right_spread_ratio)) p.right_spread_ratio = p.support_displacement_ratio;
  // Each wall's fields: its own option, else both walls', else the default (none without a height).
  const auto either = [](double own, double both) { return std::isnan(own) ? both : own; };
  for (auto [h, b, rho, q, at, lean] :
       {std::tuple{&p.left_wall_height, &p.left_wall_thickness, &p.left_wall_density, &p.left_wall_top_load,
                   &p.left_wall_top_load_at, &p.left_wall_lean},
        std::tuple{&p.right_wall_height, &p.right_wall_thickness, &p.right_wall_density, &p.right_wall_top_load,
                   &p.right_wall_top_load_at, &p.right_wall_lean}}) {
    *h = either(*h, p.wall_height);
    if (std::isnan(*h)) continue;
    *b = either(*b, p.wall_thickness);
    *rho = either(either(*rho, p.wall_density), p.density);
    *q = either(either(*q, p.wall_top_load), 0.0);
    *at = either(either(*at, p.wall_top_load_at), 0.5);
    *lean = either(either(*lean, p.wall_lean), 0.0);
  }
  p.left_support = left_kind_ == SupportKind::clamped ? "clamped" : "pinned";
  p.right_support = right_kind_ == SupportKind::clamped ? "clamped" : "pinned";
  p.crown_hinge = options_.crown_hinge;
  p.loads_file = options_.loads_file;
  p.section = section_ == SectionKind::elastic ? "elastic" : "no-tension";
  return p;
}

// Each ratio from its metre form where that was given, else the metre form from the ratio (the row
// prints both); the pointed arch's eccentricity from its rise or radius; a fill to the crown's extrados.
// The conversions are decimal (decimal_product, decimal_quotient): --thickness 0.7 --span 7 and
// --thickness-ratio 0.1 --span 7 make the same scene, bit for bit, as they do in decimal.
// Values that make no scene stay as they are: build() refuses them.
void ScenePlan::derive_metres(SceneParameters& p) const {
  const double L = p.span;
  if (!std::isnan(p.unit_weight)) p.density = p.unit_weight / p.gravity;
  const auto ratio_of = [L](double metres) { return decimal_quotient(metres, L); };
  const auto metres_of = [L](double ratio) { return decimal_product(ratio, L); };
  if (!std::isnan(p.thickness)) p.thickness_ratio = ratio_of(p.thickness);
  else p.thickness = metres_of(p.thickness_ratio);
  if (!std::isnan(p.rise)) p.rise_ratio = ratio_of(p.rise);
  if (family_->eccentricity) {
    if (!std::isnan(p.radius)) p.eccentricity = pointed_eccentricity_for_radius(ratio_of(p.radius));
    else if (!std::isnan(p.rise_ratio)) p.eccentricity = pointed_eccentricity_for_rise(p.rise_ratio);
    if (std::isnan(p.radius)) p.radius = pointed_radius(L, p.eccentricity);
  }
  if (!std::isnan(p.rise_ratio) && std::isnan(p.rise)) p.rise = metres_of(p.rise_ratio);
  if (!std::isnan(p.point_load_x)) p.point_load_at = ratio_of(p.point_load_x);
  if (!std::isnan(p.live_load_from_x)) p.live_load_from = ratio_of(p.live_load_from_x);
  if (!std::isnan(p.live_load_to_x)) p.live_load_to = ratio_of(p.live_load_to_x);
  if (fill_to_crown_) {
    try {
      p.fill_height = extrados_crown_height(*make_curve(p), p.thickness) + fill_over_crown_;
    } catch (const std::invalid_argument&) {
      // No curve: build() says why.
    }
  }
  if (!std::isnan(p.fill_height)) p.fill_height_ratio = ratio_of(p.fill_height);
  else if (!std::isnan(p.fill_height_ratio)) p.fill_height = metres_of(p.fill_height_ratio);
}

// The rules of the metre forms that depend on the span or the curve (one line naming the option).
void ScenePlan::check_metres(const SceneParameters& p) const {
  const double L = p.span;
  if (intrados_ && std::isnan(L))
    throw std::invalid_argument("--dimensions intrados: no arch of this curve and --thickness has that clear span and "
                                "intrados rise (its intrados must reach the crown's vertical)");
  // A ratio derived from its metre form keeps the ratio option's rule, stated for the metre option.
  for (const auto& [metre, given, ratio_flag, ratio] :
       {std::tuple{"--thickness", thickness_flag_ == "--thickness", "--thickness-ratio", p.thickness_ratio},
        {"--rise", shape_flag_ == "--rise", "--rise-ratio", p.rise_ratio},
        {"--fill-height", fill_in_metres_, "--fill-height-ratio", p.fill_height_ratio}}) {
    if (!given) continue;
    for (const Axis& a : options_.axes)
      if (a.flag == ratio_flag && !std::isnan(ratio) && !a.allowed(ratio))
        throw std::invalid_argument(
            fmt::format("{}: {} / span {}, got {} (span {} m)", metre, std::string_view(metre).substr(2), a.rule, ratio, L));
  }
  if (family_->eccentricity && !std::isfinite(p.eccentricity))
    throw std::invalid_argument(fmt::format("{}: gives no pointed arch (eccentricity {}) for span {} m", shape_flag_,
                                            p.eccentricity, L));
  if (family_->eccentricity && p.eccentricity < 0) {
    if (shape_flag_ == "--radius")
      throw std::invalid_argument(fmt::format(
          "--radius: a pointed arch's radius is at least half its span (the semicircle), got {} m for span {} m",
          p.radius, L));
    throw std::invalid_argument(fmt::format(
        "{}: a pointed arch rises at least half its span (the semicircle), got rise {} m for span {} m", shape_flag_,
        p.rise, L));
  }
  for (auto [flag, x] : {std::pair{"--point-load-x", p.point_load_x}, {"--live-load-from-x", p.live_load_from_x},
                         {"--live-load-to-x", p.live_load_to_x}})
    if (x > L) throw std::invalid_argument(fmt::format("{}: must lie in [0, L] (within the span, {} m), got {}", flag, L, x));
  // The live load's ends in the forms the user gave them (the library compares the ratios).
  if (!std::isnan(p.live_load) && !(p.live_load_to > p.live_load_from)) {
    auto shown = [](const std::string& flag, double ratio, double metres) {
      return flag.ends_with("-x") ? fmt::format("{} m", metres) : fmt::format("{}", ratio);
    };
    throw std::invalid_argument(fmt::format("{}: must exceed {} ({}), got {}", live_to_flag_, live_from_flag_,
                                            shown(live_from_flag_, p.live_load_from, p.live_load_from_x),
                                            shown(live_to_flag_, p.live_load_to, p.live_load_to_x)));
  }
}

ScenePlan::Built ScenePlan::build(const SceneParameters& p) const {
  Built out;
  try {
    check_metres(p);
    out.curve = make_curve(p);
    Scene scene;
    scene.curve = out.curve;
    scene.thickness = p.thickness;
    scene.material = {p.youngs_modulus, p.poisson_ratio, p.density, p.gravity, p.shear_coefficient, p.plane_strain};
    scene.left = {left_kind_, p.left_spread_ratio * p.span, p.left_settlement_ratio * p.span, p.left_rotation};
    scene.right = {right_kind_, p.right_spread_ratio * p.span, p.right_settlement_ratio * p.span, p.right_rotation};
    scene.crown_hinge = options_.crown_hinge;
    scene.horizontal_acceleration = p.horizontal_acceleration;
    scene.section = section_;
    scene.beam_model = beam_model_;
    scene.model_tolerance = model_tolerance_;
    scene.loads = options_.file_loads;
    // The force options in the unit of --units (the row echoes them as given).
    if (!std::isnan(p.point_load)) scene.loads.points.push_back({p.point_load * p.force_unit, p.point_load_at});
    if (!std::isnan(p.live_load))
      scene.loads.live.push_back({p.live_load * p.force_unit, p.live_load_from, p.live_load_to});
    if (!std::isnan(p.fill_density)) scene.loads.fills.push_back({p.fill_density, p.fill_height_ratio});
    if (!std::isnan(p.left_wall_height))
      scene.left_wall = Wall{p.left_wall_height, p.left_wall_thickness, p.left_wall_density,
                             p.left_wall_top_load * p.force_unit, p.left_wall_top_load_at};
    if (!std::isnan(p.right_wall_height))
      scene.right_wall = Wall{p.right_wall_height, p.right_wall_thickness, p.right_wall_density,
                              p.right_wall_top_load * p.force_unit, p.right_wall_top_load_at};
    scene.validate();
    lean_walls(p, scene);
    warn_of_small_loads(p, scene);
    out.scene = std::move(scene);
  } catch (const std::invalid_argument& e) {
    out.problem = problem_words(e.what());
  }
  return out;
}

// Each leaning wall moves its springing (wall_lean_movement), over the movement the options give it:
// small movements add, and their sum keeps the options' rule of small displacements.
void ScenePlan::lean_walls(const SceneParameters& p, Scene& scene) const {
  for (const bool right : {false, true}) {
    const std::optional<Wall>& wall = right ? scene.right_wall : scene.left_wall;
    const double lean = right ? p.right_wall_lean : p.left_wall_lean;
    if (!wall || lean == 0) continue;
    Support& support = right ? scene.right : scene.left;
    const Support m = wall_lean_movement(wall_outline(*scene.curve, scene.thickness, *wall, right), lean, support.kind);
    const char* side = right ? "right" : "left";
    const std::string& spread_flag = spread_flags_[right ? 1 : 0];
    // Each component over the span (the rotation in rad): the options' movement, the lean's, their sum.
    for (const auto& [what, flag, given, moved, scale] :
         {std::tuple{"spread", spread_flag, support.spread, m.spread, p.span},
          {"settlement", fmt::format("--{}-settlement-ratio", side), support.settlement, m.settlement, p.span},
          {"rotation", fmt::format("--{}-rotation", side), support.rotation, m.rotation, 1.0}}) {
      const double total = (given + moved) / scale;
      if (std::abs(total) <= kLargestMovement) continue;
      throw std::invalid_argument(fmt::format(
          "--{}-wall-lean: the {} springing's {} {}, {}{} from the lean, must lie in [-{}, {}] (beyond, "
          "small-displacement theory does not hold), got {}",
          side, side, what, scale == 1.0 ? "(rad)" : "over the span",
          given != 0 ? fmt::format("{} from {} plus ", given / scale, flag) : std::string(), moved / scale,
          kLargestMovement, kLargestMovement, total));
    }
    support.spread += m.spread;
    support.settlement += m.settlement;
    support.rotation += m.rotation;
  }
}

// A point or live load below 1 % of the arch's own weight, given as a bare number in N: most likely
// meant in kN (100 for 100 kN/m). A warning, not an error: a small load may be meant.
void ScenePlan::warn_of_small_loads(const SceneParameters& p, const Scene& scene) const {
  const double weight = p.density * p.gravity * p.thickness * scene.curve->whole_length();  // N/m
  const auto check = [&](bool bare, const char* flag, double total, double value, const char* unit) {
    if (bare && weight > 0 && total != 0 && std::abs(total) < 0.01 * weight)
      warn(flag, fmt::format("{}: {} {} is less than 1 % of the arch's own weight ({:.4g} N per metre of vault "
                             "width); if kN were meant, give {}kN or --units kN",
                             flag, value, unit, weight, value));
  };
  check(bare_newton_point_, "--point-load", p.point_load, p.point_load, "N/m");
  check(bare_newton_live_, "--live-load", p.live_load * (p.live_load_to - p.live_load_from) * p.span, p.live_load,
        "N/m^2");
}

std::string ScenePlan::problem_words(const std::string& what) const {
  std::string problem = as_option_message(what);
  // The thickness and the rise as the user gave them (the library's thickness rules are in metres, its
  // rise rules over the span).
  if (thickness_flag_ == "--thickness")
    for (std::size_t at = problem.find("--thickness-ratio"); at != std::string::npos;
         at = problem.find("--thickness-ratio", at))
      problem.erase(at + std::string_view("--thickness").size(), std::string_view("-ratio").size());
  // A wall's value as the user gave it: --wall-thickness for both walls, unless a side's own was given.
  for (const std::string& flag : walls_by_shared_flag_)
    for (std::size_t at = problem.find(flag); at != std::string::npos; at = problem.find(flag, at)) {
      const bool whole = at + flag.size() == problem.size() || !(std::isalnum(static_cast<unsigned char>(problem[at + flag.size()])) || problem[at + flag.size()] == '-');
      if (whole) problem.replace(at, flag.size(), "--wall-" + flag.substr(flag.find("-wall-") + 6));
      else at += flag.size();
    }
  if (shape_flag_ == "--rise" && problem.starts_with("--rise-ratio:"))
    problem = "--rise: rise / span" + problem.substr(std::string_view("--rise-ratio:").size());
  return problem;
}

// Scans without keeping anything, and stops at the first scene that can be made.
void ScenePlan::require_some_scene() const {
  std::string first_problem;
  for (std::size_t i = 0; i < size_; ++i) {
    Built b = build(parameters(i));
    if (b.scene) return;
    if (first_problem.empty()) first_problem = std::move(b.problem);
  }
  throw UsageError(size_ == 1 ? first_problem : "no scene of the sweep can be made; the first: " + first_problem);
}

std::shared_ptr<const Curve> ScenePlan::make_curve(const SceneParameters& p) const {
  const std::string& c = p.curve;
  if (c == "pointed") return make_pointed(p.span, p.eccentricity);
  if (c == "semicircular") return make_pointed(p.span, 0.0);
  if (c == "segmental") return make_segmental(p.span, p.rise_ratio);
  if (c == "three-centred") return make_three_centred(p.span, p.rise_ratio, p.haunch_angle);
  if (c == "four-centred") return make_four_centred(p.span, p.rise_ratio, p.haunch_angle, p.crown_angle);
  if (c == "elliptical") return make_elliptical(p.span, p.rise_ratio);
  if (c == "parabolic") return make_parabolic(p.span, p.rise_ratio);
  if (c == "catenary") return make_catenary(p.span, p.rise_ratio);
  return options_.points;
}

}  // namespace ogive::cli
