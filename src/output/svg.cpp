#include "ogive/output/svg.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include "ogive/output/csv.hpp"

namespace ogive {
namespace {

constexpr const char* kThrustColour = "#c0392b";

struct Box {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
  double x1 = -x0, y1 = -x0;
  void add(PlanePoint p) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  double width() const { return x1 - x0; }
  bool contains(PlanePoint p, double margin) const {
    return p.x >= x0 - margin && p.x <= x1 + margin && p.y >= y0 - margin && p.y <= y1 + margin;
  }
};

// Every number in the file in its shortest round-trip form (csv.hpp), so that the drawn coordinates
// are exactly the computed ones.
void number(std::string& out, double v) { append_number(out, v); }

// An SVG point: metres, y flipped (see svg.hpp).
void point(std::string& out, PlanePoint p) {
  number(out, p.x);
  out += ',';
  number(out, -p.y);
}

void attribute(std::string& out, const char* name, double v) {
  out += fmt::format(" {}=\"", name);
  number(out, v);
  out += '"';
}

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else if (static_cast<unsigned char>(c) < 0x20) out += ' ';  // control characters are not XML
    else out += c;
  }
  return out;
}

// "M p0 L p1 L p2 ...": one subpath per run of points, a new one after each gap.
std::string path_data(const std::vector<std::vector<PlanePoint>>& runs) {
  std::string d;
  for (const auto& run : runs) {
    for (std::size_t k = 0; k < run.size(); ++k) {
      if (!d.empty()) d += ' ';
      d += k == 0 ? "M " : "L ";
      point(d, run[k]);
    }
  }
  return d;
}

void path(std::string& out, const char* id, const std::vector<std::vector<PlanePoint>>& runs, const char* style) {
  out += fmt::format("<path id=\"{}\" {} d=\"{}\"/>\n", id, style, path_data(runs));
}

void line(std::string& out, PlanePoint a, PlanePoint b, const std::string& style) {
  out += "<line";
  attribute(out, "x1", a.x);
  attribute(out, "y1", -a.y);
  attribute(out, "x2", b.x);
  attribute(out, "y2", -b.y);
  out += ' ' + style + "/>\n";
}

// anchor: start, middle or end.
void text(std::string& out, PlanePoint at, double size, const char* anchor, const std::string& content) {
  out += "<text";
  attribute(out, "x", at.x);
  attribute(out, "y", -at.y);
  attribute(out, "font-size", size);
  out += fmt::format(" text-anchor=\"{}\" stroke=\"none\">{}</text>\n", anchor, escaped(content));
}

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
  const Curve& curve = *scene.curve;
  const double S = curve.length();
  // The drawing's unit (svg.hpp): the span is 100 to 1000 units, whatever its size in metres, so that
  // fonts and strokes are a few units (rsvg draws no text below about 0.1 unit, nothing at 1e-5).
  const double unit = drawing_unit(scene.span());
  auto drawn_at = [unit](double x, double y) { return PlanePoint{x / unit, y / unit}; };
  auto to_drawing = [&](PlanePoint p) { return drawn_at(p.x, p.y); };
  auto faces_in_drawing = [&](const SectionFaces& f) { return SectionFaces{to_drawing(f.intrados), to_drawing(f.extrados)}; };
  // From here on, lengths are in drawing units.
  const double L = scene.span() / unit, t = scene.thickness / unit;

  // The arch: axis and faces at equal steps of arc length over the left half, mirrored onto the right.
  // At a pointed crown the two halves' sections differ (their tangents do), so each face is cut at, or
  // carried along its crown tangent to, the crown's vertical joint x = L/2, as the voussoirs meet there.
  std::vector<PlanePoint> axis, intrados, extrados;
  const CurvePoint crown = curve.at(S);
  const bool whole = curve.extent() == CurveExtent::whole;  // a whole arch (a survey): drawn as it is
  if (whole)
    for (int k = 0; k < 2 * options.samples - 1; ++k) {
      const CurvePoint p = curve.at(k == 2 * options.samples - 2 ? S : S * k / (2 * options.samples - 2));
      const SectionFaces f = faces_in_drawing(section_faces(p, scene.thickness));
      axis.push_back(drawn_at(p.x, p.y));
      intrados.push_back(f.intrados);
      extrados.push_back(f.extrados);
    }
  for (int k = 0; k < options.samples && !whole; ++k) {
    const CurvePoint p = curve.at(k == options.samples - 1 ? S : S * k / (options.samples - 1));
    const SectionFaces f = faces_in_drawing(section_faces(p, scene.thickness));
    axis.push_back(drawn_at(p.x, p.y));
    intrados.push_back(f.intrados);
    extrados.push_back(f.extrados);
  }
  for (std::vector<PlanePoint>* face : {&intrados, &extrados}) {
    if (whole) break;
    std::vector<PlanePoint>& v = *face;
    const double joint = 0.5 * L;
    if (v.back().x < joint) {  // short of the joint: along the crown's tangent
      const double along = (joint - v.back().x) / std::cos(crown.theta);
      v.push_back({joint, v.back().y + along * std::sin(crown.theta)});
    } else if (v.back().x > joint) {  // past it: cut where the polyline crosses it
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
  for (std::vector<PlanePoint>* line : {&axis, &intrados, &extrados}) {
    if (whole) break;
    std::vector<PlanePoint>& v = *line;
    for (std::size_t k = v.size() - 1; k-- > 0;) v.push_back({L - v[k].x, v[k].y});
  }
  Box box;
  for (const auto* line : {&axis, &intrados, &extrados})
    for (PlanePoint p : *line) box.add(p);
  const double W = box.width();
  const double stroke = 0.002 * W;
  const double font = 0.022 * W;

  // Supports: the springing sections, the side of the support beyond each end of the axis.
  const CurvePoint left = curve.at_whole_arch(0), right = curve.at_whole_arch(curve.whole_length());
  const SectionFaces left_faces = faces_in_drawing(section_faces(left, scene.thickness));
  const SectionFaces right_faces = faces_in_drawing(section_faces(right, scene.thickness));
  const PlanePoint left_away{-std::cos(left.theta), -std::sin(left.theta)};
  const PlanePoint right_away{std::cos(right.theta), std::sin(right.theta)};
  const double reach = 0.3 * std::max(t, 0.05 * L);
  std::string supports;
  for (const auto& [kind, id, faces, away] :
       {std::tuple{scene.left.kind, "support-left", left_faces, left_away},
        std::tuple{scene.right.kind, "support-right", right_faces, right_away}}) {
    if (kind == SupportKind::clamped) clamped_support(supports, id, faces, away, reach, stroke);
    else pinned_support(supports, id, faces, away, reach, stroke);
  }
  Box drawn = box;
  for (const SectionFaces& f : {left_faces, right_faces})
    for (PlanePoint p : {f.intrados, f.extrados}) {
      drawn.add({p.x, p.y - 1.5 * reach});
      drawn.add({p.x, p.y + 1.5 * reach});
    }

  // The thrust line: runs of drawable stations.
  std::vector<std::vector<PlanePoint>> thrust(1);
  for (const ArchState& st : solution.profile) {
    const PlanePoint p = drawn_at(st.thrust_x, st.thrust_y);
    if (std::isfinite(p.x) && std::isfinite(p.y) && box.contains(p, kFarFromArch * L)) {
      thrust.back().push_back(p);
      // The view follows the line a little way out of the arch, no farther.
      drawn.add({std::clamp(p.x, box.x0 - 0.25 * W, box.x1 + 0.25 * W), std::clamp(p.y, box.y0 - 0.25 * W, box.y1 + 0.25 * W)});
    } else if (!thrust.back().empty()) {
      thrust.emplace_back();
    }
  }
  if (thrust.back().empty()) thrust.pop_back();

  std::string body;
  body += "<path id=\"section\" fill=\"#e8e0d0\" stroke=\"none\" d=\"";
  {
    std::vector<PlanePoint> outline = extrados;
    outline.insert(outline.end(), intrados.rbegin(), intrados.rend());
    body += path_data({outline}) + " Z\"/>\n";
  }
  const std::string face_style = fmt::format("fill=\"none\" stroke=\"black\" stroke-width=\"{}\"", stroke);
  path(body, "extrados", {extrados}, face_style.c_str());
  path(body, "intrados", {intrados}, face_style.c_str());
  const std::string axis_style = fmt::format(
      "fill=\"none\" stroke=\"#555555\" stroke-width=\"{}\" stroke-dasharray=\"{},{}\"", stroke, 6 * stroke, 3 * stroke);
  path(body, "axis", {axis}, axis_style.c_str());
  const std::string thrust_style =
      fmt::format("fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"", kThrustColour, 1.5 * stroke);
  if (!thrust.empty()) {
    // Clipped to the arch's surroundings (where the view follows it), so that a line that runs off
    // stays clear of the title, the arrows and the scale bar; its points are all in the path.
    body += "<clipPath id=\"near-the-arch\"><rect";
    for (const auto& [name, v] : {std::pair{"x", drawn.x0}, std::pair{"y", -drawn.y1}, std::pair{"width", drawn.x1 - drawn.x0},
                                  std::pair{"height", drawn.y1 - drawn.y0}})
      attribute(body, name, v);
    body += "/></clipPath>\n";
    path(body, "thrust-line", thrust, (thrust_style + " clip-path=\"url(#near-the-arch)\"").c_str());
  }
  // Further lines of thrust (limit states): dashed, their hinges circled.
  for (const ExtraThrustLine& extra : options.extra_lines) {
    std::vector<PlanePoint> points;
    for (PlanePoint p : extra.points) points.push_back(drawn_at(p.x, p.y));
    if (!points.empty())
      path(body, extra.id.c_str(), {points},
           fmt::format("fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" stroke-dasharray=\"{},{}\"", extra.colour,
                       1.2 * stroke, 4 * stroke, 2 * stroke)
               .c_str());
    body += fmt::format("<g id=\"{}-hinges\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\">\n", extra.id, extra.colour,
                        stroke);
    for (PlanePoint h : extra.hinges) {
      const PlanePoint c = drawn_at(h.x, h.y);
      body += "<circle";
      attribute(body, "cx", c.x);
      attribute(body, "cy", -c.y);
      attribute(body, "r", 0.6 * font);
      body += "/>\n";
    }
    body += "</g>\n";
  }
  body += supports;
  if (scene.crown_hinge) {  // the hinge: a pin at the crown's axis point
    const PlanePoint c = to_drawing({curve.at(curve.crown()).x, curve.at(curve.crown()).y});
    body += fmt::format("<circle id=\"crown-hinge\" cx=\"{}\" cy=\"{}\" r=\"{}\" stroke=\"black\" stroke-width=\"{}\" "
                        "fill=\"white\"/>\n",
                        c.x, -c.y, 0.4 * reach, 1.5 * stroke);
  }

  // Support movement: each springing's horizontal spread, outwards for d > 0.
  double bottom = drawn.y0;
  if (scene.left.spread != 0 || scene.right.spread != 0) {
    const double y = bottom - 1.2 * font, length = 0.08 * W;
    body += "<g id=\"support-movement\" stroke=\"#1f4e9c\" fill=\"#1f4e9c\">\n";
    for (const auto& [x, outward, d] : {std::tuple{left.x / unit, -1.0, scene.left.spread},
                                        std::tuple{right.x / unit, 1.0, scene.right.spread}}) {
      if (d == 0) continue;
      const double sign = d > 0 ? 1.0 : -1.0;
      const std::string label = fmt::format("d = {:.3g} mm {}", std::abs(d) * 1000, d > 0 ? "outwards" : "inwards");
      line(body, {x, y}, {x + sign * outward * length, y},
           fmt::format("stroke-width=\"{}\" marker-end=\"url(#arrowhead)\"", 1.5 * stroke));
      // The label below the arrow, towards the arch so that it stays in the picture.
      text(body, {x - outward * 0.5 * font, y - 1.3 * font}, 0.8 * font, outward < 0 ? "start" : "end", label);
      drawn.add({x + outward * (length + font), y});
    }
    body += "</g>\n";
    bottom = y - 1.6 * font;
  }

  // Scale bar: a round length near a quarter of the arch's width, ticks at its ends and middle.
  {
    const double length = round_length(0.25 * W);
    const double y = bottom - 1.5 * font, x = box.x0, tick = 0.4 * font;
    body += "<g id=\"scale-bar\" stroke=\"black\" fill=\"black\">\n";
    line(body, {x, y}, {x + length, y}, fmt::format("stroke-width=\"{}\"", stroke));
    for (double f : {0.0, 0.5, 1.0}) line(body, {x + f * length, y}, {x + f * length, y + tick}, fmt::format("stroke-width=\"{}\"", stroke));
    text(body, {x, y - 1.1 * font}, 0.8 * font, "middle", "0");
    text(body, {x + 0.5 * length, y - 1.1 * font}, 0.8 * font, "middle", fmt::format("{:g}", 0.5 * length * unit));
    text(body, {x + length, y - 1.1 * font}, 0.8 * font, "middle", fmt::format("{:g} m", length * unit));
    body += "</g>\n";
    bottom = y - 1.6 * font;
  }

  // Title: the caption, then the reactions (or why there are none), then a legend.
  const double title_y = drawn.y1 + (4.2 + 1.3 * static_cast<double>(options.extra_lines.size())) * font;
  std::string result;
  if (std::isfinite(solution.H_over_V))
    result = fmt::format("H/V = {:.6g}, H = {:.4g} kN/m, V = {:.4g} kN/m ({}, {})", solution.H_over_V, solution.H / 1000,
                         solution.V / 1000, to_string(solution.method), to_string(solution.status));
  else
    result = fmt::format("no solution: {}{}{}", to_string(solution.status), solution.message.empty() ? "" : ": ",
                         solution.message);
  std::string title = "<g id=\"title\" fill=\"black\">\n";
  text(title, {box.x0, title_y}, font, "start", options.title);
  text(title, {box.x0, title_y - 1.4 * font}, 0.85 * font, "start", result);
  const double legend_y = title_y - 2.6 * font;
  line(title, {box.x0, legend_y + 0.3 * font}, {box.x0 + 2 * font, legend_y + 0.3 * font}, thrust_style);
  text(title, {box.x0 + 2.5 * font, legend_y}, 0.8 * font, "start", "elastic line of thrust");
  line(title, {box.x0 + 14 * font, legend_y + 0.3 * font}, {box.x0 + 16 * font, legend_y + 0.3 * font}, axis_style);
  text(title, {box.x0 + 16.5 * font, legend_y}, 0.8 * font, "start",
       fmt::format("axis; section t = {:g} m; springings {}, {}", scene.thickness,
                   scene.left.kind == SupportKind::clamped ? "clamped" : "pinned",
                   scene.right.kind == SupportKind::clamped ? "clamped" : "pinned"));
  for (std::size_t k = 0; k < options.extra_lines.size(); ++k) {
    const ExtraThrustLine& extra = options.extra_lines[k];
    const double y = legend_y - 1.3 * font * static_cast<double>(k + 1);
    line(title, {box.x0, y + 0.3 * font}, {box.x0 + 2 * font, y + 0.3 * font},
         fmt::format("stroke=\"{}\" stroke-width=\"{}\" stroke-dasharray=\"{},{}\"", extra.colour, 1.2 * stroke,
                     4 * stroke, 2 * stroke));
    text(title, {box.x0 + 2.5 * font, y}, 0.8 * font, "start", extra.label);
  }
  title += "</g>\n";

  // The view: everything drawn, the title's width (about 40 font sizes) and a margin.
  const double margin = 1.5 * font;
  const double vx = drawn.x0 - margin, vy = -(title_y + font) - margin;
  const double vw = std::max(drawn.x1, box.x0 + 40 * font) + margin - vx;
  const double vh = -(bottom - font) + margin - vy;
  std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"";
  attribute(svg, "width", options.width_px);
  attribute(svg, "height", std::round(options.width_px * vh / vw));
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
         "markerHeight=\"4\" orient=\"auto\"><path d=\"M 0 0 L 10 5 L 0 10 Z\" fill=\"#1f4e9c\"/></marker></defs>\n";
  svg += "<rect";
  for (const auto& [name, v] : {std::pair{"x", vx}, std::pair{"y", vy}, std::pair{"width", vw}, std::pair{"height", vh}})
    attribute(svg, name, v);
  svg += " fill=\"white\"/>\n";
  svg += body + title + "</svg>\n";
  return svg;
}

}  // namespace ogive
