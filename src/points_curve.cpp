// The points curve: a user's axis points fitted by a C2 parametric cubic spline (see curve_families.hpp
// for the file format, the rules and the choice of fit).
#include <algorithm>
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

#include "ogive/curve_families.hpp"

namespace ogive {
namespace {

std::string located(const std::string& file, std::size_t line, const std::string& rule) {
  return line == 0 ? fmt::format("{}: {}", file, rule) : fmt::format("{}:{}: {}", file, line, rule);
}

// ---------------------------------------------------------------------------------------------------
// The spline.

// Second derivatives M_i of the cubic spline through (tau_i, f_i) with a not-a-knot condition at the
// springing (i = 0) and, at the crown (i = n - 1), either f'' = 0 (odd_about_crown: x - x_crown is odd
// about the crown in the mirrored fit) or f' = 0 (even about the crown: y). n >= 4.
std::vector<double> spline_moments(const std::vector<double>& tau, const std::vector<double>& f,
                                   bool odd_about_crown) {
  const std::size_t n = tau.size(), m = n - 1;
  std::vector<double> h(m), d(m);
  for (std::size_t i = 0; i < m; ++i) {
    h[i] = tau[i + 1] - tau[i];
    d[i] = (f[i + 1] - f[i]) / h[i];
  }
  // Tridiagonal system in M_1 .. M_m (row r for unknown M_r): lower[r] M_{r-1} + diag[r] M_r + upper[r] M_{r+1}.
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
  if (odd_about_crown) {
    lower[m] = 0;
    diag[m] = 1;
    rhs[m] = 0;
  } else {
    // f'(tau_m) = d_{m-1} + h_{m-1} (M_{m-1} + 2 M_m) / 6 = 0.
    lower[m] = h[m - 1];
    diag[m] = 2 * h[m - 1];
    rhs[m] = -6 * d[m - 1];
  }
  // Thomas algorithm: the rows are diagonally dominant.
  for (std::size_t r = 2; r <= m; ++r) {
    const double factor = lower[r] / diag[r - 1];
    diag[r] -= factor * upper[r - 1];
    rhs[r] -= factor * rhs[r - 1];
  }
  std::vector<double> M(n, 0.0);
  M[m] = rhs[m] / diag[m];
  for (std::size_t r = m - 1; r >= 1; --r) M[r] = (rhs[r] - upper[r] * M[r + 1]) / diag[r];
  M[0] = ((h[0] + h[1]) * M[1] - h[0] * M[2]) / h[1];
  return M;
}

// Reports a broken rule at a point (its index); must throw.
using Report = std::function<void(std::size_t, const std::string&)>;

class PointsCurve final : public ParametricCurve {
 public:
  // x, y: translated so that the springing is (0, 0); x strictly increasing; at least 4 points; each point
  // at least 1e-9 span from the previous one. A fit that is no arch goes to report (see the header).
  PointsCurve(std::vector<double> x, std::vector<double> y, const Report& report)
      : x_(std::move(x)), y_(std::move(y)) {
    const std::size_t n = x_.size();
    tau_.assign(n, 0.0);
    for (std::size_t i = 1; i < n; ++i) tau_[i] = tau_[i - 1] + std::hypot(x_[i] - x_[i - 1], y_[i] - y_[i - 1]);
    mx_ = spline_moments(tau_, x_, true);
    my_ = spline_moments(tau_, y_, false);
    span_ = 2 * x_.back();
    // Found by fuzzing: a steep last step before the crown, whose tangent the fit makes horizontal, can
    // make the spline stop or turn back just before the crown (theta = pi there, curvature ~1e5 / L), and
    // tabulating its arc length then took minutes. dx/dtau at the crown is about 1 for a sound fit.
    double value = 0, crown_speed = 0, second = 0;
    eval(x_, mx_, n - 2, tau_[n - 1] - tau_[n - 2], 0.0, 1.0, value, crown_speed, second);
    if (!(crown_speed >= 1e-3))
      report(n - 1, fmt::format("the spline through the points stops or turns back at the crown (dx/dtau = {:.3g} "
                                "there, about 1 for a smooth arch): the points are too uneven near the crown",
                                crown_speed));
    try {
      build_arc_length(tau_, 1);
    } catch (const ArcLengthError& e) {
      report(e.piece + 1, "the spline through the points nearly stops (a cusp) between this point and the previous "
                          "one: the points are too uneven there for a smooth fit");
    }
  }
  std::string family() const override { return "points"; }
  double span() const override { return span_; }
  // The interior points: the curvature's derivative jumps there (see the header).
  std::vector<double> breakpoints() const override {
    std::vector<double> out;
    for (std::size_t i = 1; i + 1 < tau_.size(); ++i) out.push_back(arc_length_at_knot(tau_[i]));
    return out;
  }

 protected:
  Jet jet(double t, std::size_t i) const override {
    const double h = tau_[i + 1] - tau_[i];
    const double A = (tau_[i + 1] - t) / h, B = (t - tau_[i]) / h;  // exact 0 and 1 at the knots
    Jet j;
    eval(x_, mx_, i, h, A, B, j.x, j.dx, j.ddx);
    eval(y_, my_, i, h, A, B, j.y, j.dy, j.ddy);
    return j;
  }

 private:
  static void eval(const std::vector<double>& f, const std::vector<double>& M, std::size_t i, double h,
                   double A, double B, double& value, double& first, double& second) {
    value = A * f[i] + B * f[i + 1] + ((A * A - 1) * A * M[i] + (B * B - 1) * B * M[i + 1]) * (h * h / 6);
    first = (f[i + 1] - f[i]) / h + ((1 - 3 * A * A) * M[i] + (3 * B * B - 1) * M[i + 1]) * (h / 6);
    second = A * M[i] + B * M[i + 1];
  }

  std::vector<double> x_, y_, tau_, mx_, my_;
  double span_ = 0;
};

// Checks the points' rules in order; report(index, rule) must throw. Returns the fitted curve.
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

}  // namespace

CurveFileError::CurveFileError(const std::string& file, std::size_t line, const std::string& rule)
    : std::invalid_argument(located(file, line, rule)), file_(file), line_(line), rule_(rule) {}

std::shared_ptr<const Curve> parse_points_curve(std::istream& in, const std::string& name) {
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
         fmt::format("{} point{}, a points curve needs at least {}", points.size(), points.size() == 1 ? "" : "s",
                     kPointsMinCount));
  return fit_points(points, [&](std::size_t index, const std::string& rule) { fail(lines[index], rule); });
}

std::shared_ptr<const Curve> read_points_curve(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw CurveFileError(path, 0, "cannot be read: it is a directory");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open())
    throw CurveFileError(path, 0, fmt::format("cannot be opened ({})", errno != 0 ? std::strerror(errno) : "unknown error"));
  return parse_points_curve(in, path);
}

std::shared_ptr<const Curve> make_points_curve(std::vector<std::pair<double, double>> xy) {
  const std::size_t n = xy.size();
  if (n < kPointsMinCount || n > kPointsMaxCount)
    throw std::invalid_argument(
        fmt::format("points: {} points given, a points curve needs {} to {}", n, kPointsMinCount, kPointsMaxCount));
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(xy[i].first) || !std::isfinite(xy[i].second))
      throw std::invalid_argument(fmt::format("points: point {} (of {}): x and y must be finite, got ({}, {})", i + 1,
                                              n, xy[i].first, xy[i].second));
  return fit_points(xy, [&](std::size_t index, const std::string& rule) {
    throw std::invalid_argument(fmt::format("points: point {} (of {}): {}", index + 1, n, rule));
  });
}

}  // namespace ogive
