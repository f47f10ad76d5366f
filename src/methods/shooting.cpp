#include "methods/shooting.hpp"

#include <algorithm>
#include <initializer_list>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "methods/bvp.hpp"
#include "methods/cvode/cvode_integrator.hpp"

namespace ogive {
namespace {

// ArchModel's problem as the integrator's system: Y' = A(theta(s)) Y + (b(s) e_Fy - h(s) e_Fx) e_last^T
// (the load rides on the last column: the particular solution, or the one state of a field's integration).
class ArchSystem final : public OdeSystem {
 public:
  explicit ArchSystem(const ArchModel& model) : model_(model) {}
  bool rhs(double s, const Eigen::Ref<const OdeMatrix>& Y, Eigen::Ref<OdeMatrix> dY) const override {
    if (model_.curved()) return curved_rhs(s, Y, dY);
    const ArchModel::SystemEntries A = model_.system_entries(model_.theta(s));
    for (Eigen::Index j = 0; j < Y.cols(); ++j) ArchModel::apply_system_matrix(A, Y.col(j).data(), dY.col(j).data());
    dY(kFy, Y.cols() - 1) += model_.load(s);
    if (model_.acceleration() != 0) dY(kFx, Y.cols() - 1) -= model_.horizontal_load(s);
    return true;
  }
  SystemMatrix jacobian_block(double s, const Eigen::Ref<const OdeMatrix>&) const override {
    if (model_.curved()) return model_.curved_system_matrix(model_.theta(s), model_.curved_bar(model_.kappa(s)));
    return model_.system_matrix(model_.theta(s));
  }
  const std::vector<double>& breakpoints() const override { return model_.breakpoints(); }

 private:
  // The curved bar (ArchModel::curved_bar): its section's terms at s; the self-weight's couple on the
  // load column.
  bool curved_rhs(double s, const Eigen::Ref<const OdeMatrix>& Y, Eigen::Ref<OdeMatrix> dY) const {
    const double theta = model_.theta(s), c = std::cos(theta), sn = std::sin(theta);
    const ArchModel::CurvedBar bar = model_.curved_bar(model_.kappa(s));
    const Eigen::Index last = Y.cols() - 1;
    for (Eigen::Index j = 0; j < last; ++j)
      model_.curved_derivative(c, sn, bar, Y.col(j).data(), dY.col(j).data(), 0.0, 0.0, false);
    model_.curved_derivative(c, sn, bar, Y.col(last).data(), dY.col(last).data(), model_.load(s),
                             model_.horizontal_load(s), true);
    return true;
  }
  const ArchModel& model_;
};

// Multiple shooting's segments integrated together, each in its own normalised parameter tau in [0, 1]:
// s = a_k + tau h_k, dY_k/dtau = h_k (A(theta(s)) Y_k + b(s) e_Fy e_last^T). One CVODE run instead of
// one per segment: Adams starts at order 1 with tiny steps and needs about 45 steps to reach order 9
// (a step trace of the equilateral arch: 61 steps in all, of which the first 30 cover 3 % of it), and
// its fixed cost per step (about the same for 30 numbers as for 300) is paid once for all segments.
// CvodeIntegrator's blocks hold each segment to the tolerance it would meet alone. Segment k's s is
// kept strictly inside it, so at its ends the system sees that segment (the knots include every
// breakpoint); segment k's columns follow segment k - 1's.
class SegmentsSystem final : public OdeSystem {
 public:
  SegmentsSystem(const ArchModel& model, const std::vector<double>& knots, const std::vector<int>& widths)
      : model_(model) {
    Eigen::Index column = 0;
    for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
      const double a = knots[k], b = knots[k + 1];
      segments_.push_back({a, b - a, std::nextafter(a, b), std::nextafter(b, a), column, widths[k]});
      column += widths[k];
    }
  }
  bool rhs(double tau, const Eigen::Ref<const OdeMatrix>& Y, Eigen::Ref<OdeMatrix> dY) const override {
    for (const Segment& g : segments_) {
      const double s = std::clamp(g.start + tau * g.length, g.inside_start, g.inside_end);
      const double theta = model_.theta(s), c = std::cos(theta), sn = std::sin(theta);
      const Eigen::Index last = g.column + g.width - 1;
      if (model_.curved()) {
        const ArchModel::CurvedBar bar = model_.curved_bar(model_.kappa(s));
        for (Eigen::Index j = g.column; j < last; ++j)
          model_.curved_derivative(c, sn, bar, Y.col(j).data(), dY.col(j).data(), 0.0, 0.0, false);
        model_.curved_derivative(c, sn, bar, Y.col(last).data(), dY.col(last).data(), model_.load(s),
                                 model_.horizontal_load(s), true);
        dY.middleCols(g.column, g.width) *= g.length;
        continue;
      }
      for (Eigen::Index j = g.column; j < last; ++j) model_.derivative(c, sn, Y.col(j).data(), dY.col(j).data(), 0.0);
      model_.derivative(c, sn, Y.col(last).data(), dY.col(last).data(), model_.load(s), model_.horizontal_load(s));
      dY.middleCols(g.column, g.width) *= g.length;
    }
    return true;
  }
  SystemMatrix jacobian_block(double, const Eigen::Ref<const OdeMatrix>&) const override {
    // The blocks differ by segment: BDF, whose linear solver factors one block for every column, keeps
    // one integration per segment.
    throw std::logic_error("SegmentsSystem: Adams only");
  }
  const std::vector<double>& breakpoints() const override { return none_; }
  Eigen::Index column(std::size_t k) const { return segments_[k].column; }
  double s_at(std::size_t k, double tau) const { return segments_[k].start + tau * segments_[k].length; }

 private:
  struct Segment {
    double start, length, inside_start, inside_end;
    Eigen::Index column;
    int width;
  };
  const ArchModel& model_;
  std::vector<Segment> segments_;
  std::vector<double> none_;
};

// Where CVODE stopped: e.s is the scaled arc length, or, for segments integrated together, the fraction
// tau of every segment's length (then s is given in the first segment).
std::string failure_message(const IntegrationError& e, const ArchModel& model, std::size_t segment,
                            std::size_t segments, const SegmentsSystem* together) {
  const double L = model.scales().length;
  std::string text =
      together ? fmt::format("CVODE {} at {:.3g} of every segment's length, s = {:.6g} m in the first (the {} "
                             "segments integrated together)",
                             e.flag_name, e.s, together->s_at(0, e.s) * L, segments)
               : fmt::format("CVODE {} at s = {:.6g} m (shooting segment {} of {})", e.flag_name, e.s * L,
                             segment + 1, segments);
  if (!e.detail.empty()) text += ": " + e.detail;
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

// The shooting solution's field: integrates the solved state from the start of its piece; kept as
// CVODE's dense output when a summary will search it (Options::unprinted_profile).
class ShootingField final : public PiecewiseField {
 public:
  ShootingField(std::shared_ptr<const ArchModel> model, const Options& options, std::vector<double> knots,
                std::vector<StateVector> starts)
      : PiecewiseField(std::move(knots), std::move(starts)), model_(std::move(model)), system_(*model_),
        options_(options), pieces_(options.unprinted_profile) {}

 protected:
  void propagate(double s_k, const StateVector& y_k, std::span<const double> s,
                 std::span<StateVector> out) const override {
    const CvodeTolerances tol = cvode_tolerances(options_);
    auto sample = [&](double atol) {
      pieces_.sample(s_k, y_k, piece_end(s_k), s, out, [&] {
        return std::make_unique<CvodeIntegrator>(system_, options_.integrator, tol.rtol, atol, options_.max_steps, 1,
                                                 options_.restart_at_breakpoints);
      });
    };
    sample(tol.atol);
    // A piece that starts at a crown hinge starts with M = 0, and an atol of 1e-6 of a tight rtol can
    // hold it below its own round-off: CVODE stops short and the piece's stations have no numbers
    // (multiple shooting of the whole three-hinged arch at CVODE rtol 3.9e-13: 16 of 129 stations).
    // Once more with retry_atol; a piece that still fails keeps its NaNs (no estimate).
    if (!out.empty() && !out[0].allFinite()) sample(retry_atol(tol.atol));
  }

 private:
  std::shared_ptr<const ArchModel> model_;
  ArchSystem system_;
  Options options_;
  FieldPieces pieces_;
};

// A later segment of multiple shooting integrates the columns of unit psi, Fx, Fy, M and the load's.
constexpr int kIntegratedColumns = 5;
constexpr std::array<int, 4> kIntegratedStarts = {kPsi, kFx, kFy, kM};

}  // namespace

CvodeTolerances cvode_tolerances(const Options& o) {
  const double factor = o.integrator == Integrator::adams ? 0.1 : 0.001;
  CvodeTolerances t;
  t.rtol = std::max(o.rtol * factor, kCvodeRtolFloor);
  // The scaled state is of order one; components that pass through zero would otherwise be held to an
  // absolute error of order rtol, which the measured errors showed to dominate. Hence a low floor.
  t.atol = o.atol > 0 ? o.atol : t.rtol * 1e-6;
  return t;
}

double retry_atol(double atol) { return std::max(16 * atol, kRetryAtol); }

std::vector<double> shooting_knots(const ArchModel& model, int segments, bool at_breakpoints) {
  const double S = model.length();
  std::vector<double> extra;
  if (segments > 1) {
    for (int k = 1; k < segments; ++k) extra.push_back(S * k / segments);
    if (at_breakpoints) extra.insert(extra.end(), model.breakpoints().begin(), model.breakpoints().end());
  }
  return merge_knots(model, extra);
}

constexpr std::size_t kTogetherSegments = 4096;

// Multiple shooting's segments integrated together with Adams (SegmentsSystem), in runs of at most
// kTogetherSegments: one run up to that many (a survey of 10^5 points, cut at each one, would otherwise
// hold every segment's columns in each of CVODE's twenty-odd vectors: a gigabyte). The first segment
// carries the march's map (m + 1 columns), every later one starts afresh (kIntegratedColumns).
class TogetherRuns {
 public:
  TogetherRuns(const ArchModel& model, const std::vector<double>& knots, const Options& options, int m)
      : model_(model), knots_(knots), options_(options), tol_(cvode_tolerances(options)), m_(m) {}
  // Integrates the run whose first segment is `first` (the first segment from Y0, the others from start).
  template <class Start>
  std::optional<IntegrationError> integrate(std::size_t first, const AffineState& Y0, const Start& start) {
    const std::size_t K = knots_.size() - 1, last = std::min(K, first + kTogetherSegments);
    if (integrator_) add(integrator_->stats());
    integrator_.reset();
    std::vector<int> widths(last - first, kIntegratedColumns);
    if (first == 0) widths[0] = m_ + 1;
    const std::vector<double> run_knots(knots_.begin() + static_cast<std::ptrdiff_t>(first),
                                        knots_.begin() + static_cast<std::ptrdiff_t>(last) + 1);
    system_.emplace(model_, run_knots, widths);
    integrator_.emplace(*system_, options_.integrator, tol_.rtol, tol_.atol, options_.max_steps, widths,
                        options_.restart_at_breakpoints);
    first_ = first;
    OdeMatrix initial(kStateSize, std::accumulate(widths.begin(), widths.end(), 0));
    for (std::size_t k = first; k < last; ++k)
      if (k == 0) initial.leftCols(m_ + 1) = Y0;
      else initial.middleCols(system_->column(k - first), kIntegratedColumns) = start;
    const double one = 1.0;
    return integrator_->integrate(0.0, initial, std::span<const double>(&one, 1),
                                  [&](std::size_t, const CvodeIntegrator::Matrix& Y) { end_ = Y; });
  }
  // Segment k's columns at its end (k in the last run integrated).
  OdeMatrix end_of(std::size_t k, int width) const { return end_.middleCols(system_->column(k - first_), width); }
  const SegmentsSystem* system() const { return system_ ? &*system_ : nullptr; }
  IntegratorStats stats() const {
    IntegratorStats s = done_;
    if (integrator_) add_to(s, integrator_->stats());
    return s;
  }

 private:
  static void add_to(IntegratorStats& to, const IntegratorStats& st) {
    to.steps += st.steps;
    to.rhs_evaluations += st.rhs_evaluations;
    to.error_test_failures += st.error_test_failures;
    to.jacobian_evaluations += st.jacobian_evaluations;
  }
  void add(const IntegratorStats& st) { add_to(done_, st); }
  const ArchModel& model_;
  const std::vector<double>& knots_;
  const Options& options_;
  CvodeTolerances tol_;
  int m_;
  std::optional<SegmentsSystem> system_;
  std::optional<CvodeIntegrator> integrator_;
  IntegratorStats done_;  // of the runs before the current one
  OdeMatrix end_;
  std::size_t first_ = 0;
};

Solution solve_shooting(std::shared_ptr<const ArchModel> model, const Options& options, int segments) {
  Solution sol;
  sol.method = segments == 1 ? Method::shooting : Method::multiple_shooting;
  sol.model = model;
  const std::vector<double> knots = shooting_knots(*model, segments, options.restart_at_breakpoints);
  const std::size_t K = knots.size() - 1;
  sol.diagnostics.segments = static_cast<int>(K);

  const CvodeTolerances tol = cvode_tolerances(options);
  const ArchSystem system(*model);
  // Single shooting carries the state's affine map [T | c] from the springing to the end: its m unknown
  // directions and the particular solution (4 columns; 5 with a hinge, whose column is 0 before it),
  // across point loads and the hinge (march adds them between pieces). Multiple shooting integrates that
  // only over its first segment; every later one starts afresh, so that no integration error grows over
  // more than one segment, and its transfer y(b) = Phi y(a) + p is applied to the map. Of Phi's six
  // columns those of unit psi, Fx, Fy and M are integrated, with p (5 columns, not 7): a unit Ux or Uy
  // at the segment's start stays a unit Ux or Uy exactly (nothing depends on the displacements). (The
  // rigid rotation's column could come from the curve's positions instead, but integrating it keeps
  // the verified error estimate of slender arches lower.)
  const int m = unknown_count(*model);
  const bool later_segments = segments > 1 && K > 1;
  // Adams integrates the segments together (SegmentsSystem), in runs of at most kTogetherSegments (one
  // run up to that many: a survey of 10^5 points, cut at each one, would otherwise hold every segment's
  // columns in each of CVODE's twenty-odd vectors, a gigabyte); BDF one segment after the other.
  const bool together = later_segments && options.integrator == Integrator::adams;
  CvodeIntegrator carried(system, options.integrator, tol.rtol, tol.atol, options.max_steps, m + 1,
                          options.restart_at_breakpoints);
  std::optional<CvodeIntegrator> fresh;
  if (later_segments && !together)
    fresh.emplace(system, options.integrator, tol.rtol, tol.atol, options.max_steps, kIntegratedColumns,
                  options.restart_at_breakpoints);
  std::optional<IntegrationError> failure;
  std::size_t failed_piece = 0;
  auto integrate = [&](CvodeIntegrator& integrator, std::size_t k, const OdeMatrix& Y0, OdeMatrix& Y1) {
    const double end = knots[k + 1];
    failure = integrator.integrate(knots[k], Y0, std::span<const double>(&end, 1),
                                   [&](std::size_t, const CvodeIntegrator::Matrix& Y) { Y1 = Y; });
    failed_piece = k;
    return !failure;
  };
  // A later segment's start: unit psi, Fx, Fy and M, and the load's column at zero (fixed size: single
  // shooting, the hot path, allocates nothing for it).
  Eigen::Matrix<double, kStateSize, kIntegratedColumns> start = Eigen::Matrix<double, kStateSize, kIntegratedColumns>::Zero();
  for (int j = 0; j < 4; ++j) start(kIntegratedStarts[j], j) = 1.0;
  std::optional<TogetherRuns> runs;
  if (together) runs.emplace(*model, knots, options, m);
  March marched;
  const bool ok = march(*model, knots,
                        [&](std::size_t k, AffineState& Y) {
                          if (together && k % kTogetherSegments == 0) {
                            failure = runs->integrate(k, Y, start);
                            failed_piece = k;
                            if (failure) return false;
                          }
                          if (together && k == 0) {
                            Y = runs->end_of(0, m + 1);
                            return true;
                          }
                          if (!later_segments || k == 0) {
                            OdeMatrix end;
                            if (!integrate(carried, k, OdeMatrix(Y), end)) return false;
                            Y = end;
                            return true;
                          }
                          OdeMatrix G;
                          if (together) G = runs->end_of(k, kIntegratedColumns);
                          else if (!integrate(*fresh, k, start, G)) return false;
                          SystemMatrix Phi = SystemMatrix::Identity();
                          for (int j = 0; j < 4; ++j) Phi.col(kIntegratedStarts[j]) = G.col(j);
                          const AffineState next = Phi.lazyProduct(Y);
                          Y = next;
                          Y.col(Y.cols() - 1) += G.col(4);
                          return true;
                        },
                        marched);
  const IntegratorStats together_stats = runs ? runs->stats() : IntegratorStats{};
  for (const IntegratorStats* stats : std::initializer_list<const IntegratorStats*>{
           &carried.stats(), fresh ? &fresh->stats() : nullptr, &together_stats}) {
    if (!stats) continue;
    const IntegratorStats& st = *stats;
    sol.diagnostics.steps += st.steps;
    sol.diagnostics.rhs_evaluations += st.rhs_evaluations;
    sol.diagnostics.error_test_failures += st.error_test_failures;
    sol.diagnostics.jacobian_evaluations += st.jacobian_evaluations;
  }
  if (!ok) {
    sol.status = Status::integrator_failure;
    sol.message = failure ? failure_message(*failure, *model, failed_piece, K,
                                            together ? runs->system() : nullptr)
                          : "integration failed";
    return sol;
  }
  // The condition of the boundary-value problem, not of a discretisation of it: the equations in the
  // unknowns are condensed through every segment's transfer, and judged by the same function as the
  // closed form's.
  BvpSolution bvp = solve_march(*model, std::move(marched));
  auto field = std::make_shared<ShootingField>(model, options, std::move(bvp.knots), std::move(bvp.starts));
  finish_solution(sol, bvp, std::move(field));
  return sol;
}

}  // namespace ogive
