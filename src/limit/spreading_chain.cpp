// The chain of rigid voussoirs of the spreading path (spreading_chain.hpp).
#include "limit/spreading_chain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/SVD>

#include "limit/limit_internal.hpp"
#include "ogive/limit/spreading.hpp"

namespace ogive::spreading_detail {

VerticalLoad moved_load(const VerticalLoad& l, const Rigid& m) {
  if (l.force == 0) return l;
  const Vec p = m(load_point(l));
  return {l.force, l.force * p.x(), l.force * p.y()};
}

void place_ring(const Ring& ring0, const Placement& at, Ring& ring) {
  ring = ring0;
  const std::size_t n = ring0.voussoirs.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Rigid& m = at.voussoir[k];
    Voussoir& v = ring.voussoirs[k];
    v.centroid = m(ring0.voussoirs[k].centroid);
    v.fill = moved_load(ring0.voussoirs[k].fill, m);
    v.live = moved_load(ring0.voussoirs[k].live, m);
  }
  for (std::size_t j = 0; j <= n; ++j) {
    const Rigid& a = j == 0 ? at.left : at.voussoir[j - 1];
    const Rigid& b = j == n ? at.right : at.voussoir[j];
    const Joint& j0 = ring0.joints[j];
    Joint& jt = ring.joints[j];
    jt.intrados = 0.5 * (a(j0.intrados) + b(j0.intrados));
    jt.extrados = 0.5 * (a(j0.extrados) + b(j0.extrados));
    jt.axis = 0.5 * (a(j0.axis) + b(j0.axis));
  }
}

double opening_sign(const Ring& ring, const Hinge& h) {
  if (h.face == Face::axis) return 0;
  const Joint& jt = ring.joints[static_cast<std::size_t>(h.joint)];
  const Vec q = h.face == Face::intrados ? jt.extrados : jt.intrados;
  const Vec e = jt.extrados - jt.intrados;
  Vec normal(e.y(), -e.x());  // oriented below towards the voussoir after the joint
  const std::size_t n = ring.voussoirs.size();
  const bool last = static_cast<std::size_t>(h.joint) >= n;  // the right springing: none after it
  const Vec c = ring.voussoirs[last ? n - 1 : static_cast<std::size_t>(h.joint)].centroid;
  if (normal.dot(c - jt.axis) < 0) normal = -normal;
  if (last) normal = -normal;
  return perp(q - h.point).dot(normal) >= 0 ? 1.0 : -1.0;
}

bool min_norm_solve(const Eigen::MatrixXd& J, const Eigen::Vector3d& r, Eigen::VectorXd& x) {
  if (J.cols() < 3) return false;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const auto& s = svd.singularValues();
  if (!(s(2) > 1e-10 * s(0))) return false;
  x = svd.solve(r);
  return true;
}

Eigen::Vector3d closure_column(const Vec& at, const Vec& q) {
  const Vec v = perp(at - q);
  return {1.0, v.x(), v.y()};
}

Mechanism choose_mechanism(const Ring& ring, std::vector<Hinge> hinges, const Twist& vL, const Twist& vR) {
  std::vector<double> sign(hinges.size());
  for (std::size_t i = 0; i < hinges.size(); ++i) sign[i] = opening_sign(ring, hinges[i]);
  for (;;) {
    const std::size_t m = hinges.size();
    Eigen::MatrixXd J(3, static_cast<Eigen::Index>(m));
    // The right springing's point taken at the first hinge: the rows are the same equations (the rates
    // sum to 0) with arms of the arch's size.
    const Vec at = m > 0 ? hinges.front().point : Vec::Zero();
    for (std::size_t i = 0; i < m; ++i) J.col(static_cast<Eigen::Index>(i)) = closure_column(at, hinges[i].point);
    Eigen::VectorXd x;
    const Vec dv = vR.at(at) - vL.at(at);
    if (!min_norm_solve(J, Eigen::Vector3d(vR.rate - vL.rate, dv.x(), dv.y()), x)) return {};
    const double scale = x.cwiseAbs().maxCoeff();
    std::size_t worst = m;
    double worst_value = -1e-9 * scale;
    for (std::size_t i = 0; i < m; ++i) {
      const double opening = sign[i] * x(static_cast<Eigen::Index>(i));
      if (opening < worst_value) {
        worst_value = opening;
        worst = i;
      }
    }
    if (worst == m) return {std::move(hinges), std::vector<double>(x.data(), x.data() + m)};
    hinges.erase(hinges.begin() + static_cast<std::ptrdiff_t>(worst));
    sign.erase(sign.begin() + static_cast<std::ptrdiff_t>(worst));
  }
}

void chain_bodies(const std::vector<Hinge>& hinges, const Eigen::VectorXd& phi, const Rigid& uL,
                  std::vector<Rigid>& bodies) {
  Rigid chain = uL;
  bodies.assign(hinges.size() + 1, chain);
  for (std::size_t i = 0; i < hinges.size(); ++i) {
    chain = chain.after(rotation_about(hinges[i].point, phi(static_cast<Eigen::Index>(i))));
    bodies[i + 1] = chain;
  }
}

bool close_chain(const std::vector<Hinge>& hinges, const Rigid& uL, const Rigid& uR, double L, Eigen::VectorXd& phi,
                 std::vector<Rigid>& bodies) {
  const std::size_t m = hinges.size();
  for (int iteration = 0; iteration < 30; ++iteration) {
    chain_bodies(hinges, phi, uL, bodies);
    const Rigid& chain = bodies.back();
    const Eigen::Vector3d residual(chain.angle - uR.angle, chain.shift.x() - uR.shift.x(), chain.shift.y() - uR.shift.y());
    if (std::abs(residual(0)) <= 1e-15 && residual.tail<2>().norm() <= 1e-15 * L) {
      bodies.back() = uR;  // equal to round-off: the springing's own motion
      return true;
    }
    Eigen::MatrixXd J(3, static_cast<Eigen::Index>(m));
    for (std::size_t i = 0; i < m; ++i) J.col(static_cast<Eigen::Index>(i)) = closure_column(chain.shift, bodies[i](hinges[i].point));
    Eigen::VectorXd step;
    if (!min_norm_solve(J, -residual, step)) return false;
    phi += step;
  }
  return false;
}

bool all_open(const Ring& ring0, const std::vector<Hinge>& hinges, const Eigen::VectorXd& phi) {
  const double scale = phi.size() > 0 ? phi.cwiseAbs().maxCoeff() : 0.0;
  for (std::size_t i = 0; i < hinges.size(); ++i)
    if (opening_sign(ring0, hinges[i]) * phi(static_cast<Eigen::Index>(i)) < -1e-9 * scale) return false;
  return true;
}

double cone_excess(const Joint& joint, const Vec& F, double friction) {
  const double size = F.norm();
  if (!(size > 0)) return 0;
  const Vec d = (joint.extrados - joint.intrados).normalized();
  const Vec n(d.y(), -d.x());
  return (std::abs(F.dot(d)) - friction * F.dot(n)) / size;
}

int sliding_joint(const Ring& ring, const ThrustState& st, double friction) {
  if (!(friction > 0)) return -1;
  int worst = -1;
  double most = kConeRoundOff;
  for (std::size_t j = 0; j < ring.joints.size(); ++j) {
    const double excess = cone_excess(ring.joints[j], st.force[j], friction);
    if (excess > most) {
      most = excess;
      worst = static_cast<int>(j);
    }
  }
  return worst;
}

bool same_hinges(const std::vector<Hinge>& a, const std::vector<Hinge>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const Hinge& x, const Hinge& y) { return x.joint == y.joint && x.face == y.face; });
}

std::vector<Hinge> with_points_of(std::vector<Hinge> hinges, const std::vector<Hinge>& points) {
  for (Hinge& h : hinges)
    for (const Hinge& p : points)
      if (p.joint == h.joint && p.face == h.face) h.point = p.point;
  return hinges;
}

Eigen::VectorXd carried_rotations(const std::vector<Hinge>& from, const Eigen::VectorXd& phi,
                                  const std::vector<Hinge>& to) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(to.size()));
  std::vector<bool> taken(from.size(), false), given(to.size(), false);
  // The pairs of one face by their distance in joints, the nearest first (the same joint: 0).
  for (int distance = 0;;) {
    int next = std::numeric_limits<int>::max();
    for (std::size_t i = 0; i < to.size(); ++i) {
      for (std::size_t k = 0; k < from.size() && !given[i]; ++k) {
        if (taken[k] || from[k].face != to[i].face) continue;
        const int gap = std::abs(from[k].joint - to[i].joint);
        if (gap == distance) {
          out(static_cast<Eigen::Index>(i)) = phi(static_cast<Eigen::Index>(k));
          taken[k] = given[i] = true;
        } else if (gap > distance) {
          next = std::min(next, gap);
        }
      }
    }
    if (next == std::numeric_limits<int>::max()) break;
    distance = next;
  }
  return out;
}

std::size_t most_closed(const Ring& ring0, const std::vector<Hinge>& hinges, const Eigen::VectorXd& phi) {
  std::size_t worst = 0;
  double most = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hinges.size(); ++i) {
    const double opening = opening_sign(ring0, hinges[i]) * phi(static_cast<Eigen::Index>(i));
    if (opening_sign(ring0, hinges[i]) != 0 && opening < most) {
      most = opening;
      worst = i;
    }
  }
  return worst;
}

std::vector<Hinge> union_of(const std::vector<Hinge>& a, const std::vector<Hinge>& b) {
  std::vector<Hinge> out = a;
  for (const Hinge& h : b)
    if (std::none_of(a.begin(), a.end(), [&](const Hinge& x) { return x.joint == h.joint && x.face == h.face; }))
      out.push_back(h);
  std::sort(out.begin(), out.end(), [](const Hinge& x, const Hinge& y) { return x.joint < y.joint; });
  return out;
}

Eigen::VectorXd kept_rotations(const std::vector<Hinge>& from, const Eigen::VectorXd& phi, const std::vector<Hinge>& to) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(to.size()));
  for (std::size_t i = 0; i < to.size(); ++i)
    for (std::size_t k = 0; k < from.size(); ++k)
      if (from[k].joint == to[i].joint && from[k].face == to[i].face) out(static_cast<Eigen::Index>(i)) = phi(static_cast<Eigen::Index>(k));
  return out;
}

Placement placement(std::size_t voussoirs, const std::vector<Hinge>& hinges, const std::vector<Rigid>& bodies) {
  Placement at;
  at.voussoir.resize(voussoirs);
  std::size_t body = 0;
  for (std::size_t k = 0; k < at.voussoir.size(); ++k) {
    while (body < hinges.size() && static_cast<std::size_t>(hinges[body].joint) <= k) ++body;
    at.voussoir[k] = bodies[body];
  }
  at.left = bodies.front();
  at.right = bodies.back();
  return at;
}

double free_work(const Ring& ring0, const std::vector<Hinge>& hinges, const std::vector<Rigid>& bodies,
                 const Eigen::VectorXd& towards, Eigen::VectorXd& mode) {
  const std::size_t m = hinges.size();
  std::vector<Vec> at(m);
  for (std::size_t i = 0; i < m; ++i) at[i] = bodies[i](hinges[i].point);
  Eigen::MatrixXd J(3, static_cast<Eigen::Index>(m));
  for (std::size_t i = 0; i < m; ++i) J.col(static_cast<Eigen::Index>(i)) = closure_column(at.front(), at[i]);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
  mode = svd.matrixV().col(static_cast<Eigen::Index>(m) - 1);
  if (towards.size() == mode.size() && mode.dot(towards) < 0) mode = -mode;
  double work = 0;
  std::size_t body = 0;
  for_each_load(ring0, [&](std::size_t k, double f, const Vec& p0) {
    while (body < m && static_cast<std::size_t>(hinges[body].joint) <= k) ++body;
    const Vec p = bodies[body](p0);  // where the voussoir's body has carried the load's point
    Vec v = Vec::Zero();
    for (std::size_t i = 0; i < body; ++i) v += mode(static_cast<Eigen::Index>(i)) * perp(p - at[i]);
    work -= f * v.y();
  });
  return work;
}

bool balance(const Ring& ring0, const std::vector<Hinge>& hinges, const Rigid& uL, const Rigid& uR,
             Eigen::VectorXd& phi, std::vector<Rigid>& bodies) {
  double scale = 0;
  for_each_load(ring0, [&](std::size_t, double f, const Vec&) { scale += std::abs(f); });
  const double tolerance = 1e-11 * scale * ring0.span;
  Eigen::VectorXd mode;
  const double g0 = free_work(ring0, hinges, bodies, Eigen::VectorXd(), mode);
  if (std::abs(g0) <= tolerance) return true;
  const Eigen::VectorXd base = phi, towards = mode;
  double s0 = 0, g_prev = g0, s1 = g0 > 0 ? 1e-6 : -1e-6;
  for (int iteration = 0; iteration < 40; ++iteration) {
    Eigen::VectorXd trial = base + s1 * towards;
    if (!close_chain(hinges, uL, uR, ring0.span, trial, bodies)) return false;
    const double g1 = free_work(ring0, hinges, bodies, towards, mode);
    const double slope = (g1 - g_prev) / (s1 - s0);
    if (std::abs(g1) <= tolerance) {
      phi = trial;
      return slope < 0;  // stable: the work on the mode turns against it beyond the balance
    }
    if (!(slope != 0) || !std::isfinite(slope)) return false;
    s0 = s1;
    g_prev = g1;
    s1 -= g1 / slope;
    if (!(std::abs(s1) <= kMostBalanceTurn)) return false;
  }
  return false;
}

// Whether two rings' hinges are at the same places (joints of one ring need not have the other's numbers).
bool same_places(const std::vector<Hinge>& a, const std::vector<Hinge>& b, double L) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [&](const Hinge& x, const Hinge& y) {
    return x.face == y.face && (x.point - y.point).norm() <= 1e-9 * L;
  });
}

// The hinges at collapse that can roll on: those on a face, but not on a springing's joint.
std::vector<Hinge> rolling_hinges(const Ring& ring, const std::vector<Hinge>& hinges) {
  std::vector<Hinge> out;
  const int last = static_cast<int>(ring.joints.size()) - 1;
  for (const Hinge& h : hinges)
    if (h.face != Face::axis && h.joint > 0 && h.joint < last) out.push_back(h);
  return out;
}

// The longest arc length (m) of the two voussoirs on each side of each hinge.
double coarsest_next_to(const Ring& ring, const std::vector<Hinge>& hinges) {
  double most = 0;
  const int n = static_cast<int>(ring.voussoirs.size());
  for (const Hinge& h : hinges)
    for (int k = std::max(h.joint - 2, 0); k < std::min(h.joint + 2, n); ++k)
      most = std::max(most, ring.joints[static_cast<std::size_t>(k + 1)].s - ring.joints[static_cast<std::size_t>(k)].s);
  return most;
}

ThrustState start_state(const Ring& ring, const SpreadStep& s) {
  if (s.hinges.empty()) return {};
  const Hinge& h = s.hinges.front();
  const limit_detail::LoadsLeftOfJoints left = limit_detail::loads_left_of_joints(ring);
  const double live = ring.has_live_load() ? 1.0 : 0.0;  // the path's live loads at their full value
  const std::size_t j = static_cast<std::size_t>(h.joint);
  // The force across the hinge's joint and its moment about the origin (thrust_state's M_left there).
  const Vec F(s.H, s.V_left - left.dead[j].force - live * left.live[j].force);
  const double M = limit_detail::cross(h.point, F) + left.dead[j].moment + live * left.live[j].moment;
  return thrust_state(ring, s.H, s.V_left, M, 1.0);
}

std::vector<double> grazing_fractions(const Scene& scene, const LimitOptions& options, const Ring& ring,
                                      const ThrustState& st) {
  const std::vector<double> edges = limit_detail::load_fractions(*scene.curve, scene.thickness, scene.loads, options);
  std::vector<double> out;
  const int first = ring.left_springing(), m = ring.crown_joint() - first;  // voussoirs per side
  const std::vector<double>& f = ring.joint_fractions;
  if (!st.found() || static_cast<int>(f.size()) + 1 != m) return out;
  // A side joint's fraction (0 the springing, 1 the crown) and the crossing's distance from a face.
  const auto at = [&](int i) { return i <= 0 ? 0.0 : i >= m ? 1.0 : f[static_cast<std::size_t>(i - 1)]; };
  const auto inside = [&](int j, Face face) {
    const Joint& jt = ring.joints[static_cast<std::size_t>(j)];
    const Vec e = jt.extrados - jt.intrados;
    const double s = (st.crossing[static_cast<std::size_t>(j)] - jt.intrados).dot(e) / e.norm();
    return face == Face::intrados ? s : e.norm() - s;
  };
  for (const Hinge& h : st.hinges) {
    if (h.face == Face::axis) continue;
    const int j = h.joint - first;
    const int i = j <= m ? j : 2 * m - j;  // its side's joint, counted from the springing
    if (i < 1 || i + 1 >= m) continue;     // a springing's, the crown's or the one beside the crown
    // At a load's edge the line bends more on one side than on the other: no parabola fits it there.
    const auto at_edge = [&](double x) { return std::abs(x - at(i)) <= limit_detail::kFractionGap; };
    if (std::any_of(edges.begin(), edges.end(), at_edge)) continue;
    const int step = j <= m ? 1 : -1;       // towards the crown along the ring
    const double e0 = inside(h.joint - step, h.face), e1 = inside(h.joint, h.face), e2 = inside(h.joint + step, h.face);
    const double f0 = at(i - 1), f1 = at(i), f2 = at(i + 1);
    if (!(e0 > e1 && e2 > e1)) continue;  // no graze: the line crosses the face there, or a kink
    // The parabola's vertex through (f0, e0), (f1, e1), (f2, e2).
    const double a = (f1 - f0) * (e1 - e2), b = (f1 - f2) * (e1 - e0);
    const double vertex = f1 - 0.5 * ((f1 - f0) * a - (f1 - f2) * b) / (a - b);
    if (!(vertex > f0 && vertex < f2)) continue;
    if (std::none_of(f.begin(), f.end(), [&](double x) { return std::abs(x - vertex) <= 1e-12; }) &&
        std::none_of(out.begin(), out.end(), [&](double x) { return std::abs(x - vertex) <= 1e-12; }))
      out.push_back(vertex);
  }
  return out;
}

std::vector<double> with_grazing(const Ring& ring, std::vector<double> fractions, const std::vector<double>& graze) {
  // The intrados' length of a side (m), the fractions' measure: its chords, to well within the reach below.
  double side = 0;
  for (int j = ring.left_springing(); j < ring.crown_joint(); ++j)
    side += (ring.joints[static_cast<std::size_t>(j + 1)].intrados - ring.joints[static_cast<std::size_t>(j)].intrados).norm();
  // A joint this near a grazing point touches the line too (the line's distance from a face grows with
  // the square of the distance from the point): the contact would stand on two joints. The refinements
  // that follow halve the voussoirs beside it to kSpreadJointSpacing L where the capacity settles there.
  const double reach = 0.5 * kSpreadJointSpacing * ring.span / side;
  std::erase_if(fractions, [&](double x) {
    return !limit_detail::is_wall_fraction(x) &&
           std::any_of(graze.begin(), graze.end(), [&](double g) { return std::abs(x - g) < reach; });
  });
  fractions.insert(fractions.end(), graze.begin(), graze.end());
  return limit_detail::merged_fractions(std::move(fractions));
}

}  // namespace ogive::spreading_detail
