// The linear programs' private parts (limit_lp.cpp and limit_lp_friction.cpp; no other file): the
// unknowns, the tolerances and the programs' state, LimitLp::Impl. No LP library here (limit_lp.cpp only).
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "limit/dense_lp.hpp"
#include "limit/limit_internal.hpp"

namespace ogive::limit_detail {

enum Column { kH = 0, kV = 1, kM = 2, kLambda = 3, kMu = 4, kUnknowns = 5 };

// The gradient of what a program maximises, over the scaled unknowns.
using Objective = std::array<double, kUnknowns>;

// Bounds that keep every program bounded (in units of the total load W and the span L, far beyond any
// arch's real values); an optimum on one of them means "no finite answer".
constexpr double kCap = 1e6;

// Only the margin's sign matters; bounded, it stays finite where the thrust may grow without bound (a
// flat, thick arch holds a straight thrust line of any H).
constexpr double kMaxMargin = 1.0;

// Feasibility and optimality tolerances of the scaled programs (coefficients of order one).
constexpr double kFeasibility = 1e-11;

// The ratio of the live to the dead load (either way) beyond which the collapse program is solved in
// units of the dead load (LimitLp::collapse): below it the two scales differ by less than this factor, and
// the answers by far less than the limit tolerance.
constexpr double kCollapseScaleRatio = 1e3;

using Inequality = DenseRow;

// LimitLp's rows: the joints', then the sign rows of H and lambda, then the caps (unknown c's z_c <= cap at
// 2c and -z_c <= cap at 2c + 1 from there), then (finite f_c) the crushing cuts.
constexpr int kSignRows = 2;

// The crushing condition of a face (finite f_c) holds at a vertex when violated by no more than this, in
// the program's units (W L, as every row): the tolerance of the LP's own rows. A tangent cut at the
// vertex's own normal force is violated exactly as much, so the LP leaves it there.
constexpr double kCrushingTolerance = kFeasibility;
// The programs one question may solve for its crushing cuts: with the Newton step below, a handful;
// plain tangent cuts alone (each round quarters the violation) within about twenty.
constexpr int kMaxCutRounds = 60;
// Newton's steps on the tight rows, and the residual (in the rows' units) at which it has converged.
constexpr int kMaxNewtonSteps = 30;
constexpr double kNewtonResidual = 1e-14;

// A program with the unknowns in `fixed` (NaN: free) held: the free unknowns, and every row's right-hand
// side with the held unknowns moved there.
struct Held {
  std::vector<int> free;
  std::vector<double> b;
  bool infeasible = false;  // a row of held unknowns only is violated
};

struct LimitLp::Impl {
  LpWorkspace::Impl* workspace = nullptr;
  LpSolver solver = LpSolver::dense;
  LiveKind live = LiveKind::vertical;
  std::vector<Inequality> rows;
  double weight = 1, span = 1;  // the scales: forces in W, lengths in L
  double dead_weight = 0, live_weight = 0;  // the dead and the live loads in magnitude (W their sum)
  int joint_rows = 0;  // the rows of the joints, before the sign and cap rows
  // lambda = lambda_scale times the program's own unknown (1 but in the collapse at the loads' scale)
  double lambda_scale = 1;
  mutable int fallbacks = 0;
  std::vector<RowKey> keys;  // each joint, sign and cap row's, ascending
  // Work areas kept from one program (and one ring) to the next.
  LoadsLeftOfJoints left;
  mutable Held held;

  // Crushing (finite f_c): f_c in the program's units (f_c L / W; infinity: none), and for each joint its
  // normal force N = a . z + c and the index of its intrados row (the extrados row follows it).
  double strength = std::numeric_limits<double>::infinity();
  struct Normal {
    std::array<double, kUnknowns> a{};
    double c = 0;
    int face_row = 0;
  };
  std::vector<Normal> normals;
  // Friction: per joint the index of its first friction row (the second follows) and its shear and
  // normal force as linear functions of the unknowns (T = along . z + c, N = normal . z + c, program
  // units), and the friction coefficient.
  struct Sliding {
    int row = 0;
    Normal along, normal;
  };
  std::vector<Sliding> sliding;
  double friction = 0;
  std::vector<Inequality> coulomb;  // the friction rows as load() made them, while hold_sliding holds N
  std::vector<int> row_face;  // per joint row: 2 j + face (0 intrados, 1 extrados) of a face row, else -1
  // The cuts, rows cuts_begin on: joint, face and the normal force (N/m) they touch the condition at.
  struct Cut {
    int joint = 0, face = 0;
    double force = 0;
  };
  int cuts_begin = 0;
  std::vector<Cut> cuts, previous_cuts;  // previous_cuts: the last ring's (warm starts by index)
  std::size_t previous_joints = 0;
  int cut_rounds = 0;

  // Maximises objective . z (scaled unknowns) with the unknowns in `fixed` (NaN: free) held.
  Answer optimise(const Objective& objective, const std::array<double, kUnknowns>& fixed,
                  const std::vector<int>* warm = nullptr);
  // The optimum of the dense method or of Clp: the scaled unknowns (the held ones as given) and the basis.
  struct Solved {
    Outcome outcome = Outcome::failure;
    std::array<double, kUnknowns> z{};
    std::vector<int> basis;
  };
  mutable int programs = 0;  // the linear programs solve() solved
  Solved solve(const Held& h, const std::array<double, kUnknowns>& fixed, const Objective& objective,
               const std::vector<int>* warm) const {
    ++programs;
    return solver == LpSolver::dense ? dense(h, fixed, objective, warm) : clp(h, fixed, objective, warm);
  }
  Solved dense(const Held& h, const std::array<double, kUnknowns>& fixed, const Objective& objective,
               const std::vector<int>* warm) const;
  Solved clp(const Held& h, const std::array<double, kUnknowns>& fixed, const Objective& objective,
             const std::vector<int>* warm) const;
  // The answer in SI units from the scaled unknowns z; unbounded where an unknown the objective pushes
  // reached its cap.
  Answer unscaled(std::array<double, kUnknowns> z, const Objective& objective) const;
  Answer finish(const Solved& s, const Objective& objective) const {
    Answer a;
    a.outcome = s.outcome;
    if (s.outcome != Outcome::optimal) return a;
    a = unscaled(s.z, objective);
    a.basis = s.basis;
    return a;
  }

  // The crushing program (finite f_c): optimise's question solved exactly by tangent cuts.
  Answer crushed(const Objective& objective, const std::array<double, kUnknowns>& fixed,
                 const std::vector<int>* warm);
  double normal_force(int joint, const std::array<double, kUnknowns>& z) const {
    const Normal& n = normals[static_cast<std::size_t>(joint)];
    return n.c + n.a[0] * z[0] + n.a[1] * z[1] + n.a[2] * z[2] + n.a[3] * z[3] + n.a[4] * z[4];
  }
  // How far z breaks the crushing condition of the joint's face (> 0: broken), in the rows' units.
  double crushing(int joint, int face, const std::array<double, kUnknowns>& z) const {
    return crushing(joint, face, z, normal_force(joint, z));
  }
  // The same with the joint's normal force N at z given (both faces share it).
  double crushing(int joint, int face, const std::array<double, kUnknowns>& z, double N) const {
    const Inequality& row = rows[static_cast<std::size_t>(normals[static_cast<std::size_t>(joint)].face_row + face)];
    double g = -row.b;
    for (int c = 0; c < kUnknowns; ++c) g += row.a[c] * z[c];
    return g + N * N / (2 * strength);
  }
  // The tangent cut of the face's condition at normal force N0 (program units; N^2 >= 2 N0 N - N0^2).
  Inequality cut_row(int joint, int face, double N0) const;
  // Appends the cut at N0 (unless the face has one there already); its row.
  int add_cut(int joint, int face, double N0);
  // The face (2 j + face) whose condition row r stands for, or -1 for a row of no face.
  int face_of(int r) const {
    if (r >= cuts_begin) {
      const Cut& c = cuts[static_cast<std::size_t>(r - cuts_begin)];
      return 2 * c.joint + c.face;
    }
    return r < joint_rows ? row_face[static_cast<std::size_t>(r)] : -1;
  }
  // Newton's method from z on the basis' rows, each face's as its exact condition: the tangent cuts at
  // its solution (the optimum when the basis' rows are the optimum's active ones), and the basis with
  // those cuts for its faces' rows (the basis itself when its rows hold their conditions at z already);
  // empty when it fails.
  std::vector<int> newton(const std::vector<int>& basis, std::array<double, kUnknowns>& z,
                          const std::vector<int>& free);
  // newton() on the basis from z, and the vertex of the basis it returns (held's right-hand sides
  // extended to its cuts); an empty basis when it fails.
  Solved refined(const std::vector<int>& basis, const std::array<double, kUnknowns>& z,
                 const std::array<double, kUnknowns>& fixed);
  // Whether s (z and a basis of cuts tight there) is the crushing program's optimum (the KKT conditions,
  // to the LP's tolerances), so that no program need confirm it.
  bool optimal(const Solved& s, const Objective& objective, const std::vector<int>& free) const;
  // A warm basis with the last ring's cuts made anew here (when the joints are as many).
  std::vector<int> carried(const std::vector<int>& warm);
};

}  // namespace ogive::limit_detail
