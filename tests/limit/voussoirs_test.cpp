// The ring of voussoirs (src/limit/voussoirs.cpp, make_ring): weights and centroids against the annulus,
// the pointed ring against its circular segments whatever the joints, the joints at a pointed crown,
// and a crown kink that no vertical joint can cut.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "ogive/limit/limit.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

constexpr double kGamma = 2348.0 * 9.81;  // the scenes' unit weight, N/m^3

}  // namespace

TEST_CASE("limit: the ring's weight and centroids are those of the annulus, the axis weight is rho g t per axis length") {
  const auto curve = make_pointed(10.0, 0.0);
  const double R = 5.0, t = 0.8, r_in = R - t / 2, r_out = R + t / 2;
  LimitOptions o;
  o.joints_count = 9;  // 45-degree voussoirs: the quadrature must be exact on large pieces too
  const Ring ring = make_ring(*curve, t, kGamma, o);
  REQUIRE(ring.voussoirs.size() == 8);
  CHECK(close(ring.total_weight(), kGamma * std::numbers::pi * R * t, kExact));
  // An annulus sector of angle 2b has its centroid at 2/3 (r_out^3 - r_in^3) / (r_out^2 - r_in^2) sin(b) / b.
  const double b = std::numbers::pi / 16;
  const double radius = 2.0 / 3.0 * (std::pow(r_out, 3) - std::pow(r_in, 3)) / (r_out * r_out - r_in * r_in) * std::sin(b) / b;
  for (std::size_t k = 0; k < ring.voussoirs.size(); ++k) {
    const double angle = std::numbers::pi - (2 * k + 1) * b;  // from the centre (L/2, 0), springing at pi
    CHECK(std::abs(ring.voussoirs[k].centroid.x() - (R + radius * std::cos(angle))) <= kExact * R);
    CHECK(std::abs(ring.voussoirs[k].centroid.y() - radius * std::sin(angle)) <= kExact * R);
  }
  o.weight = WeightModel::axis;
  const Ring axis = make_ring(*curve, t, kGamma, o);
  CHECK(close(axis.total_weight(), kGamma * t * 2.0 * curve->length(), kExact));
}

TEST_CASE("limit: the pointed ring weighs what the two annulus segments left of mid-span weigh, whatever the joints") {
  // Each half is the part of an annulus (centre eps L beyond mid-span, radii R -+ t/2) above the
  // springing line and before mid-span: half a circular segment of each disc, cut at d = eps L from the
  // centre, of area r^2 acos(d/r) - d sqrt(r^2 - d^2).
  const double eps = 0.5, L = 10.0, t = 1.5, R = (0.5 + eps) * L, d = eps * L;
  auto segment = [&](double r) { return r * r * std::acos(d / r) - d * std::sqrt(r * r - d * d); };
  const double area = segment(R + t / 2) - segment(R - t / 2);  // both halves
  for (JointOrientation j : {JointOrientation::radial, JointOrientation::vertical})
    for (int n : {9, kDefaultJointsCount}) {
      LimitOptions o;
      o.joints = j;
      o.joints_count = n;
      CHECK(close(make_ring(*make_pointed(L, eps), t, kGamma, o).total_weight(), kGamma * area, kExact));
    }
}

TEST_CASE("limit: at a pointed crown the crown joint is vertical and every joint cuts the arch in two") {
  for (JointOrientation j : {JointOrientation::radial, JointOrientation::vertical}) {
    LimitOptions o;
    o.joints = j;
    const Ring ring = make_ring(*make_pointed(10.0, 0.5), 1.5, kGamma, o);
    const Joint& crown = ring.joints[ring.joints.size() / 2];
    CHECK(crown.intrados.x() == 5.0);
    CHECK(crown.extrados.x() == 5.0);
    CHECK(crown.extrados.y() > crown.intrados.y());
    // The left half's joints lie left of mid-span, in order, both ends on the faces' correct sides.
    for (std::size_t k = 0; k + 1 < ring.joints.size() / 2; ++k) {
      CHECK(ring.joints[k].intrados.x() < 5.0);
      CHECK(ring.joints[k].extrados.x() < 5.0);
      CHECK(ring.joints[k + 1].intrados.x() > ring.joints[k].intrados.x());
      CHECK(ring.voussoirs[k].weight > 0);
    }
  }
}

TEST_CASE("limit: a whole curve whose crown is an asymmetric kink is refused, naming the curve") {
  // The left half of the equilateral arch (eps 0.5) joined at its crown to the mirror image of the left
  // half of a sharper pointed arch (eps 1.0), raised so that the crowns meet: the two sides' faces cut
  // the crown's vertical at different heights.
  class Kinked final : public Curve {
   public:
    Kinked() : left_(make_pointed(10.0, 0.5)), right_(make_pointed(10.0, 1.0)) {}
    CurveExtent extent() const override { return CurveExtent::whole; }
    std::string family() const override { return "kinked"; }
    double span() const override { return 10.0; }
    double length() const override { return left_->length() + right_->length(); }
    double crown() const override { return left_->length(); }
    CurvePoint at(double s) const override {
      const double S = left_->length();
      if (s <= S) return left_->at(s);
      CurvePoint p = mirror(right_->at(length() - s), 10.0);
      p.y += left_->at(S).y - right_->at(right_->length()).y;  // the crowns meet
      return p;
    }
    std::vector<double> breakpoints() const override { return {left_->length()}; }
    double max_curvature() const override { return std::max(left_->max_curvature(), right_->max_curvature()); }

   private:
    std::shared_ptr<const Curve> left_, right_;
  };
  CHECK_THROWS_WITH_AS(make_ring(*std::make_shared<Kinked>(), 0.8, kGamma, {}), doctest::Contains("kink"),
                       std::invalid_argument);
}
