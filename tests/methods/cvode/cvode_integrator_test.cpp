// The CVODE wrapper on its own (src/methods/cvode/cvode_integrator.hpp), on Y' = -k Y: the vector kernels compiled
// for a fixed length against those for any length, the block norm, ogive's fixed-point solver where its
// iteration fails, and misuse.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

#include "methods/cvode/cvode_integrator.hpp"
#include "ogive/model/arch_model.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

// Y' = -k Y, k_i the decay rate of row i: stiff where k h > 1 for some row, and there Adams'
// fixed-point iteration diverges.
class Decay final : public OdeSystem {
 public:
  explicit Decay(StateVector k, std::vector<double> breakpoints = {})
      : k_(std::move(k)), breakpoints_(std::move(breakpoints)) {}
  bool rhs(double, const Eigen::Ref<const OdeMatrix>& Y, Eigen::Ref<OdeMatrix> dY) const override {
    dY = -(k_.asDiagonal() * Y);
    return true;
  }
  SystemMatrix jacobian_block(double, const Eigen::Ref<const OdeMatrix>&) const override {
    return SystemMatrix((-k_).asDiagonal());
  }
  const std::vector<double>& breakpoints() const override { return breakpoints_; }

 private:
  StateVector k_;
  std::vector<double> breakpoints_;
};

OdeMatrix integrate_to(CvodeIntegrator& integrator, const OdeMatrix& Y0, double end) {
  OdeMatrix out;
  const auto failure = integrator.integrate(0.0, Y0, std::span<const double>(&end, 1),
                                            [&](std::size_t, const OdeMatrix& Y) { out = Y; });
  REQUIRE_FALSE(failure);
  return out;
}

}  // namespace

TEST_CASE("CVODE wrapper: a block integrated alone and beside its copy gives the same bits") {
  // Four columns (24 numbers: the kernels compiled for that length, one block) against the same four
  // twice, as blocks {4, 4} (48 numbers: the kernels for any length and the block norm). With identical
  // blocks every norm CVODE takes (its error test, its iteration's convergence, its first step) is the
  // single block's, so every step is the same and so is every bit of the result.
  StateVector k;
  k << 1.0, 3.0, 0.5, 2.0, 5.0, 0.25;
  const Decay system(k);
  OdeMatrix Y0(kStateSize, 4);
  for (Eigen::Index j = 0; j < 4; ++j)
    for (Eigen::Index i = 0; i < kStateSize; ++i) Y0(i, j) = std::cos(1.0 + i + 7.0 * j);  // of both signs
  OdeMatrix twice(kStateSize, 8);
  twice << Y0, Y0;
  for (const Integrator kind : {Integrator::adams, Integrator::bdf}) {
    CAPTURE(static_cast<int>(kind));
    CvodeIntegrator alone(system, kind, 1e-9, 1e-15, 100000, 4);
    CvodeIntegrator paired(system, kind, 1e-9, 1e-15, 100000, std::vector<int>{4, 4});
    const OdeMatrix a = integrate_to(alone, Y0, 2.0);
    const OdeMatrix b = integrate_to(paired, twice, 2.0);
    CHECK(alone.stats().steps > 10);
    CHECK(paired.stats().steps == alone.stats().steps);
    CHECK(paired.stats().rhs_evaluations == alone.stats().rhs_evaluations);
    CHECK((b.leftCols(4).array() == a.array()).all());
    CHECK((b.rightCols(4).array() == a.array()).all());
  }
}

TEST_CASE("CVODE wrapper: Adams' fixed-point iteration fails on a stiff system, and CVODE recovers") {
  // One row decays at k = 1e4, the others at 1, over s in [0, 1]. Once the fast row has decayed, the
  // error test would allow steps of the slow rows' scale, k h >> 1, where the iteration diverges: each
  // failure makes CVODE retry with a smaller step. The slow rows must still meet the solver's stated
  // tolerance (measured: 0.14 rtol after about 12 000 steps, 2 000 of them failures of the iteration).
  const double rtol = 1e-8, end = 1.0;
  StateVector k = StateVector::Ones();
  k(kUx) = 1e4;
  const Decay system(k);
  CvodeIntegrator integrator(system, Integrator::adams, rtol, 1e-14, 1000000, 1);
  const OdeMatrix Y = integrate_to(integrator, OdeMatrix::Ones(kStateSize, 1), end);
  const IntegratorStats& st = integrator.stats();
  CAPTURE(st.steps);
  CHECK(st.convergence_failures > 0);
  const double exact = std::exp(-end);
  for (Eigen::Index i = 1; i < kStateSize; ++i)
    CHECK(std::abs(Y(i, 0) - exact) <= rtol * exact);
  // The fast row, exp(-1e4) in truth, to within rtol of its largest value (1).
  CHECK(std::abs(Y(kUx, 0)) <= rtol);
}

TEST_CASE("CVODE wrapper: tolerances must be positive") {
  const Decay system(StateVector::Ones());
  CHECK_THROWS_AS(CvodeIntegrator(system, Integrator::adams, 0.0, 1e-12, 1000, 1), std::invalid_argument);
  CHECK_THROWS_AS(CvodeIntegrator(system, Integrator::adams, 1e-8, 0.0, 1000, 1), std::invalid_argument);
  CHECK_THROWS_AS(CvodeIntegrator(system, Integrator::bdf, -1e-8, 1e-12, 1000, 1), std::invalid_argument);
}

TEST_CASE("CVODE wrapper: an output one ulp past the start or a breakpoint is that point's state") {
  // CVODE refuses to step to a tout within two round-offs of where it starts (CV_TOO_CLOSE). Stations
  // equally spaced over the arch round to one ulp past a shooting segment's knot or a curve's
  // breakpoint, and a whole piece of a profile came out without numbers. Such an output takes the state
  // where the span starts: the two differ by round-off.
  const double rtol = 1e-10, breakpoint = 0.3;
  // The global error on this short, smooth span, in units of the local tolerance.
  constexpr double kShortSpanGlobalError = 10;
  const Decay system(StateVector::Ones(), {breakpoint});
  const double start = 0.1;
  const std::vector<double> outputs = {std::nextafter(start, 1.0), std::nextafter(breakpoint, 0.0), breakpoint,
                                       std::nextafter(breakpoint, 1.0), 0.7};
  for (const Integrator kind : {Integrator::adams, Integrator::bdf}) {
    CAPTURE(static_cast<int>(kind));
    CvodeIntegrator integrator(system, kind, rtol, 1e-16, 100000, 1);
    std::vector<double> got(outputs.size(), std::nan(""));
    const auto failure = integrator.integrate(start, OdeMatrix::Ones(kStateSize, 1), outputs,
                                              [&](std::size_t i, const OdeMatrix& Y) { got[i] = Y(0, 0); });
    REQUIRE_FALSE(failure);
    for (std::size_t i = 0; i < outputs.size(); ++i) {
      CAPTURE(i);
      // The exact state exp(-(s - start)).
      CHECK(std::abs(got[i] - std::exp(-(outputs[i] - start))) <= kShortSpanGlobalError * rtol);
    }
  }
  // The last output one ulp past a breakpoint: the span from the breakpoint to it is too short to step.
  CvodeIntegrator integrator(system, Integrator::adams, rtol, 1e-16, 100000, 1);
  const double end = std::nextafter(breakpoint, 1.0);
  double got = std::nan("");
  const auto failure = integrator.integrate(start, OdeMatrix::Ones(kStateSize, 1), std::span<const double>(&end, 1),
                                            [&](std::size_t, const OdeMatrix& Y) { got = Y(0, 0); });
  REQUIRE_FALSE(failure);
  CHECK(std::abs(got - std::exp(-(end - start))) <= kShortSpanGlobalError * rtol);
}

TEST_CASE("CVODE wrapper: the dense output is CVODE's interpolant of the same steps, to round-off") {
  // integrate_dense keeps every step's polynomial (from CVodeGetDky) instead of interpolating at
  // outputs named in advance. Its steps are integrate()'s (the first sized toward each span's end), so
  // at every output, across a breakpoint, one ulp past it and at the ends, the two agree to a few
  // round-offs of the state (kDenseAgreement), and both meet the solver's tolerance against exp(-s).
  constexpr double kDenseAgreement = 8 * std::numeric_limits<double>::epsilon();
  constexpr double kGlobalError = 10;  // the global error on this smooth span, in units of rtol
  const double rtol = 1e-10, breakpoint = 0.3, start = 0.1, end = 1.7;
  StateVector k;
  k << 1.0, 3.0, 0.5, 2.0, 5.0, 0.25;
  const Decay system(k, {breakpoint});
  std::vector<double> outputs = {start, std::nextafter(start, 1.0), 0.2, std::nextafter(breakpoint, 0.0), breakpoint,
                                 std::nextafter(breakpoint, 1.0)};
  for (int i = 1; i <= 37; ++i) outputs.push_back(breakpoint + (end - breakpoint) * i / 37.0);
  const StateVector y0 = StateVector::Ones();
  for (const Integrator kind : {Integrator::adams, Integrator::bdf}) {
    CAPTURE(static_cast<int>(kind));
    CvodeIntegrator stepping(system, kind, rtol, 1e-16, 100000, 1), keeping(system, kind, rtol, 1e-16, 100000, 1);
    std::vector<StateVector> integrated(outputs.size());
    REQUIRE_FALSE(stepping.integrate(start, y0, outputs, [&](std::size_t i, const OdeMatrix& Y) { integrated[i] = Y.col(0); }));
    DenseTrajectory trajectory;
    REQUIRE_FALSE(keeping.integrate_dense(start, y0, end, trajectory));
    CHECK_FALSE(trajectory.failed());
    CHECK(keeping.stats().steps == stepping.stats().steps);
    for (std::size_t i = 0; i < outputs.size(); ++i) {
      CAPTURE(outputs[i]);
      const StateVector dense = trajectory.at(outputs[i]);
      CHECK((dense - integrated[i]).cwiseAbs().maxCoeff() <= kDenseAgreement);
      for (Eigen::Index r = 0; r < kStateSize; ++r)
        CHECK(std::abs(dense[r] - std::exp(-k[r] * (outputs[i] - start))) <= kGlobalError * rtol);
    }
    // Before its start and beyond its end the piece's ends: no extrapolation.
    CHECK((trajectory.at(start - 1) - y0).cwiseAbs().maxCoeff() == 0);
    CHECK((trajectory.at(end) - integrated.back()).cwiseAbs().maxCoeff() <= kDenseAgreement);
    CHECK((trajectory.at(end + 1) - trajectory.at(end)).cwiseAbs().maxCoeff() == 0);
  }
}

TEST_CASE("CVODE wrapper: a dense integration that cannot go on fails whole, within the step limit") {
  // A system whose right-hand side fails beyond s = 0.5: CVODE cannot pass it. Every state of the
  // trajectory is then non-finite (no plausible number), and a step limit of 50 steps holds per span.
  class Wall final : public OdeSystem {
   public:
    bool rhs(double s, const Eigen::Ref<const OdeMatrix>& Y, Eigen::Ref<OdeMatrix> dY) const override {
      dY = -Y;
      return s < 0.5;
    }
    SystemMatrix jacobian_block(double, const Eigen::Ref<const OdeMatrix>&) const override {
      return -SystemMatrix::Identity();
    }
    const std::vector<double>& breakpoints() const override { return none_; }

   private:
    std::vector<double> none_;
  } wall;
  CvodeIntegrator integrator(wall, Integrator::adams, 1e-8, 1e-14, 50, 1);
  DenseTrajectory trajectory;
  const auto failure = integrator.integrate_dense(0.0, StateVector::Ones(), 1.0, trajectory);
  REQUIRE(failure);
  CHECK(trajectory.failed());
  CHECK(integrator.stats().steps <= 50);
  for (double s : {0.0, 0.25, 0.75}) CHECK_FALSE(trajectory.at(s).allFinite());
}
