#include "cli.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <condition_variable>
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "ogive/version.hpp"
#include "ogive/geometry/curve_families.hpp"
#include "ogive/output/csv.hpp"
#include "ogive/limit/limit.hpp"
#include "ogive/model/loads_file.hpp"
#include "ogive/solve/solve.hpp"
#include "ogive/output/svg.hpp"
#include "ogive/core/thrust_line.hpp"
#include "values.hpp"

namespace ogive::cli {
namespace {

// ---------------------------------------------------------------------------------------------
// Scene options: every numeric one takes a value, a list or a range; the scenes are their product.

struct SceneParameters {
  std::size_t scene = 0;  // 1-based number in the sweep
  std::string curve;
  double eccentricity, rise_ratio, haunch_angle, crown_angle;
  double span, thickness_ratio, support_displacement_ratio;
  double youngs_modulus, poisson_ratio, density, gravity, shear_coefficient;
  bool plane_strain;
  // Loads and supports (NaN: not given).
  double point_load, point_load_at, live_load, live_load_from, live_load_to, fill_density, fill_height_ratio;
  double left_spread_ratio, right_spread_ratio, left_settlement_ratio, right_settlement_ratio, left_rotation,
      right_rotation;
  const char* left_support = "clamped";
  const char* right_support = "clamped";
  const char* section = "elastic";
  bool crown_hinge = false;
  std::string loads_file;
};

// A numeric scene option: its flag, its text as given ("" = the curve family's default), the rule
// its values must meet.
struct Axis {
  std::string flag;
  std::string text;
  double SceneParameters::*field;
  std::function<bool(double)> allowed;
  std::string rule;
  std::vector<double> values{};
};

bool positive(double v) { return v > 0; }

// Which parameters each generator curve takes, and its defaults (see include/ogive/geometry/curve_families.hpp).
struct CurveFamily {
  std::string name;
  bool eccentricity = false, rise = false, haunch = false, crown = false, file = false;
  const char* default_rise = "";
  const char* default_haunch = "";
  const char* default_crown = "";
};

const std::vector<CurveFamily> kFamilies = {
    {"pointed", true},
    {"semicircular"},
    {"segmental", false, true, false, false, false, "0.25"},
    {"three-centred", false, true, true, false, false, "0.3333333333333333", "60"},
    {"four-centred", false, true, true, true, false, "0.42", "45", "15"},
    {"elliptical", false, true, false, false, false, "0.5"},
    {"parabolic", false, true, false, false, false, "0.5"},
    {"catenary", false, true, false, false, false, "0.5"},
    {"points", false, false, false, false, true},
    {"whole-points", false, false, false, false, true},
};

template <class Enum>
Enum lookup(const std::map<std::string, Enum>& names, const std::string& text, const char* flag) {
  const auto it = names.find(text);
  if (it != names.end()) return it->second;
  std::string known;
  for (const auto& [name, value] : names) known += (known.empty() ? "" : ", ") + name;
  throw UsageError(fmt::format("{}: unknown value '{}' (known: {})", flag, text, known));
}

bool within_span(double v) { return v >= 0 && v <= 1; }
bool small_movement(double v) { return std::abs(v) <= 0.01; }
constexpr const char* kSpanRule = "must lie in [0, 1] (x / L within the span)";
constexpr const char* kMovementRule = "must lie in [-0.01, 0.01] (beyond, small-displacement theory does not hold)";

struct SceneOptions {
  std::string curve = "pointed";
  std::string curve_file;
  bool plane_strain = false;
  std::shared_ptr<const Curve> points;  // read once from curve_file
  std::string supports = "clamped", left_support, right_support;
  std::string section = "elastic";
  bool crown_hinge = false;
  std::string loads_file;
  Loads file_loads;  // read once from loads_file
  std::vector<Axis> axes{
      // Order: the last axis varies fastest in the output.
      {"--point-load", "", &SceneParameters::point_load, [](double) { return true; }, "must be a finite number"},
      {"--point-load-at", "", &SceneParameters::point_load_at, within_span, kSpanRule},
      {"--live-load", "", &SceneParameters::live_load, [](double) { return true; }, "must be a finite number"},
      {"--live-load-from", "", &SceneParameters::live_load_from, within_span, kSpanRule},
      {"--live-load-to", "", &SceneParameters::live_load_to, within_span, kSpanRule},
      {"--fill-density", "", &SceneParameters::fill_density, [](double v) { return v >= 0; }, "must be >= 0"},
      {"--fill-height-ratio", "", &SceneParameters::fill_height_ratio, [](double v) { return v > 0 && v <= 100; },
       "must lie in (0, 100] (the fill's level above the springing line, over the span)"},
      {"--left-spread-ratio", "", &SceneParameters::left_spread_ratio, small_movement, kMovementRule},
      {"--right-spread-ratio", "", &SceneParameters::right_spread_ratio, small_movement, kMovementRule},
      {"--left-settlement-ratio", "0", &SceneParameters::left_settlement_ratio, small_movement, kMovementRule},
      {"--right-settlement-ratio", "0", &SceneParameters::right_settlement_ratio, small_movement, kMovementRule},
      {"--left-rotation", "0", &SceneParameters::left_rotation, small_movement, kMovementRule},
      {"--right-rotation", "0", &SceneParameters::right_rotation, small_movement, kMovementRule},
      {"--span", "10", &SceneParameters::span, positive, "must be > 0"},
      {"--youngs-modulus", "14.8e9", &SceneParameters::youngs_modulus, positive, "must be > 0"},
      {"--poisson-ratio", "0.2", &SceneParameters::poisson_ratio,
       [](double v) { return v > -1 && v <= 0.5; }, "must lie in (-1, 0.5]"},
      {"--density", "2348", &SceneParameters::density, [](double v) { return v >= 0; },
       "must be >= 0 (0: no self-weight, with another load)"},
      {"--gravity", "9.81", &SceneParameters::gravity, positive, "must be > 0"},
      {"--shear-coefficient", "0.8333333333333334", &SceneParameters::shear_coefficient,
       [](double v) { return v > 0 && v <= 2; }, "must lie in (0, 2]"},
      {"--thickness-ratio", "0.08", &SceneParameters::thickness_ratio,
       [](double v) { return v > 0 && v < 1; }, "must lie in (0, 1)"},
      {"--support-displacement-ratio", "0", &SceneParameters::support_displacement_ratio,
       [](double v) { return std::abs(v) <= 0.01; },
       "must lie in [-0.01, 0.01] (d/L; beyond, small-displacement theory does not hold)"},
      {"--haunch-angle", "", &SceneParameters::haunch_angle, [](double v) { return v > 0 && v < 90; },
       "must lie in (0, 90)"},
      {"--crown-angle", "", &SceneParameters::crown_angle, [](double v) { return v > 0 && v < 90; },
       "must lie in (0, 90)"},
      {"--rise-ratio", "", &SceneParameters::rise_ratio, [](double v) { return v > 0 && v <= 2; },
       "must lie in (0, 2]"},
      {"--eccentricity", "0", &SceneParameters::eccentricity, [](double v) { return v >= 0 && v <= 100; },
       "must lie in [0, 100]"},
  };
};

// What each scene option is, with its unit, for --help (the rules are the Axis table's).
const std::map<std::string, std::string> kAxisMeaning = {
    {"--span", "span L between the springings' axis points, m"},
    {"--youngs-modulus", "Young's modulus E, Pa"},
    {"--poisson-ratio", "Poisson's ratio nu (shear modulus G = E / (2 (1 + nu)))"},
    {"--density", "density rho, kg/m^3"},
    {"--gravity", "gravitational acceleration g, m/s^2"},
    {"--shear-coefficient", "Timoshenko shear coefficient k (5/6 for a rectangle)"},
    {"--thickness-ratio", "thickness over span t/L"},
    {"--support-displacement-ratio", "outward movement of each springing over span d/L (0.0003 = 0.03 %)"},
    {"--haunch-angle", "three- and four-centred: angle the haunch arc turns through, degrees"},
    {"--crown-angle", "four-centred: the tangent's angle above the horizontal at the crown, degrees"},
    {"--rise-ratio", "rise over span h/L (not for pointed, semicircular, points, whole-points)"},
    {"--eccentricity", "pointed: the centres' offset beyond mid-span over the span (0 semicircle, 0.5 equilateral)"},
    {"--point-load", "vertical point load P on the axis, N per metre of vault width, downwards"},
    {"--point-load-at", "where the point load acts, x / L from the left springing (default 0.5)"},
    {"--live-load", "uniform load q per horizontal length, N/m^2 (N/m per metre of width), downwards"},
    {"--live-load-from", "where the live load starts, x / L (default 0)"},
    {"--live-load-to", "where the live load ends, x / L (default 1)"},
    {"--fill-density", "fill density rho_f, kg/m^3: load rho_f g max(0, h_f - y_extrados(x)) per horizontal length"},
    {"--fill-height-ratio", "the fill's level h_f above the springing line, over the span"},
    {"--left-spread-ratio", "left springing's horizontal movement, outwards positive, over the span"},
    {"--right-spread-ratio", "right springing's horizontal movement, outwards positive, over the span"},
    {"--left-settlement-ratio", "left springing's vertical movement, downwards positive, over the span"},
    {"--right-settlement-ratio", "right springing's vertical movement, downwards positive, over the span"},
    {"--left-rotation", "left springing's rotation, rad, counter-clockwise positive (clamped only)"},
    {"--right-rotation", "right springing's rotation, rad, counter-clockwise positive (clamped only)"},
};

void add_scene_options(CLI::App& cmd, SceneOptions& o) {
  std::string names;
  for (const CurveFamily& f : kFamilies) names += (names.empty() ? "" : ", ") + f.name;
  cmd.add_option("--curve", o.curve, "generator curve: " + names)->capture_default_str();
  cmd.add_option("--curve-file", o.curve_file,
                 "with --curve points: CSV file with header x,y and the axis points in m, springing (y = 0) to crown; "
                 "with --curve whole-points: springing to springing (any heights); - reads it from standard input");
  // What an option without a default text means when it is not given.
  auto absent = [](const std::string& flag) -> std::string {
    if (flag == "--rise-ratio" || flag == "--haunch-angle" || flag == "--crown-angle") return " (default: the curve's)";
    if (flag == "--left-spread-ratio" || flag == "--right-spread-ratio") return " (default: --support-displacement-ratio)";
    if (flag == "--point-load-at" || flag == "--live-load-from" || flag == "--live-load-to") return "";
    return " (default: none)";
  };
  for (Axis& a : o.axes)
    cmd.add_option(a.flag, a.text,
                   fmt::format("{}; {}; a value, a list a,b,c or a range start:stop:count{}", kAxisMeaning.at(a.flag),
                               a.rule, a.text.empty() ? absent(a.flag) : ""))
        ->capture_default_str();
  cmd.add_flag("--plane-strain", o.plane_strain, "plane strain: E / (1 - nu^2) for axial and bending stiffness");
  cmd.add_option("--supports", o.supports, "both springings: clamped or pinned")->capture_default_str();
  cmd.add_option("--left-support", o.left_support, "left springing: clamped or pinned (default: --supports)");
  cmd.add_option("--right-support", o.right_support, "right springing: clamped or pinned (default: --supports)");
  cmd.add_option("--section", o.section,
                 "elastic (linear) or no-tension (cracks where the resultant leaves the kern; Newton on explicit forces "
                 "by quadrature, or shooting; a "
                 "sweep of support movements is traced in order)")
      ->capture_default_str();
  cmd.add_flag("--crown-hinge", o.crown_hinge, "a hinge at the crown (M = 0): the three-hinged arch with --supports pinned");
  cmd.add_option("--loads-file", o.loads_file,
                 "CSV of loads, header kind,value,a,b: point,P,a, | live,q,a,b | fill,rho_f,h_f/L, (README: Loads)");
}

const std::map<std::string, SupportKind> kSupportKinds = {{"clamped", SupportKind::clamped},
                                                          {"pinned", SupportKind::pinned}};
const std::map<std::string, SectionKind> kSectionKinds = {{"elastic", SectionKind::elastic},
                                                          {"no-tension", SectionKind::no_tension}};

// "rise_ratio: rule" from the library becomes "--rise-ratio: rule"; the scene's lengths are given
// as ratios of the span on the command line, so "thickness: ..." names --thickness-ratio.
std::string as_option_message(const std::string& what) {
  const std::size_t colon = what.find(':');
  if (colon == std::string::npos || what.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") < colon) return what;
  std::string field = what.substr(0, colon);
  if (field == "thickness" || field == "support_displacement" || field == "left_spread" || field == "right_spread" ||
      field == "left_settlement" || field == "right_settlement")
    field += "_ratio";
  std::string flag = "--" + field;
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag + what.substr(colon);
}

// The scenes of a sweep, one at a time: the product of the axes' values, never held all at once (a
// million scenes must not cost memory). Malformed options (a value outside its rule, an unknown curve)
// are refused here, before anything is printed; a combination of valid values that makes no scene
// (a thickness that does not fit a flat arch) is a row of its own, status invalid_scene.
class ScenePlan {
 public:
  ScenePlan(SceneOptions& o, const CLI::App& cmd) : options_(o) {
    const auto family =
        std::find_if(kFamilies.begin(), kFamilies.end(), [&](const CurveFamily& f) { return f.name == o.curve; });
    if (family == kFamilies.end()) {
      std::string names;
      for (const CurveFamily& f : kFamilies) names += (names.empty() ? "" : ", ") + f.name;
      throw UsageError(fmt::format("--curve: unknown curve '{}' (known: {})", o.curve, names));
    }
    family_ = &*family;
    auto refuse_unless = [&](bool applies, const char* flag) {
      if (!applies && cmd.count(flag) > 0) throw UsageError(fmt::format("{}: does not apply to --curve {}", flag, o.curve));
    };
    refuse_unless(family->eccentricity, "--eccentricity");
    refuse_unless(family->rise, "--rise-ratio");
    refuse_unless(family->haunch, "--haunch-angle");
    refuse_unless(family->crown, "--crown-angle");
    refuse_unless(family->file, "--curve-file");
    refuse_unless(!family->file, "--span");  // a points file sets its own span
    if (family->file) {
      if (o.curve_file.empty())
        throw UsageError(fmt::format("--curve-file: --curve {} needs a file of axis points", o.curve));
      try {
        // "-": the points come on standard input (a survey piped from another program).
        const bool whole = o.curve == "whole-points";
        if (o.curve_file == "-")
          o.points = whole ? parse_whole_points_curve(std::cin, "<stdin>") : parse_points_curve(std::cin, "<stdin>");
        else
          o.points = whole ? read_whole_points_curve(o.curve_file) : read_points_curve(o.curve_file);
      } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
      }
    }
    // Loads and supports: options that need another, and each springing's kind.
    auto needs = [&](const char* flag, const char* other) {
      if (cmd.count(flag) > 0 && cmd.count(other) == 0) throw UsageError(fmt::format("{}: needs {}", flag, other));
    };
    needs("--point-load-at", "--point-load");
    needs("--live-load-from", "--live-load");
    needs("--live-load-to", "--live-load");
    needs("--fill-height-ratio", "--fill-density");
    needs("--fill-density", "--fill-height-ratio");
    for (const char* side : {"--left-spread-ratio", "--right-spread-ratio"})
      if (cmd.count(side) > 0 && cmd.count("--support-displacement-ratio") > 0)
        throw UsageError(fmt::format("{}: cannot be combined with --support-displacement-ratio (both springings "
                                     "spreading alike): give each side's spread instead",
                                     side));
    left_kind_ = o.left_support.empty() ? lookup(kSupportKinds, o.supports, "--supports")
                                        : lookup(kSupportKinds, o.left_support, "--left-support");
    right_kind_ = o.right_support.empty() ? lookup(kSupportKinds, o.supports, "--supports")
                                          : lookup(kSupportKinds, o.right_support, "--right-support");
    if (!o.left_support.empty() || !o.right_support.empty()) lookup(kSupportKinds, o.supports, "--supports");
    section_ = lookup(kSectionKinds, o.section, "--section");
    for (const auto& [flag, kind] : {std::pair{"--left-rotation", left_kind_}, {"--right-rotation", right_kind_}})
      if (kind == SupportKind::pinned && cmd.count(flag) > 0)
        throw UsageError(fmt::format("{}: does not apply to a pinned springing (it turns freely: its rotation is a "
                                     "result, not a given movement)",
                                     flag));
    if (!o.loads_file.empty()) {
      if (o.loads_file == "-" && o.curve_file == "-")
        throw UsageError("--loads-file: standard input already holds the curve's points (--curve-file -)");
      try {
        o.file_loads = o.loads_file == "-" ? parse_loads(std::cin, "<stdin>") : read_loads_file(o.loads_file);
      } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
      }
    }
    for (Axis& a : o.axes) {
      std::string text = a.text;
      const bool given = cmd.count(a.flag) > 0;  // given text is parsed as it stands, even if empty
      if (!given && text.empty()) {
        if (a.flag == "--rise-ratio") text = family->default_rise;
        if (a.flag == "--haunch-angle") text = family->default_haunch;
        if (a.flag == "--crown-angle") text = family->default_crown;
      }
      if (family->file && a.flag == "--span") text = fmt::format("{}", o.points->span());
      // Not a parameter of this curve: one NaN, printed as an empty field.
      const bool absent = !given && text.empty();
      a.values = absent ? std::vector<double>{std::numeric_limits<double>::quiet_NaN()} : parse_values(text, a.flag);
      for (double v : a.values)
        if (!std::isnan(v) && !a.allowed(v)) throw UsageError(fmt::format("{}: {}, got {}", a.flag, a.rule, v));
      size_ *= a.values.size();
      if (size_ > kMaxValues)
        throw UsageError(fmt::format("{}: the options give more than {} scenes", a.flag, kMaxValues));
    }
    require_some_scene();
  }

  std::size_t size() const { return size_; }

  // The columns of the inputs that take more than one value.
  std::vector<std::string> varying_inputs() const {
    std::vector<std::string> out;
    for (const Axis& a : options_.axes) {
      if (a.values.size() < 2) continue;
      std::string name = a.flag.substr(2);
      std::replace(name.begin(), name.end(), '-', '_');
      out.push_back(name);
    }
    return out;
  }

  // Scene number `index` (0-based) of the sweep; the last axis varies fastest.
  SceneParameters parameters(std::size_t index) const {
    SceneParameters p{};
    p.scene = index + 1;
    p.curve = options_.curve;
    p.plane_strain = options_.plane_strain;
    for (std::size_t i = options_.axes.size(); i-- > 0;) {
      const Axis& a = options_.axes[i];
      p.*(a.field) = a.values[index % a.values.size()];
      index /= a.values.size();
    }
    if (!family_->eccentricity) p.eccentricity = std::numeric_limits<double>::quiet_NaN();
    // The defaults of the load and movement options, as the row prints them.
    if (!std::isnan(p.point_load) && std::isnan(p.point_load_at)) p.point_load_at = 0.5;
    if (!std::isnan(p.live_load) && std::isnan(p.live_load_from)) p.live_load_from = 0;
    if (!std::isnan(p.live_load) && std::isnan(p.live_load_to)) p.live_load_to = 1;
    if (std::isnan(p.left_spread_ratio)) p.left_spread_ratio = p.support_displacement_ratio;
    if (std::isnan(p.right_spread_ratio)) p.right_spread_ratio = p.support_displacement_ratio;
    p.left_support = left_kind_ == SupportKind::clamped ? "clamped" : "pinned";
    p.right_support = right_kind_ == SupportKind::clamped ? "clamped" : "pinned";
    p.crown_hinge = options_.crown_hinge;
    p.loads_file = options_.loads_file;
    p.section = section_ == SectionKind::elastic ? "elastic" : "no-tension";
    return p;
  }

  // The scene of p, or why there is none (one line naming the option and the rule): the curve's
  // factory and Scene::validate judge the combination.
  struct Built {
    std::optional<Scene> scene;
    std::shared_ptr<const Curve> curve;  // set whenever the curve itself could be made
    std::string problem;
  };
  Built build(const SceneParameters& p) const {
    Built out;
    try {
      out.curve = make_curve(p);
      Scene scene;
      scene.curve = out.curve;
      scene.thickness = p.thickness_ratio * p.span;
      scene.material = {p.youngs_modulus, p.poisson_ratio, p.density, p.gravity, p.shear_coefficient, p.plane_strain};
      scene.left = {left_kind_, p.left_spread_ratio * p.span, p.left_settlement_ratio * p.span, p.left_rotation};
      scene.right = {right_kind_, p.right_spread_ratio * p.span, p.right_settlement_ratio * p.span, p.right_rotation};
      scene.crown_hinge = options_.crown_hinge;
      scene.section = section_;
      scene.loads = options_.file_loads;
      if (!std::isnan(p.point_load)) scene.loads.points.push_back({p.point_load, p.point_load_at});
      if (!std::isnan(p.live_load)) scene.loads.live.push_back({p.live_load, p.live_load_from, p.live_load_to});
      if (!std::isnan(p.fill_density)) scene.loads.fills.push_back({p.fill_density, p.fill_height_ratio});
      scene.validate();
      out.scene = std::move(scene);
    } catch (const std::invalid_argument& e) {
      out.problem = as_option_message(e.what());
    }
    return out;
  }

  // Exit 2 (UsageError) when no scene of the sweep can be made: the first one's reason. Scans without
  // keeping anything (and stops at the first scene that can be made), before anything is printed.
  void require_some_scene() const {
    std::string first_problem;
    for (std::size_t i = 0; i < size_; ++i) {
      Built b = build(parameters(i));
      if (b.scene) return;
      if (first_problem.empty()) first_problem = std::move(b.problem);
    }
    throw UsageError(size_ == 1 ? first_problem : "no scene of the sweep can be made; the first: " + first_problem);
  }

 private:
  std::shared_ptr<const Curve> make_curve(const SceneParameters& p) const {
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

  const SceneOptions& options_;
  const CurveFamily* family_ = nullptr;
  SupportKind left_kind_ = SupportKind::clamped, right_kind_ = SupportKind::clamped;
  SectionKind section_ = SectionKind::elastic;
  std::size_t size_ = 1;

 public:
  bool no_tension() const { return section_ == SectionKind::no_tension; }
};

// ---------------------------------------------------------------------------------------------
// Columns: every column of every command, its unit and meaning, in one place. `--columns help` prints a
// command's as CSV; the README lists them; a test checks that every header name is documented here.

struct ColumnDoc {
  std::string_view name, unit, meaning;
};

const std::vector<ColumnDoc> kColumnDocs = {
    {"scene", "", "scene number in the sweep, from 1"},
    {"curve", "", "generator curve family"},
    {"eccentricity", "", "pointed arch: centres eccentricity x span beyond mid-span (0 semicircle, 0.5 equilateral)"},
    {"rise_ratio", "", "rise / span: as asked, or for curves without --rise-ratio their own (12 digits)"},
    {"haunch_angle", "deg", "three- and four-centred arches: angle turned by the haunch arc"},
    {"crown_angle", "deg", "four-centred arch: tangent's angle at the pointed crown"},
    {"span", "m", "span L between the springings, on the axis"},
    {"thickness_ratio", "", "thickness t / span"},
    {"support_displacement_ratio", "", "outward movement d of each springing / span"},
    {"youngs_modulus", "Pa", "Young's modulus E"},
    {"poisson_ratio", "", "Poisson's ratio nu"},
    {"density", "kg/m^3", "density rho"},
    {"gravity", "m/s^2", "gravitational acceleration g"},
    {"shear_coefficient", "", "Timoshenko shear coefficient k"},
    {"plane_strain", "", "true: plane strain, E / (1 - nu^2); false: plane stress"},
    {"section", "", "elastic (linear) or no-tension (cracks beyond the kern)"},
    {"left_support", "", "left springing: clamped (rotation given) or pinned (M = 0)"},
    {"right_support", "", "right springing: clamped or pinned"},
    {"crown_hinge", "", "true: a hinge at the crown (M = 0 there)"},
    {"left_spread_ratio", "", "left springing's horizontal movement, outwards positive / span"},
    {"right_spread_ratio", "", "right springing's horizontal movement, outwards positive / span"},
    {"left_settlement_ratio", "", "left springing's vertical movement, downwards positive / span"},
    {"right_settlement_ratio", "", "right springing's vertical movement, downwards positive / span"},
    {"left_rotation", "rad", "left springing's given rotation, counter-clockwise positive"},
    {"right_rotation", "rad", "right springing's given rotation, counter-clockwise positive"},
    {"point_load", "N/m", "vertical point load P on the axis, downwards, per metre of vault width"},
    {"point_load_at", "", "where P acts, x / span from the left springing"},
    {"live_load", "N/m^2", "uniform load q per horizontal length, downwards, per metre of vault width"},
    {"live_load_from", "", "where the live load starts, x / span"},
    {"live_load_to", "", "where the live load ends, x / span"},
    {"fill_density", "kg/m^3", "fill density rho_f (load rho_f g max(0, h_f - y_extrados) per horizontal length)"},
    {"fill_height_ratio", "", "the fill's level h_f above the springing line / span"},
    {"loads_file", "", "the --loads-file whose loads the scene carries too"},
    {"method", "", "method that produced the numbers (closed-form, shooting, multiple-shooting)"},
    {"integrator", "", "CVODE's method (adams, bdf); empty for the closed form"},
    {"rtol", "", "relative error asked (--rtol); success guarantees it"},
    {"status", "", "success, or why not (README: What status promises); limit: success or inadmissible"},
    {"domain", "", "the model solved: half (a symmetric scene, the right half by symmetry) or whole (springing to springing)"},
    {"H", "N/m", "horizontal reaction H_left: inward push of the left support on the arch, per metre of vault (limit --thrust-line: of that state)"},
    {"V", "N/m", "vertical reaction V_left of the left support (half the load of a symmetric scene; limit: half the total vertical load), per metre of vault"},
    {"H_over_V", "", "normalized horizontal reaction H_left / V_left"},
    {"H_left", "N/m", "left support's horizontal reaction on the arch, positive pointing into the span (+x)"},
    {"V_left", "N/m", "left support's vertical reaction on the arch, upwards positive"},
    {"M_left", "N m/m", "left support's couple on the arch, counter-clockwise positive (0 when pinned)"},
    {"H_right", "N/m", "right support's horizontal reaction on the arch, positive pointing into the span (-x)"},
    {"V_right", "N/m", "right support's vertical reaction on the arch, upwards positive"},
    {"M_right", "N m/m", "right support's couple on the arch, counter-clockwise positive (0 when pinned)"},
    {"max_thrust_eccentricity", "%", "largest |thrust_eccentricity| along the arch; empty if N is not a compression everywhere"},
    {"max_thrust_eccentricity_at", "m", "arc length from the left springing where it occurs"},
    {"thrust_in_kern", "", "true: compression everywhere and |thrust_eccentricity| <= 100 % (no tension in the section)"},
    {"thrust_in_section", "", "true: compression everywhere and |thrust_eccentricity| <= 300 % (resultant inside the masonry)"},
    {"steps", "", "CVODE steps, all solves of the row"},
    {"rhs_evaluations", "", "CVODE right-hand-side evaluations"},
    {"segments", "", "shooting segments (arcs for the closed form)"},
    {"newton_iterations", "", "no-tension section: Newton iterations, all solves of the row (0 for the elastic section)"},
    {"condition_estimate", "", "Skeel condition number of the boundary-value problem"},
    {"error_estimate", "", "estimated relative error of the row's numbers (thrust eccentricities in units of the kern)"},
    {"boundary_residual", "", "largest residual of the six boundary conditions (and a hinge's M = 0), scaled units"},
    {"equilibrium_residual", "", "largest residual of the domain's equilibrium (forces, moments) / its load"},
    {"message", "", "why the status is not success; empty on success"},
    {"s", "m", "arc length from the left springing (limit --thrust-line: of the joint's axis point)"},
    {"x", "m", "axis point, horizontal from the left springing"},
    {"y", "m", "axis point, up from the springing line"},
    {"theta", "rad", "tangent angle to the horizontal, in the direction of increasing s"},
    {"kappa", "1/m", "curvature d theta / ds (negative: turning downwards)"},
    {"intrados_x", "m", "the section's (limit: the joint's) end on the intrados, horizontal (profile: axis point - t/2 along the normal)"},
    {"intrados_y", "m", "the section's end on the intrados, vertical"},
    {"extrados_x", "m", "the section's (limit: the joint's) end on the extrados, horizontal (profile: axis point + t/2 along the normal)"},
    {"extrados_y", "m", "the section's end on the extrados, vertical"},
    {"Ux", "m", "horizontal displacement of the axis"},
    {"Uy", "m", "vertical displacement of the axis"},
    {"psi", "rad", "rotation of the cross-section, counter-clockwise positive"},
    {"N", "N/m", "normal force, negative in compression"},
    {"shear_force", "N/m", "shear force (V of the model's equations)"},
    {"M", "N m/m", "bending moment: couple of the part beyond s on the part before s"},
    {"thrust_eccentricity", "%", "e = 600 M / (N t): offset of the compression in per cent of the kern half-width t/6; < 0 towards the extrados"},
    {"thrust_x", "m", "where the resultant crosses the section or joint (line of thrust), horizontal"},
    {"thrust_y", "m", "where the resultant crosses the section (line of thrust), vertical"},
    {"compressed_depth", "", "no-tension section: the compressed depth c over t (1 while the resultant is in the kern; 0 at a hinge); empty for the elastic section"},
    {"cracked", "", "no-tension section: true where the resultant lies beyond the kern (the section is cracked); empty for the elastic section"},
    {"warning", "", "tension, outside_section (|e| > 300 %), outside_kern (|e| > 100 %), no_normal_force, or empty"},
    {"reference_method", "", "check: what the row is compared with"},
    {"reference_status", "", "check: the reference's own status"},
    {"reference_error", "", "check and bench: the reference's own estimated error"},
    {"reference_H_over_V", "", "check: the reference's H / V"},
    {"relative_difference", "", "check: |H/V - reference| / max(|reference|, 0.01)"},
    {"tolerance", "", "check: the rtol the row is held to"},
    {"within_tolerance", "", "check: true when the row says success and relative_difference <= rtol + reference_error"},
    {"chosen_method", "", "bench: the method auto chose (or the method itself)"},
    {"error_H_over_V", "", "bench: true error of H/V against the reference"},
    {"error_profile", "", "bench: true error of the profile (profile_difference) against the reference"},
    {"median_seconds", "s", "bench: median time of one solve"},
    {"file", "", "draw: the SVG file written for the scene"},
    {"joints", "", "limit: joint orientation, radial (normal to the axis) or vertical"},
    {"weight", "", "limit: voussoir (each voussoir's weight at its centroid) or axis (rho g t per axis length)"},
    {"joints_count", "", "limit: joints springing to springing, both included"},
    {"friction", "", "limit: friction coefficient of the joints; empty: no sliding check"},
    {"H_min", "N/m", "limit: minimum horizontal thrust of an admissible state"},
    {"H_max", "N/m", "limit: maximum horizontal thrust of an admissible state"},
    {"H_min_over_V", "", "limit: H_min / V"},
    {"H_max_over_V", "", "limit: H_max / V"},
    {"thickness_min_ratio", "", "limit: t_min / span, the thinnest arch of the same axis that stands"},
    {"geometric_safety_factor", "", "limit: t / t_min"},
    {"hinges_min", "", "limit: hinges of the minimum-thrust state, x/L:face joined by ';' (face: intrados, extrados, or axis for a pin)"},
    {"hinges_max", "", "limit: hinges of the maximum-thrust state, x/L:face joined by ';'"},
    {"load_factor", "", "limit: multiplier on the live load (every point and live load) at collapse (static LP)"},
    {"load_factor_mechanism", "", "limit: the same from the mechanism of those hinges by virtual work"},
    {"hinges_collapse", "", "limit: hinges of the collapse mechanism, x/L:face joined by ';'"},
    {"lp_solves", "", "limit: linear programs solved for the row"},
    {"state", "", "limit --thrust-line: min, max or collapse"},
    {"joint", "", "limit --thrust-line: joint index from the left springing"},
    {"hinge", "", "limit --thrust-line: intrados, extrados (a hinge) or axis (a pin), else empty"},
};

const ColumnDoc* find_column_doc(std::string_view name) {
  for (const ColumnDoc& d : kColumnDocs)
    if (d.name == name) return &d;
  return nullptr;
}

const std::vector<std::string> kSceneColumns = {
    "scene", "curve", "eccentricity", "rise_ratio", "haunch_angle", "crown_angle", "span", "thickness_ratio",
    "support_displacement_ratio", "youngs_modulus", "poisson_ratio", "density", "gravity", "shear_coefficient",
    "plane_strain", "section", "left_support", "right_support", "crown_hinge", "left_spread_ratio", "right_spread_ratio",
    "left_settlement_ratio", "right_settlement_ratio", "left_rotation", "right_rotation", "point_load",
    "point_load_at", "live_load", "live_load_from", "live_load_to", "fill_density", "fill_height_ratio", "loads_file"};

// The --columns and --all-columns options of a command.
struct ColumnText {
  std::string columns;
  bool all_columns = false;
  const CLI::Option* option = nullptr;  // --columns, to tell an empty list from none given
  bool given() const { return option && option->count() > 0; }
};

// " (did you mean 'x'?)" for the candidate closest to a misspelt name (edit distance at most 2), or "".
std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates) {
  if (name.size() > 100) return "";
  std::size_t best = std::string::npos, best_distance = 3;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const std::string& c = candidates[i];
    std::vector<std::size_t> row(c.size() + 1);
    for (std::size_t j = 0; j <= c.size(); ++j) row[j] = j;
    for (std::size_t a = 1; a <= name.size(); ++a) {
      std::size_t diagonal = row[0];
      row[0] = a;
      for (std::size_t j = 1; j <= c.size(); ++j) {
        const std::size_t up = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (name[a - 1] == c[j - 1] ? 0 : 1)});
        diagonal = up;
      }
    }
    if (row[c.size()] < best_distance) {
      best_distance = row[c.size()];
      best = i;
    }
  }
  return best == std::string::npos ? "" : " (did you mean '" + candidates[best] + "'?)";
}

// A command's columns in their full order, and which of them are printed: by default the scene number,
// the inputs that vary in the sweep and the command's results; `--columns a,b` chooses (in the full
// order), `--all-columns` prints everything.
class Columns {
 public:
  Columns(std::vector<std::string> results, std::vector<std::string> defaults)
      : all_(kSceneColumns), defaults_(std::move(defaults)) {
    all_.insert(all_.end(), results.begin(), results.end());
  }
  const std::vector<std::string>& all() const { return all_; }

  // The user's --columns and --all-columns.
  void select(const ColumnText& ct, const std::vector<std::string>& varying_inputs,
              const std::vector<std::string>& varying_solver = {}) {
    const std::string& text = ct.columns;
    if (ct.given() && ct.all_columns) throw UsageError("--columns: give either --columns or --all-columns");
    keep_.assign(all_.size(), ct.all_columns);
    if (ct.all_columns) return;
    std::vector<std::string> wanted;
    if (!ct.given()) {
      wanted = defaults_;
      wanted.push_back("scene");
      wanted.insert(wanted.end(), varying_inputs.begin(), varying_inputs.end());
      wanted.insert(wanted.end(), varying_solver.begin(), varying_solver.end());
    } else {
      for (std::size_t pos = 0; pos <= text.size();) {
        const std::size_t comma = std::min(text.find(',', pos), text.size());
        const std::string name = text.substr(pos, comma - pos);
        if (std::find(all_.begin(), all_.end(), name) == all_.end())
          throw UsageError(fmt::format("--columns: no column '{}' in this command's output{} (--columns help lists them)",
                                       name.substr(0, 60), suggestion(name)));
        wanted.push_back(name);
        pos = comma + 1;
      }
    }
    for (std::size_t i = 0; i < all_.size(); ++i)
      keep_[i] = std::find(wanted.begin(), wanted.end(), all_[i]) != wanted.end();
  }
  const std::vector<bool>* keep() const { return &keep_; }
  bool selected(std::string_view name) const {
    for (std::size_t i = 0; i < all_.size(); ++i)
      if (all_[i] == name) return keep_[i];
    return false;
  }
  std::string header() const {
    std::string out;
    for (std::size_t i = 0; i < all_.size(); ++i)
      if (keep_[i]) out += (out.empty() ? "" : ",") + all_[i];
    return out + "\n";
  }
  // --columns help: the command's columns, their units and meanings, as CSV.
  std::string help() const {
    std::string out = "column,unit,meaning\n";
    CsvRow row;
    for (const std::string& name : all_) {
      const ColumnDoc* d = find_column_doc(name);
      row.add(name).add(d ? d->unit : "").add(d ? d->meaning : "");
      out += row.take();
    }
    return out;
  }

 private:
  std::string suggestion(const std::string& name) const { return did_you_mean(name, all_); }
  std::vector<std::string> all_, defaults_;
  std::vector<bool> keep_;
};

void add_column_options(CLI::App& cmd, ColumnText& text) {
  text.option = cmd.add_option("--columns", text.columns,
                 "columns to print, comma-separated, in the output's order; 'help' lists every column with its "
                 "unit (default: scene, the inputs that vary, the results)");
  cmd.add_flag("--all-columns", text.all_columns, "print every column, the inputs that do not vary included");
}

// A parameter that does not apply to the scene's curve is an empty field, never "nan".
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void add_parameter(CsvRow& row, double value) {
  if (std::isnan(value)) row.add(std::string_view{});
  else row.add(value);
}

// Twelve significant digits: a rise derived from the geometry (exact to about 1e-15) prints as the
// number it is meant to be, 0.5 for the semicircle and not 0.4999999999999999.
double rounded(double value) {
  if (!std::isfinite(value) || value == 0) return value;
  return std::stod(fmt::format("{:.12g}", value));
}

// curve may be null (a scene whose curve could not be made): its rise is then the one asked for.
void add_scene_columns(CsvRow& row, const SceneParameters& p, const Curve* curve) {
  row.add(static_cast<std::int64_t>(p.scene)).add(p.curve);
  add_parameter(row, p.eccentricity);
  if (!std::isnan(p.rise_ratio)) row.add(p.rise_ratio);  // the rise asked for
  else if (curve) row.add(rounded(curve->rise() / curve->span()));
  else row.add(std::string_view{});
  add_parameter(row, p.haunch_angle);
  add_parameter(row, p.crown_angle);
  row.add(p.span).add(p.thickness_ratio).add(p.support_displacement_ratio);
  row.add(p.youngs_modulus).add(p.poisson_ratio).add(p.density).add(p.gravity).add(p.shear_coefficient);
  row.add_bool(p.plane_strain);
  row.add(p.section).add(p.left_support).add(p.right_support).add_bool(p.crown_hinge);
  for (double v : {p.left_spread_ratio, p.right_spread_ratio, p.left_settlement_ratio, p.right_settlement_ratio,
                   p.left_rotation, p.right_rotation, p.point_load, p.point_load_at, p.live_load, p.live_load_from,
                   p.live_load_to, p.fill_density, p.fill_height_ratio})
    add_parameter(row, v);
  row.add(p.loads_file);
}

// ---------------------------------------------------------------------------------------------
// Solver options, bound straight into ogive::Options.

const std::map<std::string, Method> kMethods = {{"closed-form", Method::closed_form},
                                                {"shooting", Method::shooting},
                                                {"multiple-shooting", Method::multiple_shooting},
                                                {"quadrature", Method::quadrature},
                                                {"auto", Method::automatic}};
const std::map<std::string, Integrator> kIntegrators = {{"adams", Integrator::adams}, {"bdf", Integrator::bdf}};

// Method and integrator are bound as text and mapped here, so that only their names are accepted.
struct SolverText {
  std::string method = "auto";
  std::string integrator = "adams";
  std::string rtol = "1e-8";  // a value, a list or a range, like a scene option
  bool no_verify = false;
  bool ignore_breakpoints = false;
};

// CLI11 would read "" as 0 and saturate huge integers; numeric options must be what parse_number
// accepts (the whole text, finite), and counts whole numbers within what an int holds.
// What is wrong with an option's text as a number (empty if nothing): not what parse_number accepts,
// or, for counts, not a whole number up to 1e9.
std::string number_problem(const std::string& text, bool count) {
  double v = 0;
  try {
    v = parse_number(text, "");
  } catch (const UsageError&) {
    return "'" + text.substr(0, 60) + "' is not a finite number";
  }
  if (count && (v != std::floor(v) || std::abs(v) > 1e9))
    return "'" + text.substr(0, 60) + "' is not a whole number up to 1e9";
  return {};
}
const CLI::Validator kFiniteNumber([](std::string& text) { return number_problem(text, false); }, "NUMBER");
const CLI::Validator kCount([](std::string& text) { return number_problem(text, true); }, "COUNT");

// check chooses its methods itself (every one); bench also answers to the plural spellings it had.
void add_solver_options(CLI::App& cmd, Options& o, SolverText& text, bool with_method = true, bool plurals = false) {
  if (with_method)
    cmd.add_option(plurals ? "--method,--methods" : "--method", text.method, "closed-form (circular arcs only), quadrature (the force method, every curve), shooting, "
                   "multiple-shooting or auto (the closed form where it applies, else the quadrature where its estimate "
                   "meets --rtol, else shooting with 1, 2, 4 .. 64 segments until the error estimate meets --rtol); a "
                   "list a,b gives a row for each")->capture_default_str();
  cmd.add_option(plurals ? "--integrator,--integrators" : "--integrator", text.integrator, "CVODE's method: adams or bdf (the closed form uses none); a list "
                   "a,b gives a row for each")->capture_default_str();
  cmd.add_option(plurals ? "--rtol,--rtols" : "--rtol", text.rtol,
                 "relative error asked of every printed number; must lie in [1e-14, 0.1]; status success "
                 "guarantees it. CVODE itself runs at rtol/10 (adams) or rtol/1000 (bdf), and a verifying solve "
                 "at rtol/16. A value, a list a,b,c or a range start:stop:count: a row for each")
      ->capture_default_str();
  cmd.add_option("--atol", o.atol,
                 "CVODE's absolute tolerance on the scaled state; must be >= 0 (0: 1e-6 of CVODE's rtol); the "
                 "verifying solve uses the smaller of atol and that default, /16")
      ->check(kFiniteNumber)->capture_default_str();
  cmd.add_option("--segments", o.segments, "multiple-shooting segments over the domain (breakpoints and loads add more); must lie in [1, 10000]")->check(kCount)->capture_default_str();
  cmd.add_option("--max-steps", o.max_steps, "CVODE step limit per integration span; must be >= 1")->check(kCount)->capture_default_str();
  cmd.add_flag("--no-verify", text.no_verify,
               "skip the second solve at rtol/16 that estimates the error (raw methods, for benchmarks): the "
               "status is then at best unverified, never success; auto always verifies");
  cmd.add_flag("--ignore-breakpoints", text.ignore_breakpoints,
               "let CVODE step across jumps of curvature (for stability studies)");
  cmd.add_flag("--whole-arch", o.whole_arch,
               "solve a symmetric scene over the whole arch too (a check; by default the half, the smaller model)");
}

void apply_solver_text(Options& o, const SolverText& text) {
  o.verify = !text.no_verify;
  o.restart_at_breakpoints = !text.ignore_breakpoints;
}

void check_options(const Options& o) {
  std::string why;
  if (!o.is_valid(&why)) throw UsageError(as_option_message(why));
}

// Comma-separated names ("a,b"): each one, empty ones included (the lookup refuses them).
std::vector<std::string> split_names(const std::string& text) {
  std::vector<std::string> names;
  for (std::size_t pos = 0; pos <= text.size();) {
    const std::size_t comma = std::min(text.find(',', pos), text.size());
    names.push_back(text.substr(pos, comma - pos));
    pos = comma + 1;
  }
  return names;
}

// The solver options of a command: --method, --integrator and --rtol take lists (and --rtol ranges),
// like the scene options; each combination is a row of its own, after the scene's (rtol fastest).
struct SolverSweep {
  std::vector<Options> combinations;
  std::vector<std::string> varying;  // the columns among method, integrator and rtol that take several values
};

SolverSweep solver_sweep(Options base, const SolverText& text, bool with_method = true) {
  apply_solver_text(base, text);
  std::vector<Method> methods;
  for (const std::string& name : with_method ? split_names(text.method) : std::vector<std::string>{"auto"})
    methods.push_back(lookup(kMethods, name, "--method"));
  std::vector<Integrator> integrators;
  for (const std::string& name : split_names(text.integrator)) integrators.push_back(lookup(kIntegrators, name, "--integrator"));
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

// The integrator column: CVODE's method, empty for the methods that use none.
std::string_view integrator_of(Method method, const Options& o) {
  return method == Method::closed_form || method == Method::quadrature ? std::string_view{} : to_string(o.integrator);
}

// The status of a row whose options are each valid but make no scene together (Scene::validate or the
// curve's factory refused the combination); its message says why. Not a library Status: solve() is
// never called for it.
constexpr std::string_view kInvalidScene = "invalid_scene";

// A row with the scene's inputs and a few named fields (status, message, ...); every other field empty:
// an impossible scene, or a solve that produced no numbers.
std::string sparse_row(const Columns& columns, const SceneParameters& p, const Curve* curve,
                       const std::vector<std::pair<std::string_view, std::string>>& fields) {
  CsvRow row(columns.keep());
  add_scene_columns(row, p, curve);
  for (std::size_t i = kSceneColumns.size(); i < columns.all().size(); ++i) {
    const auto it = std::find_if(fields.begin(), fields.end(), [&](const auto& f) { return f.first == columns.all()[i]; });
    row.add(it == fields.end() ? std::string_view{} : std::string_view(it->second));
  }
  return row.take();
}

std::string invalid_scene_row(const Columns& columns, const SceneParameters& p, const ScenePlan::Built& b) {
  return sparse_row(columns, p, b.curve.get(), {{"status", std::string(kInvalidScene)}, {"message", b.problem}});
}

// ---------------------------------------------------------------------------------------------
// Output: rows are written as they are made, in pieces of whole rows, so that the first row of a long
// sweep arrives at once, memory does not grow with the sweep, and a killed run leaves only complete
// rows (each piece goes out in one write after the stream's buffer was emptied). A failed write (disk
// full, a closed stdout) ends the run: OutputError, exit status kExitOutput. A closed pipe raises
// SIGPIPE before any of this, which ends the process quietly, as `| head` expects.

struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class RowWriter {
 public:
  explicit RowWriter(std::ostream& out) : out_(out) {}
  void write(const std::string& rows) {
    buffer_ += rows;
    // The header and the first row go out at once; then pieces of 64 KiB, or what 0.2 s produced.
    if (pieces_ < 2 || buffer_.size() >= kPiece || Clock::now() - last_ >= kInterval) flush();
  }
  void flush() {
    errno = 0;
    if (!buffer_.empty()) out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    out_.flush();
    if (!out_) {
      const int code = errno;
      throw OutputError(code ? std::string("cannot write the output: ") + std::strerror(code)
                             : std::string("cannot write the output"));
    }
    buffer_.clear();
    ++pieces_;
    last_ = Clock::now();
  }

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr std::size_t kPiece = 1 << 16;
  static constexpr std::chrono::milliseconds kInterval{200};
  std::ostream& out_;
  std::string buffer_;
  int pieces_ = 0;
  Clock::time_point last_ = Clock::now();
};

// ---------------------------------------------------------------------------------------------
// Subcommands.

// Commands that print rows along the arch: at least two stations, at most 10^7 rows in all.
void check_stations(int stations) {
  if (stations < 2 || stations > 1000000)
    throw UsageError(fmt::format("--stations: must lie in [2, 1000000], got {}", stations));
}

void check_rows(std::size_t scenes, int stations) {
  if (scenes * static_cast<std::size_t>(stations) > 10 * kMaxValues)
    throw UsageError(fmt::format("--stations: {} scenes x {} stations exceed {} rows", scenes, stations, 10 * kMaxValues));
}

// Where a scene's rows go: the writer (one thread) or the scene's slot in the reorder window.
using Emit = std::function<void(const std::string&)>;

// Every scene of the plan in order, built; `rows_of(p, scene, emit)` emits a valid scene's rows and
// returns whether it succeeded; `invalid_row(p, built)` returns the row of an impossible one. Returns
// whether every scene's row succeeded.
//
// With threads > 1, scenes are solved in parallel (each thread keeps its own SUNDIALS objects) and
// written in order: a worker takes the next chunk of consecutive scenes (so that locking costs little
// against scenes of a few microseconds) only while it lies within a window of 4 x threads
// chunks of the next one to be written, so memory stays bounded and the output is byte-identical to
// one thread's. The callbacks must not share mutable state between calls.
template <class Solved, class Invalid>
bool for_each_scene(const ScenePlan& plan, RowWriter& writer, int threads, Solved rows_of, Invalid invalid_row) {
  // One scene: its rows to emit, and whether it succeeded.
  auto one = [&](std::size_t i, const Emit& emit) {
    const SceneParameters p = plan.parameters(i);
    ScenePlan::Built built = plan.build(p);
    if (!built.scene) {
      emit(invalid_row(p, built));
      return false;
    }
    return rows_of(p, *built.scene, emit);
  };
  const std::size_t n = plan.size();
  bool all_ok = true;
  if (threads <= 1 || n <= 1) {
    const Emit to_writer = [&](const std::string& text) { writer.write(text); };
    for (std::size_t i = 0; i < n; ++i) all_ok = one(i, to_writer) && all_ok;
    writer.flush();
    return all_ok;
  }
  struct Slot {
    std::string text;
    bool ok = true, done = false;
  };
  // Chunks of up to 128 scenes, but at least 16 per thread so that a short sweep is shared out too.
  const std::size_t kChunk = std::clamp<std::size_t>(n / (16 * static_cast<std::size_t>(threads)), 1, 128);
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  const std::size_t window = 4 * static_cast<std::size_t>(threads);
  std::vector<Slot> slots(window);
  std::mutex mutex;
  std::condition_variable solved, space;
  std::size_t next_to_take = 0, next_to_write = 0;
  bool stop = false;
  std::exception_ptr failure;
  auto work = [&] {
    for (;;) {
      std::size_t i;
      {
        std::unique_lock lock(mutex);
        space.wait(lock, [&] { return stop || next_to_take >= chunks || next_to_take < next_to_write + window; });
        if (stop || next_to_take >= chunks) return;
        i = next_to_take++;
      }
      Slot result;
      try {
        const Emit into_slot = [&](const std::string& text) { result.text += text; };
        for (std::size_t scene = i * kChunk; scene < std::min(n, (i + 1) * kChunk); ++scene)
          result.ok = one(scene, into_slot) && result.ok;
      } catch (...) {
        std::lock_guard lock(mutex);
        if (!failure) failure = std::current_exception();
        stop = true;
        solved.notify_all();
        space.notify_all();
        return;
      }
      result.done = true;
      std::lock_guard lock(mutex);
      slots[i % window] = std::move(result);
      solved.notify_all();
    }
  };
  std::vector<std::thread> pool;
  // Stops and joins the workers on every way out, an exception from the writer included.
  struct Joiner {
    std::vector<std::thread>& pool;
    std::mutex& mutex;
    bool& stop;
    std::condition_variable& space;
    ~Joiner() {
      {
        std::lock_guard lock(mutex);
        stop = true;
      }
      space.notify_all();
      for (std::thread& t : pool) t.join();
    }
  } joiner{pool, mutex, stop, space};
  for (int t = 0; t < threads; ++t) pool.emplace_back(work);
  for (std::size_t w = 0; w < chunks; ++w) {
    Slot slot;
    {
      std::unique_lock lock(mutex);
      solved.wait(lock, [&] { return slots[w % window].done || failure; });
      if (failure) std::rethrow_exception(failure);
      slot = std::move(slots[w % window]);
      slots[w % window] = Slot{};
      ++next_to_write;
    }
    space.notify_all();
    all_ok = slot.ok && all_ok;
    writer.write(slot.text);
  }
  writer.flush();
  return all_ok;
}

// "half" or "whole": the model a solution used (empty without one).
std::string_view domain_of(const Solution& sol) {
  if (!sol.model) return "";
  return sol.model->half() ? "half" : "whole";
}

const Columns kThrustColumns(
    {"method", "integrator", "rtol", "status", "domain", "H", "V", "H_over_V", "H_left", "V_left", "M_left", "H_right",
     "V_right", "M_right", "max_thrust_eccentricity",
     "max_thrust_eccentricity_at", "thrust_in_kern", "thrust_in_section", "steps", "rhs_evaluations", "segments",
     "newton_iterations", "condition_estimate", "error_estimate", "boundary_residual", "equilibrium_residual", "message"},
    // The thrust line's summary is asked for by name (or --all-columns): it samples the whole field,
    // about 50 times the cost of the reactions in closed form, which a sweep of 10^6 scenes would feel.
    {"method", "status", "domain", "H", "V", "H_over_V", "H_left", "V_left", "M_left", "H_right", "V_right", "M_right",
     "error_estimate", "message"});

// Stations at which a verified solve checks the profile when the thrust line is summarised.
constexpr int kSummaryStations = 65;

int run_thrust(SceneOptions& so, const CLI::App& cmd, SolverSweep sweep, const ColumnText& ct, int threads,
               std::ostream& out) {
  const ScenePlan plan(so, cmd);
  Columns columns = kThrustColumns;
  columns.select(ct, plan.varying_inputs(), sweep.varying);
  const bool summary = columns.selected("max_thrust_eccentricity") || columns.selected("max_thrust_eccentricity_at") ||
                       columns.selected("thrust_in_kern") || columns.selected("thrust_in_section");
  // The summary prints eccentricities: their accuracy must be part of the error estimate.
  if (summary)
    for (Options& o : sweep.combinations) o.stations = kSummaryStations;
  // No-tension scenes are traced in order, each from the previous one (continuation): one thread.
  if (plan.no_tension()) threads = 1;
  std::vector<Solution> previous(sweep.combinations.size());
  RowWriter writer(out);
  writer.write(columns.header());
  const bool all_ok = for_each_scene(
      plan, writer, threads,
      [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        bool ok = true;
        std::string text;
        for (std::size_t c = 0; c < sweep.combinations.size(); ++c) {
          const Options& o = sweep.combinations[c];
          CsvRow row(columns.keep());
          const Solution sol = solve(scene, o, plan.no_tension() ? &previous[c] : nullptr);
          if (plan.no_tension() && sol.field) previous[c] = sol;
          const ThrustLineSummary line = summary ? summarize_thrust_line(sol) : ThrustLineSummary{};
          add_scene_columns(row, p, scene.curve.get());
          row.add(to_string(sol.method)).add(integrator_of(sol.method, o)).add(o.rtol);
          row.add(to_string(sol.status)).add(domain_of(sol)).add(sol.H).add(sol.V).add(sol.H_over_V);
          const Reactions& r = sol.reactions;
          if (sol.field) row.add(r.H_left).add(r.V_left).add(r.M_left).add(r.H_right).add(r.V_right).add(r.M_right);
          else for (int k = 0; k < 6; ++k) row.add(std::string_view{});
          row.add(line.max_abs_e).add(line.max_abs_e_at);
          if (line.ok) row.add_bool(line.in_kern).add_bool(line.in_section);
          else row.add(std::string_view{}).add(std::string_view{});
          const Diagnostics& d = sol.diagnostics;
          row.add(d.steps).add(d.rhs_evaluations).add(d.segments).add(d.newton_iterations);
          row.add(d.condition_estimate).add(d.error_estimate);
          row.add(d.boundary_residual).add(d.equilibrium_residual).add(sol.message);
          text += row.take();
          ok = ok && sol.ok();
        }
        emit(text);
        return ok;
      },
      [&](const SceneParameters& p, const ScenePlan::Built& b) { return invalid_scene_row(columns, p, b); });
  return all_ok ? kExitOk : kExitNotConverged;
}

// What the station's numbers mean for masonry, which resists no tension: the normal force is tensile
// (or zero, and e undefined), or the compression's resultant lies outside the section (|e| > 300 %: a
// hinge would form, beyond the linear model) or outside the kern (|e| > 100 %: the elastic section is
// partly in tension).
std::string_view section_warning(const ArchState& st) {
  if (st.N == 0) return "no_normal_force";
  if (st.N > 0) return "tension";
  if (std::abs(st.e) > 300) return "outside_section";
  if (std::abs(st.e) > 100) return "outside_kern";
  return "";
}

const Columns kProfileColumns(
    {"method", "integrator", "rtol", "status", "H_over_V", "error_estimate", "message", "s", "x", "y", "theta",
     "intrados_x", "intrados_y",
     "extrados_x", "extrados_y", "Ux", "Uy", "psi", "N", "shear_force", "M", "thrust_eccentricity", "thrust_x",
     "thrust_y", "compressed_depth", "cracked", "warning"},
    {"status", "message", "s", "x", "y", "theta", "intrados_x", "intrados_y", "extrados_x", "extrados_y", "Ux", "Uy",
     "psi", "N", "shear_force", "M", "thrust_eccentricity", "thrust_x", "thrust_y", "compressed_depth", "cracked",
     "warning"});
constexpr int kProfilePiece = 4096;  // stations sampled and written at a time

int run_profile(SceneOptions& so, const CLI::App& cmd, SolverSweep sweep, int stations, const ColumnText& ct,
                int threads, std::ostream& out) {
  check_stations(stations);
  const ScenePlan plan(so, cmd);
  check_rows(plan.size() * sweep.combinations.size(), stations);
  Columns columns = kProfileColumns;
  columns.select(ct, plan.varying_inputs(), sweep.varying);
  // The solve verifies the profile at kVerificationStations at most; longer profiles are sampled
  // piece by piece from the verified field below, so that memory does not grow with the stations.
  for (Options& o : sweep.combinations) o.stations = std::min(stations, kVerificationStations);
  // A scene's rows wait in the reorder window while other threads work: beyond one piece of stations
  // per scene, scenes are solved one after another instead, to keep memory bounded.
  if (stations * sweep.combinations.size() > static_cast<std::size_t>(kProfilePiece)) threads = 1;
  // No-tension scenes are traced in order, each from the previous one (continuation): one thread.
  if (plan.no_tension()) threads = 1;
  std::vector<Solution> previous(sweep.combinations.size());
  RowWriter writer(out);
  writer.write(columns.header());
  const bool all_ok = for_each_scene(
      plan, writer, threads,
      [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        bool ok = true;
        for (std::size_t c = 0; c < sweep.combinations.size(); ++c) {
          const Options& o = sweep.combinations[c];
          const Solution sol = solve(scene, o, plan.no_tension() ? &previous[c] : nullptr);
          if (plan.no_tension() && sol.field) previous[c] = sol;
          const std::string integrator(integrator_of(sol.method, o));
          if (!sol.field) {  // unsolved: one row that says so, no numbers
            emit(sparse_row(columns, p, scene.curve.get(),
                            {{"method", to_string(sol.method)}, {"integrator", integrator},
                             {"rtol", fmt::format("{}", o.rtol)}, {"status", to_string(sol.status)},
                             {"message", sol.message}}));
            ok = false;
            continue;
          }
          ok = ok && sol.ok();
          // The scene's fields are formatted once, then each station's after them.
          CsvRow row(columns.keep());
          add_scene_columns(row, p, scene.curve.get());
          row.add(to_string(sol.method)).add(integrator).add(o.rtol).add(to_string(sol.status)).add(sol.H_over_V);
          row.add(sol.diagnostics.error_estimate).add(sol.message);
          row.mark();
          for (int first = 0; first < stations; first += kProfilePiece) {
            const int count = std::min(kProfilePiece, stations - first);
            const std::vector<ArchState> piece =
                stations == o.stations ? std::vector<ArchState>(sol.profile.begin() + first, sol.profile.begin() + first + count)
                                       : sample_stations(sol, stations, first, count);
            std::string text;
            for (const ArchState& st : piece) {
              // The section's two ends, so that a plot shows the thrust line against the masonry.
              const SectionFaces faces = section_faces(CurvePoint{st.x, st.y, st.theta, 0.0}, scene.thickness);
              row.add(st.s).add(st.x).add(st.y).add(st.theta);
              row.add(faces.intrados.x).add(faces.intrados.y).add(faces.extrados.x).add(faces.extrados.y);
              row.add(st.Ux).add(st.Uy).add(st.psi);
              row.add(st.N).add(st.V).add(st.M).add(st.e).add(st.thrust_x).add(st.thrust_y);
              add_parameter(row, st.compressed_depth);
              if (std::isnan(st.compressed_depth)) row.add(std::string_view{});
              else row.add_bool(st.cracked);
              row.add(section_warning(st));
              text += row.take_to_mark();
            }
            emit(text);
          }
        }
        return ok;
      },
      [&](const SceneParameters& p, const ScenePlan::Built& b) { return invalid_scene_row(columns, p, b); });
  return all_ok ? kExitOk : kExitNotConverged;
}

// The reference a scene's H/V is checked against: the closed form where it applies (a piecewise-circular
// curve, the elastic section, no live load or fill); otherwise
// verified multiple shooting far tighter than anything checked against it (rtol 1e-12, or 100 times
// tighter than asked down to 2e-13, what Adams can still verify; 32 segments), its own error stated.
double reference_rtol(const Options& o) { return std::max(std::min(1e-12, o.rtol / 100), 2e-13); }

Solution reference_solution(const Scene& scene, Options o) {
  if (!scene.curve->arcs().empty()) {
    Options exact = o;
    exact.method = Method::closed_form;
    Solution sol = solve(scene, exact);
    if (sol.status != Status::not_applicable) return sol;  // a live load, a fill, the no-tension section: not its
  }
  {
    o.method = Method::multiple_shooting;
    o.integrator = Integrator::adams;
    o.rtol = reference_rtol(o);
    // Newton shooting of the no-tension section converges to 1e-11, not to 1e-12 (its residual's noise).
    if (scene.section == SectionKind::no_tension) o.rtol = std::max(o.rtol, 1e-11);
    o.atol = 0;
    o.segments = 32;
    o.verify = true;
    o.restart_at_breakpoints = true;
  }
  return solve(scene, o);
}

// The reference's own error: its error estimate (which includes its condition times round-off), NaN
// when it has no numbers.
double reference_error(const Solution& ref) {
  return ref.field ? ref.diagnostics.error_estimate : std::numeric_limits<double>::quiet_NaN();
}

// The error of H/V by the measure of the status (Diagnostics::error_estimate): relative to
// max(|H/V|, 1/100).
double thrust_difference(double H_over_V, double reference) {
  return std::abs(H_over_V - reference) / std::max(std::abs(reference), 0.01);
}

const Columns kCheckColumns(
    {"method", "integrator", "rtol", "segments", "status", "H_over_V", "reference_method", "reference_status",
     "reference_error", "reference_H_over_V", "relative_difference", "tolerance", "within_tolerance", "message"},
    {"method", "integrator", "rtol", "segments", "status", "H_over_V", "reference_method", "reference_status",
     "reference_error", "reference_H_over_V", "relative_difference", "tolerance", "within_tolerance", "message"});

// Every applicable method on every scene, against the reference. A row is within tolerance when the
// method says success and its difference from the reference is within rtol plus the reference's own
// error (a flagged reference is not the method's failure: its status and error are printed).
int run_check(SceneOptions& so, const CLI::App& cmd, const SolverSweep& sweep, const ColumnText& ct, int threads,
              std::ostream& out) {
  const ScenePlan plan(so, cmd);
  Columns columns = kCheckColumns;
  columns.select(ct, plan.varying_inputs());
  RowWriter writer(out);
  writer.write(columns.header());
  const bool all_ok = for_each_scene(
      plan, writer, threads,
      [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        CsvRow row(columns.keep());
        bool ok = true;
        std::string text;
        for (const Options& base : sweep.combinations) {
          const Solution reference = reference_solution(scene, base);
          const std::string reference_method = reference.method == Method::closed_form
                                                   ? "closed-form"
                                                   : fmt::format("multiple-shooting rtol {}", reference_rtol(base));
          const double ref_error = reference_error(reference);
          for (Method m : {Method::closed_form, Method::quadrature, Method::shooting, Method::multiple_shooting}) {
            if (m == Method::closed_form && scene.curve->arcs().empty()) continue;  // not applicable
            if (m == Method::quadrature && !base.restart_at_breakpoints) continue;  // not applicable either
            Options o = base;
            o.method = m;
            const Solution sol = solve(scene, o);
            const double diff = thrust_difference(sol.H_over_V, reference.H_over_V);
            const bool known = reference.field && sol.field;
            const bool within = sol.ok() && known && within_tolerance(diff, o.rtol + ref_error);
            ok = ok && within;
            add_scene_columns(row, p, scene.curve.get());
            row.add(to_string(sol.method)).add(integrator_of(sol.method, o)).add(o.rtol);
            row.add(sol.diagnostics.segments).add(to_string(sol.status)).add(sol.H_over_V).add(reference_method);
            row.add(to_string(reference.status)).add(ref_error).add(reference.H_over_V).add(diff).add(o.rtol);
            if (known) row.add_bool(within);
            else row.add(std::string_view{});
            row.add(sol.message);
            text += row.take();
          }
        }
        emit(text);
        return ok;
      },
      [&](const SceneParameters& p, const ScenePlan::Built& b) { return invalid_scene_row(columns, p, b); });
  return all_ok ? kExitOk : kExitNotConverged;
}

const Columns kCurveColumns({"status", "message", "s", "x", "y", "theta", "kappa"},
                            {"status", "message", "s", "x", "y", "theta", "kappa"});

// The geometry: s, x, y, theta, kappa at equally spaced stations over the whole arch.
int run_curve(SceneOptions& so, const CLI::App& cmd, int stations, const ColumnText& ct, int threads,
              std::ostream& out) {
  check_stations(stations);
  const ScenePlan plan(so, cmd);
  check_rows(plan.size(), stations);
  Columns columns = kCurveColumns;
  columns.select(ct, plan.varying_inputs());
  RowWriter writer(out);
  writer.write(columns.header());
  const bool all_ok = for_each_scene(
      plan, writer, threads,
      [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        CsvRow row(columns.keep());
        const Curve& curve = *scene.curve;
        add_scene_columns(row, p, &curve);
        row.add("success").add(std::string_view{});
        row.mark();
        const double S = curve.length();
        std::string text;
        for (int k = 0; k < stations; ++k) {
          const double s = 2.0 * S * k / (stations - 1);
          const CurvePoint pt = curve.at_whole_arch(s);
          row.add(s).add(pt.x).add(pt.y).add(pt.theta).add(pt.kappa);
          text += row.take_to_mark();
          if (text.size() >= (1u << 16)) {
            emit(text);
            text.clear();
          }
        }
        emit(text);
        return true;
      },
      [&](const SceneParameters& p, const ScenePlan::Built& b) { return invalid_scene_row(columns, p, b); });
  return all_ok ? kExitOk : kExitNotConverged;
}

// ---------------------------------------------------------------------------------------------
// Limit analysis.

const std::map<std::string, JointOrientation> kJointOrientations = {{"radial", JointOrientation::radial},
                                                                    {"vertical", JointOrientation::vertical}};
const std::map<std::string, WeightModel> kWeightModels = {{"voussoir", WeightModel::voussoir},
                                                          {"axis", WeightModel::axis}};
enum class ThrustLine { min, max, collapse };
const std::map<std::string, ThrustLine> kThrustLines = {
    {"min", ThrustLine::min}, {"max", ThrustLine::max}, {"collapse", ThrustLine::collapse}};

struct LimitText {
  std::string joints = "radial", weight = "voussoir", thrust_line;
  int joints_count = kDefaultJointsCount;
  double friction = 0;
  int repeats = 0;
};

void add_limit_options(CLI::App& cmd, LimitText& t) {
  cmd.add_option("--joints", t.joints, "interior joints: radial (normal to the axis) or vertical")->capture_default_str();
  cmd.add_option("--weight", t.weight, "voussoir (the ring's true weight at each centroid) or axis (rho g t per axis length)")
      ->capture_default_str();
  cmd.add_option("--joints-count", t.joints_count, "joints springing to springing, both included; odd, >= 5")
      ->check(kCount)->capture_default_str();
  cmd.add_option("--friction", t.friction, "friction coefficient of the joints (> 0): adds the sliding check")
      ->check(kFiniteNumber);
  cmd.add_option("--thrust-line", t.thrust_line, "instead of the summary, one row per joint of the min, max or collapse state");
  cmd.add_option("--repeats", t.repeats, "solve each scene this many times and add median_seconds (benchmark)")
      ->check(kCount);
}

// The options as the library's, refused with the option's name when they break a rule.
LimitOptions limit_options(const LimitText& t, const CLI::App& cmd) {
  LimitOptions o;
  o.joints = lookup(kJointOrientations, t.joints, "--joints");
  o.weight = lookup(kWeightModels, t.weight, "--weight");
  o.joints_count = t.joints_count;
  if (cmd.count("--friction") > 0 && !(t.friction > 0))
    throw UsageError(fmt::format("--friction: must be > 0 (omit it for no sliding check), got {}", t.friction));
  o.friction = t.friction;
  // The loads are the scene's (--point-load, --live-load, --fill-density, --loads-file) and so are the
  // pins (--supports pinned, --crown-hinge); the supports' movements do not enter rigid voussoirs.
  for (const char* flag : {"--support-displacement-ratio", "--left-spread-ratio", "--right-spread-ratio",
                           "--left-settlement-ratio", "--right-settlement-ratio", "--left-rotation", "--right-rotation"})
    if (cmd.count(flag) > 0)
      throw UsageError(fmt::format("{}: does not apply to limit (rigid voussoirs ignore the supports' movements: a "
                                   "spreading support brings the arch to H_min)",
                                   flag));
  if (!t.thrust_line.empty()) lookup(kThrustLines, t.thrust_line, "--thrust-line");
  if (t.repeats < 0 || t.repeats > 100000)
    throw UsageError(fmt::format("--repeats: must lie in [0, 100000] (0: no timing), got {}", t.repeats));
  std::string why;
  if (!o.is_valid(&why)) throw UsageError(as_option_message(why));
  return o;
}

// Hinges as "x/L:face" joined by ';' (x of the hinge point, on the intrados or extrados), e.g.
// "0.1129:intrados;0.5:extrados": no commas inside the CSV field.
std::string hinge_text(const std::vector<Hinge>& hinges, double span) {
  std::string text;
  for (const Hinge& h : hinges) {
    if (!text.empty()) text += ';';
    text += fmt::format("{:.6g}:{}", h.point.x() / span, to_string(h.face));
  }
  return text;
}

const std::vector<std::string> kLimitSetup = {"joints", "weight", "joints_count", "friction"};

void add_limit_setup(CsvRow& row, const LimitOptions& o) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  row.add(to_string(o.joints)).add(to_string(o.weight)).add(o.joints_count);
  row.add(o.friction > 0 ? o.friction : nan);
}


// The columns of limit: a summary per scene, or (--thrust-line) one row per joint of one state.
Columns limit_columns(bool lines, bool timed) {
  std::vector<std::string> results = kLimitSetup, defaults;
  const std::vector<std::string> summary = {
      "status", "H_min", "H_max", "V", "H_min_over_V", "H_max_over_V", "thickness_min_ratio",
      "geometric_safety_factor", "hinges_min", "hinges_max", "load_factor", "load_factor_mechanism",
      "hinges_collapse", "lp_solves", "message", "median_seconds"};
  const std::vector<std::string> joints = {"state",      "status",     "H",          "load_factor", "joint",
                                           "s",          "intrados_x", "intrados_y", "extrados_x",  "extrados_y",
                                           "thrust_x",   "thrust_y",   "hinge"};
  const std::vector<std::string>& own = lines ? joints : summary;
  results.insert(results.end(), own.begin(), own.end());
  for (const std::string& name : own)
    if (name != "lp_solves" && (name != "median_seconds" || timed)) defaults.push_back(name);
  return Columns(results, defaults);
}

// One row per scene (or, with --thrust-line, one per joint), each written as soon as it is solved.
// Exit 0 when every scene has an answer (success, or inadmissible: an arch that cannot stand is an
// answer, not a failure), 3 when an LP failed or a scene could not be made.
int run_limit(SceneOptions& so, const CLI::App& cmd, const LimitText& text, const ColumnText& ct, std::ostream& out) {
  const LimitOptions o = limit_options(text, cmd);
  const ScenePlan plan(so, cmd);
  const bool lines = !text.thrust_line.empty();
  if (lines && kThrustLines.at(text.thrust_line) == ThrustLine::collapse && cmd.count("--point-load") == 0 &&
      cmd.count("--live-load") == 0 && so.file_loads.points.empty() && so.file_loads.live.empty())
    throw UsageError("--thrust-line collapse: a load factor needs a live load (--point-load, --live-load or a "
                     "--loads-file with point or live rows)");
  if (lines) check_rows(plan.size(), o.joints_count);
  Columns columns = limit_columns(lines, text.repeats > 0);
  columns.select(ct, plan.varying_inputs());
  RowWriter writer(out);
  writer.write(columns.header());
  const bool all_answered = for_each_scene(
      plan, writer, 1,  // one thread: the timings (--repeats), and Clp kept to one thread
      [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        const double L = scene.span();
        LimitResult r;
        std::vector<double> seconds;
        for (int k = 0; k < std::max(1, text.repeats); ++k) {
          const auto t0 = std::chrono::steady_clock::now();
          r = analyse_limit(scene, o);
          seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
        std::nth_element(seconds.begin(), seconds.begin() + seconds.size() / 2, seconds.end());
        const bool answered = r.status != LimitStatus::lp_failure;
        CsvRow row(columns.keep());
        if (lines) {
          const ThrustLine which = kThrustLines.at(text.thrust_line);
          const ThrustState& st = which == ThrustLine::min   ? r.min_state
                                  : which == ThrustLine::max ? r.max_state
                                                             : r.collapse_state;
          add_scene_columns(row, p, scene.curve.get());
          add_limit_setup(row, o);
          row.add(text.thrust_line).add(to_string(r.status)).add(st.H).add(st.load_factor);
          if (!st.found()) {  // no such state: one row that says so, no numbers
            for (int k = 0; k < 9; ++k) row.add(std::string_view{});
            emit(row.take());
            return answered;
          }
          row.mark();
          // Rebuild the ring the state belongs to (the same options give the same joints).
          const Ring ring = make_ring(*scene.curve, scene.thickness, scene.material.density * scene.material.gravity, o);
          std::string text_rows;
          for (std::size_t j = 0; j < ring.joints.size(); ++j) {
            const Joint& joint = ring.joints[j];
            std::string hinge;
            for (const Hinge& h : st.hinges)
              if (h.joint == static_cast<int>(j)) hinge = to_string(h.face);
            row.add(static_cast<std::int64_t>(j)).add(joint.s).add(joint.intrados.x()).add(joint.intrados.y());
            row.add(joint.extrados.x()).add(joint.extrados.y()).add(st.crossing[j].x()).add(st.crossing[j].y()).add(hinge);
            text_rows += row.take_to_mark();
          }
          emit(text_rows);
          return answered;
        }
        add_scene_columns(row, p, scene.curve.get());
        add_limit_setup(row, o);
        row.add(to_string(r.status)).add(r.H_min()).add(r.H_max()).add(r.V).add(r.H_min() / r.V).add(r.H_max() / r.V);
        row.add(r.thickness_min / L).add(scene.thickness / r.thickness_min);
        row.add(hinge_text(r.min_state.hinges, L)).add(hinge_text(r.max_state.hinges, L));
        row.add(r.load_factor()).add(r.load_factor_mechanism).add(hinge_text(r.collapse_state.hinges, L));
        row.add(r.lp_solves).add(r.message);
        if (text.repeats > 0) row.add(seconds[seconds.size() / 2]);
        else row.add(std::string_view{});
        emit(row.take());
        return answered;
      },
      [&](const SceneParameters& p, const ScenePlan::Built& b) { return invalid_scene_row(columns, p, b); });
  return all_answered ? kExitOk : kExitNotConverged;
}

constexpr int kBenchProfileStations = 41;

// Time per solve (median over repeats) and true error against the reference, one row per method,
// integrator and rtol. Failed runs stay in the table with their status.
const Columns kBenchColumns(
    {"method", "integrator", "rtol", "segments", "status", "chosen_method", "H_over_V", "error_H_over_V",
     "error_profile", "error_estimate", "reference_error", "median_seconds", "steps", "rhs_evaluations",
     "condition_estimate", "message"},
    {"method", "integrator", "rtol", "segments", "status", "chosen_method", "H_over_V", "error_H_over_V",
     "error_profile", "error_estimate", "reference_error", "median_seconds", "steps", "rhs_evaluations",
     "condition_estimate", "message"});

int run_bench(SceneOptions& so, const CLI::App& cmd, const SolverSweep& sweep, int repeats, const ColumnText& ct,
              std::ostream& out) {
  if (repeats < 1 || repeats > 100000) throw UsageError(fmt::format("--repeats: must lie in [1, 100000], got {}", repeats));
  const Options& first = sweep.combinations.front();
  const ScenePlan plan(so, cmd);
  if (plan.size() * sweep.combinations.size() > kMaxValues)
    throw UsageError(fmt::format("--rtol: {} scenes x {} solver combinations exceed {} rows", plan.size(),
                                 sweep.combinations.size(), kMaxValues));
  // The reference is tighter than the tightest rtol benchmarked.
  Options ref_options = first;
  for (const Options& o : sweep.combinations) ref_options.rtol = std::min(ref_options.rtol, o.rtol);
  ref_options.stations = kBenchProfileStations;
  Columns columns = kBenchColumns;
  columns.select(ct, plan.varying_inputs());
  RowWriter writer(out);
  writer.write(columns.header());
  for_each_scene(
      plan, writer, 1,  // one thread: the timings are the point
      [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        CsvRow row(columns.keep());
        const Solution reference = reference_solution(scene, ref_options);
        // The reference is the closed form exactly where it applies (a piecewise-circular curve, the
        // elastic section, no live load or fill).
        const bool closed_form_applies = reference.method == Method::closed_form;
        for (const Options& o : sweep.combinations) {
          const Method m = o.method;
          const double rtol = o.rtol;
          if (m == Method::closed_form && !closed_form_applies) continue;  // not applicable
          // The closed form has neither integrator nor tolerance; auto where it applies is the closed form:
          // one row, not one per integrator and rtol.
          const bool exact = m == Method::closed_form || (m == Method::automatic && closed_form_applies);
          if (exact && (o.integrator != first.integrator || o.rtol != first.rtol)) continue;
          if (m == Method::quadrature && o.integrator != first.integrator) continue;  // no integrator
          std::vector<double> seconds;
          Solution sol;
          for (int r = 0; r < repeats; ++r) {
            const auto t0 = std::chrono::steady_clock::now();
            sol = solve(scene, o);
            seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
          }
          std::nth_element(seconds.begin(), seconds.begin() + repeats / 2, seconds.end());
          // The profile's error, outside the timing, from the same solve with stations.
          Options profiled = o;
          profiled.stations = kBenchProfileStations;
          const Solution with_profile = solve(scene, profiled);
          // The row's status is the worse of the two solves: a profile that missed its tolerance says so.
          const Solution& judged = sol.ok() ? with_profile : sol;
          const double estimate = std::max(sol.diagnostics.error_estimate, with_profile.diagnostics.error_estimate);
          add_scene_columns(row, p, scene.curve.get());
          row.add(to_string(m)).add(exact ? std::string_view{} : integrator_of(m, o));
          if (exact) row.add(std::string_view{});
          else row.add(rtol);
          row.add(sol.diagnostics.segments).add(to_string(judged.status));
          row.add(to_string(sol.method));
          row.add(sol.H_over_V).add(thrust_difference(sol.H_over_V, reference.H_over_V));
          row.add(profile_difference(with_profile.profile, reference.profile, scene.thickness)).add(estimate);
          row.add(reference_error(reference));
          row.add(seconds[repeats / 2]).add(sol.diagnostics.steps).add(sol.diagnostics.rhs_evaluations);
          row.add(sol.diagnostics.condition_estimate).add(judged.message);
          emit(row.take());
        }
        return true;
      },
      [&](const SceneParameters& p, const ScenePlan::Built& b) { return invalid_scene_row(columns, p, b); });
  return kExitOk;
}

// ---------------------------------------------------------------------------------------------
// Help: what the program is, and two examples per subcommand.

void add_help_texts(CLI::App& app) {
  app.footer(
      "Units are SI: m, Pa, kg/m^3, m/s^2; forces per metre of vault length (N/m). Every numeric scene option\n"
      "takes a value, a list a,b,c or a range start:stop:count; several give their cartesian product.\n"
      "Output: CSV on stdout, an empty field for no number; exit 0 every row solved (status success),\n"
      "3 some row not, 2 bad input (one line on stderr), 1 internal error. The model, the sign conventions\n"
      "and every output column: docs/model.md. `ogive SUBCOMMAND --help` lists a subcommand's options.");
  const std::map<std::string, std::string> examples = {
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
  };
  for (CLI::App* sub : app.get_subcommands({})) {
    const auto it = examples.find(sub->get_name());
    if (it != examples.end()) sub->footer("Examples:\n" + it->second + "\nUnits, output columns, signs: docs/model.md.");
  }
}

// ---------------------------------------------------------------------------------------------
// draw: one SVG file per scene (include/ogive/output/svg.hpp), and one CSV row per file on stdout.

// Scenes one draw may write: each is a file, and a sweep of thousands of pictures is a mistake.
constexpr std::size_t kMaxDrawings = 1000;

struct DrawTargets {
  std::string output;      // --output FILE: exactly one scene
  std::string output_dir;  // --output-dir DIR: one file per scene, named by draw_file_name
  bool limit = false;      // --limit: the limit analysis' minimum and maximum thrust lines too
};

// The minimum and maximum thrust states of the limit analysis (default options: radial joints, the
// voussoirs' own weight) as lines to draw, with their hinges; none where the arch cannot stand.
std::vector<ExtraThrustLine> limit_lines(const Scene& scene) {
  const LimitResult r = analyse_limit(scene, LimitOptions{});
  std::vector<ExtraThrustLine> lines;
  for (const auto& [state, id, name, colour] :
       {std::tuple{&r.min_state, "thrust-line-min", "minimum", "#1e8449"},
        std::tuple{&r.max_state, "thrust-line-max", "maximum", "#7d3c98"}}) {
    if (!state->found()) continue;
    ExtraThrustLine line;
    line.id = id;
    line.colour = colour;
    line.label = fmt::format("{} thrust (limit analysis, rigid voussoirs): H/V = {:.4g}, {} hinges", name,
                             state->H / r.V, state->hinges.size());
    for (const Eigen::Vector2d& c : state->crossing) line.points.push_back({c.x(), c.y()});
    for (const Hinge& h : state->hinges) line.hinges.push_back({h.point.x(), h.point.y()});
    lines.push_back(std::move(line));
  }
  return lines;
}

// The drawing's caption: the curve, its shape parameters, span, t/L and d/L, as the options name them.
std::string draw_title(const SceneParameters& p) {
  std::string title = p.curve;
  for (const auto& [name, v] : {std::pair{"eccentricity", p.eccentricity}, std::pair{"rise ratio", p.rise_ratio},
                                std::pair{"haunch angle", p.haunch_angle}, std::pair{"crown angle", p.crown_angle}})
    if (!std::isnan(v)) title += fmt::format(", {} {}", name, v);
  title += fmt::format(", span {:.6g} m, t/L {}, d/L {}{}", p.span, p.thickness_ratio, p.support_displacement_ratio,
                       p.plane_strain ? ", plane strain" : "");
  if (!std::isnan(p.point_load)) title += fmt::format(", P {:g} N/m at x/L {:g}", p.point_load, p.point_load_at);
  if (!std::isnan(p.live_load))
    title += fmt::format(", q {:g} N/m^2 over x/L {:g}..{:g}", p.live_load, p.live_load_from, p.live_load_to);
  if (!std::isnan(p.fill_density)) title += fmt::format(", fill {:g} kg/m^3 to {:g} L", p.fill_density, p.fill_height_ratio);
  if (p.crown_hinge) title += ", crown hinge";
  return title;
}

// The file of one scene in --output-dir: the curve, then each option that varies in the sweep with the
// scene's value, e.g. "pointed_thickness-ratio-0.2_eccentricity-0.5.svg" (the order of --help).
std::string draw_file_name(const SceneParameters& p, const SceneOptions& so) {
  std::string name = p.curve;
  for (const Axis& a : so.axes)
    if (a.values.size() > 1) name += fmt::format("_{}-{}", a.flag.substr(2), p.*(a.field));
  return name + ".svg";
}

// Refuses, before anything is solved or printed, a target that cannot be written: a directory where a
// file should be, a missing directory, a file that cannot be opened for writing.
void check_writable(const std::string& path, const char* flag) {
  if (path.find_first_of(",\r\n") != std::string::npos)
    throw UsageError(fmt::format("{}: the path must not contain a comma or a line break (it is printed in the CSV)", flag));
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw UsageError(fmt::format("{}: '{}' is a directory, not a file", flag, path));
  // Appending creates the file if needed and leaves an existing one as it is until it is drawn.
  std::ofstream probe(path, std::ios::app);
  if (!probe) throw UsageError(fmt::format("{}: cannot write '{}': {}", flag, path, std::strerror(errno)));
}

const Columns kDrawColumns({"method", "status", "H", "V", "H_over_V", "message", "file"},
                           {"method", "status", "H", "V", "H_over_V", "message", "file"});

int run_draw(SceneOptions& so, const CLI::App& cmd, Options o, const DrawTargets& to, const ColumnText& ct,
             std::ostream& out) {
  check_stations(o.stations);
  check_options(o);
  if (to.output.empty() == to.output_dir.empty())
    throw UsageError(to.output.empty() ? "--output: draw needs --output FILE.svg (one scene) or --output-dir DIR "
                                         "(one file per scene)"
                                       : "--output-dir: give --output FILE.svg or --output-dir DIR, not both");
  const ScenePlan plan(so, cmd);
  if (!to.output.empty() && plan.size() > 1)
    throw UsageError(fmt::format("--output: the options give {} scenes and one file holds one drawing; use "
                                 "--output-dir DIR for one file per scene", plan.size()));
  if (plan.size() > kMaxDrawings)
    throw UsageError(fmt::format("--output-dir: the options give {} scenes, more than {} drawings", plan.size(), kMaxDrawings));
  Columns columns = kDrawColumns;
  columns.select(ct, plan.varying_inputs());
  std::vector<std::string> files;
  if (!to.output.empty()) {
    files.push_back(to.output);
  } else {
    std::error_code ec;
    if (!std::filesystem::is_directory(to.output_dir, ec))
      throw UsageError(fmt::format("--output-dir: '{}' is not an existing directory", to.output_dir));
    std::set<std::string> seen;
    for (std::size_t i = 0; i < plan.size(); ++i) {
      const std::string name = draw_file_name(plan.parameters(i), so);
      if (!seen.insert(name).second)
        throw UsageError(fmt::format("--output-dir: two scenes would both be drawn into {} (a value repeats)", name));
      files.push_back((std::filesystem::path(to.output_dir) / name).string());
    }
  }
  for (const std::string& f : files) check_writable(f, to.output.empty() ? "--output-dir" : "--output");

  RowWriter writer(out);
  writer.write(columns.header());
  const bool all_ok = for_each_scene(
      plan, writer, 1,  // one file at a time
      [&](const SceneParameters& p, const Scene& scene, const Emit& emit) {
        const Solution sol = solve(scene, o);
        DrawingOptions drawing;
        drawing.title = draw_title(p);
        if (to.limit) drawing.extra_lines = limit_lines(scene);
        const std::string& path = files[p.scene - 1];
        std::ofstream file(path, std::ios::trunc);
        file << arch_svg(scene, sol, drawing);
        file.close();
        if (!file) throw OutputError(fmt::format("cannot write {}: {}", path, std::strerror(errno)));
        CsvRow row(columns.keep());
        add_scene_columns(row, p, scene.curve.get());
        row.add(to_string(sol.method)).add(to_string(sol.status)).add(sol.H).add(sol.V).add(sol.H_over_V);
        row.add(sol.message).add(path);
        emit(row.take());
        return sol.ok();
      },
      [&](const SceneParameters& p, const ScenePlan::Built& b) { return invalid_scene_row(columns, p, b); });
  return all_ok ? kExitOk : kExitNotConverged;
}

}  // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"ogive: thrust and line of thrust of arches and barrel vaults (CSV on stdout)", "ogive"};
  app.require_subcommand(1);
  SceneOptions thrust_scene, profile_scene, check_scene, bench_scene;
  Options thrust_options, profile_options, check_options_, bench_options;
  SolverText thrust_text, profile_text, check_text, bench_text;
  profile_options.stations = 101;
  // Only the subcommand named first on the command line is given its options: CLI11 checks every new
  // option's names against all of its command's others, and giving all seven commands theirs was half
  // of the instructions of a one-scene run (7 of 15 million; 4.5 ms became 3.9 ms, the rest mostly the
  // dynamic loader). The others are still registered, so `ogive --help` lists them and a misspelt one
  // is still named.
  const std::string named = args.empty() ? std::string() : args.front();
  const auto wanted = [&](const CLI::App* cmd) { return cmd->get_name() == named; };

  CLI::App* thrust = app.add_subcommand("thrust", "reactions H, V and H/V: one row per scene");
  if (wanted(thrust)) {
    add_scene_options(*thrust, thrust_scene);
    add_solver_options(*thrust, thrust_options, thrust_text);
  }

  CLI::App* profile = app.add_subcommand("profile", "N, V, M, e and the thrust line along the arch");
  if (wanted(profile)) {
    add_scene_options(*profile, profile_scene);
    add_solver_options(*profile, profile_options, profile_text);
    profile->add_option("--stations", profile_options.stations, "stations, equally spaced in arc length, springing to springing; must lie in [2, 1000000]")
        ->check(kCount)
        ->capture_default_str();
  }

  CLI::App* check = app.add_subcommand("check", "every method's H/V against the closed form");
  if (wanted(check)) {
    add_scene_options(*check, check_scene);
    add_solver_options(*check, check_options_, check_text, false);
  }

  SceneOptions curve_scene;
  int curve_stations = 101;
  CLI::App* curve = app.add_subcommand("curve", "the generator curve: s, x, y, theta, kappa");
  if (wanted(curve)) {
    add_scene_options(*curve, curve_scene);
    curve->add_option("--stations", curve_stations, "stations, equally spaced in arc length, springing to springing; must lie in [2, 1000000]")->check(kCount)->capture_default_str();
  }

  CLI::App* bench = app.add_subcommand("bench", "median time per solve and true error, per method and rtol");
  // The same options as every other command's, with a benchmark's defaults (and the plural spellings
  // that older scripts used).
  bench_text.method = "closed-form,shooting,multiple-shooting";
  bench_text.rtol = "1e-6,1e-8,1e-10";
  int repeats = 21;
  if (wanted(bench)) {
    add_scene_options(*bench, bench_scene);
    add_solver_options(*bench, bench_options, bench_text, true, true);
    bench->add_option("--repeats", repeats, "solves per row, the median time is printed; must lie in [1, 100000]")->check(kCount)->capture_default_str();
  }

  SceneOptions draw_scene;
  Options draw_options;
  SolverText draw_text;
  DrawTargets draw_targets;
  draw_options.stations = 101;
  CLI::App* draw = app.add_subcommand("draw", "an SVG picture of each scene to scale: arch, thrust line, supports");
  if (wanted(draw)) {
    add_scene_options(*draw, draw_scene);
    add_solver_options(*draw, draw_options, draw_text);
    draw->add_option("--stations", draw_options.stations,
                     "points of the thrust line, springing to springing; must lie in [2, 1000000]")
        ->check(kCount)
        ->capture_default_str();
    draw->add_option("--output", draw_targets.output, "the SVG file of the one scene (refused for a sweep)");
    draw->add_flag("--limit", draw_targets.limit,
                   "also draw the limit analysis' minimum and maximum thrust lines with their hinges (ogive limit's "
                   "defaults: radial joints, the voussoirs' weight)");
    draw->add_option("--output-dir", draw_targets.output_dir,
                     "an existing directory: one SVG per scene, named after the curve and the options that vary");
  }

  SceneOptions limit_scene;
  LimitText limit_text;
  CLI::App* limit = app.add_subcommand(
      "limit", "limit analysis (rigid voussoirs, no tension): H_min, H_max, t_min, collapse load; one row per scene");
  if (wanted(limit)) {
    add_scene_options(*limit, limit_scene);
    add_limit_options(*limit, limit_text);
  }

  add_help_texts(app);
  app.set_version_flag("--version", std::string("ogive ") + kVersion, "print the version and exit");
  // Bare `ogive`: the help, but on stderr with status 2, since stdout is for CSV only and a script that
  // forgot the subcommand should fail rather than read the help as data.
  if (args.empty()) {
    err << app.help();
    return kExitUsage;
  }

  ColumnText thrust_columns, profile_columns, check_columns, curve_columns, bench_columns, draw_columns;
  ColumnText limit_columns_text;
  const std::pair<CLI::App*, ColumnText*> column_options[] = {
      {draw, &draw_columns},       {limit, &limit_columns_text}, {thrust, &thrust_columns}, {profile, &profile_columns},
      {check, &check_columns},     {curve, &curve_columns},      {bench, &bench_columns}};
  for (const auto& [cmd, text] : column_options)
    if (wanted(cmd)) add_column_options(*cmd, *text);

  // Sweeps use every core by default; the rows come out in the same order, byte for byte, with any N.
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  int threads = cores;
  for (CLI::App* cmd : {thrust, profile, check, curve})
    if (wanted(cmd))
      cmd->add_option("--threads", threads,
                      fmt::format("scenes solved in parallel, 1 .. 256 (default: every core, {} here); the output "
                                  "is the same with any number",
                                  cores))
          ->check(kCount);

  std::vector<const char*> argv{"ogive"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e, out, err);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e, out, err);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e, out, err);
  } catch (const CLI::ParseError& e) {
    std::string what = e.what();
    std::replace(what.begin(), what.end(), '\n', ' ');
    // An option nobody knows: suggest the closest option of the subcommand (or subcommand name).
    std::vector<std::string> names;
    CLI::App* where = &app;
    for (CLI::App* sub : app.get_subcommands({}))
      if (sub->parsed()) where = sub;
    for (const CLI::Option* opt : where->get_options())
      for (const std::string& n : opt->get_lnames()) names.push_back("--" + n);
    if (where == &app)
      for (CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
    std::string hint;
    for (const std::string& word : args)
      if (hint.empty() && std::find(names.begin(), names.end(), word.substr(0, word.find('='))) == names.end() &&
          (word.rfind("--", 0) == 0 || where == &app))
        hint = did_you_mean(word.substr(0, word.find('=')), names);
    err << "ogive: " << what << hint << "\n";
    return kExitUsage;
  }
  try {
    if (threads < 1 || threads > 256) throw UsageError(fmt::format("--threads: must lie in [1, 256], got {}", threads));
    // --columns help: the command's columns with units and meanings, nothing solved.
    const std::pair<CLI::App*, std::pair<const ColumnText*, const Columns*>> helps[] = {
        {thrust, {&thrust_columns, &kThrustColumns}},  {profile, {&profile_columns, &kProfileColumns}},
        {check, {&check_columns, &kCheckColumns}},     {curve, {&curve_columns, &kCurveColumns}},
        {bench, {&bench_columns, &kBenchColumns}},     {draw, {&draw_columns, &kDrawColumns}}};
    const Columns limit_help = limit_columns(!limit_text.thrust_line.empty(), limit_text.repeats > 0);
    if (limit->parsed() && limit_columns_text.columns == "help") {
      RowWriter writer(out);
      writer.write(limit_help.help());
      writer.flush();
      return kExitOk;
    }
    for (const auto& [cmd, what] : helps)
      if (cmd->parsed() && what.first->columns == "help") {
        RowWriter writer(out);
        writer.write(what.second->help());
        writer.flush();
        return kExitOk;
      }
    if (thrust->parsed())
      return run_thrust(thrust_scene, *thrust, solver_sweep(thrust_options, thrust_text), thrust_columns, threads, out);
    if (profile->parsed())
      return run_profile(profile_scene, *profile, solver_sweep(profile_options, profile_text), profile_options.stations,
                         profile_columns, threads, out);
    if (check->parsed())
      return run_check(check_scene, *check, solver_sweep(check_options_, check_text, false), check_columns, threads, out);
    if (curve->parsed()) return run_curve(curve_scene, *curve, curve_stations, curve_columns, threads, out);
    if (draw->parsed()) {
      const SolverSweep sweep = solver_sweep(draw_options, draw_text);
      if (sweep.combinations.size() != 1)
        throw UsageError("--rtol: draw takes one method, integrator and rtol (a picture per scene)");
      return run_draw(draw_scene, *draw, sweep.combinations.front(), draw_targets, draw_columns, out);
    }
    if (limit->parsed()) return run_limit(limit_scene, *limit, limit_text, limit_columns_text, out);
    if (bench->parsed())
      return run_bench(bench_scene, *bench, solver_sweep(bench_options, bench_text), repeats, bench_columns, out);
  } catch (const UsageError& e) {
    err << "ogive: " << e.what() << "\n";
    return kExitUsage;
  } catch (const OutputError& e) {
    err << "ogive: " << e.what() << "\n";
    return kExitOutput;
  } catch (const std::invalid_argument& e) {
    err << "ogive: " << e.what() << "\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    err << "ogive: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return kExitUsage;
}

}  // namespace ogive::cli
