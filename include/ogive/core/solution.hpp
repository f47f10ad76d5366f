// What a solve returns and how it is asked (the shared types below the methods and the dispatcher):
// the Method and Options, the Status with what each one promises, the Diagnostics, the StateField and the
// Solution with its reactions and profile. Methods (closed_form.hpp, shooting.hpp, quadrature.hpp) fill
// a Solution; the dispatcher (solve.hpp) chooses, verifies and judges them. The library never prints.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ogive/model/arch_model.hpp"
#include "ogive/model/scene.hpp"

namespace ogive {

enum class Method {
  closed_form,        // matrix exponential arc by arc; piecewise-circular curves, no live load or fill
  shooting,           // CVODE, one shooting segment over the domain (pieces only at point loads, a hinge)
  multiple_shooting,  // CVODE, Options::segments segments joined by continuity
  automatic,          // the smallest model that meets rtol: the closed form where it applies, else the
                      // quadrature method where its estimate meets rtol, else shooting with 1, 2, 4, ...
                      // 64 segments until the error estimate meets rtol (the no-tension section: the
                      // quadrature form, then Newton shooting; solve.hpp)
  quadrature,         // the force method: nested Chebyshev integrals per panel, its own error estimate
                      // (src/methods/quadrature.hpp); any curve, the symmetric clamped arch under its
                      // own weight. The no-tension section: Newton on explicit forces with adaptive
                      // Gauss-Kronrod integrals (no_tension.hpp), verified by a solve at rtol / 16
};
enum class Integrator { adams, bdf };

// What a solve's numbers are worth. Only `success` is a guarantee; the numbers of ill_conditioned,
// tolerance_not_met and unverified solutions are printed (IsSolutionUsable in Ceres' words: a field
// exists) but carry no promise.
enum class Status {
  success,             // every reported number is within_tolerance(error_estimate, rtol): its estimated
                       // relative error is at most rtol, by an estimate no option switches off
  not_applicable,      // the method cannot treat this scene (closed form on a non-circular curve)
  integrator_failure,  // CVODE stopped with an error flag; the message names it and where (s in m)
  singular_system,     // the boundary-value system is singular to working precision
  ill_conditioned,     // solved, but condition * unit round-off exceeds rtol: digits may be lost
  tolerance_not_met,   // solved, but the error estimate, or the boundary or equilibrium residual, exceeds rtol
                       // (below rtol 2.56e-12 with Adams or 2.56e-10 with BDF the verifying solves, which
                       // stop at CVODE's floor, start looser than rtol asks; the message says so)
  unverified,          // solved by CVODE without an error estimate: Options::verify was off, CVODE stepped
                       // across breakpoints, a verifying solve failed or has a station without numbers,
                       // or (no-tension section) the second solve did not converge or would run within 16
                       // times CVODE's floor (rtol below 2.56e-12 with Adams, 2.56e-10 with BDF)
  not_converged,       // no-tension section: Newton did not reach the boundary conditions (the iterations
                       // are in Diagnostics::newton_iterations, the message says where it stopped)
  inadmissible,        // no-tension section: no state keeps the resultant inside every section (the arch
                       // cannot stand as a no-tension arch: too thin for its loads)
};

// The one definition of "within tolerance", used by the status, `auto`, `check`, the stability map and
// the tests: a relative error no larger than rtol. No factor stands between --rtol and this promise.
inline bool within_tolerance(double relative_error, double rtol) { return relative_error <= rtol; }

const char* to_string(Method m);
const char* to_string(Integrator i);
const char* to_string(Status s);

struct Options {
  Method method = Method::automatic;
  Integrator integrator = Integrator::adams;
  // The relative error asked of every printed number, in [1e-14, 1e-1]; `success` guarantees it. CVODE
  // itself runs tighter (shooting.hpp, cvode_tolerances: rtol / 10 for Adams, rtol / 1000 for BDF),
  // because it controls local errors only.
  double rtol = 1e-8;
  // CVODE's absolute tolerance on the scaled state (order-one numbers); 0 (the default) means 1e-6 of
  // CVODE's rtol. A verified solve uses the smaller of atol and that default (divided by 16 for its
  // tighter solve): a loose atol changes neither its numbers nor its estimate nor its status. Raw
  // solves (verify off) take it as given.
  double atol = 0.0;
  int segments = 8;    // multiple shooting: segments over the domain (>= 1; breakpoints, loads, a hinge add more)
  std::int64_t max_steps = 200000;  // CVODE step limit for one integration span
  // Profile stations over the whole arch, springing to springing (0: none, else >= 2). With a profile,
  // its error is part of the estimate, compared at kVerificationStations stations whatever this number.
  int stations = 0;
  // The profile is asked for only so that the estimate covers the whole field, which a summary then reads
  // (summarize_thrust_line), and is not printed. The closed form, whose estimate is its round-off bound,
  // then takes the field's largest force and couple from field_scan's few states a piece instead of
  // kVerificationStations stations, and every method returns no profile.
  bool unprinted_profile = false;
  // Estimate the global error of a CVODE solve by a second solve at rtol / 16 (about 2.5x the time):
  // CVODE controls local errors only, and the stability map (docs/methods.md) measured unverified solves at up
  // to 67 rtol (single shooting, a rough survey) and 37 rtol (BDF). Off (for benchmarks of the raw
  // methods), a CVODE solve's status is at best `unverified`, never `success`. Method::automatic always
  // verifies; the closed form's estimate is its round-off bound and needs no second solve.
  bool verify = true;
  // Restart the integrator at every breakpoint of the curve (jumps of curvature). Off only for studies
  // of what a step across a jump costs (the stability map).
  bool restart_at_breakpoints = true;
  // Solve a symmetric scene over the whole arch as well (a check: by default such a scene is solved over
  // the half, the smaller model; ArchModel::half() says which one a solution used).
  bool whole_arch = false;
  // Estimate the beam model's own error (Diagnostics::model_error_estimate) even when the scene asks no
  // model tolerance: a second solve, with the curved bar (ogive/solve/model_error.hpp).
  bool estimate_model_error = false;

  // Ceres-style check: false with the reason in *why (naming the field) when an option is unusable.
  bool is_valid(std::string* why) const;
};

// Plain numbers describing how the solution was found.
struct Diagnostics {
  std::int64_t steps = 0;                // CVODE steps over all spans (0 for the closed form)
  std::int64_t rhs_evaluations = 0;      // right-hand-side evaluations (CVODE); angle evaluations (quadrature)
  std::int64_t error_test_failures = 0;  // CVODE local error test failures
  std::int64_t jacobian_evaluations = 0; // CVODE Jacobian evaluations (BDF)
  int segments = 0;                      // shooting segments used (arcs for the closed form, panels for the quadrature)
  int newton_iterations = 0;             // no-tension section: Newton iterations, all solves of the row
  // Skeel's condition number cond(Q) = || |Q^-1| |Q| ||_inf of the boundary-value matrix Q of the
  // scaled problem in its m unknowns (the springing state's three unknown components, and psi's jump at
  // a hinge inside the domain): Q = B_end Phi(S) U without a hinge. Invariant to the scaling of its rows. Every method reports the condition
  // of the same problem: multiple shooting condenses its segments' transfers into Phi(S) U for this
  // estimate, so it does not grow with the number of segments.
  double condition_estimate = std::numeric_limits<double>::quiet_NaN();
  // max |BC residual|, scaled (the no-tension quadrature's over the size of the integrals it is a
  // difference of, which a hinge's rotations make much larger than one)
  double boundary_residual = std::numeric_limits<double>::quiet_NaN();
  double equilibrium_residual = std::numeric_limits<double>::quiet_NaN(); // relative to the domain's load
  // Estimated relative error of the printed numbers, never smaller than condition_estimate times
  // round-off. CVODE methods (verified): the differences between solves at rtol, rtol / 16 and tighter
  // (solution_difference: the reactions, H/V and, with a profile, profile_difference; solve.cpp,
  // solve_verified, says how they are combined and which solve is returned). The quadrature method: the
  // same difference between its last two degrees (quadrature.hpp). The closed form: its round-off
  // bound alone. NaN when not estimated (status unverified, or a failed solve).
  double error_estimate = std::numeric_limits<double>::quiet_NaN();
  // The beam model's own error, relative, in H/V against the two-dimensional arch: its difference from
  // the curved bar's H/V plus the curved bar's calibrated bound (ogive/solve/model_error.hpp). NaN when
  // not asked (Scene::model_tolerance 0, Options::estimate_model_error off) or not estimable.
  double model_error_estimate = std::numeric_limits<double>::quiet_NaN();
};

// The solved state along the model's domain (the half or the whole arch) in scaled units: lets any method serve as another's reference.
class StateField {
 public:
  virtual ~StateField() = default;
  // Scaled states at scaled arc lengths s (ascending, within the model's domain [0, S~]) into out (same
  // size). At a point load or a hinge, the state before it (on its left); at s = 0 the arch's state.
  virtual void sample(std::span<const double> s, std::span<StateVector> out) const = 0;
};

struct Solution {
  Status status = Status::not_applicable;
  std::string message;
  Method method = Method::automatic;  // the method that produced the numbers (never automatic)
  // Both springings' reactions (arch_model.hpp: H into the span, V up, M counter-clockwise); NaN-free
  // only when a field exists.
  Reactions reactions;
  double H = std::numeric_limits<double>::quiet_NaN();         // N/m, H_left: the inward push of the left support
  double V = std::numeric_limits<double>::quiet_NaN();         // N/m, V_left (half the load of a symmetric scene)
  double H_over_V = std::numeric_limits<double>::quiet_NaN();  // H_left / V_left
  std::vector<ArchState> profile;  // Options::stations states, springing to springing
  Diagnostics diagnostics;

  bool ok() const { return status == Status::success; }
  // The state at arc length s (m) of the whole arch, 0 <= s <= its length; the right half by symmetry
  // when the model is the half arch. Requires a solved field (status success or ill_conditioned).
  ArchState at(double s) const;

  std::shared_ptr<const ArchModel> model;
  std::shared_ptr<const StateField> field;
  // The scaled state at the left springing (before a point load there), when a field exists: what a
  // neighbouring scene's nonlinear solve starts from (continuation).
  StateVector springing_state = StateVector::Constant(std::numeric_limits<double>::quiet_NaN());
};


// The profile's error is estimated at this many equally spaced stations, whatever the number of printed
// stations (they are sampled from the same verified field afterwards): so the estimate, and the status,
// do not depend on --stations, and no quantity is measured against its size at a few stations where it
// vanishes (psi and Ux at the springings and the crown). Odd, so that the crown is one of them; the
// fields are smooth between them.
inline constexpr int kVerificationStations = 129;

// Fills solution.profile with `stations` equally spaced states over the whole arch from its field.
void sample_profile(Solution& solution, int stations);
// Stations first .. first + count - 1 of `stations` equally spaced ones over the whole arch, from the
// solution's field (empty without a field or for indices out of range): a long profile in pieces, so
// that memory does not grow with the number of stations.
std::vector<ArchState> sample_stations(const Solution& solution, int stations, int first, int count);

// The error measure of reactions against a reference: each force's difference relative to the larger of
// its own size and F / 100, F being the largest of the reference's |H_left|, |V_left|, |V_right| (H crosses
// zero under support spreading, where no relative error of H means anything: its absolute error is
// then held to rtol V / 100); each couple's relative to the larger of the largest |M| and F t / 6 (the
// couple that puts the thrust at the kern's edge).
double reaction_difference(const Reactions& a, const Reactions& reference, double thickness);

// The round-off bound of a solution's numbers by the measures above: condition x machine epsilon,
// amplified where a measure's scale is smaller than the terms a number is summed from. A couple is a
// sum of forces (up to F, the largest) times lever arms up to the span L, so its absolute round-off is
// about F L eps; measured against max(|M|, F t / 6) that is A = F L / max(|M|, F t / 6) times larger (up
// to 6 L / t on a thin near-funicular arch). The factors are measured against a 40-digit reference
// (benchmarks/pessimism: the closed form's true error over random circular arches, t/L 0.005 .. 0.25,
// at most a third of the bound): the reactions (kRoundoffFloor + kRoundoffReactions x A) x condition x
// eps (thick arches, A small, lose some 4 x condition x eps), the profile (sampled station by station,
// more operations) kRoundoffProfile x condition x eps x A of the profile. The closed form's
// error_estimate is this bound, and every method's estimate is at least this.
inline constexpr double kRoundoffFloor = 8;
inline constexpr double kRoundoffReactions = 0.5;
inline constexpr double kRoundoffProfile = 4;
// CVODE's profile is sampled from its integrated field (the dense output at every station, after
// hundreds of steps): more operations than the closed form's. Over 40 random circular arches
// (benchmarks/pessimism/calibration.py, seed 1) its error at rtol 1e-12 that the three verifying solves'
// differences did not see reached the closed form's bound itself (single shooting with Adams: 1.0 of
// it), where the closed form's own stays below 1 / 2.8 of it; its own factor keeps the margin the
// reactions' bound has over the closed form's worst (1.2). (On a thin pointed arch, seed 2, one row
// reached 1.9 times the closed form's bound: the tightest solve, held by CVODE's floor, returned on a
// difference that round-off made small; solve.cpp no longer returns it there.)
inline constexpr double kRoundoffProfileIntegrated = 1.25 * kRoundoffProfile;
// The quadrature's (elastic section) is of its own arithmetic, whose round-off has two sources that add
// rather than multiply: the boundary-value solve (condition x eps in the springing's forces; the solved
// state meets the six conditions, the couples' among them, to round-off) and the couples summed from
// terms of size F L (A x eps at the couples' scale). So kRoundoffQuadrature x eps x (condition + A), A the
// reactions' or, with a profile, the larger with the profile's. Against the 40-digit reference
// (benchmarks/pessimism/calibration.py: 200 random circular arches, seeds 1 and 2, none of them the
// pessimism table's; t/L 0.005 .. 0.25; at the degree it converges at, and 30 more forced to degree
// 256, where the error does not grow) its true error reached 6.2 eps (condition + A) (the displacements
// of thin pointed arches): the factor keeps a margin of 1.6, more than the closed form's bound has on
// the reactions (1.2). The closed form's product condition x A overstates the quadrature's round-off
// by 10^1 .. 10^2 on thin arches.
inline constexpr double kRoundoffQuadrature = 10;
double roundoff_bound(const Solution& solution);

// The larger of reaction_difference and the relative difference of H/V (relative to max(|H/V|, 1/100);
// 0 where V_left is below F / 100): solution_difference without the profiles. NaN where H/V is not finite.
double reaction_and_thrust_difference(const Reactions& a, const Reactions& reference, double thickness);

// The largest of the relative differences of the reactions, of H/V (relative to max(|H/V|, 1/100)) and
// of the profiles (when both carry one): the error estimate of a solution a against a tighter one b. NaN
// when either has no field, or when any of these differences is NaN (a station without numbers: never
// dropped).
double solution_difference(const Solution& a, const Solution& b);
// The same for two solved solutions from their reactions and profiles alone (a's field may have been
// dropped once its profile was sampled, to free its memory).
double sampled_solution_difference(const Solution& a, const Solution& b);

// The error measure of a profile against a reference at the same stations: the largest difference of
// the displacement (Ux, Uy) relative to the largest |U| of the reference, of psi relative to the
// largest |psi|, of the forces (N, V) relative to the largest resultant, and of M relative to the
// larger of max |M| and max |N| t / 6 (the moment that puts the thrust line at the kern's edge, so that
// it measures e in units of the kern). NaN if the sizes differ, either is empty or holds non-finite values.
double profile_difference(const std::vector<ArchState>& profile, const std::vector<ArchState>& reference,
                          double thickness);

}  // namespace ogive
