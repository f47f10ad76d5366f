#include "ogive/output/svg.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "ogive/output/csv.hpp"
#include "svg_draw.hpp"

namespace ogive {
namespace {

using namespace svg_draw;

constexpr const char* kThrustColour = "#c0392b";

// The largest of 1, 2, 5 times a power of ten not above `target` (> 0).
double round_length(double target) {
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * decade <= target) return m * decade;
  return decade;
}

// A clamped springing: the support's face along the springing section, reaching `reach` beyond both
// faces, with hatches on the support's side `away` (a unit vector out of the arch).
void clamped_support(std::string& out, const char* id, const SectionFaces& faces, PlanePoint away, double reach,
                     double stroke) {
  const double dx = faces.extrados.x - faces.intrados.x, dy = faces.extrados.y - faces.intrados.y;
  const double length = std::hypot(dx, dy);
  const PlanePoint u{dx / length, dy / length};  // along the section, intrados to extrados
  const PlanePoint a{faces.intrados.x - reach * u.x, faces.intrados.y - reach * u.y};
  const PlanePoint b{faces.extrados.x + reach * u.x, faces.extrados.y + reach * u.y};
  const double total = length + 2 * reach;
  const int hatches = 10;
  const double depth = total / hatches;  // hatches as long as they are apart, as drawings show them
  // Hatches at 45 degrees between the support's side and the section's direction.
  const PlanePoint h{(away.x - u.x) / std::sqrt(2.0), (away.y - u.y) / std::sqrt(2.0)};
  out += fmt::format("<g id=\"{}\" stroke=\"black\" stroke-linecap=\"round\">\n", id);
  line(out, a, b, fmt::format("stroke-width=\"{}\"", 2 * stroke));
  for (int k = 1; k <= hatches; ++k) {
    const double f = total * k / hatches;
    const PlanePoint q{a.x + f * u.x, a.y + f * u.y};
    line(out, q, {q.x + depth * h.x, q.y + depth * h.y}, fmt::format("stroke-width=\"{}\"", stroke));
  }
  out += "</g>\n";
}

// A pinned springing: a pin (circle) at the axis point, on a triangle standing on a hatched base beyond
// the springing, so that the section visibly turns freely.
void pinned_support(std::string& out, const char* id, const SectionFaces& faces, PlanePoint away, double reach,
                    double stroke) {
  const PlanePoint pin{0.5 * (faces.intrados.x + faces.extrados.x), 0.5 * (faces.intrados.y + faces.extrados.y)};
  const double size = 1.5 * reach;
  const PlanePoint normal{-away.y, away.x};  // across the support's direction
  const PlanePoint base{pin.x + size * away.x, pin.y + size * away.y};
  const PlanePoint left{base.x + 0.6 * size * normal.x, base.y + 0.6 * size * normal.y};
  const PlanePoint right{base.x - 0.6 * size * normal.x, base.y - 0.6 * size * normal.y};
  out += fmt::format("<g id=\"{}\" stroke=\"black\" stroke-linecap=\"round\" fill=\"none\">\n", id);
  for (auto [a, b] : {std::pair{pin, left}, std::pair{pin, right}, std::pair{left, right}})
    line(out, a, b, fmt::format("stroke-width=\"{}\"", 2 * stroke));
  out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\" stroke-width=\"{}\" fill=\"white\"/>\n", pin.x, -pin.y,
                     0.25 * size, 1.5 * stroke);
  const int hatches = 6;
  for (int k = 0; k <= hatches; ++k) {
    const double f = 1.2 * size * (static_cast<double>(k) / hatches - 0.5);
    const PlanePoint q{base.x + f * normal.x, base.y + f * normal.y};
    line(out, q, {q.x + 0.3 * size * (away.x - normal.x), q.y + 0.3 * size * (away.y - normal.y)},
         fmt::format("stroke-width=\"{}\"", stroke));
  }
  out += "</g>\n";
}

std::string face_style(double stroke) {
  return fmt::format("fill=\"none\" stroke=\"black\" stroke-width=\"{}\"", stroke);
}
std::string axis_style(double stroke) {
  return fmt::format("fill=\"none\" stroke=\"#555555\" stroke-width=\"{}\" stroke-dasharray=\"{},{}\"", stroke,
                     6 * stroke, 3 * stroke);
}
std::string thrust_style(double stroke) {
  return fmt::format("fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"", kThrustColour, 1.5 * stroke);
}
// A further line of thrust: dashed, in its colour.
std::string extra_line_style(const ExtraThrustLine& extra, double stroke) {
  return fmt::format("stroke=\"{}\" stroke-width=\"{}\" stroke-dasharray=\"{},{}\"", extra.colour, 1.2 * stroke,
                     4 * stroke, 2 * stroke);
}

// A face of the left half ends at the crown's vertical joint x = `joint`: carried to it along the
// crown's tangent when short of it, cut where the polyline crosses it when past it.
void end_at_crown_joint(std::vector<PlanePoint>& v, double joint, double crown_theta) {
  if (v.back().x < joint) {
    const double along = (joint - v.back().x) / std::cos(crown_theta);
    v.push_back({joint, v.back().y + along * std::sin(crown_theta)});
  } else if (v.back().x > joint) {
    std::size_t k = v.size() - 1;
    while (k > 0 && v[k - 1].x > joint) --k;
    if (k > 0) {
      const PlanePoint a = v[k - 1], b = v[k];
      const double f = (joint - a.x) / (b.x - a.x);
      v.resize(k);
      v.push_back({joint, a.y + f * (b.y - a.y)});
    }
  }
}

// The arch: axis and faces at equal steps of arc length over the left half, mirrored onto the right.
// At a pointed crown the two halves' sections differ (their tangents do), so each face is cut at, or
// carried along its crown tangent to, the crown's vertical joint x = L/2, as the voussoirs meet there.
// A whole arch (a survey) is drawn as it is, springing to springing.
Outline arch_outline(const Scene& scene, int samples, const Frame& frame) {
  const Curve& curve = *scene.curve;
  const double S = curve.length();
  Outline o;
  auto add = [&](double s) {
    const CurvePoint p = curve.at(s);
    const SectionFaces f = frame.faces(section_faces(p, scene.thickness));
    o.axis.push_back(frame.at(p.x, p.y));
    o.intrados.push_back(f.intrados);
    o.extrados.push_back(f.extrados);
  };
  if (curve.extent() == CurveExtent::whole) {
    for (int k = 0; k < 2 * samples - 1; ++k) add(k == 2 * samples - 2 ? S : S * k / (2 * samples - 2));
    return o;
  }
  for (int k = 0; k < samples; ++k) add(k == samples - 1 ? S : S * k / (samples - 1));
  const CurvePoint crown = curve.at(S);
  for (std::vector<PlanePoint>* face : {&o.intrados, &o.extrados})
    end_at_crown_joint(*face, 0.5 * frame.L, crown.theta);
  for (std::vector<PlanePoint>* line : {&o.axis, &o.intrados, &o.extrados}) {
    std::vector<PlanePoint>& v = *line;
    for (std::size_t k = v.size() - 1; k-- > 0;) v.push_back({frame.L - v[k].x, v[k].y});
  }
  return o;
}

// A springing: its axis point (m), its section's faces (drawing units), the side of its support beyond
// the end of the axis.
struct Springing {
  const char* id;
  SupportKind kind;
  CurvePoint point;
  SectionFaces faces;
  PlanePoint away;
};

std::vector<Springing> springings(const Scene& scene, const Frame& frame) {
  const Curve& curve = *scene.curve;
  const CurvePoint left = curve.at_whole_arch(0), right = curve.at_whole_arch(curve.whole_length());
  return {{"support-left", scene.left.kind, left, frame.faces(section_faces(left, scene.thickness)),
           PlanePoint{-std::cos(left.theta), -std::sin(left.theta)}},
          {"support-right", scene.right.kind, right, frame.faces(section_faces(right, scene.thickness)),
           PlanePoint{std::cos(right.theta), std::sin(right.theta)}}};
}

// The supports, drawn on the springing sections; the view takes in their reach.
std::string supports_svg(const std::vector<Springing>& ends, const Frame& frame, Box& drawn) {
  std::string out;
  for (const Springing& e : ends) {
    if (e.kind == SupportKind::clamped) clamped_support(out, e.id, e.faces, e.away, frame.reach, frame.stroke);
    else pinned_support(out, e.id, e.faces, e.away, frame.reach, frame.stroke);
  }
  for (const Springing& e : ends)
    for (PlanePoint p : {e.faces.intrados, e.faces.extrados}) {
      drawn.add({p.x, p.y - 1.5 * frame.reach});
      drawn.add({p.x, p.y + 1.5 * frame.reach});
    }
  return out;
}

// The walls under the springings (Scene::left_wall, right_wall): each outline filled (#wall-left,
// #wall-right), the wedge under an inclined springing joint included, and the ground under its base
// hatched as a clamped support is (#ground-left, #ground-right); the view takes them in.
void draw_walls(std::string& body, const Scene& scene, const Frame& frame, Box& drawn) {
  for (bool right : {false, true}) {
    const std::optional<Wall>& wall = right ? scene.right_wall : scene.left_wall;
    if (!wall) continue;
    std::vector<PlanePoint> outline;
    for (const PlanePoint& c : wall_corners(wall_outline(*scene.curve, scene.thickness, *wall, right)))
      outline.push_back(frame.at(c.x, c.y));
    for (PlanePoint q : outline) drawn.add(q);
    path(body, right ? "wall-right" : "wall-left", {outline},
         fmt::format("fill=\"#e8e2d6\" stroke=\"black\" stroke-width=\"{}\"", frame.stroke).c_str());
    const SectionFaces base{outline[0], outline[1]};
    clamped_support(body, right ? "ground-right" : "ground-left", base, PlanePoint{0.0, -1.0}, frame.reach,
                    frame.stroke);
    for (PlanePoint q : {outline[0], outline[1]}) drawn.add({q.x, q.y - 1.5 * frame.reach});
  }
}

// The thrust line: runs of drawable stations (finite, not far from the arch); the view follows the
// line a little way out of the arch, no farther.
std::vector<std::vector<PlanePoint>> thrust_runs(const Solution& solution, const Frame& frame, Box& drawn) {
  const Box& box = frame.box;
  const double W = frame.W;
  std::vector<std::vector<PlanePoint>> thrust(1);
  for (const ArchState& st : solution.profile) {
    const PlanePoint p = frame.at(st.thrust_x, st.thrust_y);
    if (std::isfinite(p.x) && std::isfinite(p.y) && box.contains(p, kFarFromArch * frame.L)) {
      thrust.back().push_back(p);
      drawn.add({std::clamp(p.x, box.x0 - 0.25 * W, box.x1 + 0.25 * W),
                 std::clamp(p.y, box.y0 - 0.25 * W, box.y1 + 0.25 * W)});
    } else if (!thrust.back().empty()) {
      thrust.emplace_back();
    }
  }
  if (thrust.back().empty()) thrust.pop_back();
  return thrust;
}

// The masonry: the filled section, the faces and the dashed axis.
void draw_arch(std::string& body, const Outline& o, double stroke) {
  body += "<path id=\"section\" fill=\"#e8e0d0\" stroke=\"none\" d=\"";
  std::vector<PlanePoint> outline = o.extrados;
  outline.insert(outline.end(), o.intrados.rbegin(), o.intrados.rend());
  body += path_data({outline}) + " Z\"/>\n";
  path(body, "extrados", {o.extrados}, face_style(stroke).c_str());
  path(body, "intrados", {o.intrados}, face_style(stroke).c_str());
  path(body, "axis", {o.axis}, axis_style(stroke).c_str());
}

// The elastic line of thrust, clipped to the arch's surroundings (where the view follows it), so that
// a line that runs off stays clear of the title, the arrows and the scale bar; its points are all in
// the path.
void draw_thrust_line(std::string& body, const std::vector<std::vector<PlanePoint>>& thrust, const Box& drawn,
                      double stroke) {
  if (thrust.empty()) return;
  body += "<clipPath id=\"near-the-arch\"><rect";
  for (const auto& [name, v] : {std::pair{"x", drawn.x0}, std::pair{"y", -drawn.y1},
                                std::pair{"width", drawn.x1 - drawn.x0}, std::pair{"height", drawn.y1 - drawn.y0}})
    attribute(body, name, v);
  body += "/></clipPath>\n";
  path(body, "thrust-line", thrust, (thrust_style(stroke) + " clip-path=\"url(#near-the-arch)\"").c_str());
}

// Further lines of thrust (limit states): dashed, their hinges circled.
void draw_extra_lines(std::string& body, const std::vector<ExtraThrustLine>& extra_lines, const Frame& frame) {
  for (const ExtraThrustLine& extra : extra_lines) {
    std::vector<PlanePoint> points;
    for (PlanePoint p : extra.points) points.push_back(frame.at(p.x, p.y));
    if (!points.empty())
      path(body, extra.id.c_str(), {points}, ("fill=\"none\" " + extra_line_style(extra, frame.stroke)).c_str());
    hinge_circles(body, extra.id + "-hinges", extra.hinges, frame, 0.6 * frame.font,
                  fmt::format("fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"", extra.colour, frame.stroke));
  }
}

// The crown hinge: a pin at the crown's axis point.
void draw_crown_hinge(std::string& body, const Curve& curve, const Frame& frame) {
  const CurvePoint crown = curve.at(curve.crown());
  const PlanePoint c = frame.at(crown.x, crown.y);
  body += fmt::format("<circle id=\"crown-hinge\" cx=\"{}\" cy=\"{}\" r=\"{}\" stroke=\"black\" stroke-width=\"{}\" "
                      "fill=\"white\"/>\n",
                      c.x, -c.y, 0.4 * frame.reach, 1.5 * frame.stroke);
}

// Support movement: an arrow below each springing that spreads, outwards for d > 0, with its value.
// Returns the new bottom of the drawing.
double draw_support_movement(std::string& body, const Scene& scene, const std::vector<Springing>& ends,
                             const Frame& frame, Box& drawn, double bottom) {
  if (scene.left.spread == 0 && scene.right.spread == 0) return bottom;
  const double font = frame.font;
  const double y = bottom - 1.2 * font, length = 0.08 * frame.W;
  body += "<g id=\"support-movement\" stroke=\"#1f4e9c\" fill=\"#1f4e9c\">\n";
  for (const auto& [x, outward, d] : {std::tuple{ends[0].point.x / frame.unit, -1.0, scene.left.spread},
                                      std::tuple{ends[1].point.x / frame.unit, 1.0, scene.right.spread}}) {
    if (d == 0) continue;
    const double sign = d > 0 ? 1.0 : -1.0;
    const std::string label = fmt::format("d = {:.3g} mm {}", std::abs(d) * 1000, d > 0 ? "outwards" : "inwards");
    line(body, {x, y}, {x + sign * outward * length, y},
         fmt::format("stroke-width=\"{}\" marker-end=\"url(#arrowhead)\"", 1.5 * frame.stroke));
    // The label below the arrow, towards the arch so that it stays in the picture.
    text(body, {x - outward * 0.5 * font, y - 1.3 * font}, 0.8 * font, outward < 0 ? "start" : "end", label);
    drawn.add({x + outward * (length + font), y});
  }
  body += "</g>\n";
  return y - 1.6 * font;
}

// Horizontal acceleration: an arrow above the arch, to the right for a > 0, with its value. Grows
// `drawn` upwards (the title goes above it).
void draw_horizontal_acceleration(std::string& body, const Scene& scene, const Frame& frame, Box& drawn) {
  const double a = scene.horizontal_acceleration;
  if (a == 0) return;
  const double font = frame.font, length = 0.12 * frame.W, sign = a > 0 ? 1.0 : -1.0;
  const double y = drawn.y1 + 1.5 * font, x = 0.5 * (frame.box.x0 + frame.box.x1);
  body += "<g id=\"horizontal-acceleration\" stroke=\"#1f4e9c\" fill=\"#1f4e9c\">\n";
  line(body, {x - 0.5 * sign * length, y}, {x + 0.5 * sign * length, y},
       fmt::format("stroke-width=\"{}\" marker-end=\"url(#arrowhead)\"", 1.5 * frame.stroke));
  text(body, {x, y + 0.6 * font}, 0.8 * font, "middle",
       fmt::format("horizontal acceleration a = {:g} g on the self-weight and fill", a));
  body += "</g>\n";
  drawn.add({x, y + 1.6 * font});
}

// Scale bar: a round length near a quarter of the arch's width, ticks at its ends and middle. Returns
// the new bottom of the drawing.
double draw_scale_bar(std::string& body, const Frame& frame, double bottom) {
  const double font = frame.font, stroke = frame.stroke;
  const double length = round_length(0.25 * frame.W);
  const double y = bottom - 1.5 * font, x = frame.box.x0, tick = 0.4 * font;
  body += "<g id=\"scale-bar\" stroke=\"black\" fill=\"black\">\n";
  line(body, {x, y}, {x + length, y}, fmt::format("stroke-width=\"{}\"", stroke));
  for (double f : {0.0, 0.5, 1.0})
    line(body, {x + f * length, y}, {x + f * length, y + tick}, fmt::format("stroke-width=\"{}\"", stroke));
  text(body, {x, y - 1.1 * font}, 0.8 * font, "middle", "0");
  text(body, {x + 0.5 * length, y - 1.1 * font}, 0.8 * font, "middle", fmt::format("{:g}", 0.5 * length * frame.unit));
  text(body, {x + length, y - 1.1 * font}, 0.8 * font, "middle", fmt::format("{:g} m", length * frame.unit));
  body += "</g>\n";
  return y - 1.6 * font;
}

// The reactions' line of the title, or why there are none.
std::string result_text(const Solution& solution) {
  if (std::isfinite(solution.H_over_V))
    return fmt::format("H/V = {:.6g}, H = {:.4g} kN/m, V = {:.4g} kN/m ({}, {})", solution.H_over_V, solution.H / 1000,
                       solution.V / 1000, to_string(solution.method), to_string(solution.status));
  return fmt::format("no solution: {}{}{}", to_string(solution.status), solution.message.empty() ? "" : ": ",
                     solution.message);
}

// A springing's support and movement, in mm and rad: "left clamped, spreads 0.8 mm outwards".
std::string springing_text(const char* side, const Support& support) {
  std::string t = fmt::format("{} {}", side, support.kind == SupportKind::clamped ? "clamped" : "pinned");
  if (support.spread != 0)
    t += fmt::format(", spreads {:.4g} mm {}", std::abs(support.spread) * 1000, support.spread > 0 ? "outwards" : "inwards");
  if (support.settlement != 0)
    t += fmt::format(", settles {:.4g} mm{}", std::abs(support.settlement) * 1000, support.settlement > 0 ? "" : " upwards");
  if (support.rotation != 0) t += fmt::format(", turns {:.4g} rad", support.rotation);
  if (support.spread == 0 && support.settlement == 0 && support.rotation == 0) t += ", fixed";
  return t;
}

// The title's lines: the caption wrapped to the page, the reactions (or why there are none), the
// springings; then the legend, a line each.
struct TitleText {
  std::vector<std::string> lines;
  std::string load_scale;  // the load arrows' scales, "" without loads
  std::size_t legend_lines(const DrawingOptions& o) const {
    return 1 + o.extra_lines.size() + o.mechanisms.size() + o.spread_stages.size() + (load_scale.empty() ? 0 : 1);
  }
  double height(const DrawingOptions& o, double font) const {
    return (1.4 * static_cast<double>(lines.size()) + 1.3 * static_cast<double>(legend_lines(o))) * font;
  }
};

TitleText title_text(const Scene& scene, const Solution& solution, const DrawingOptions& options, double chars) {
  TitleText t;
  t.lines = wrap(options.title, static_cast<std::size_t>(chars));
  t.lines.push_back(result_text(solution));
  t.lines.push_back(fmt::format("springings: {}; {}", springing_text("left", scene.left),
                                springing_text("right", scene.right)));
  return t;
}

// Title at title_y: the title's lines, then a legend.
std::string title_svg(const Scene& scene, const TitleText& t, const DrawingOptions& options, const Frame& frame,
                      double title_y) {
  const double font = frame.font, x0 = frame.box.x0;
  std::string title = "<g id=\"title\" fill=\"black\">\n";
  double y = title_y;
  for (std::size_t k = 0; k < t.lines.size(); ++k, y -= 1.4 * font)
    text(title, {x0, y}, k + 2 < t.lines.size() ? font : 0.85 * font, "start", t.lines[k]);
  const double legend_y = y + 0.2 * font;
  const bool cracking = scene.section == SectionKind::no_tension;
  line(title, {x0, legend_y + 0.3 * font}, {x0 + 2 * font, legend_y + 0.3 * font}, thrust_style(frame.stroke));
  text(title, {x0 + 2.5 * font, legend_y}, 0.8 * font, "start",
       cracking ? "cracked-section line of thrust (no-tension section; cracks shaded)" : "elastic line of thrust");
  const double axis_x = x0 + (cracking ? 30 : 14) * font;
  line(title, {axis_x, legend_y + 0.3 * font}, {axis_x + 2 * font, legend_y + 0.3 * font}, axis_style(frame.stroke));
  text(title, {axis_x + 2.5 * font, legend_y}, 0.8 * font, "start", fmt::format("axis; section t = {:g} m", scene.thickness));
  y = legend_y;
  // One more legend line below the last: a stroke in `style`, then its label.
  auto legend_line = [&](const std::string& style, const std::string& label) {
    y -= 1.3 * font;
    line(title, {x0, y + 0.3 * font}, {x0 + 2 * font, y + 0.3 * font}, style);
    text(title, {x0 + 2.5 * font, y}, 0.8 * font, "start", label);
  };
  for (const ExtraThrustLine& extra : options.extra_lines) legend_line(extra_line_style(extra, frame.stroke), extra.label);
  for (const CollapseMechanism& m : options.mechanisms)
    legend_line(fmt::format("stroke=\"{}\" stroke-width=\"{}\"", m.colour, 3 * frame.stroke), m.label);
  for (const SpreadStageDrawing& stage : options.spread_stages)
    legend_line(fmt::format("stroke=\"{}\" stroke-width=\"{}\"", stage.colour, 3 * frame.stroke), stage.label);
  if (!t.load_scale.empty()) text(title, {x0, y - 1.3 * font}, 0.8 * font, "start", t.load_scale);
  title += "</g>\n";
  return title;
}

// The document around the drawing: its size, the view (everything drawn, the title's width of about
// 40 font sizes and a margin), the unit, the arrowhead and a white background.
std::string document(const std::string& content, const Frame& frame, const Box& drawn, double title_y, double bottom,
                     double width_px) {
  const double font = frame.font, unit = frame.unit;
  const double margin = 1.5 * font;
  const double vx = drawn.x0 - margin, vy = -(title_y + font) - margin;
  const double vw = std::max(drawn.x1, frame.box.x0 + 40 * font) + margin - vx;
  const double vh = -(bottom - font) + margin - vy;
  std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"";
  attribute(svg, "width", width_px);
  attribute(svg, "height", std::round(width_px * vh / vw));
  svg += " viewBox=\"";
  for (double v : {vx, vy, vw, vh}) {
    number(svg, v);
    svg += ' ';
  }
  svg.back() = '"';
  svg += " font-family=\"sans-serif\" data-metres-per-unit=\"";
  number(svg, unit);
  svg += "\">\n";
  svg += fmt::format("<desc>ogive draw: one user unit is {:g} m; the arch's point (x, y) is drawn at (x, -y) / {:g}.</desc>\n",
                     unit, unit);
  svg += "<defs><marker id=\"arrowhead\" viewBox=\"0 0 10 10\" refX=\"8\" refY=\"5\" markerWidth=\"4\" "
         "markerHeight=\"4\" orient=\"auto\"><path d=\"M 0 0 L 10 5 L 0 10 Z\" fill=\"#1f4e9c\"/></marker>";
  svg += fmt::format("<marker id=\"load-arrowhead\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"5\" "
                     "markerHeight=\"5\" orient=\"auto\"><path d=\"M 0 0 L 10 5 L 0 10 Z\" fill=\"{}\"/></marker>",
                     kLoadColour);
  svg += fmt::format("<pattern id=\"fill-hatch\" patternUnits=\"userSpaceOnUse\" width=\"{0}\" height=\"{0}\" "
                     "patternTransform=\"rotate(45)\"><rect width=\"{0}\" height=\"{0}\" fill=\"#f3ead8\"/>"
                     "<line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"{0}\" stroke=\"#a88a5a\" stroke-width=\"{1}\"/></pattern></defs>\n",
                     font, 0.1 * font);
  svg += "<rect";
  for (const auto& [name, v] : {std::pair{"x", vx}, std::pair{"y", vy}, std::pair{"width", vw}, std::pair{"height", vh}})
    attribute(svg, name, v);
  svg += " fill=\"white\"/>\n";
  return svg + content + "</svg>\n";
}

}  // namespace

double drawing_unit(double span) { return std::pow(10.0, std::floor(std::log10(span)) - 2); }

bool DrawingOptions::is_valid(std::string* why) const {
  auto fail = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  if (samples < 2 || samples > 100000) return fail(fmt::format("samples: must lie in [2, 100000], got {}", samples));
  if (!(width_px >= 16 && width_px <= 100000))
    return fail(fmt::format("width_px: must lie in [16, 100000], got {}", width_px));
  return true;
}

std::string arch_svg(const Scene& scene, const Solution& solution, const DrawingOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(why);
  scene.validate();
  Frame frame;
  frame.unit = drawing_unit(scene.span());
  frame.L = scene.span() / frame.unit;
  frame.t = scene.thickness / frame.unit;
  const Outline outline = arch_outline(scene, options.samples, frame);
  for (const auto* points : {&outline.axis, &outline.intrados, &outline.extrados})
    for (PlanePoint p : *points) frame.box.add(p);
  frame.W = frame.box.width();
  frame.stroke = 0.002 * frame.W;
  frame.font = 0.022 * frame.W;
  frame.reach = 0.3 * std::max(frame.t, 0.05 * frame.L);

  // What is drawn grows the view beyond the arch: the supports, the thrust line, the loads, the arrows.
  Box drawn = frame.box;
  const std::vector<Springing> ends = springings(scene, frame);
  // A springing on a wall has the wall for its support (draw_walls).
  std::vector<Springing> held;
  for (const Springing& e : ends)
    if (!(e.id == std::string("support-left") ? scene.left_wall : scene.right_wall)) held.push_back(e);
  const std::string supports = supports_svg(held, frame, drawn);
  const std::vector<std::vector<PlanePoint>> thrust = thrust_runs(solution, frame, drawn);
  std::string body;
  draw_fills(body, scene, outline, frame, drawn);
  draw_walls(body, scene, frame, drawn);
  draw_arch(body, outline, frame.stroke);
  draw_cracks(body, scene, solution, frame);
  for (const CollapseMechanism& m : options.mechanisms) draw_mechanism(body, scene, m, frame, drawn);
  for (const SpreadStageDrawing& stage : options.spread_stages) draw_spread_stage(body, stage, frame, drawn);
  draw_thrust_line(body, thrust, drawn, frame.stroke);
  draw_extra_lines(body, options.extra_lines, frame);
  body += supports;
  if (scene.crown_hinge) draw_crown_hinge(body, *scene.curve, frame);
  TitleText title = title_text(scene, solution, options, std::max(drawn.width(), 40 * frame.font) / (0.6 * frame.font));
  title.load_scale = draw_loads(body, scene, outline, frame, drawn, !thrust.empty());
  draw_horizontal_acceleration(body, scene, frame, drawn);
  double bottom = draw_support_movement(body, scene, ends, frame, drawn, drawn.y0);
  bottom = draw_scale_bar(body, frame, bottom);
  const double title_y = drawn.y1 + title.height(options, frame.font) + 1.5 * frame.font;
  body += title_svg(scene, title, options, frame, title_y);
  return document(body, frame, drawn, title_y, bottom, options.width_px);
}

}  // namespace ogive
