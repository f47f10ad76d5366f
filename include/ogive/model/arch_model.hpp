// The arch model of docs/model.md in non-dimensional form: the linear two-point boundary-value problem
//   y' = A(theta(s)) y + b(s) e_Fy   on 0 < s < S~,   with jumps of Fy at point loads,
// three conditions at each end and, with a hinge inside the domain, M = 0 there and psi free to jump.
// No solver types here: every method (closed form, shooting, quadrature) solves this one problem.
//
// The domain: a symmetric scene (Scene::symmetric) is solved over the half arch, springing to crown,
// with the crown's conditions of symmetry (Ux = 0, psi = 0 or M = 0 at a crown hinge, Fy = -P/2 for a
// point load P at the crown); every other scene over the whole arch, springing to springing.
//
// Scaling (why: so that one matrix mixes numbers of order one whatever t/L and E are):
//   length       L (the span)              s~ = s / L, x~, y~, kappa~ = kappa L
//   force        w L                       Fx~, Fy~ (w = Scene::reference_load_per_length, the
//                                          self-weight per axis length when that is the only load)
//   moment       w L^2                     M~
//   displacement w L^4 / (E I)             Ux~, Uy~
//   rotation     w L^3 / (E I)             psi~
// With c = cos theta, sn = sin theta, N~ = c Fx~ + sn Fy~, V~ = -sn Fx~ + c Fy~, the system reads
//   Ux~'  = a_N N~ c - (a_V V~ + psi~) sn          a_N = E I / (E A L^2) = (t/L)^2 / 12
//   Uy~'  = a_N N~ sn + (a_V V~ + psi~) c          a_V = E I / (k G A L^2) (Timoshenko; 0 for
//                                                    Euler-Bernoulli: no shear strain)
//   psi~' = M~
//   Fx~'  = 0,   Fy~' = b(s),   M~' = sn Fx~ - c Fy~
// i.e. y' = A(theta(s)) y + b(s) e_Fy, b being the vertical load per axis length over w: the
// self-weight's constant, a live load's q c / w under it, a fill's rho_f g max(0, h_f - y_e(x)) c / w:
// the fill's weight per horizontal length over the axis point's x, y_e(x) the height of the true extrados
// (the axis offset by t/2 along the normal) over that x, as limit analysis weighs it (zero where no
// extrados lies over x).
// A point load P at s_P makes Fy jump by P / (w L): Fy(s_P+) = Fy(s_P-) + P~.
// A horizontal acceleration a (Scene::horizontal_acceleration, a fraction of g) adds the horizontal load
// h(s) = a (b_self + b_fill(s)) per axis length, over w, to +x on the axis point: the self-weight's and the
// fill's (not a point or live load's) times a. Then Fx~' = -h(s) instead of 0; with a = 0 nothing changes.
#pragma once

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "ogive/model/scene.hpp"

namespace ogive {

// Global components, in this order, everywhere in ogive.
enum StateIndex : int { kUx = 0, kUy = 1, kPsi = 2, kFx = 3, kFy = 4, kM = 5 };
inline constexpr int kStateSize = 6;
using StateVector = Eigen::Matrix<double, kStateSize, 1>;
using SystemMatrix = Eigen::Matrix<double, kStateSize, kStateSize>;

// SI value of one scaled unit of each kind.
struct Scales {
  double length = 1, force = 1, moment = 1, displacement = 1, rotation = 1;
};

// Linear two-point conditions at_start * y(0) + at_end * y(S~) = rhs (scaled). Rows 0-2 act at the left
// springing, each fixing one component (Ux, Uy, and psi if clamped or M if pinned; its coefficient 1)
// given the springing's forces (the curved bar's clamped springing moves by its held face's compliance
// times Fx, Fy and M: the rows' other coefficients, on components no row fixes); rows 3-5 at the
// domain's end: the right springing's, or the crown's symmetry.
struct BoundaryConditions {
  SystemMatrix at_start = SystemMatrix::Zero();
  SystemMatrix at_end = SystemMatrix::Zero();
  StateVector rhs = StateVector::Zero();
};

// A point load inside the domain or at its ends (scaled): Fy(s+) = Fy(s-) + force.
struct PointJump {
  double s = 0;
  double force = 0;
};

// Both springings' reactions in global components, N/m and N m/m per metre of vault width: H positive
// pointing into the span (so H_left pushes to +x, H_right to -x), V upwards, M counter-clockwise, each
// the support's action on the arch. Without horizontal loads H_left = H_right.
struct Reactions {
  double H_left = 0, V_left = 0, M_left = 0;
  double H_right = 0, V_right = 0, M_right = 0;
};

// The state at one point of the axis, in SI units, with the quantities the user reads.
struct ArchState {
  double s = 0;                  // m, arc length from the left springing over the whole arch
  double x = 0, y = 0;           // m, axis point
  double theta = 0;              // rad, tangent angle in the direction of increasing s
  double Ux = 0, Uy = 0;         // m, displacement of the axis
  double psi = 0;                // rad, rotation of the cross-section (counter-clockwise positive)
  double Fx = 0, Fy = 0;         // N/m, force of the part beyond s on the part before s
  double M = 0;                  // N m/m, couple of the part beyond s on the part before s
  double N = 0;                  // N/m, normal force, negative in compression
  double V = 0;                  // N/m, shear force
  double e = 0;                  // %, eccentricity of the compression, 600 M / (N t): 100 at the kern's
                                 // edge (t/6), 300 at the section's face; NaN where N = 0
  double thrust_x = 0, thrust_y = 0;  // m, where the resultant crosses the section (the thrust line);
                                      // NaN where N = 0
  // No-tension section (section.hpp): the compressed depth over t (1 in the kern) and whether the
  // section is cracked (the resultant beyond the kern); NaN and false for the elastic section.
  double compressed_depth = std::numeric_limits<double>::quiet_NaN();
  bool cracked = false;
  // Pa, the greatest compressive stress in the section (unit width), positive in compression
  // (section.hpp, compressive_stress); NaN where N is not a compression or the no-tension section's
  // resultant lies outside the section.
  double compressive_stress = std::numeric_limits<double>::quiet_NaN();
};

class ArchModel {
 public:
  // The scene must be valid (Scene::validate); the model keeps a copy of it. whole_arch = true solves a
  // symmetric scene over the whole arch too (the half is the default for it: the smaller model).
  explicit ArchModel(Scene scene, bool whole_arch = false);

  const Scene& scene() const { return scene_; }
  // The domain's curve: the scene's half (half() true) or the whole arch.
  const Curve& curve() const { return *curve_; }
  bool half() const { return half_; }
  const Scales& scales() const { return scales_; }
  double length() const { return length_; }  // S~: the domain's scaled length
  double a_N() const { return a_N_; }
  double a_V() const { return a_V_; }
  BeamModel beam_model() const { return scene_.beam_model; }
  bool curved() const { return scene_.beam_model == BeamModel::curved; }

  // The curved bar (BeamModel::curved; docs/model.md, "Beam models") at scaled curvature k = kappa L
  // (negative for an arch): the thick circular bar's section law of plane elasticity (curved_section.hpp)
  // at the local radius R = 1 / |kappa|, rho = |k| t~ / 2 < 1 (Scene::validate):
  //   eps~  = a_N (axial N~ + coupling' k M~)      (the centroid's axis strain, in Ux~' and Uy~')
  //   rot~  = a_V shear V~ + psi~                   (the axis' turn, in Ux~' and Uy~')
  //   psi~' = bending M~ + a_N coupling' k N~
  // with CurvedSection's factors (axial, coupling', bending, shear): symmetric, the complementary energy
  // of Golovin's and Michell's stresses per length. Winkler-Bach's bar (plane sections about the neutral
  // axis of pure bending, no radial stress) is the same law with axial = coupling' = 1 and bending =
  // I / (A R e); the radial stress adds to all four, and its Poisson strain along the axis makes
  // coupling' 1 + 6 nu / 5 as rho -> 0. And each slice of the arch, an annular sector, weighs at its
  // centroid, t^2 / (12 R) beyond the axis towards the extrados: the self-weight's load (b_self down,
  // a b_self to +x) brings the couple offset (b_self sn - a b_self c) into M~', offset = a_N k.
  // In the struct coupling = a_N k coupling'. The self-weight is a body force: its own stress across the
  // depth strains the section (CurvedSection's load terms), eps~ += load_strain q~ and psi~' +=
  // load_curvature q~ with q~ = -b_self (c + a sn) its part along the extrados normal (-sn, c):
  // load_strain = -sign(k) a_N t~ load_extension, load_curvature = -a_N load_curvature'.
  // For the other models coupling 0, offset 0, the load terms 0, the factors 1.
  struct CurvedBar {
    double coupling = 0, bending = 1, axial = 1, shear = 1, offset = 0, load_strain = 0, load_curvature = 0;
  };
  // The self-weight's part along the extrados normal (-sn, c) per scaled length (q~ above).
  double weight_normal_load(double c, double sn) const { return -self_weight_ * (c + acceleration() * sn); }
  CurvedBar curved_bar(double k) const;
  // A pointed crown's kink (a half curve whose crown tangent is not horizontal) for the curved bar: there
  // the axis turns by a finite angle at a point, kappa a Dirac delta, and the section law's coupling terms
  // (coupling' k M~ in eps~, coupling' k N~ in psi~') integrate to a jump of the state across the turn,
  // y+ = y- + kink_jump(theta1, theta2) y- with f = a_N (1 + 6 nu / 5) (coupling' as t/R -> 0):
  //   Ux~, Uy~ jump by f M~ (sin theta2 - sin theta1, cos theta1 - cos theta2)
  //   psi~    jumps by f (Fx~ (sin theta2 - sin theta1) + Fy~ (cos theta1 - cos theta2))
  //           and by crown_wedge(theta_c) t~ / 12 M~ |theta2 - theta1| / theta_c  (the wedge's joint:
  //           each leg's crown section against the symmetry line, curved_section.hpp)
  // (the integrals of the bar's coupling over the turn at constant forces: kappa ds = d theta). Over the
  // half the turn from the crown's tangent to the symmetry line's (0) enters the crown's conditions; over
  // the whole arch kink() is the crown's knot, its turn from theta_c to -theta_c taken in two halves on
  // either side of a crown load. None for the other models or a smooth crown.
  struct Kink {
    double s = 0;                         // scaled arc length of the crown in the whole domain
    double theta_before = 0, theta_after = 0;
  };
  const std::optional<Kink>& kink() const { return kink_; }
  SystemMatrix kink_jump(double theta1, double theta2) const;
  double kappa(double s) const;  // the scaled curvature kappa L at scaled arc length s
  // dy of the curved bar: derivative()'s equations with the bar's section law and, on the load column
  // (self_weight true), the self-weight's couple.
  void curved_derivative(double c, double sn, const CurvedBar& bar, const double* y, double* dy, double load,
                         double horizontal, bool self_weight) const;
  SystemMatrix curved_system_matrix(double theta, const CurvedBar& bar) const;

  double theta(double s) const;      // tangent angle at scaled arc length s
  // A(theta)'s entries that can be non-zero (every other entry is 0 for every theta; A(psi, M) = 1).
  struct SystemEntries {
    double ux_psi, ux_fx, ux_fy, uy_psi, uy_fx, uy_fy, m_fx, m_fy;
  };
  SystemEntries system_entries(double theta) const;
  SystemMatrix system_matrix(double theta) const;  // A(theta), from system_entries
  // dy = A y over A's entries that can be non-zero: the sums of the full product in its order, less
  // terms that are exact zeros, so the same numbers at a quarter of the work (shooting's right-hand
  // side runs this for every column).
  static void apply_system_matrix(const SystemEntries& A, const double* y, double* dy);
  // b(s): the vertical load per axis length at s, over w.
  double load(double s) const;
  // h(s): the horizontal load per axis length at s, over w, to +x (0 without a horizontal acceleration).
  double horizontal_load(double s) const;
  // The scene's horizontal acceleration a (a fraction of g); 0: no horizontal load anywhere.
  double acceleration() const { return scene_.horizontal_acceleration; }
  // True when b is the same constant everywhere and there are no point loads (self-weight alone).
  bool uniform_load() const { return uniform_; }
  // The self-weight's part of b (w_self / w), and whether b is that constant alone (no live load or fill;
  // point loads may be present).
  double self_weight() const { return self_weight_; }
  bool self_weight_only_distributed() const { return scene_.loads.live.empty() && scene_.loads.fills.empty(); }
  // dy = A y + load * e_Fy - horizontal * e_Fx at the angle whose cosine and sine are c and sn (the one
  // place of this arithmetic; inline: the quadrature calls it at every node).
  void derivative(double c, double sn, const double* y, double* dy, double load, double horizontal = 0.0) const;
  // Interior points where A or b is not smooth (the curve's breakpoints, a live load's ends, where a fill
  // starts to bear, the axis points under the extrados' breaks when there is a fill) and where the state jumps (point loads, a hinge), ascending, scaled: integrators
  // restart there. jumps(): the point loads, ascending, at 0 <= s <= S~ (those at the ends act on the
  // springing's side of the end state: see reactions).
  const std::vector<double>& breakpoints() const { return breakpoints_; }
  const std::vector<PointJump>& jumps() const { return jumps_; }
  // The hinge inside the domain (scaled arc length), if any: a crown hinge of a whole-arch domain (over the
  // half, a crown hinge is the end condition M = 0).
  std::optional<double> hinge() const { return hinge_; }
  const BoundaryConditions& boundary_conditions() const { return bc_; }

  // The reactions from the states at the domain's ends: y0 before a point load at s = 0, yS after one at
  // S~ (a load at a springing goes into its support). Over the half, the right springing's are the
  // left's mirror image.
  Reactions reactions(const StateVector& y0, const StateVector& yS) const;

  // The SI displacements, rotation, forces and couple of the scaled state y, with N and V for a section
  // whose tangent is (c, sn): the part of to_physical that needs no point of the curve (s, x, y, theta,
  // e and the thrust point stay 0; compressed_depth NaN).
  ArchState section_state(double c, double sn, const StateVector& y) const;

  // The SI state at scaled arc length s of the domain; mirrored = true maps it onto the right half
  // (at s_whole = 2S - s) using the scene's symmetry (half() only).
  ArchState to_physical(double s, const StateVector& y, bool mirrored = false) const;

  // |Boundary-condition residual| (max norm, scaled; with a hinge, |M| there too) and the relative
  // residual of the domain's global equilibrium (vertical and horizontal forces, moments about the left
  // springing) over the domain's total load.
  double boundary_residual(const StateVector& y0, const StateVector& yS, double hinge_moment = 0) const;
  double equilibrium_residual(const StateVector& y0, const StateVector& yS) const;
  // The total vertical load on the domain, the total horizontal load (to +x) and the moment of all loads
  // about the left springing, int (b x + h y) ds, clockwise positive (scaled), point loads at the ends and
  // the crown's half load included.
  double total_load() const { return total_load_; }
  double total_horizontal_load() const { return total_horizontal_load_; }
  double load_moment() const { return load_moment_; }

 private:
  Scene scene_;
  std::shared_ptr<const Curve> curve_;
  bool half_ = true;
  bool uniform_ = true;
  Scales scales_;
  double length_, a_N_, a_V_;
  double self_weight_ = 0;   // w_self / w
  double crown_load_ = 0;    // half a point load at the crown of a half domain (scaled)
  std::vector<double> breakpoints_;
  std::vector<PointJump> jumps_;
  std::optional<double> hinge_;
  std::optional<Kink> kink_;
  double crown_kink_angle_ = 0;  // the half curve's crown tangent where it is a kink of the curved bar, else 0
  BoundaryConditions bc_;
  double total_load_ = 0, total_horizontal_load_ = 0, load_moment_ = 0;
  // The curved bar's moment of the self-weight's offset from the axis, added to load_moment_.
  void sum_centroid_offset();
  // The curved bar's section factors (curved_section: a quadrature over the depth, too slow for every
  // right-hand side) as Chebyshev series in rho^2 over 0 <= rho <= kTabulatedRho, of the scene's nu;
  // beyond it curved_bar computes them.
  static constexpr double kTabulatedRho = 0.5;
  static constexpr int kSectionDegree = 16;
  std::array<std::array<double, kSectionDegree + 1>, 6> section_series_{};
  double section_poisson_ratio() const;
  void tabulate_section();
  // The constructor's steps, in order: the curved bar's crown kink (find_kink); where the loads act and where the system is not smooth (the
  // curve's breakpoints, the point loads, the hinge, the live loads' ends, where the fill meets the
  // extrados and under the extrados' breaks); the six boundary conditions; the domain's total load and its moment.
  void find_kink();
  void place_loads();
  void set_boundary_conditions();
  // The curved bar's clamped springing (left, or the right one) as a held face: the 3 x 3 compliance
  // (scaled) from the state's (Fx, Fy, M) there to its (Ux, Uy, psi) beyond the support's.
  Eigen::Matrix3d held_face_compliance(bool left) const;
  void sum_loads();
  // b beyond the self-weight at scaled arc length s, whose axis point is p.
  double distributed_load(double s, const CurvePoint& p) const;
  // The fills' part of it alone (the mass that a horizontal acceleration moves, with the self-weight).
  double fill_load(double s, const CurvePoint& p) const;
  // One fill's weight per axis length (N/m) over an axis point with tangent cosine c, under extrados e.
  double fill_weight(const FillLoad& f, double extrados_y, double c) const;
  // The true extrados over the domain's axis points (arch_model.cpp; only with fills).
  struct Extrados;
  std::shared_ptr<const Extrados> extrados_;
  // Where each live load acts, in scaled arc length: the same numbers as its breakpoints, so that the
  // load switches exactly where the integrator restarts (not where x(s) = a L rounds to one side).
  struct LiveSpan {
    double from = 0, to = 0, intensity = 0;
  };
  std::vector<LiveSpan> live_spans_;
};

inline void ArchModel::apply_system_matrix(const SystemEntries& A, const double* y, double* dy) {
  dy[kUx] = A.ux_psi * y[kPsi] + A.ux_fx * y[kFx] + A.ux_fy * y[kFy];
  dy[kUy] = A.uy_psi * y[kPsi] + A.uy_fx * y[kFx] + A.uy_fy * y[kFy];
  dy[kPsi] = y[kM];
  dy[kFx] = 0.0;
  dy[kFy] = 0.0;
  dy[kM] = A.m_fx * y[kFx] + A.m_fy * y[kFy];
}

// The six equations of the header comment.
inline void ArchModel::derivative(double c, double sn, const double* y, double* dy, double load,
                                  double horizontal) const {
  const double N = c * y[kFx] + sn * y[kFy];
  const double V = -sn * y[kFx] + c * y[kFy];
  const double rot = a_V_ * V + y[kPsi];
  dy[kUx] = a_N_ * N * c - rot * sn;
  dy[kUy] = a_N_ * N * sn + rot * c;
  dy[kPsi] = y[kM];
  dy[kFx] = 0.0 - horizontal;  // +0, as before horizontal loads, where there is none
  dy[kFy] = load;
  dy[kM] = sn * y[kFx] - c * y[kFy];
}

}  // namespace ogive
