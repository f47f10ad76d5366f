#include "ogive/output/html_report.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "ogive/limit/limit.hpp"
#include "ogive/output/csv.hpp"
#include "ogive/output/svg.hpp"
#include "ogive/solve/solve.hpp"
#include "ogive/version.hpp"
#include "svg_draw.hpp"

namespace ogive {
namespace {

using svg_draw::escaped;

constexpr const char* kStyle =
    "body{font-family:sans-serif;max-width:60em;margin:1em auto;padding:0 1em;color:#222}"
    "h1{font-size:1.3em}h2{font-size:1.05em;margin-top:1.2em;border-bottom:1px solid #ccc}"
    "table{border-collapse:collapse;margin:.3em 0}td,th{border:1px solid #ccc;padding:.15em .5em;text-align:left}"
    "td.n{text-align:right;font-variant-numeric:tabular-nums}svg{max-width:100%;height:auto}"
    ".note{color:#555;font-size:.9em}@media print{section{break-inside:avoid}body{max-width:none}}"
    "#verdict{border:3px solid;padding:.2em 1em;margin:1em 0}#verdict.pass{border-color:#1e8449}"
    "#verdict.fail{border-color:#c0392b}#verdict.not_assessed{border-color:#b9770e}"
    ".word{font-size:1.8em;font-weight:bold;margin:.2em 0}.pass .word{color:#1e8449}.fail .word{color:#c0392b}"
    ".not_assessed .word{color:#b9770e}td.fail{color:#c0392b;font-weight:bold}td.pass{color:#1e8449}"
    "#warnings li{color:#c0392b}";

// A number to 4 significant digits in `scale` units, its full SI value in data-value; "-" when NaN.
std::string cell(double si, double scale = 1, const char* unit = "") {
  if (!std::isfinite(si)) return "<td class=\"n\">-</td>";
  std::string full;
  append_number(full, si);
  return fmt::format("<td class=\"n\" data-value=\"{}\">{:.4g}{}{}</td>", full, si / scale, *unit ? " " : "", unit);
}

std::string row(const std::string& name, const std::string& cells) {
  return "<tr><th>" + name + "</th>" + cells + "</tr>\n";
}

// H over half the total vertical load its own state carries ((V_left + V_right) / 2): the one H/V of
// the page, so that the elastic, cracking and limit thrusts compare like with like also when the scene
// is not symmetric.
double over_half_load(double H, double V_left, double V_right) { return H / (0.5 * (V_left + V_right)); }
double over_half_load(const Solution& sol) {
  return over_half_load(sol.H, sol.reactions.V_left, sol.reactions.V_right);
}

// A criterion as the page names it, with its unit.
std::pair<const char*, const char*> criterion_words(Criterion c) {
  switch (c) {
    case Criterion::geometric_safety_factor: return {"geometric factor of safety t / t<sub>min</sub>", ""};
    case Criterion::load_factor: return {"collapse load factor (point and live loads)", ""};
    case Criterion::horizontal_load_factor: return {"collapse acceleration a<sub>c</sub>", "g"};
    case Criterion::spread_capacity_ratio: return {"spreading capacity (span increase at collapse / span)", ""};
    case Criterion::max_thrust_eccentricity: return {"largest thrust eccentricity |e| (at most)", "%"};
  }
  return {"?", ""};
}

// Beside the spreading capacity on walls: each wall's lean at the collapse of the spreading path, the
// numbers a surveyor measures (its rotation about its base's outer toe, its top's outward displacement).
std::string walls_lean(const Assessment& a) {
  const SpreadResult& sr = a.spreading;
  const Outcome o = a[Criterion::spread_capacity_ratio].outcome;
  if ((o != Outcome::pass && o != Outcome::fail) || !(std::isfinite(sr.left_wall_rotation) || std::isfinite(sr.right_wall_rotation)))
    return "";
  std::string s = "<table id=\"walls-lean\">\n<tr><th>the walls' lean at the spreading collapse</th><th>rotation "
                  "outwards</th><th>top's outward displacement</th></tr>\n";
  for (const auto& [side, rotation, top] : {std::tuple{"left wall", sr.left_wall_rotation, sr.left_wall_top_displacement},
                                            std::tuple{"right wall", sr.right_wall_rotation, sr.right_wall_top_displacement}})
    if (std::isfinite(rotation)) s += row(side, cell(rotation, 1, "rad") + cell(top, 0.001, "mm"));
  return s + fmt::format("</table>\n<p class=\"note\">The walls turn outwards about their bases' outer toes, the arch "
                         "of rigid voussoirs following them to collapse ({}{}{}).</p>\n",
                         to_string(sr.collapse), sr.message.empty() ? "" : ": ", escaped(sr.message));
}

std::string verdict_section(const Assessment& a, const ReportOptions& o) {
  static constexpr const char* kWord[] = {"PASS", "FAIL", "NOT ASSESSED"};
  const char* verdict = to_string(a.verdict);
  std::string s = fmt::format("<section id=\"verdict\" class=\"{}\"><h2>Verdict</h2>\n<p class=\"word\">{}</p>\n",
                              verdict, kWord[static_cast<int>(a.verdict)]);
  const CriterionResult& g = a[a.governing];
  const auto [name, unit] = criterion_words(g.criterion);
  if (g.outcome == Outcome::pass || g.outcome == Outcome::fail)
    s += fmt::format("<p>Governed by the {}: {:.4g}{}{} against {:.4g}{}{} required (margin {:.3g}).</p>\n", name,
                     g.value, *unit ? " " : "", unit, g.required, *unit ? " " : "", unit, g.margin);
  else if (g.outcome == Outcome::not_assessed)
    s += fmt::format("<p>The {} could not be assessed: {}</p>\n", name, escaped(g.reason));
  else
    s += "<p>No criterion was required.</p>\n";
  s += "<table>\n<tr><th>criterion</th><th>value</th><th>required</th><th>outcome</th></tr>\n";
  for (const CriterionResult& r : a.criteria) {
    if (r.outcome == Outcome::not_required && std::isnan(r.value)) continue;
    const auto [words, u] = criterion_words(r.criterion);
    s += row(words, cell(r.value, 1, u) + cell(r.required, 1, u) +
                        fmt::format("<td class=\"{0}\">{0}{1}{2}</td>", to_string(r.outcome), r.reason.empty() ? "" : ": ",
                                    escaped(r.reason)));
  }
  s += "</table>\n" + walls_lean(a);
  if (!a.warnings.empty() || !o.warnings.empty()) {
    s += "<ul id=\"warnings\">\n";
    for (const auto* list : {&a.warnings, &o.warnings})
      for (const std::string& w : *list) s += "<li>" + escaped(w) + "</li>\n";
    s += "</ul>\n";
  }
  return s + "</section>\n";
}

// The geometry that follows from the inputs, read off the ring of voussoirs: its springing joints'
// intrados points give the clear span, its crown joint the intrados' and extrados' rises.
std::string geometry_section(const Scene& scene, const Ring& ring) {
  std::string s = "<section id=\"geometry\"><h2>Geometry</h2>\n<table>\n";
  const CurvePoint crown = scene.curve->at(scene.curve->crown());
  s += row("span of the axis L", cell(scene.span(), 1, "m"));
  s += row("rise of the axis", cell(crown.y, 1, "m"));
  if (!ring.joints.empty()) {
    const Joint& c = ring.joints[static_cast<std::size_t>(ring.crown_joint())];
    s += row("clear span (between the intrados' springing points)",
             cell(ring.joints.back().intrados.x() - ring.joints.front().intrados.x(), 1, "m"));
    s += row("rise of the intrados at the crown", cell(c.intrados.y() - ring.joints.front().intrados.y(), 1, "m"));
    s += row("rise of the extrados at the crown", cell(c.extrados.y(), 1, "m"));
    for (const FillLoad& f : scene.loads.fills) {
      s += row("fill level above the springing line", cell(f.height_ratio * scene.span(), 1, "m"));
      s += row("fill depth over the extrados' crown", cell(f.height_ratio * scene.span() - c.extrados.y(), 1, "m"));
    }
  }
  s += row("thickness t", cell(scene.thickness, 1, "m"));
  return s + "</table></section>\n";
}

const char* support_words(SupportKind k) { return k == SupportKind::clamped ? "clamped" : "pinned"; }

std::string assumptions_section(const Scene& scene, const ReportOptions& o) {
  std::string s = "<section id=\"assumptions\"><h2>Assumptions</h2>\n<ul>\n";
  s += fmt::format("<li>The elastic analysis: a unit-width slice of the vault as a Timoshenko curved beam (E = {:.4g} "
                   "GPa, &nu; = {:.3g}), {} section, {} and {} springings{}.</li>\n",
                   scene.material.youngs_modulus / 1e9, scene.material.poisson_ratio,
                   scene.section == SectionKind::elastic ? "elastic" : "no-tension (cracking)",
                   support_words(scene.left.kind), support_words(scene.right.kind),
                   scene.crown_hinge ? ", a hinge at the crown" : "");
  s += "<li>The limit analysis, the collapse load, the collapse acceleration and the spreading capacity: rigid "
       "voussoirs between radial joints, each with its true weight at its centroid (Heyman): no tensile strength, "
       "unlimited compressive strength, no sliding.</li>\n";
  s += "<li>The fill is a dead load on the extrados, with neither stiffness nor passive resistance; point and live "
       "loads act on the arch where given, not spread by the fill.</li>\n";
  s += scene.has_walls() ? "<li>Left out: crushing and sliding of the masonry (of the walls too), the vault's "
                           "three-dimensional action.</li>\n"
                         : "<li>Left out: the walls or piers under the springings (taken as rigid unless moved), "
                           "crushing and sliding of the masonry, the vault's three-dimensional action.</li>\n";
  s += fmt::format("<li>ogive {}{}{}.</li>\n", kVersion, o.date.empty() ? "" : ", ", escaped(o.date));
  return s + "</ul></section>\n";
}

std::string reactions_section(const Solution& sol) {
  const Reactions& r = sol.reactions;
  std::string s = "<section id=\"reactions\"><h2>Reactions (per metre of vault width)</h2>\n<table>\n"
                  "<tr><th></th><th>H (inwards)</th><th>V (up)</th><th>M (counter-clockwise)</th></tr>\n";
  s += row("left springing", cell(r.H_left, 1000, "kN/m") + cell(r.V_left, 1000, "kN/m") + cell(r.M_left, 1000, "kN m/m"));
  s += row("right springing",
           cell(r.H_right, 1000, "kN/m") + cell(r.V_right, 1000, "kN/m") + cell(r.M_right, 1000, "kN m/m"));
  s += fmt::format("</table>\n<p class=\"note\">solved by the {} method; numerical status {}{}{}</p></section>\n",
                   to_string(sol.method), to_string(sol.status), sol.message.empty() ? "" : ": ", escaped(sol.message));
  return s;
}

std::string thrusts_section(const Scene& scene, const Solution& sol, const LimitResult& lim) {
  std::string s = "<section id=\"thrusts\"><h2>Thrusts</h2>\n<table>\n<tr><th></th><th>H</th><th>H/V</th></tr>\n";
  s += row(scene.section == SectionKind::no_tension ? "no-tension section (cracked)" : "elastic",
           cell(sol.H, 1000, "kN/m") + cell(over_half_load(sol)));
  s += row("minimum (limit analysis)", cell(lim.H_min(), 1000, "kN/m") + cell(lim.H_min() / lim.V));
  s += row("maximum (limit analysis)", cell(lim.H_max(), 1000, "kN/m") + cell(lim.H_max() / lim.V));
  s += fmt::format("</table>\n<p class=\"note\">H/V: the thrust over half the total vertical load of its own state "
                   "(the elastic arch's axis weight, the voussoirs' true weight). Limit analysis (rigid no-tension "
                   "voussoirs, radial joints): status {}{}{}</p></section>\n",
                   to_string(lim.status), lim.message.empty() ? "" : ": ", escaped(lim.message));
  return s;
}

std::string safety_section(const Scene& scene, const LimitResult& lim) {
  std::string s = "<section id=\"safety\"><h2>Geometric safety</h2>\n<table>\n";
  s += row("thickness t", cell(scene.thickness, 1, "m"));
  s += row("minimum thickness t<sub>min</sub>", cell(lim.thickness_min, 1, "m"));
  s += row("geometric safety factor t / t<sub>min</sub>", cell(scene.thickness / lim.thickness_min));
  // On walls: the least wall thickness for the arch as it is, beside each wall's own.
  for (const auto& [side, wall] : {std::pair{"left", &scene.left_wall}, std::pair{"right", &scene.right_wall}})
    if (*wall) s += row(fmt::format("{} wall thickness b<sub>w</sub> (height {:.4g} m)", side, (*wall)->height),
                        cell((*wall)->thickness, 1, "m"));
  if (scene.has_walls()) {
    s += row("least wall thickness b<sub>min</sub>", cell(lim.wall_thickness_min, 1, "m"));
    s += row("wall factor b<sub>w</sub> / b<sub>min</sub> (the thinner wall)",
             cell(scene.thinnest_wall() / lim.wall_thickness_min));
  }
  return s + "</table></section>\n";
}

std::string collapse_section(const Scene& scene, const LimitResult& lim) {
  std::string s = "<section id=\"collapse\"><h2>Collapse</h2>\n";
  const ThrustState& c = lim.collapse_state;
  if (!c.found()) return s + "<p>No collapse load factor: the scene has no point or live load to multiply, or the "
                             "arch does not carry its dead load.</p></section>\n";
  s += "<table>\n" + row("collapse load factor (point and live loads)", cell(c.load_factor)) + "</table>\n";
  s += "<table>\n<tr><th>hinge</th><th>x</th><th>y</th><th>face</th></tr>\n";
  // A coordinate within round-off of zero (a springing's face point, 2e-17 m) is shown as 0.
  const auto coordinate = [&](double v) { return std::abs(v) < 1e-12 * scene.span() ? 0.0 : v; };
  for (std::size_t k = 0; k < c.hinges.size(); ++k) {
    const Hinge& h = c.hinges[k];
    s += row(fmt::format("{}", k + 1), cell(coordinate(h.point.x()), 1, "m") + cell(coordinate(h.point.y()), 1, "m") +
                                          fmt::format("<td>{}</td>", to_string(h.face)));
  }
  return s + "</table></section>\n";
}

// The spreading chart: H/V of the no-tension section against d/L, on a log axis with d = 0 at its left.
// A scene of the no-tension section whose springings do not spread is its own point at d = 0: `sol`.
std::string spreading_section(const Scene& scene, const Solution& sol, const ReportOptions& o, const LimitResult& lim) {
  std::vector<double> ratios{0};
  for (int k = 0; k + 1 < o.spread_points; ++k) ratios.push_back(std::pow(10.0, -6 + 4.0 * k / (o.spread_points - 2)));
  struct Point {
    double ratio, H_over_V;
  };
  std::vector<Point> points;
  std::vector<std::string> failed;
  const bool own_point = scene.section == SectionKind::no_tension && scene.left.spread == 0 && scene.right.spread == 0;
  for (double r : ratios) {
    Scene s = scene;
    s.section = SectionKind::no_tension;
    s.set_support_displacement(r * scene.span());
    const Solution at = r == 0 && own_point ? sol : solve(s, o.solver);
    if (at.ok()) points.push_back({r, over_half_load(at)});
    else failed.push_back(fmt::format("d/L = {:g}: {}", r, to_string(at.status)));
  }
  const double w = 600, h = 300, left = 60, right = 20, top = 20, bottom = 50;
  double lo = lim.H_min() / lim.V, hi = lo;
  for (const Point& p : points) {
    lo = std::isfinite(lo) ? std::min(lo, p.H_over_V) : p.H_over_V;
    hi = std::isfinite(hi) ? std::max(hi, p.H_over_V) : p.H_over_V;
  }
  if (!std::isfinite(lo)) lo = 0, hi = 1;
  const double pad = 0.1 * std::max(hi - lo, 0.01 * std::abs(hi) + 1e-12);
  lo -= pad;
  hi += pad;
  auto X = [&](double r) {  // d = 0 at the left, then 1e-6 .. 1e-2 over the rest
    const double zero = left + 20;
    return r <= 0 ? left : zero + (w - right - zero) * (std::log10(r) + 6) / 4;
  };
  auto Y = [&](double v) { return top + (h - top - bottom) * (hi - v) / (hi - lo); };
  std::string s = "<section id=\"spreading\"><h2>Support spreading: the cracking arch's H/V</h2>\n";
  s += fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
                   "font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n",
                   w, h);
  s += fmt::format("<path d=\"M {0} {1} L {0} {2} L {3} {2}\" fill=\"none\" stroke=\"black\"/>\n", left, top, h - bottom,
                   w - right);
  for (int e = -6; e <= -2; ++e)
    s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">1e{}</text>\n", X(std::pow(10.0, e)), h - bottom + 15, e);
  s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">0</text>\n", left, h - bottom + 15);
  s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">outward spread of each springing, d/L</text>\n",
                   0.5 * (left + w - right), h - 12);
  for (double v : {lo + pad, hi - pad})
    s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{:.4g}</text>\n", left - 4, Y(v) + 4, v);
  s += fmt::format("<text x=\"12\" y=\"{}\" transform=\"rotate(-90 12 {})\" text-anchor=\"middle\">H/V</text>\n",
                   0.5 * (top + h - bottom), 0.5 * (top + h - bottom));
  const double min_ratio = lim.H_min() / lim.V;
  if (std::isfinite(min_ratio))
    s += fmt::format("<line id=\"chart-minimum\" x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"#1e8449\" "
                     "stroke-dasharray=\"6,3\"/><text x=\"{2}\" y=\"{3}\" text-anchor=\"end\" fill=\"#1e8449\">minimum "
                     "thrust (limit analysis) {4:.4g}</text>\n",
                     left, Y(min_ratio), w - right, Y(min_ratio) - 4, min_ratio);
  std::string d;
  for (const Point& p : points) d += fmt::format("{}{} {}", d.empty() ? "M " : " L ", X(p.ratio), Y(p.H_over_V));
  s += "<path id=\"chart-line\" fill=\"none\" stroke=\"#c0392b\" stroke-width=\"2\" d=\"" + d + "\"/>\n";
  for (const Point& p : points) {
    std::string full;
    append_number(full, p.H_over_V);
    s += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"3\" fill=\"#c0392b\" data-d-over-L=\"{:g}\" data-value=\"{}\"/>\n",
                     X(p.ratio), Y(p.H_over_V), p.ratio, full);
  }
  s += "</svg>\n<p class=\"note\">The scene with the no-tension section, both springings spreading outwards by d "
       "(other movements as given); solved with the same solver options.</p>\n";
  if (!failed.empty()) {
    s += "<p class=\"note\">Not drawn:";
    for (const std::string& f : failed) s += " " + escaped(f) + ";";
    s += "</p>\n";
  }
  return s + "</section>\n";
}

}  // namespace

bool ReportOptions::is_valid(std::string* why) const {
  if (spread_points < 2 || spread_points > 41) {
    if (why) *why = fmt::format("spread_points: must lie in [2, 41], got {}", spread_points);
    return false;
  }
  return solver.is_valid(why) && require.is_valid(why) && limit.is_valid(why);
}

Solution report_solution(const Scene& scene, const ReportOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(why);
  scene.validate();
  // The assessment's solve (its thrust line's summary searches the field), with the drawing's profile.
  Solution sol = solve(scene, assessment_solve_options(options.solver));
  if (sol.field && options.solver.stations > 0) sample_profile(sol, options.solver.stations);
  return sol;
}

std::string html_report(const Scene& scene, const ReportOptions& options) {
  return html_report(scene, report_solution(scene, options), options);
}

std::string html_report(const Scene& scene, const Solution& sol, const ReportOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(why);
  scene.validate();
  AssessmentOptions assessment;
  assessment.require = options.require;
  assessment.elastic = options.solver;
  assessment.limit = options.limit;
  const Assessment a = assess(scene, assessment, sol);
  const LimitResult& lim = a.limit;
  DrawingOptions drawing;
  drawing.title = options.title;
  add_limit_analysis(drawing, scene, lim);
  add_wall_resultants(drawing, scene, sol);
  std::string svg = arch_svg(scene, sol, drawing);
  svg.erase(0, svg.find("<svg"));  // inline: no XML declaration

  std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<title>ogive report: " + escaped(options.title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
  page += "<h1>" + escaped(options.title) + "</h1>\n";
  page += verdict_section(a, options);
  page += "<section id=\"drawing\"><h2>The arch</h2>\n" + svg + "</section>\n";
  page += reactions_section(sol) + thrusts_section(scene, sol, lim) + safety_section(scene, lim) + collapse_section(scene, lim);
  page += spreading_section(scene, sol, options, lim);
  page += geometry_section(scene, lim.ring);
  page += "<section id=\"inputs\"><h2>Inputs as given</h2>\n<table>\n";
  for (const auto& [name, value] : options.inputs)
    page += "<tr><th>" + escaped(name) + "</th><td>" + escaped(value) + "</td></tr>\n";
  page += "</table></section>\n" + assumptions_section(scene, options) + "</body>\n</html>\n";
  return page;
}

}  // namespace ogive
