// The drawing's shared pieces (private to src/output/): the frame it is made to, the outline of the arch,
// and the writers of SVG elements, so that svg.cpp (the arch, the thrust lines, the title) and
// svg_loads.cpp (the loads, the fill, the cracks, the mechanism) draw in one way.
#pragma once

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "ogive/geometry/curve.hpp"
#include "ogive/output/csv.hpp"
#include "ogive/output/svg.hpp"

namespace ogive::svg_draw {

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
inline void number(std::string& out, double v) { append_number(out, v); }

// An SVG point: metres, y flipped (see svg.hpp).
inline void point(std::string& out, PlanePoint p) {
  number(out, p.x);
  out += ',';
  number(out, -p.y);
}

inline void attribute(std::string& out, const char* name, double v) {
  out += fmt::format(" {}=\"", name);
  number(out, v);
  out += '"';
}

inline std::string escaped(const std::string& text) {
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
inline std::string path_data(const std::vector<std::vector<PlanePoint>>& runs) {
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

inline void path(std::string& out, const char* id, const std::vector<std::vector<PlanePoint>>& runs, const char* style) {
  out += fmt::format("<path id=\"{}\" {} d=\"{}\"/>\n", id, style, path_data(runs));
}

inline void line(std::string& out, PlanePoint a, PlanePoint b, const std::string& style) {
  out += "<line";
  attribute(out, "x1", a.x);
  attribute(out, "y1", -a.y);
  attribute(out, "x2", b.x);
  attribute(out, "y2", -b.y);
  out += ' ' + style + "/>\n";
}

// anchor: start, middle or end.
inline void text(std::string& out, PlanePoint at, double size, const char* anchor, const std::string& content) {
  out += "<text";
  attribute(out, "x", at.x);
  attribute(out, "y", -at.y);
  attribute(out, "font-size", size);
  out += fmt::format(" text-anchor=\"{}\" stroke=\"none\">{}</text>\n", anchor, escaped(content));
}

// The sizes the drawing is made to, in drawing units (svg.hpp): the span is 100 to 1000 units, whatever
// its size in metres, so that fonts and strokes are a few units (rsvg draws no text below about 0.1
// unit, nothing at 1e-5).
struct Frame {
  double unit = 1;            // metres per drawing unit
  double L = 0, t = 0;        // span and thickness
  Box box;                    // the arch's outline
  double W = 0;               // the outline's width
  double stroke = 0, font = 0;
  double reach = 0;           // how far a support reaches beyond the section's faces
  PlanePoint at(double x, double y) const { return PlanePoint{x / unit, y / unit}; }
  SectionFaces faces(const SectionFaces& f) const {
    return SectionFaces{at(f.intrados.x, f.intrados.y), at(f.extrados.x, f.extrados.y)};
  }
};

// Hinges as circles of radius `r` (drawing units) in a group `id` with the given style.
inline void hinge_circles(std::string& out, const std::string& id, const std::vector<PlanePoint>& hinges,
                          const Frame& frame, double r, const std::string& style) {
  out += fmt::format("<g id=\"{}\" {}>\n", id, style);
  for (PlanePoint h : hinges) {
    const PlanePoint c = frame.at(h.x, h.y);
    out += "<circle";
    attribute(out, "cx", c.x);
    attribute(out, "cy", -c.y);
    attribute(out, "r", r);
    out += "/>\n";
  }
  out += "</g>\n";
}

// The arch's axis and faces, in drawing units.
struct Outline {
  std::vector<PlanePoint> axis, intrados, extrados;
};

constexpr const char* kLoadColour = "#333333";

// The pieces of svg_loads.cpp; each draws into `body` and grows `drawn` by what it adds.
// The fill: the region between the extrados and each fill's level, hatched, its level marked.
void draw_fills(std::string& body, const Scene& scene, const Outline& outline, const Frame& frame, Box& drawn);
// Point loads and live loads: arrows to one force scale, down onto the top of the fill or extrados,
// each labelled; with a thrust line drawn, a note at each point load that the line jumps there.
// Returns the legend line that states the arrows' scales ("" without loads).
std::string draw_loads(std::string& body, const Scene& scene, const Outline& outline, const Frame& frame, Box& drawn,
                       bool thrust_drawn);
// The cracked zones of a no-tension solution: at each pair of neighbouring cracked stations, the part of
// the section beyond the compressed depth, on the face away from the resultant, shaded.
void draw_cracks(std::string& body, const Scene& scene, const Solution& solution, const Frame& frame);
// The collapse mechanism: the blocks between its four hinges, rotated as the mechanism moves
// (exaggerated), outlined in its colour.
void draw_mechanism(std::string& body, const Scene& scene, const CollapseMechanism& mechanism, const Frame& frame,
                    Box& drawn);
// A spreading stage: its ring where it has moved, outlined in its colour, its thrust line and hinges.
void draw_spread_stage(std::string& body, const SpreadStageDrawing& stage, const Frame& frame, Box& drawn);
// The words of `text` in lines of at most `width` characters, broken after ", " where it can be.
std::vector<std::string> wrap(const std::string& text, std::size_t width);

}  // namespace ogive::svg_draw
