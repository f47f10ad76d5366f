// An SVG drawing of one scene and its solution, to scale, for people to look at (`ogive draw`).
//
// Coordinates: one SVG user unit is drawing_unit(span) metres (0.1 m for a 10 m arch; the root element
// says it in data-metres-per-unit, and its <desc> in words); a point (x, y) of the arch (x from the left springing,
// y up from the springing line, as in curve.hpp) is drawn at SVG (x, -y) / unit, since SVG's y axis
// points down. So every coordinate in the file times the unit reads back as metres with the sign of y
// flipped; the rendered scale (pixels per unit) is the width attribute over the viewBox width.
//
// What is drawn, with the element ids that scripts and tests can find:
//   #section    the arch's cross-sections, filled (extrados, then intrados back), springing to springing
//   #extrados, #intrados, #axis   the faces at +-t/2 along the section's normal (section_faces of
//               curve.hpp) and the generator curve, sampled at DrawingOptions::samples points over the
//               left half (equal steps of arc length) and mirrored onto the right; at a pointed crown
//               each face ends at the vertical crown joint x = L/2 (cut there, or carried to it along
//               the crown's tangent)
//   #thrust-line-min, #thrust-line-max, ... (DrawingOptions::extra_lines) further lines of thrust, dashed,
//               with their hinges as circles in #thrust-line-min-hinges, ...
//   #thrust-line  the elastic line of thrust: the solution's profile points (thrust_x, thrust_y) in
//               order, one per station; a station with no thrust point (N = 0) or one farther than
//               kFarFromArch spans from the arch starts a new subpath and is not drawn
//   #wall-left, #wall-right   the walls under the springings (Scene::left_wall, right_wall), filled,
//               with the ground under each base hatched (#ground-left, #ground-right); a springing on a
//               wall has no support drawn of its own. The limit analysis' lines (extra_lines) run down
//               through the walls to their bases, with the hinges at the walls' beds; `ogive draw` adds
//               the elastic arch's resultant down each wall as extra lines (#wall-resultant-left, ...).
//   #support-left, #support-right   clamped springings: a line along the springing section, hatched on
//               the side of the support, as engineering drawings show a fixed support
//   #support-movement   when the scene's support displacement d is non-zero: an arrow at each springing
//               in the direction it moves (outwards for d > 0) with the value of d
//   #scale-bar  a bar of a round length in metres with its ticks and labels
//   #fill       each fill of the scene: the region between the extrados and its level, hatched, with its
//               level and density written on it
//   #loads      point loads (N/m) as arrows down onto the top of the fill or the extrados, their length
//               proportional to the force, and live loads (N/m^2) as rows of arrows over their extent,
//               their length proportional to the intensity; the legend says both scales. Beside each
//               point load, when a thrust line is drawn, a note that the line jumps there (the normal
//               force changes under the load, so M / N does).
//               (A horizontal acceleration is drawn above the crown, #horizontal-acceleration.)
//   #cracks     no-tension section: where the resultant leaves the kern, the cracked depth of the
//               section (t times one minus the compressed depth) on the face away from it, shaded
//   #mechanism  DrawingOptions::mechanisms: the collapse mechanism's moving blocks, displaced
//   #spread-stage  DrawingOptions::spread_stages: the rigid voussoirs of the spreading mechanism where
//               they have moved (to scale, not exaggerated), the ring outlined as one piece (a joint
//               that has opened is a notch), with the stage's line of thrust
//               (#spread-stage-thrust-line) and its hinges (#spread-stage-hinges); on walls each leaning
//               wall where it has turned about its base's outer toe (#spread-stage-wall-left, -right)
//   #title      the caption given in DrawingOptions::title wrapped to the page, below it H/V, H and V (or
//               the status and message of an unsolved scene), each springing's support and movement, and
//               the legend (the line of thrust is "elastic" or "cracked-section" after the scene's
//               section)
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ogive/model/scene.hpp"
#include "ogive/core/solution.hpp"
#include "ogive/limit/limit.hpp"
#include "ogive/limit/spreading.hpp"

namespace ogive {

// Thrust-line points farther than this many spans outside the arch's bounding box are not drawn (the
// line runs off to infinity where N changes sign; renderers misbehave on coordinates near 1e300).
inline constexpr double kFarFromArch = 10.0;

// Metres per SVG user unit: the power of ten that makes the span 100 to 1000 units (1e-2 m for spans
// in [1, 10) m, 0.1 m in [10, 100) m), whatever the span. Renderers need it: rsvg draws no text in
// fonts of a tenth of a unit and nothing at all when one unit is a million pixels.
double drawing_unit(double span);

// A further line of thrust drawn beside the elastic one (the limit analysis' minimum and maximum thrust
// states): its points in m (x from the left springing, y up), in order, and its hinges (points on a
// face), each marked with a circle. Drawn as <path id="ID"> and <g id="ID-hinges">.
struct ExtraThrustLine {
  std::string id;                  // element id, e.g. "thrust-line-min"; letters, digits and '-'
  std::string label;               // legend text
  std::string colour = "#1e8449";  // SVG colour
  std::vector<PlanePoint> points;  // m
  std::vector<PlanePoint> hinges;  // m
};

// A collapse mechanism (the limit analysis' collapse state): four hinges in order along the arch split it
// into the blocks that move, each turning about a hinge or about the meeting point of its neighbours'
// lines of hinges (its instantaneous centre). Drawn as #mechanism: each moving block's outline displaced
// (exaggerated to a twentieth of the span at the most), with its hinges. Fewer or more than four hinges
// are not drawn.
struct CollapseMechanism {
  std::vector<double> hinge_s;     // m, arc length of each hinge's joint along the whole arch, ascending
  std::vector<PlanePoint> hinges;  // m, each hinge's point (on a face), in the same order
  double load_x = 0;               // m: the blocks move so that the arch under x = load_x goes down
  std::string label;               // legend text
  std::string colour = "#b9770e";  // SVG colour
};

// A state of the arch of rigid voussoirs on spreading supports (spreading.hpp): the voussoirs where they
// have moved, its line of thrust and its hinges, drawn over the arch at d = 0 to the same scale.
struct SpreadStageDrawing {
  std::vector<std::vector<PlanePoint>> voussoirs;  // m, each voussoir's outline (its four corners)
  std::vector<PlanePoint> thrust_line;              // m, one point per joint
  std::vector<PlanePoint> hinges;                   // m
  std::vector<std::vector<PlanePoint>> walls;       // m, each leaning wall's outline where it has turned
  std::vector<bool> right_walls;                    // for each of walls: the right one (else the left)
  std::string label;                                // legend text
  std::string colour = "#1f618d";                   // SVG colour
};

// The last state of a spreading path (SpreadResult::shape and path.back()), labelled with the span's
// increase (span_increase_ratio, the caller's: the path knows d, not the shares) and H/V; nothing unless
// the result is a success.
std::optional<SpreadStageDrawing> spread_stage_drawing(const SpreadResult& result, double span_increase_ratio);

// A wall's outline (m): the base's inner and outer corners, the top's outer corner, the springing
// joint's extrados and intrados points, the highest bed's inner corner (the wedge under a sloping
// springing joint included).
std::vector<PlanePoint> wall_corners(const WallOutline& wall);

// Into `stage`, each wall of `scene` that leans (a rotation != 0, rad, outwards: the left wall
// counter-clockwise, the right one clockwise) turned as a rigid body about its base's outer toe, as the
// spreading path turns it (spreading.hpp, Walls).
void add_leaning_walls(SpreadStageDrawing& stage, const Scene& scene, double left_rotation, double right_rotation);

struct DrawingOptions {
  std::string title;      // caption, e.g. the scene's parameters; plain text (escaped here), wrapped to the page
                          // at ", "
  std::vector<ExtraThrustLine> extra_lines;  // drawn after the elastic line, each with a legend line
  std::vector<CollapseMechanism> mechanisms;  // drawn over the arch, each with a legend line
  std::vector<SpreadStageDrawing> spread_stages;  // drawn over the arch, each with a legend line
  int samples = 101;      // points of the intrados, extrados and axis over the half arch, in [2, 100000]
  double width_px = 960;  // width of the rendered picture, px, in [16, 100000]; the height follows

  // Ceres-style check: false with the reason in *why (naming the field) when an option is unusable.
  bool is_valid(std::string* why) const;
};

// The limit analysis' minimum and maximum thrust states, and the collapse state of a horizontal
// acceleration where it was computed, as lines to draw, with their hinges and a label that gives H/V
// (a_c for the collapse state) and the number of hinges; a state that was not found is left out.
std::vector<ExtraThrustLine> limit_thrust_lines(const LimitResult& result);

// The collapse mechanism of the limit analysis' collapse state (a live load's), labelled with its load
// factor; none without a collapse state or unless it has four hinges, all in the arch (a mechanism that
// turns a wall is not drawn displaced). `scene` is the analysed one.
std::optional<CollapseMechanism> collapse_mechanism(const Scene& scene, const LimitResult& result);
// The limit analysis into a drawing: its thrust lines (limit_thrust_lines) and its collapse mechanism
// (collapse_mechanism), where there is one. `scene` is the analysed one.
void add_limit_analysis(DrawingOptions& drawing, const Scene& scene, const LimitResult& result);
// The elastic (or cracked-section) arch's resultant carried down each of the scene's rigid walls
// (ogive/core/wall_resultant.hpp), springing to base, as extra lines `wall-resultant-left/right`; none
// without walls or without the solution's field.
void add_wall_resultants(DrawingOptions& drawing, const Scene& scene, const Solution& solution);

// The SVG document (UTF-8 text). The scene must be valid (Scene::validate); the solution is the
// scene's, with or without a profile (without one, or unsolved, no thrust line is drawn and the title
// says why). Throws std::invalid_argument naming the field for invalid options.
std::string arch_svg(const Scene& scene, const Solution& solution, const DrawingOptions& options = {});

}  // namespace ogive
