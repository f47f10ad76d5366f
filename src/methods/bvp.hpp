// Shared by the methods (private header): the one boundary-value solve of ArchModel's problem, whatever
// method supplied the transfers, and the bookkeeping that turns its solution into a Solution.
//
// The unknowns z are the left springing's three free components (the conditions fix the other three),
// then, with a hinge inside the domain, the jump of psi there. Every state is affine in z: y = T z + c,
// carried as one matrix [T | c] (an AffineState, 6 x (m + 1)). A method marches it from the springing to
// the domain's end piece by piece (march): by integrating its columns (single shooting: 4 columns, 5
// with a hinge), or by applying each piece's transfer y(b) = Phi y(a) + p (closed form, multiple
// shooting). Between pieces the march adds the point loads' jumps and opens the hinge's column. The end
// conditions and the hinge's M = 0 are then m equations in z (solve_march): K = 1 piece is single
// shooting, K > 1 the same equations, condensed.
#pragma once

#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "ogive/core/solution.hpp"

namespace ogive {

// At most 4 unknowns (+ the constant column): fixed-capacity storage, so that the closed form's and the
// quadrature's whole solve allocates nothing (dynamic matrices doubled the time of a closed-form scene).
inline constexpr int kMaxUnknowns = 4;
using AffineState = Eigen::Matrix<double, kStateSize, Eigen::Dynamic, Eigen::ColMajor, kStateSize, kMaxUnknowns + 1>;
using AffineRow = Eigen::Matrix<double, 1, Eigen::Dynamic, Eigen::RowMajor, 1, kMaxUnknowns + 1>;
using ReducedMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxUnknowns, kMaxUnknowns>;
using ReducedVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxUnknowns, 1>;

// The springing's conditions fix three components of y(0) (Ux, Uy and psi or M), so y(0) = start + U u:
// each column of U a unit free component and what it moves the fixed ones by (a held face's compliance).
struct SpringingSplit {
  Eigen::Matrix<double, kStateSize, 3> U = Eigen::Matrix<double, kStateSize, 3>::Zero();
  StateVector start = StateVector::Zero();
};
SpringingSplit springing_split(const ArchModel& model);

// The number of unknowns m: 3, plus 1 with a hinge inside the domain.
int unknown_count(const ArchModel& model);

// The piece boundaries every method must stop at: 0, the point loads and the hinge strictly inside, S~.
std::vector<double> required_knots(const ArchModel& model);
// Those knots merged with `extra` (inside (0, S~)), ascending, knots closer than 1e-9 S~ merged onto the
// required one.
std::vector<double> merge_knots(const ArchModel& model, std::vector<double> extra);

// The march: [T | c] at each piece's start (after that knot's jump and hinge) and at the end (after a
// point load there), with the hinge's M row just before it.
struct March {
  std::vector<double> knots;          // s_0 = 0 < ... < s_K = S~
  std::vector<AffineState> starts;    // K entries
  AffineState end;
  AffineRow hinge_row;                // m + 1: the M row just before the hinge; empty without one
  SpringingSplit split;               // the springing's, for the solve
};

// Moves Y (= [T | c], m + 1 columns) from knots[k] to knots[k + 1]; false on failure (the method keeps
// its reason).
using Advance = std::function<bool(std::size_t k, AffineState& Y)>;
// Marches through `knots` (from required_knots or merge_knots); false if an advance failed.
bool march(const ArchModel& model, const std::vector<double>& knots, const Advance& advance, March& out);

struct BvpSolution {
  StateVector y0 = StateVector::Zero();  // scaled state at the left springing (before a load there)
  StateVector yS = StateVector::Zero();  // scaled state at the domain's end (after a load there)
  std::vector<double> knots;             // the march's
  std::vector<StateVector> starts;       // the state at each piece's start
  double hinge_moment = 0;               // M just before the hinge (0 to round-off)
  double condition = std::numeric_limits<double>::infinity();  // boundary_value_condition
};

// Skeel's condition number || |Q^-1| |Q| ||_inf of the m x m matrix Q of the equations in z: the
// relative error that round-off in the conditions can cause in the solution, whatever the units of the
// rows. Infinite when Q is singular. Every method reports this one number for a scene.
double boundary_value_condition(const ReducedMatrix& Q);

// Solves the end conditions and the hinge's for z; the states follow (the march's knots move into it).
BvpSolution solve_march(const ArchModel& model, March&& march);

// The whole transfer y(S~) = Phi y(0) + p of a model without jumps or hinge, solved (the quadrature's).
BvpSolution solve_single_segment(const ArchModel& model, const SystemMatrix& Phi, const StateVector& p);

// Fills reactions, residuals and the condition estimate from bvp's ends, hinge moment and condition (its
// knots and starts may have been moved into the field). Status success (provisional: solve() judges
// it against rtol with judge_solution), or singular_system when the condition exceeds 1 / round-off.
void finish_solution(Solution& sol, const BvpSolution& bvp, std::shared_ptr<const StateField> field);

// A field made of pieces: the state at every piece's start and a way to carry it to any s inside the
// piece. Samples at a knot come from the piece that ends there (the state before a point load or a hinge).
class PiecewiseField : public StateField {
 public:
  PiecewiseField(std::vector<double> knots, std::vector<StateVector> starts)
      : knots_(std::move(knots)), starts_(std::move(starts)) {}
  void sample(std::span<const double> s, std::span<StateVector> out) const override;

 protected:
  // The states at s (ascending, inside the piece that starts at s_k) from the piece's start state y_k.
  virtual void propagate(double s_k, const StateVector& y_k, std::span<const double> s,
                         std::span<StateVector> out) const = 0;
  // The end of the piece that starts at s_k.
  double piece_end(double s_k) const;

 private:
  std::vector<double> knots_;
  std::vector<StateVector> starts_;
};


}  // namespace ogive
