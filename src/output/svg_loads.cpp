// What the drawing shows beyond the arch and its thrust lines: the fill, the loads, the cracked zones of a
// no-tension section, the collapse mechanism and the resultant down the walls (svg.hpp lists the elements).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "ogive/core/wall_resultant.hpp"
#include "svg_draw.hpp"

namespace ogive::svg_draw {
namespace {

// The highest point of a face (drawing units) above x: the top of the masonry there; NaN outside it.
double top_at(const std::vector<PlanePoint>& face, double x) {
  double top = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k + 1 < face.size(); ++k) {
    const PlanePoint a = face[k], b = face[k + 1];
    if (x < std::min(a.x, b.x) || x > std::max(a.x, b.x)) continue;
    const double y = a.x == b.x ? std::max(a.y, b.y) : a.y + (x - a.x) / (b.x - a.x) * (b.y - a.y);
    if (!(y <= top)) top = y;
  }
  return top;
}

// Where a load arrow lands at x: the top of the fill there, or of the extrados.
double surface_at(const Scene& scene, const Outline& outline, const Frame& frame, double x) {
  double top = top_at(outline.extrados, x);
  for (const FillLoad& f : scene.loads.fills) top = std::max(top, f.height_ratio * frame.L);
  return top;
}

void arrow(std::string& out, PlanePoint tail, PlanePoint tip, double stroke) {
  line(out, tail, tip, fmt::format("stroke-width=\"{}\" marker-end=\"url(#load-arrowhead)\"", stroke));
}

// Forces in kN, as an engineer writes them.
std::string kilo(double v) { return fmt::format("{:.4g}", v / 1000); }

}  // namespace

std::vector<std::string> wrap(const std::string& text, std::size_t width) {
  std::vector<std::string> lines;
  std::string current;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(", ", start);
    end = end == std::string::npos ? text.size() : end + 2;
    const std::string piece = text.substr(start, end - start);
    if (!current.empty() && current.size() + piece.size() > width + 2) {  // the trailing ", " may overhang
      lines.push_back(current);
      current.clear();
    }
    current += piece;
    start = end;
  }
  if (!current.empty() || lines.empty()) lines.push_back(current);
  for (std::string& l : lines)
    while (!l.empty() && (l.back() == ' ' || l.back() == ',')) l.pop_back();
  return lines;
}

void draw_fills(std::string& body, const Scene& scene, const Outline& outline, const Frame& frame, Box& drawn) {
  if (scene.loads.fills.empty()) return;
  body += "<g id=\"fill\">\n";
  for (const FillLoad& f : scene.loads.fills) {
    const double level = f.height_ratio * frame.L;
    std::vector<PlanePoint> region{{outline.extrados.front().x, level}};
    for (PlanePoint p : outline.extrados) region.push_back({p.x, std::min(p.y, level)});
    region.push_back({outline.extrados.back().x, level});
    body += "<path fill=\"url(#fill-hatch)\" stroke=\"none\" d=\"" + path_data({region}) + " Z\"/>\n";
    line(body, region.front(), region.back(), fmt::format("stroke=\"#7a5c2e\" stroke-width=\"{}\"", frame.stroke));
    text(body, {region.front().x + 0.5 * frame.font, level + 0.4 * frame.font}, 0.75 * frame.font, "start",
         fmt::format("fill {:g} kg/m^3 to {:.4g} m", f.density, f.height_ratio * scene.span()));
    drawn.add({region.front().x, level + 1.5 * frame.font});
  }
  body += "</g>\n";
}

std::string draw_loads(std::string& body, const Scene& scene, const Outline& outline, const Frame& frame, Box& drawn,
                       bool thrust_drawn) {
  const Loads& loads = scene.loads;
  if (loads.points.empty() && loads.live.empty()) return "";
  double P_max = 0, q_max = 0;
  for (const PointLoad& p : loads.points) P_max = std::max(P_max, std::abs(p.force));
  for (const LiveLoad& q : loads.live) q_max = std::max(q_max, std::abs(q.intensity));
  // One drawing unit of arrow per so many N/m (N/m^2): the largest point load a fifth of the arch's
  // width long, the largest live load a tenth.
  const double per_unit_P = P_max / (0.2 * frame.W), per_unit_q = q_max / (0.1 * frame.W);
  const double font = frame.font, stroke = 1.5 * frame.stroke;
  body += fmt::format("<g id=\"loads\" stroke=\"{0}\" fill=\"{0}\">\n", kLoadColour);
  for (const PointLoad& p : loads.points) {
    if (p.force == 0) continue;
    const double x = p.at * frame.L, top = surface_at(scene, outline, frame, x);
    const double length = std::abs(p.force) / per_unit_P;
    const PlanePoint surface{x, top}, away{x, top + length};
    if (p.force > 0) arrow(body, away, surface, stroke);
    else arrow(body, surface, away, stroke);
    // The label on the side of the arrow with more room, so that it stays in the picture.
    const bool right = x <= 0.45 * frame.L;
    const double label_x = x + (right ? 0.4 : -0.4) * font;
    const char* anchor = right ? "start" : "end";
    text(body, {label_x, top + length - 0.3 * font}, 0.8 * font, anchor, fmt::format("P = {} kN/m", kilo(p.force)));
    if (thrust_drawn)
      text(body, {label_x, top + length - 1.3 * font}, 0.7 * font, anchor,
           "the line of thrust jumps here: N changes under P, and so does M/N");
    drawn.add({x, top + length + font});
  }
  for (const LiveLoad& q : loads.live) {
    const double from = q.from * frame.L, to = q.to * frame.L, length = std::abs(q.intensity) / per_unit_q;
    const int arrows = std::max(2, static_cast<int>(std::round((to - from) / (0.05 * frame.W))) + 1);
    double highest = -std::numeric_limits<double>::infinity();
    std::vector<PlanePoint> tails;
    for (int k = 0; k < arrows; ++k) {
      const double x = from + (to - from) * k / (arrows - 1);
      const double top = surface_at(scene, outline, frame, x);
      tails.push_back({x, top + length});
      highest = std::max(highest, top + length);
      if (q.intensity > 0) arrow(body, tails.back(), {x, top}, frame.stroke);
      else arrow(body, {x, top}, tails.back(), frame.stroke);
    }
    body += fmt::format("<path fill=\"none\" stroke-width=\"{}\" d=\"{}\"/>\n", frame.stroke, path_data({tails}));
    text(body, {0.5 * (from + to), highest + 0.4 * font}, 0.8 * font, "middle",
         fmt::format("q = {} kN/m^2", kilo(q.intensity)));
    drawn.add({from, highest + 1.5 * font});
  }
  body += "</g>\n";
  std::string legend = "load arrows to scale:";
  const double metres_per_unit = frame.unit;
  if (P_max > 0) legend += fmt::format(" 1 m of arrow = {} kN/m (point)", kilo(per_unit_P / metres_per_unit));
  if (q_max > 0)
    legend += fmt::format("{} 1 m of arrow = {} kN/m^2 (live)", P_max > 0 ? "," : "", kilo(per_unit_q / metres_per_unit));
  return legend;
}

void draw_cracks(std::string& body, const Scene& scene, const Solution& solution, const Frame& frame) {
  if (scene.section != SectionKind::no_tension) return;
  // The cracked part of one station's section: from the face away from the resultant, inwards by the
  // cracked depth; `side` is +1 when the crack is on the extrados.
  struct Crack {
    PlanePoint face, inner;
    int side;
  };
  auto crack = [&](const ArchState& st) -> std::optional<Crack> {
    if (!st.cracked || !std::isfinite(st.compressed_depth) || !std::isfinite(st.thrust_x)) return std::nullopt;
    const CurvePoint p{st.x, st.y, st.theta};
    const PlanePoint out = along_normal(p, 1.0);  // a metre towards the extrados
    const double towards = (st.thrust_x - st.x) * (out.x - st.x) + (st.thrust_y - st.y) * (out.y - st.y);
    const int side = towards > 0 ? -1 : 1;
    const double t = scene.thickness, depth = (1 - st.compressed_depth) * t;
    const PlanePoint f = along_normal(p, side * 0.5 * t), i = along_normal(p, side * (0.5 * t - depth));
    return Crack{frame.at(f.x, f.y), frame.at(i.x, i.y), side};
  };
  body += "<g id=\"cracks\" fill=\"#c0392b\" fill-opacity=\"0.35\" stroke=\"none\">\n";
  const auto& profile = solution.profile;
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    const auto a = crack(profile[k]), b = crack(profile[k + 1]);
    if (!a || !b || a->side != b->side) continue;
    body += "<path d=\"" + path_data({{a->face, a->inner, b->inner, b->face}}) + " Z\"/>\n";
  }
  body += "</g>\n";
}

namespace {

// A moving block of the mechanism: the arch between two hinges, turning by `angle` about `centre` (m).
struct Block {
  double s0, s1;
  PlanePoint centre;
  double angle;
};

PlanePoint turned(PlanePoint x, const Block& b) {
  const double c = std::cos(b.angle), s = std::sin(b.angle), dx = x.x - b.centre.x, dy = x.y - b.centre.y;
  return {b.centre.x + c * dx - s * dy, b.centre.y + s * dx + c * dy};
}

// The outline of the arch between s0 and s1 (m, along the whole arch): the extrados, then the intrados back.
std::vector<PlanePoint> block_outline(const Scene& scene, double s0, double s1) {
  std::vector<PlanePoint> ext, in;
  const int n = 24;
  for (int k = 0; k <= n; ++k) {
    const SectionFaces f = section_faces(scene.curve->at_whole_arch(s0 + (s1 - s0) * k / n), scene.thickness);
    ext.push_back(f.extrados);
    in.push_back(f.intrados);
  }
  ext.insert(ext.end(), in.rbegin(), in.rend());
  return ext;
}

// The three moving blocks of a four-hinge mechanism A B C D, with unit rotation of the first: A-B turns
// about A, C-D about D, and B-C about the meeting point I of the lines AB and DC, its rotation such that
// B and C move with both neighbours (small displacements: theta perp(X - P)). Empty when AB and DC are
// parallel (the middle block translates; not drawn).
std::vector<Block> mechanism_blocks(const CollapseMechanism& m) {
  const PlanePoint A = m.hinges[0], B = m.hinges[1], C = m.hinges[2], D = m.hinges[3];
  const PlanePoint u{B.x - A.x, B.y - A.y}, v{C.x - D.x, C.y - D.y};
  const double cross = u.x * v.y - u.y * v.x;
  if (std::abs(cross) < 1e-12 * std::hypot(u.x, u.y) * std::hypot(v.x, v.y)) return {};
  const double a = ((D.x - A.x) * v.y - (D.y - A.y) * v.x) / cross;
  const PlanePoint I{A.x + a * u.x, A.y + a * u.y};
  auto dot = [](PlanePoint p, PlanePoint q) { return p.x * q.x + p.y * q.y; };
  const PlanePoint BI{B.x - I.x, B.y - I.y}, CI{C.x - I.x, C.y - I.y}, CD{C.x - D.x, C.y - D.y};
  const double theta2 = dot(u, BI) / dot(BI, BI);
  const double theta3 = theta2 * dot(CI, CD) / dot(CD, CD);
  return {{m.hinge_s[0], m.hinge_s[1], A, 1.0}, {m.hinge_s[1], m.hinge_s[2], I, theta2},
          {m.hinge_s[2], m.hinge_s[3], D, theta3}};
}

}  // namespace

void draw_mechanism(std::string& body, const Scene& scene, const CollapseMechanism& m, const Frame& frame, Box& drawn) {
  if (m.hinges.size() != 4 || m.hinge_s.size() != 4) return;
  std::vector<Block> blocks = mechanism_blocks(m);
  if (blocks.empty()) return;
  // The sense: the arch under load_x goes down. The size: the largest displacement a twentieth of the span.
  double largest = 0, sense = 1;
  for (const Block& b : blocks) {
    for (PlanePoint x : block_outline(scene, b.s0, b.s1)) {
      largest = std::max(largest, std::abs(b.angle) * std::hypot(x.x - b.centre.x, x.y - b.centre.y));
    }
    const CurvePoint mid0 = scene.curve->at_whole_arch(b.s0), mid1 = scene.curve->at_whole_arch(b.s1);
    if (m.load_x >= std::min(mid0.x, mid1.x) && m.load_x <= std::max(mid0.x, mid1.x))
      sense = b.angle * (m.load_x - b.centre.x) > 0 ? -1 : 1;  // the vertical velocity is angle (x - centre x)
  }
  if (!(largest > 0)) return;
  for (Block& b : blocks) b.angle *= sense * 0.05 * scene.span() / largest;
  body += fmt::format("<g id=\"mechanism\" fill=\"{0}\" fill-opacity=\"0.15\" stroke=\"{0}\" stroke-width=\"{1}\">\n",
                      m.colour, frame.stroke);
  for (const Block& b : blocks) {
    std::vector<PlanePoint> outline;
    for (PlanePoint x : block_outline(scene, b.s0, b.s1)) {
      const PlanePoint moved = turned(x, b);
      outline.push_back(frame.at(moved.x, moved.y));
      drawn.add(outline.back());
    }
    body += "<path stroke-dasharray=\"" + fmt::format("{},{}", 3 * frame.stroke, 2 * frame.stroke) + "\" d=\"" +
            path_data({outline}) + " Z\"/>\n";
  }
  for (PlanePoint h : m.hinges) {  // the hinges where they are, before the blocks move
    const PlanePoint c = frame.at(h.x, h.y);
    body += "<circle fill=\"none\" stroke-width=\"" + fmt::format("{}", 2 * frame.stroke) + "\"";
    attribute(body, "cx", c.x);
    attribute(body, "cy", -c.y);
    attribute(body, "r", 0.45 * frame.font);
    body += "/>\n";
  }
  body += "</g>\n";
  // Numbered from the left springing, as the report's hinge table numbers them.
  body += fmt::format("<g id=\"mechanism-hinge-numbers\" fill=\"{}\" font-size=\"{}\" font-weight=\"bold\">\n", m.colour,
                      0.8 * frame.font);
  for (std::size_t k = 0; k < m.hinges.size(); ++k) {
    const PlanePoint c = frame.at(m.hinges[k].x, m.hinges[k].y);
    body += "<text";
    attribute(body, "x", c.x + 0.6 * frame.font);
    attribute(body, "y", -c.y - 0.6 * frame.font);
    body += fmt::format(">{}</text>\n", k + 1);
  }
  body += "</g>\n";
}

void draw_spread_stage(std::string& body, const SpreadStageDrawing& stage, const Frame& frame, Box& drawn) {
  // The ring as one outline (the intrados corners in order, then the extrados' back): a joint that has
  // opened shows as a notch in it, and 400 voussoirs draw no hatching of their own.
  std::vector<PlanePoint> outline;
  for (const std::vector<PlanePoint>& v : stage.voussoirs)
    for (int corner : {0, 3}) outline.push_back(frame.at(v[corner].x, v[corner].y));
  for (auto v = stage.voussoirs.rbegin(); v != stage.voussoirs.rend(); ++v)
    for (int corner : {2, 1}) outline.push_back(frame.at((*v)[corner].x, (*v)[corner].y));
  for (const PlanePoint& p : outline) drawn.add(p);
  if (!outline.empty())
    body += fmt::format("<path id=\"spread-stage\" fill=\"{0}\" fill-opacity=\"0.15\" stroke=\"{0}\" stroke-width=\"{1}\" "
                        "d=\"{2} Z\"/>\n",
                        stage.colour, frame.stroke, path_data({outline}));
  std::vector<PlanePoint> line;
  for (PlanePoint p : stage.thrust_line) line.push_back(frame.at(p.x, p.y));
  if (!line.empty())
    path(body, "spread-stage-thrust-line", {line},
         fmt::format("fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"", stage.colour, 2 * frame.stroke).c_str());
  for (std::size_t k = 0; k < stage.walls.size(); ++k) {
    std::vector<PlanePoint> wall;
    for (const PlanePoint& c : stage.walls[k]) drawn.add(wall.emplace_back(frame.at(c.x, c.y)));
    body += fmt::format("<path id=\"spread-stage-wall-{0}\" fill=\"{1}\" fill-opacity=\"0.15\" stroke=\"{1}\" "
                        "stroke-width=\"{2}\" d=\"{3} Z\"/>\n",
                        stage.right_walls[k] ? "right" : "left", stage.colour, frame.stroke, path_data({wall}));
  }
  hinge_circles(body, "spread-stage-hinges", stage.hinges, frame, 0.45 * frame.font,
                fmt::format("fill=\"white\" stroke=\"{}\" stroke-width=\"{}\"", stage.colour, 1.5 * frame.stroke));
}

}  // namespace ogive::svg_draw

namespace ogive {

std::optional<SpreadStageDrawing> spread_stage_drawing(const SpreadResult& r, double span_increase_ratio) {
  if (r.status != SpreadStatus::success || r.path.empty()) return std::nullopt;
  auto plane = [](const Eigen::Vector2d& p) { return PlanePoint{p.x(), p.y()}; };
  SpreadStageDrawing stage;
  for (const auto& corners : r.shape.voussoirs) {
    std::vector<PlanePoint>& outline = stage.voussoirs.emplace_back();
    for (const Eigen::Vector2d& c : corners) outline.push_back(plane(c));
  }
  for (const Eigen::Vector2d& p : r.shape.thrust_line) stage.thrust_line.push_back(plane(p));
  const SpreadStep& last = r.path.back();
  for (const Hinge& h : last.hinges) stage.hinges.push_back(plane(h.point));
  stage.label = fmt::format("rigid voussoirs, span increased by {:.4g} L{}: H/V {:.4g}, crown drop {:.4g} L, {} hinges",
                            span_increase_ratio, r.stopped ? "" : " (collapse)", last.H / last.V_left,
                            last.crown_drop / r.ring.span, last.hinges.size());
  return stage;
}

std::vector<PlanePoint> wall_corners(const WallOutline& o) {
  const Eigen::Vector2d I = o.joint.intrados, E = o.joint.extrados;
  return {{o.inner_x, o.base_y}, {o.outer_x, o.base_y}, {o.outer_x, std::max(o.top_y, E.y())},
          {E.x(), E.y()},        {I.x(), I.y()},        {o.inner_x, o.top_y}};
}

void add_leaning_walls(SpreadStageDrawing& stage, const Scene& scene, double left_rotation, double right_rotation) {
  for (const auto& [right, theta] : {std::pair{false, left_rotation}, std::pair{true, right_rotation}}) {
    const std::optional<Wall>& wall = right ? scene.right_wall : scene.left_wall;
    if (!wall || !(theta != 0)) continue;
    const WallOutline o = wall_outline(*scene.curve, scene.thickness, *wall, right);
    // Outwards: the left wall counter-clockwise, the right one clockwise, about the outer toe.
    const Eigen::Rotation2Dd turn(right ? -theta : theta);
    const Eigen::Vector2d toe(o.outer_x, o.base_y);
    std::vector<PlanePoint>& turned = stage.walls.emplace_back();
    for (const PlanePoint& c : wall_corners(o)) {
      const Eigen::Vector2d p = toe + turn * (Eigen::Vector2d(c.x, c.y) - toe);
      turned.push_back({p.x(), p.y()});
    }
    stage.right_walls.push_back(right);
  }
}

std::vector<ExtraThrustLine> limit_thrust_lines(const LimitResult& r) {
  std::vector<ExtraThrustLine> lines;
  for (const auto& [state, id, name, colour] :
       {std::tuple{&r.min_state, "thrust-line-min", "minimum", "#1e8449"},
        std::tuple{&r.max_state, "thrust-line-max", "maximum", "#7d3c98"},
        std::tuple{&r.horizontal_state, "thrust-line-horizontal", "collapse", "#d35400"}}) {
    if (!state->found()) continue;
    ExtraThrustLine line;
    line.id = id;
    line.colour = colour;
    line.label = state == &r.horizontal_state
                     ? fmt::format("collapse at a_c = {:.4g} g (limit analysis, rigid voussoirs): {} hinges",
                                   state->load_factor, state->hinges.size())
                     : fmt::format("{} thrust (limit analysis, rigid voussoirs): H/V = {:.4g}, {} hinges", name,
                                   state->H / r.V, state->hinges.size());
    for (const Eigen::Vector2d& c : state->crossing) line.points.push_back({c.x(), c.y()});
    for (const Hinge& h : state->hinges) line.hinges.push_back({h.point.x(), h.point.y()});
    lines.push_back(std::move(line));
  }
  return lines;
}

std::optional<CollapseMechanism> collapse_mechanism(const Scene& scene, const LimitResult& r) {
  const ThrustState& c = r.collapse_state;
  if (!c.found() || c.hinges.size() != 4) return std::nullopt;
  // The displaced blocks are the arch's: a mechanism that turns a wall is drawn by its hinges alone.
  for (const Hinge& h : c.hinges)
    if (h.joint < r.ring.left_springing() || h.joint > r.ring.right_springing()) return std::nullopt;
  CollapseMechanism m;
  for (const Hinge& h : c.hinges) {
    m.hinge_s.push_back(r.ring.joints[static_cast<std::size_t>(h.joint)].s);
    m.hinges.push_back({h.point.x(), h.point.y()});
  }
  // The blocks move so that the load the factor multiplies goes down: the first point load, or the
  // middle of the first live load.
  const Loads& loads = scene.loads;
  m.load_x = !loads.points.empty() ? loads.points.front().at * scene.span()
             : !loads.live.empty() ? 0.5 * (loads.live.front().from + loads.live.front().to) * scene.span()
                                   : 0.5 * scene.span();
  m.label = fmt::format("collapse mechanism at load factor {:.4g} (limit analysis; displacements exaggerated)",
                        c.load_factor);
  return m;
}

void add_limit_analysis(DrawingOptions& drawing, const Scene& scene, const LimitResult& result) {
  drawing.extra_lines = limit_thrust_lines(result);
  if (std::optional<CollapseMechanism> m = collapse_mechanism(scene, result)) drawing.mechanisms.push_back(std::move(*m));
}

// The line drawn through 40 beds of each wall: smooth to the eye at any wall's height.
constexpr int kWallResultantBeds = 40;

void add_wall_resultants(DrawingOptions& drawing, const Scene& scene, const Solution& solution) {
  if (!solution.field) return;
  for (bool right : {false, true}) {
    if (!(right ? scene.right_wall : scene.left_wall)) continue;
    ExtraThrustLine line;
    line.id = right ? "wall-resultant-right" : "wall-resultant-left";
    line.colour = "#c0392b";
    line.label = fmt::format("{} wall: the line of thrust's resultant down the rigid wall", right ? "right" : "left");
    for (const WallBedCrossing& b : wall_resultant(scene, solution.reactions, right, kWallResultantBeds).beds)
      line.points.push_back({b.x, b.y});
    drawing.extra_lines.push_back(std::move(line));
  }
}

}  // namespace ogive
