#include "ogive/core/thrust_line.hpp"

#include <algorithm>
#include <cmath>

namespace ogive {
namespace {

// One point of the domain (scaled arc length s): its state, the slope M' N - M N' (scaled), whose sign
// is that of d(M/N)/ds, N' (scaled), and the compressive stress's slope (scaled; 0 where it has none).
struct Probe {
  double s = 0;
  ArchState state;
  double slope = 0, dN = 0, stress_slope = 0;
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
    const CompressiveStress stress = compressive_stress(model_.scene().section, N, y[kM], model_.scene().thickness / L);
    return {s, std::move(state), dy[kM] * N - y[kM] * dN, dN, stress.d_N * dN + stress.d_M * dy[kM]};
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

// The largest |e| and compressive stress seen, and whether every normal force seen was a compression
// (and every stress finite).
struct Largest {
  double e = -1, at = 0;
  double stress = -1, stress_at = 0;
  bool compressed = true, bounded = true;
  void see(const ArchState& st) {
    if (!(st.N < 0)) compressed = false;
    else if (std::abs(st.e) > e) {
      e = std::abs(st.e);
      at = st.s;
    }
    if (!(st.compressive_stress >= 0)) bounded = false;
    else if (st.compressive_stress > stress) {
      stress = st.compressive_stress;
      stress_at = st.s;
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

namespace {

// The largest values over the field: the bracketing points' probes, then in each interval between
// neighbours of one piece (a piece's last probe and the next one's first are the two insides apart,
// across a jump) the zeros of `slope` refined (where it changes sign, or with `falls_only` where it
// falls through zero: the maxima), and the largest N where N' falls through zero (a normal force that
// turns tensile between two bracketing points need not change the sign of the slope).
Largest scan_field(const Solution& sol, double Probe::*slope, bool falls_only) {
  const Scan scan(sol);
  const std::vector<Probe> probes = scan.probes(scan.points());
  Largest largest;
  for (const Probe& p : probes) largest.see(p.state);
  // A tensile or vanishing normal force anywhere: nothing is bounded.
  if (!largest.compressed) return largest;
  const double S = sol.model->length();
  const double tol = 1e-9 * (sol.model->half() ? 2 * S : S);
  for (std::size_t i = 0; i + 1 < probes.size(); ++i) {
    const Probe &p = probes[i], &q = probes[i + 1];
    if (q.s - p.s <= 1e-12 * S) continue;
    const bool changes = falls_only ? p.*slope > 0 && q.*slope < 0
                                    : (p.*slope < 0) != (q.*slope < 0) && p.*slope != 0 && q.*slope != 0;
    if (changes) refine(scan, p, q, slope, tol, largest);
    if (p.dN > 0 && q.dN < 0) refine(scan, p, q, &Probe::dN, tol, largest);
  }
  return largest;
}

}  // namespace

ThrustLineSummary summarize_thrust_line(const Solution& sol) {
  ThrustLineSummary out;
  if (!sol.field || !sol.model) return out;
  out.ok = true;
  // The extrema of e where its slope changes sign (maxima of |e| may be minima of e).
  const Largest largest = scan_field(sol, &Probe::slope, false);
  if (!largest.compressed) return out;  // N reached zero somewhere: e unbounded
  out.max_abs_e = largest.e;
  out.max_abs_e_at = largest.at;
  out.in_kern = largest.e <= 100;
  out.in_section = largest.e <= 300;
  return out;
}

StressSummary summarize_compressive_stress(const Solution& sol) {
  StressSummary out;
  if (!sol.field || !sol.model) return out;
  out.ok = true;
  // The stress is smooth on each piece but where M = 0 (a kink of |M|: a minimum) and, for the no-tension
  // section, C1 at the kern's edge: its maxima inside a piece are where its slope falls through zero.
  const Largest largest = scan_field(sol, &Probe::stress_slope, true);
  if (!largest.compressed || !largest.bounded) return out;
  out.max_compressive_stress = largest.stress;
  out.max_compressive_stress_at = largest.stress_at;
  return out;
}

}  // namespace ogive
