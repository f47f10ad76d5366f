// One entry point: Solution solve(const Scene&, const Options&).
//
// Two error channels. Misuse (an invalid Scene or Options) throws std::invalid_argument naming the
// field and the rule it breaks. Numerical outcomes are a Status in the Solution; the library never
// prints.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ogive/arch_model.hpp"
#include "ogive/scene.hpp"

namespace ogive {

enum class Method {
  closed_form,        // matrix exponential arc by arc; piecewise-circular curves only
  shooting,           // CVODE, one shooting segment over the half arch
  multiple_shooting,  // CVODE, Options::segments segments joined by continuity
  automatic,          // the smallest model that meets rtol: the closed form where it applies, else the
                      // quadrature method where its estimate meets rtol, else shooting with 1, 2, 4, ...
                      // 64 segments until the error estimate meets rtol
  quadrature,         // the force method: nested Chebyshev integrals per panel, its own error estimate
                      // (include/ogive/quadrature.hpp); any curve
};
enum class Integrator { adams, bdf };

enum class Status {
  success,             // every reported number meets the asked tolerance
  not_applicable,      // the method cannot treat this scene (closed form on a non-circular curve)
  integrator_failure,  // CVODE stopped with an error flag; the message names it and where (s in m)
  singular_system,     // the boundary-value system is singular to working precision
  ill_conditioned,     // solved, but condition * unit round-off exceeds rtol: digits may be lost
  tolerance_not_met,   // solved, but the a-posteriori error estimate exceeds 10 * rtol
};

const char* to_string(Method m);
const char* to_string(Integrator i);
const char* to_string(Status s);

struct Options {
  Method method = Method::automatic;
  Integrator integrator = Integrator::adams;
  double rtol = 1e-8;  // relative tolerance asked of the result (CVODE's rtol), in [1e-14, 1e-1]
  double atol = 0.0;   // absolute tolerance of the scaled state; 0 means rtol * 1e-3
  int segments = 8;    // multiple shooting: segments over the half arch (>= 1; breakpoints add more)
  std::int64_t max_steps = 200000;  // CVODE step limit for one integration span
  int stations = 0;    // profile stations over the whole arch, springing to springing (0: none, else >= 2)
  // Estimate the global error of a CVODE solve by a second solve at rtol / 16 (about 2.5x the time):
  // CVODE controls local errors only, and the stability map (README) measured unverified solves at up
  // to 67 rtol (single shooting, a rough survey) and 37 rtol (BDF). Off, a solve is only as good as the
  // tolerance factors measured in the tests; for benchmarks of the raw methods. Method::automatic
  // always verifies; the closed form never needs to.
  bool verify = true;
  // Restart the integrator at every breakpoint of the curve (jumps of curvature). Off only for studies
  // of what a step across a jump costs (the stability map).
  bool restart_at_breakpoints = true;

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
  double condition_estimate = std::numeric_limits<double>::quiet_NaN();  // 1-norm, scaled system
  double boundary_residual = std::numeric_limits<double>::quiet_NaN();   // max |BC residual|, scaled
  double equilibrium_residual = std::numeric_limits<double>::quiet_NaN(); // relative to half weight
  // A-posteriori relative error of the printed numbers (CVODE methods with Options::verify, and always
  // under Method::automatic): the difference between a solve at rtol and one at rtol / 16, of H
  // relative to |H| and, with a profile, profile_difference. The solution returned is the tighter one.
  // The quadrature method's: the same difference between its last two degrees (quadrature.hpp).
  // NaN when not estimated (the closed form needs none).
  double error_estimate = std::numeric_limits<double>::quiet_NaN();
};

// The solved state along the half arch in scaled units: lets any method serve as another's reference.
class StateField {
 public:
  virtual ~StateField() = default;
  // Scaled states at scaled arc lengths s (ascending, within [0, S~]) into out (same size).
  virtual void sample(std::span<const double> s, std::span<StateVector> out) const = 0;
};

struct Solution {
  Status status = Status::not_applicable;
  std::string message;
  Method method = Method::automatic;  // the method that produced the numbers (never automatic)
  double H = std::numeric_limits<double>::quiet_NaN();         // N/m, inward push of a support
  double V = std::numeric_limits<double>::quiet_NaN();         // N/m, half the weight
  double H_over_V = std::numeric_limits<double>::quiet_NaN();  // normalized horizontal reaction
  std::vector<ArchState> profile;  // Options::stations states, springing to springing
  Diagnostics diagnostics;

  bool ok() const { return status == Status::success; }
  // The state at arc length s (m) of the whole arch, 0 <= s <= 2S; right half by symmetry.
  // Requires a solved field (status success or ill_conditioned).
  ArchState at(double s) const;

  std::shared_ptr<const ArchModel> model;
  std::shared_ptr<const StateField> field;
};

Solution solve(const Scene& scene, const Options& options = {});

// Fills solution.profile with `stations` equally spaced states over the whole arch from its field.
void sample_profile(Solution& solution, int stations);

// The error measure of a profile against a reference at the same stations: the largest difference of
// the displacement (Ux, Uy) relative to the largest |U| of the reference, of psi relative to the
// largest |psi|, of the forces (N, V) relative to the largest resultant, and of M relative to the
// larger of max |M| and max |N| t / 6 (the moment that puts the thrust line at the kern's edge, so that
// it measures e in units of the kern). NaN if the sizes differ, either is empty or holds non-finite values.
double profile_difference(const std::vector<ArchState>& profile, const std::vector<ArchState>& reference,
                          double thickness);

}  // namespace ogive
