// The points curves: a user's axis points fitted by a C2 parametric cubic spline, over the half arch
// (mirrored fit) or the whole arch (see curve_families.hpp for the file format, the rules and the fits).
#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <istream>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "ogive/geometry/curve_families.hpp"

namespace ogive {
namespace {

std::string located(const std::string& file, std::size_t line, const std::string& rule) {
  return line == 0 ? fmt::format("{}: {}", file, rule) : fmt::format("{}:{}: {}", file, line, rule);
}

// ---------------------------------------------------------------------------------------------------
// The spline.

// The condition at the last knot (the first is always not-a-knot).
enum class SplineEnd {
  kZeroSecond,  // f'' = 0: x - x_crown, odd about the crown of the mirrored half fit
  kZeroFirst,   // f' = 0: y, even about the crown of the mirrored half fit
  kNotAKnot,    // the last two pieces are one cubic: the right springing of a whole fit
};

// Second derivatives M_i of the cubic spline through (tau_i, f_i) with a not-a-knot condition at
// i = 0 and the given condition at i = n - 1. n >= 4.
std::vector<double> spline_moments(const std::vector<double>& tau, const std::vector<double>& f, SplineEnd end) {
  const std::size_t n = tau.size(), m = n - 1;
  std::vector<double> h(m), d(m);
  for (std::size_t i = 0; i < m; ++i) {
    h[i] = tau[i + 1] - tau[i];
    d[i] = (f[i + 1] - f[i]) / h[i];
  }
  // Tridiagonal system in M_1 .. M_last (row r for unknown M_r): lower[r] M_{r-1} + diag[r] M_r + upper[r] M_{r+1}.
  std::vector<double> lower(n, 0.0), diag(n, 0.0), upper(n, 0.0), rhs(n, 0.0);
  for (std::size_t i = 1; i < m; ++i) {
    lower[i] = h[i - 1];
    diag[i] = 2 * (h[i - 1] + h[i]);
    upper[i] = h[i];
    rhs[i] = 6 * (d[i] - d[i - 1]);
  }
  // Not-a-knot: M_0 = ((h0 + h1) M_1 - h0 M_2) / h1, substituted into row 1 (multiplied by h1).
  diag[1] = (h[0] + h[1]) * (h[0] + 2 * h[1]);
  upper[1] = (h[1] - h[0]) * (h[1] + h[0]);
  rhs[1] *= h[1];
  lower[1] = 0;
  std::size_t last = m;  // the last unknown of the system
  switch (end) {
    case SplineEnd::kZeroSecond:
      lower[m] = 0;
      diag[m] = 1;
      rhs[m] = 0;
      break;
    case SplineEnd::kZeroFirst:
      // f'(tau_m) = d_{m-1} + h_{m-1} (M_{m-1} + 2 M_m) / 6 = 0.
      lower[m] = h[m - 1];
      diag[m] = 2 * h[m - 1];
      rhs[m] = -6 * d[m - 1];
      break;
    case SplineEnd::kNotAKnot: {
      // The mirror image of the first row: M_m = ((a + b) M_{m-1} - b M_{m-2}) / a (a = h_{m-2},
      // b = h_{m-1}), substituted into row m - 1 (multiplied by a). n >= 4 keeps it apart from row 1.
      const double a = h[m - 2], b = h[m - 1];
      last = m - 1;
      lower[last] = (a - b) * (a + b);
      diag[last] = (a + b) * (2 * a + b);
      rhs[last] *= a;
      upper[last] = 0;
      break;
    }
  }
  // Thomas algorithm: the rows are diagonally dominant (the not-a-knot rows too: (a + b)(a + 2b) > |a^2 - b^2|).
  for (std::size_t r = 2; r <= last; ++r) {
    const double factor = lower[r] / diag[r - 1];
    diag[r] -= factor * upper[r - 1];
    rhs[r] -= factor * rhs[r - 1];
  }
  std::vector<double> M(n, 0.0);
  M[last] = rhs[last] / diag[last];
  for (std::size_t r = last - 1; r >= 1; --r) M[r] = (rhs[r] - upper[r] * M[r + 1]) / diag[r];
  M[0] = ((h[0] + h[1]) * M[1] - h[0] * M[2]) / h[1];
  if (end == SplineEnd::kNotAKnot) M[m] = ((h[m - 2] + h[m - 1]) * M[m - 1] - h[m - 1] * M[m - 2]) / h[m - 2];
  return M;
}

// One coordinate of the spline on piece i (length h) at A = (tau_{i+1} - tau) / h, B = 1 - A: its
// value and its first two tau-derivatives.
void spline_eval(const std::vector<double>& f, const std::vector<double>& M, std::size_t i, double h, double A,
                 double B, double& value, double& first, double& second) {
  value = A * f[i] + B * f[i + 1] + ((A * A - 1) * A * M[i] + (B * B - 1) * B * M[i + 1]) * (h * h / 6);
  first = (f[i + 1] - f[i]) / h + ((1 - 3 * A * A) * M[i] + (3 * B * B - 1) * M[i + 1]) * (h / 6);
  second = A * M[i] + B * M[i + 1];
}

// df/dtau on piece i as a quadratic in B: c[0] + c[1] B + c[2] B^2 (spline_eval's `first` expanded with
// A = 1 - B).
std::array<double, 3> spline_slope_coefficients(const std::vector<double>& f, const std::vector<double>& M,
                                                std::size_t i, double h) {
  return {(f[i + 1] - f[i]) / h - h * (2 * M[i] + M[i + 1]) / 6, h * M[i], 0.5 * h * (M[i + 1] - M[i])};
}

// Reports a broken rule at a point (its index); must throw.
using Report = std::function<void(std::size_t, const std::string&)>;

// The parametric cubic spline x(tau), y(tau) in cumulative chord length tau through the points, not-a-knot
// at the first point, the given conditions at the last. The two curves below differ in those conditions
// and in what their ends mean.
class PointsSpline : public ParametricCurve {
 public:
  // The interior points: the curvature's derivative jumps there (see the header).
  std::vector<double> breakpoints() const override {
    std::vector<double> out;
    for (std::size_t i = 1; i + 1 < tau_.size(); ++i) out.push_back(arc_length_at_knot(tau_[i]));
    return out;
  }

 protected:
  // x, y: translated so that the first point is (0, 0); x strictly increasing; at least 4 points; each
  // point at least 1e-9 span from the previous one.
  PointsSpline(std::vector<double> x, std::vector<double> y, SplineEnd x_end, SplineEnd y_end)
      : x_(std::move(x)), y_(std::move(y)) {
    const std::size_t n = x_.size();
    tau_.assign(n, 0.0);
    for (std::size_t i = 1; i < n; ++i) tau_[i] = tau_[i - 1] + std::hypot(x_[i] - x_[i - 1], y_[i] - y_[i - 1]);
    mx_ = spline_moments(tau_, x_, x_end);
    my_ = spline_moments(tau_, y_, y_end);
  }
  // Tabulates the arc length; a spline that nearly stops somewhere (a cusp) goes to report, naming the
  // point that ends the piece.
  void tabulate(const Report& report) {
    try {
      build_arc_length(tau_, 1);
    } catch (const ArcLengthError& e) {
      report(e.piece + 1, "the spline through the points nearly stops (a cusp) between this point and the previous "
                          "one: the points are too uneven there for a smooth fit");
    }
  }
  Jet jet(double t, std::size_t i) const override {
    const double h = tau_[i + 1] - tau_[i];
    const double A = (tau_[i + 1] - t) / h, B = (t - tau_[i]) / h;  // exact 0 and 1 at the knots
    Jet j;
    spline_eval(x_, mx_, i, h, A, B, j.x, j.dx, j.ddx);
    spline_eval(y_, my_, i, h, A, B, j.y, j.dy, j.ddy);
    return j;
  }

  std::vector<double> x_, y_, tau_, mx_, my_;
};

// The half arch: the points from the springing to the crown, fitted with their mirror image.
class PointsCurve final : public PointsSpline {
 public:
  PointsCurve(std::vector<double> x, std::vector<double> y, const Report& report)
      : PointsSpline(std::move(x), std::move(y), SplineEnd::kZeroSecond, SplineEnd::kZeroFirst), span_(2 * x_.back()) {
    const std::size_t n = x_.size();
    // Found by fuzzing: a steep last step before the crown, whose tangent the fit makes horizontal, can
    // make the spline stop or turn back just before the crown (theta = pi there, curvature ~1e5 / L), and
    // tabulating its arc length then took minutes. dx/dtau at the crown is about 1 for a sound fit.
    double value = 0, crown_speed = 0, second = 0;
    spline_eval(x_, mx_, n - 2, tau_[n - 1] - tau_[n - 2], 0.0, 1.0, value, crown_speed, second);
    if (!(crown_speed >= 1e-3))
      report(n - 1, fmt::format("the spline through the points stops or turns back at the crown (dx/dtau = {:.3g} "
                                "there, about 1 for a smooth arch): the points are too uneven near the crown",
                                crown_speed));
    tabulate(report);
  }
  std::string family() const override { return "points"; }
  double span() const override { return span_; }

 private:
  double span_;
};

// The whole arch: the points from the left springing to the right one, not-a-knot at both.
class WholePointsCurve final : public PointsSpline {
 public:
  WholePointsCurve(std::vector<double> x, std::vector<double> y, const Report& report)
      : PointsSpline(std::move(x), std::move(y), SplineEnd::kNotAKnot, SplineEnd::kNotAKnot) {
    const std::size_t n = x_.size();
    // The points' x increase, but a cubic between them may still turn back (uneven points); x(s) must
    // never decrease (curve.hpp). dx/dtau is a quadratic in each piece: its minimum is at an end or at its
    // vertex.
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const auto [c0, c1, c2] = spline_slope_coefficients(x_, mx_, i, tau_[i + 1] - tau_[i]);
      double lowest = std::min(c0, c0 + c1 + c2);
      if (c2 > 0 && -c1 > 0 && -c1 < 2 * c2) lowest = std::min(lowest, c0 - c1 * c1 / (4 * c2));
      if (!(lowest > 0))
        report(i + 1, fmt::format("the spline folds back between this point and the previous one (dx/dtau = {:.3g}; x "
                                  "must increase along the whole arch): the points are too uneven there, or the "
                                  "tangent too close to vertical",
                                  lowest));
    }
    tabulate(report);
    crown_ = find_crown();
  }
  CurveExtent extent() const override { return CurveExtent::whole; }
  std::string family() const override { return "whole-points"; }
  double span() const override { return x_.back(); }
  double crown() const override { return crown_; }
  double right_springing_height() const override { return y_.back(); }

 private:
  // The arc length of the fit's highest point: the largest y among the knots and the roots of dy/dtau
  // inside the pieces (a quadratic each), a root polished by Newton on dy/dtau.
  double find_crown() const {
    const std::size_t n = x_.size();
    std::size_t best_piece = 0;
    double best_t = 0, best_y = 0;
    const auto consider = [&](std::size_t piece, double t) {
      const Jet j = jet(t, piece);
      if (j.y > best_y) {
        best_y = j.y;
        best_t = t;
        best_piece = piece;
      }
    };
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const double h = tau_[i + 1] - tau_[i];
      consider(i, tau_[i + 1]);
      const auto [c0, c1, c2] = spline_slope_coefficients(y_, my_, i, h);
      // Roots of c0 + c1 B + c2 B^2 in (0, 1), without cancellation (q = -(c1 + sign(c1) sqrt(disc)) / 2).
      std::array<double, 2> roots{-1, -1};
      if (c2 == 0) {
        if (c1 != 0) roots[0] = -c0 / c1;
      } else {
        const double disc = c1 * c1 - 4 * c2 * c0;
        if (disc >= 0) {
          const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
          roots = {q / c2, q != 0 ? c0 / q : -1};
        }
      }
      for (double B : roots)
        if (B > 0 && B < 1) consider(i, tau_[i] + B * h);
    }
    // Newton on dy/dtau = 0 (y'' < 0 at a maximum), kept inside the piece.
    if (best_t > tau_[best_piece] && best_t < tau_[best_piece + 1]) {
      for (int it = 0; it < 8; ++it) {
        const Jet j = jet(best_t, best_piece);
        if (!(j.ddy < 0)) break;
        const double next = std::clamp(best_t - j.dy / j.ddy, tau_[best_piece], tau_[best_piece + 1]);
        if (next == best_t) break;
        best_t = next;
      }
    }
    return at_parameter(best_t).s;
  }

  double crown_ = 0;
};

// Checks the half points' rules in order; report(index, rule) must throw. Returns the fitted curve.
std::shared_ptr<const Curve> fit_points(const std::vector<std::pair<double, double>>& xy, const Report& report) {
  const std::size_t n = xy.size();
  const double span_estimate = 2 * std::abs(xy.back().first - xy.front().first);
  // Found by fuzzing: coordinates near 1e300 overflowed the spline (nan geometry), points 1e-300 apart
  // gave it zero-length pieces. The span bounds the coordinates and the spacing below.
  if (xy.back().first > xy.front().first && !(span_estimate >= kMinSpan && span_estimate <= kMaxSpan))
    report(n - 1, fmt::format("the span 2 (x_crown - x_springing) must lie in [{}, {}] m, got {}", kMinSpan, kMaxSpan,
                              span_estimate));
  const double y0 = xy.front().second;
  if (!(std::abs(y0) <= 1e-9 * span_estimate))
    report(0, fmt::format("the first point is the springing and must lie on the springing line y = 0 "
                          "(|y| <= 1e-9 span), got y = {}",
                          y0));
  for (std::size_t i = 1; i < n; ++i) {
    const auto [x, y] = xy[i];
    const auto [px, py] = xy[i - 1];
    if (x == px && y == py) report(i, fmt::format("repeated point ({}, {}), the same as the previous one", x, y));
    if (!(x > px)) report(i, fmt::format("x must increase from springing to crown ({} after {})", x, px));
    if (!(y > 0))
      report(i, fmt::format("every point after the springing must lie above the springing line y = 0, got y = {}", y));
    if (y < py)
      report(i, fmt::format("y must not fall from springing to crown ({} after {}): the crown is the highest point",
                            y, py));
    if (!(std::hypot(x - px, y - py) >= 1e-9 * span_estimate))
      report(i, fmt::format("the point lies {} m from the previous one, less than 1e-9 of the span",
                            std::hypot(x - px, y - py)));
  }
  if (!(xy.back().second <= 100 * span_estimate))
    report(n - 1, fmt::format("the rise (the crown's y) must be at most 100 spans, got {} for a span of {}",
                              xy.back().second, span_estimate));
  std::vector<double> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = xy[i].first - xy.front().first;
    y[i] = xy[i].second;
  }
  y[0] = 0;
  return std::make_shared<PointsCurve>(std::move(x), std::move(y), report);
}

// Checks the whole points' rules in order; report(index, rule) must throw. Returns the fitted curve.
std::shared_ptr<const Curve> fit_whole_points(const std::vector<std::pair<double, double>>& xy, const Report& report) {
  const std::size_t n = xy.size();
  const auto [x0, y0] = xy.front();
  const double span = xy.back().first - x0;
  // As for the half: the span bounds the coordinates and the spacing (overflow, zero-length pieces).
  if (span > 0 && !(span >= kMinSpan && span <= kMaxSpan))
    report(n - 1, fmt::format("the span x_last - x_first (springing to springing) must lie in [{}, {}] m, got {}",
                              kMinSpan, kMaxSpan, span));
  for (std::size_t i = 1; i < n; ++i) {
    const auto [x, y] = xy[i];
    const auto [px, py] = xy[i - 1];
    if (x == px && y == py) report(i, fmt::format("repeated point ({}, {}), the same as the previous one", x, y));
    if (!(x > px))
      report(i, fmt::format("x must increase from springing to springing ({} after {}): the arch folds back here", x,
                            px));
    if (!(std::hypot(x - px, y - py) >= 1e-9 * span))
      report(i, fmt::format("the point lies {} m from the previous one, less than 1e-9 of the span",
                            std::hypot(x - px, y - py)));
  }
  // Heights above the left springing, bounded before the chord is drawn through them (so that no
  // difference below overflows).
  const double right = xy.back().second - y0;
  if (!(std::abs(right) <= 100 * span))
    report(n - 1, fmt::format("the right springing must lie within 100 spans of the left one's height, got {} for a "
                              "span of {}",
                              right, span));
  std::size_t highest = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (xy[i].second > xy[highest].second) highest = i;
  const double rise = xy[highest].second - y0;
  if (!(rise <= 100 * span))
    report(highest, fmt::format("the rise (the highest point's height above the left springing) must be at most 100 "
                                "spans, got {} for a span of {}",
                                rise, span));
  std::vector<double> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = xy[i].first - x0;
    y[i] = xy[i].second - y0;
  }
  x[0] = y[0] = 0;
  // An arch, not a sag: every interior point strictly above the chord from springing to springing.
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double chord = right * (x[i] / x[n - 1]);
    if (!(y[i] > chord))
      report(i, fmt::format("every point between the springings must lie above the chord joining them: y = {} "
                            "here, the chord's height {} (heights above the left springing)",
                            y[i], chord));
  }
  // And it has a crown: its highest point lies between the springings (found by fuzzing: points that
  // only fall from the left springing, all above the chord, gave a curve of rise 0).
  if (highest == 0 || highest == n - 1)
    report(highest, fmt::format("the highest point is the {} springing: a whole arch rises from both springings to a "
                                "crown between them",
                                highest == 0 ? "left" : "right"));
  return std::make_shared<WholePointsCurve>(std::move(x), std::move(y), report);
}

// ---------------------------------------------------------------------------------------------------
// The file.

enum class LineStatus { kOk, kEnd, kTooLong };

// Reads one line (without its "\n" or "\r\n"); refuses lines longer than the limit without reading on.
LineStatus next_line(std::streambuf& buf, std::string& line) {
  line.clear();
  int c = buf.sbumpc();
  if (c == std::char_traits<char>::eof()) return LineStatus::kEnd;
  while (c != std::char_traits<char>::eof() && c != '\n') {
    line.push_back(static_cast<char>(c));
    if (line.size() > kPointsMaxLineLength + 1) return LineStatus::kTooLong;
    c = buf.sbumpc();
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line.size() > kPointsMaxLineLength ? LineStatus::kTooLong : LineStatus::kOk;
}

std::string_view trim(std::string_view s) {
  const auto space = [](char c) { return c == ' ' || c == '\t'; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

// The text quoted in a message: printable ASCII as is, other bytes as \xNN, at most 40 characters.
std::string quoted(std::string_view text) {
  std::string out = "\"";
  const std::size_t shown = std::min<std::size_t>(text.size(), 40);
  for (std::size_t i = 0; i < shown; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\')
      out.push_back(static_cast<char>(c));
    else
      out += fmt::format("\\x{:02x}", c);
  }
  if (shown < text.size()) out += "...";
  return out + "\"";
}

// Parses one coordinate; returns the rule it breaks, or an empty string.
std::string parse_number(std::string_view field, const char* name, double& value) {
  std::string_view digits = field;
  if (!digits.empty() && digits.front() == '+') {
    digits.remove_prefix(1);  // from_chars takes '-' but not '+'
    if (!digits.empty() && digits.front() == '-') digits = {};
  }
  if (digits.empty()) return fmt::format("{} is not a number: {}", name, quoted(field));
  const char* end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, value, std::chars_format::general);
  if (ec == std::errc::invalid_argument || ptr != end) return fmt::format("{} is not a number: {}", name, quoted(field));
  if (ec == std::errc::result_out_of_range)
    return fmt::format("{} is out of the range of a double: {}", name, quoted(field));
  if (!std::isfinite(value)) return fmt::format("{} must be a finite number, got {}", name, quoted(field));
  return {};
}

bool blank(std::string_view line) { return trim(line).empty(); }

bool is_header(std::string_view line) {
  const auto fields = split_fields(line);
  const auto lower_is = [](std::string_view f, char c) {
    return f.size() == 1 && std::tolower(static_cast<unsigned char>(f[0])) == c;
  };
  return fields.size() == 2 && lower_is(fields[0], 'x') && lower_is(fields[1], 'y');
}

// The fit of one kind of points file (its rules, then the spline).
using Fit = std::shared_ptr<const Curve> (*)(const std::vector<std::pair<double, double>>&, const Report&);

// Reads a points file of either kind (one syntax: see the header) and fits it; `family` names the curve
// in the count's message.
std::shared_ptr<const Curve> parse_points_file(std::istream& in, const std::string& name, std::string_view family,
                                               Fit fit) {
  const auto fail = [&](std::size_t line, const std::string& rule) { throw CurveFileError(name, line, rule); };
  if (!in || in.rdbuf() == nullptr) fail(0, "cannot be read");
  std::streambuf& buf = *in.rdbuf();
  std::vector<std::pair<double, double>> points;
  std::vector<std::size_t> lines;  // the line of each point
  std::string line;
  std::size_t line_no = 0, first_blank = 0;
  bool header_seen = false;
  for (;;) {
    const LineStatus status = next_line(buf, line);
    if (status == LineStatus::kEnd) break;
    ++line_no;
    if (status == LineStatus::kTooLong)
      fail(line_no, fmt::format("line longer than {} characters", kPointsMaxLineLength));
    std::string_view text = line;
    if (line_no == 1 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte-order mark
    if (blank(text)) {
      if (first_blank == 0) first_blank = line_no;
      continue;
    }
    if (first_blank != 0)
      fail(first_blank, header_seen ? "blank line inside the data (only trailing blank lines are allowed)"
                                    : "expected the header x,y, got a blank line");
    if (!header_seen) {
      if (!is_header(text)) fail(line_no, fmt::format("the header must be x,y, got {}", quoted(text)));
      header_seen = true;
      continue;
    }
    const auto fields = split_fields(text);
    if (fields.size() != 2) fail(line_no, fmt::format("expected 2 fields x,y, got {}", fields.size()));
    double x = 0, y = 0;
    if (std::string rule = parse_number(fields[0], "x", x); !rule.empty()) fail(line_no, rule);
    if (std::string rule = parse_number(fields[1], "y", y); !rule.empty()) fail(line_no, rule);
    if (points.size() == kPointsMaxCount) fail(line_no, fmt::format("more than {} points", kPointsMaxCount));
    points.emplace_back(x, y);
    lines.push_back(line_no);
  }
  if (in.bad()) fail(0, "read error");
  if (!header_seen) fail(1, "empty file: expected the header x,y");
  if (points.size() < kPointsMinCount)
    fail(points.empty() ? 1 : lines.back(),
         fmt::format("{} point{}, a {} curve needs at least {}", points.size(), points.size() == 1 ? "" : "s", family,
                     kPointsMinCount));
  return fit(points, [&](std::size_t index, const std::string& rule) { fail(lines[index], rule); });
}

// Opens a points file for parse (a directory or a file that cannot be opened is a CurveFileError at line 0).
using Parse = std::shared_ptr<const Curve> (*)(std::istream&, const std::string&);
std::shared_ptr<const Curve> read_points_file(const std::string& path, Parse parse) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw CurveFileError(path, 0, "cannot be read: it is a directory");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open())
    throw CurveFileError(path, 0, fmt::format("cannot be opened ({})", errno != 0 ? std::strerror(errno) : "unknown error"));
  return parse(in, path);
}

// Points given directly: the count and finiteness, then the fit's rules, as "points: point K (of N): rule".
std::shared_ptr<const Curve> make_from_points(const std::vector<std::pair<double, double>>& xy,
                                              std::string_view family, Fit fit) {
  const std::size_t n = xy.size();
  if (n < kPointsMinCount || n > kPointsMaxCount)
    throw std::invalid_argument(
        fmt::format("points: {} points given, a {} curve needs {} to {}", n, family, kPointsMinCount, kPointsMaxCount));
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(xy[i].first) || !std::isfinite(xy[i].second))
      throw std::invalid_argument(fmt::format("points: point {} (of {}): x and y must be finite, got ({}, {})", i + 1,
                                              n, xy[i].first, xy[i].second));
  return fit(xy, [&](std::size_t index, const std::string& rule) {
    throw std::invalid_argument(fmt::format("points: point {} (of {}): {}", index + 1, n, rule));
  });
}

}  // namespace

CurveFileError::CurveFileError(const std::string& file, std::size_t line, const std::string& rule)
    : std::invalid_argument(located(file, line, rule)), file_(file), line_(line), rule_(rule) {}

std::shared_ptr<const Curve> parse_points_curve(std::istream& in, const std::string& name) {
  return parse_points_file(in, name, "points", fit_points);
}

std::shared_ptr<const Curve> read_points_curve(const std::string& path) {
  return read_points_file(path, parse_points_curve);
}

std::shared_ptr<const Curve> make_points_curve(std::vector<std::pair<double, double>> xy) {
  return make_from_points(xy, "points", fit_points);
}

std::shared_ptr<const Curve> parse_whole_points_curve(std::istream& in, const std::string& name) {
  return parse_points_file(in, name, "whole-points", fit_whole_points);
}

std::shared_ptr<const Curve> read_whole_points_curve(const std::string& path) {
  return read_points_file(path, parse_whole_points_curve);
}

std::shared_ptr<const Curve> make_whole_points_curve(std::vector<std::pair<double, double>> xy) {
  return make_from_points(xy, "whole-points", fit_whole_points);
}

}  // namespace ogive
