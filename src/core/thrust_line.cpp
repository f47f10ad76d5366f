#include "ogive/core/thrust_line.hpp"

#include <algorithm>
#include <cmath>

namespace ogive {
namespace {

// One point of the domain (scaled arc length s): its state, the slope M' N - M N' (scaled), whose sign
// is that of d(M/N)/ds, and N' (scaled).
struct Probe {
  double s = 0;
  ArchState state;
  double slope = 0, dN = 0;
};

// The field's smooth pieces and their probes.
class Scan {
 public:
  explicit Scan(const Solution& sol) : sol_(sol), model_(*sol.model) {}

  // The bracketing points of every piece, ascending: a piece's ends are taken just inside it (1e-13 of
  // the domain's length: each side's own limit, not the neighbour's, where the state or the tangent
  // jumps), but for the domain's own ends.
  std::vector<double> points() const {
    const double S = model_.length();
    std::vector<double> knots{0.0};
    for (double b : model_.breakpoints())
      if (b > 0 && b < S && b > knots.back()) knots.push_back(b);
    knots.push_back(S);
    const double inside = 1e-13 * S;
    std::vector<double> out;
    for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
      const double a = k == 0 ? knots[k] : knots[k] + inside;
      const double b = k + 2 == knots.size() ? knots[k + 1] : knots[k + 1] - inside;
      const double turn = std::abs(model_.theta(b) - model_.theta(a));
      const int n = std::max(kScanIntervals, static_cast<int>(std::ceil(turn / kScanTurn)));
      out.push_back(a);
      for (int i = 1; i < n; ++i) out.push_back(a + (b - a) * i / n);
      out.push_back(b);
    }
    return out;
  }

  Probe probe(double s, const StateVector& y) const {
    const double L = model_.scales().length;
    ArchState state = model_.to_physical(s, y);
    const double c = std::cos(state.theta), sn = std::sin(state.theta);
    StateVector dy;
    if (model_.curved())
      model_.curved_derivative(c, sn, model_.curved_bar(model_.kappa(s)), y.data(), dy.data(), model_.load(s),
                               model_.horizontal_load(s), true);
    else
      model_.derivative(c, sn, y.data(), dy.data(), model_.load(s), model_.horizontal_load(s));
    const double N = c * y[kFx] + sn * y[kFy], V = -sn * y[kFx] + c * y[kFy];
    const double dN = c * dy[kFx] + sn * dy[kFy] + curvature(s * L) * L * V;
    return {s, std::move(state), dy[kM] * N - y[kM] * dN, dN};
  }

  // 1/m at arc length x (m, inside a piece): a circular arc's own constant, read without evaluating the
  // curve's point there (the ArchState has done that once).
  double curvature(double x) const {
    const auto arcs = model_.curve().arcs();
    return arcs.empty() ? model_.curve().at(x).kappa : arc_at(arcs, x).kappa;
  }

  Probe probe(double s) const {
    StateVector y;
    sol_.field->sample(std::span<const double>(&s, 1), std::span<StateVector>(&y, 1));
    return probe(s, y);
  }

  std::vector<Probe> probes(const std::vector<double>& s) const {
    std::vector<StateVector> y(s.size());
    sol_.field->sample(s, y);
    std::vector<Probe> out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) out.push_back(probe(s[i], y[i]));
    return out;
  }

 private:
  const Solution& sol_;
  const ArchModel& model_;
};

// The largest |e| seen, and whether every normal force seen was a compression.
struct Largest {
  double e = -1, at = 0;
  bool compressed = true;
  void see(const ArchState& st) {
    if (!(st.N < 0)) compressed = false;
    else if (std::abs(st.e) > e) {
      e = std::abs(st.e);
      at = st.s;
    }
  }
};

// The zero of f (the slope, or N') between two probes where it has opposite signs, to `tol` in s: Brent's
// method (inverse quadratic interpolation or the secant where it steps well inside the bracket, else
// bisection). Every probe is seen by `largest`.
void refine(const Scan& scan, const Probe& lo, const Probe& hi, double Probe::*f, double tol, Largest& largest) {
  double a = lo.s, b = hi.s, fa = lo.*f, fb = hi.*f;
  double c = a, fc = fa, d = b - a, e = d;
  for (int iteration = 0; iteration < 100 && largest.compressed; ++iteration) {
    if ((fb > 0) == (fc > 0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double half = 0.5 * (c - b);
    if (std::abs(half) <= 0.5 * tol || fb == 0) return;
    if (std::abs(e) >= 0.5 * tol && std::abs(fa) > std::abs(fb)) {
      const double r = fb / fa;
      double p, q;
      if (a == c) {
        p = 2 * half * r;
        q = 1 - r;
      } else {
        const double qa = fa / fc, rb = fb / fc;
        p = r * (2 * half * qa * (qa - rb) - (b - a) * (rb - 1));
        q = (qa - 1) * (rb - 1) * (r - 1);
      }
      if (p > 0) q = -q;
      p = std::abs(p);
      if (2 * p < std::min(3 * half * q - std::abs(0.5 * tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = e = half;
      }
    } else {
      d = e = half;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > 0.5 * tol ? d : std::copysign(0.5 * tol, half);
    const Probe q = scan.probe(b);
    largest.see(q.state);
    fb = q.*f;
  }
}

}  // namespace

std::vector<ArchState> field_scan(const Solution& sol) {
  std::vector<ArchState> out;
  if (!sol.field || !sol.model) return out;
  const Scan scan(sol);
  for (const Probe& p : scan.probes(scan.points())) out.push_back(p.state);
  return out;
}

ThrustLineSummary summarize_thrust_line(const Solution& sol) {
  ThrustLineSummary out;
  if (!sol.field || !sol.model) return out;
  out.ok = true;
  const Scan scan(sol);
  const std::vector<Probe> probes = scan.probes(scan.points());
  Largest largest;
  for (const Probe& p : probes) largest.see(p.state);
  // A tensile or vanishing normal force anywhere: the eccentricity has no bound, and the line of thrust
  // is neither in the kern nor in the section.
  if (!largest.compressed) return out;
  const double S = sol.model->length();
  const double tol = 1e-9 * (sol.model->half() ? 2 * S : S);
  // Each interval between neighbours of one piece (a piece's last probe and the next one's first are
  // the two insides apart, across a jump): the extrema of e where the slope changes sign, and the largest
  // N where N' falls through zero (a normal force that turns tensile between two bracketing points need
  // not change the sign of e's slope).
  for (std::size_t i = 0; i + 1 < probes.size(); ++i) {
    const Probe &p = probes[i], &q = probes[i + 1];
    if (q.s - p.s <= 1e-12 * S) continue;
    if ((p.slope < 0) != (q.slope < 0) && p.slope != 0 && q.slope != 0)
      refine(scan, p, q, &Probe::slope, tol, largest);
    if (p.dN > 0 && q.dN < 0) refine(scan, p, q, &Probe::dN, tol, largest);
  }
  if (!largest.compressed) return out;  // N reached zero between the bracketing points
  out.max_abs_e = largest.e;
  out.max_abs_e_at = largest.at;
  out.in_kern = largest.e <= 100;
  out.in_section = largest.e <= 300;
  return out;
}

}  // namespace ogive
