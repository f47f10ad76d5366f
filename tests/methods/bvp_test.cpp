// The boundary-value step shared by the shooting methods (src/methods/bvp.hpp): a singular system is a
// status without numbers, never a number.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <string>

#include "methods/bvp.hpp"
#include "ogive/solve/solve.hpp"
#include "support/scenes.hpp"

using namespace ogive;

TEST_CASE("trust: a singular boundary-value system is a status - never a number") {
  const ArchModel model(paper_scene(0.5));
  // A transfer that maps every state to zero leaves the end's conditions without the unknowns: Q = 0.
  const double condition = boundary_value_condition(ReducedMatrix(ReducedMatrix::Zero(3, 3)));
  CHECK(std::isinf(condition));
  Solution sol;
  sol.model = std::make_shared<const ArchModel>(model);
  BvpSolution bvp;
  bvp.condition = condition;
  finish_solution(sol, bvp, nullptr);
  CHECK(sol.status == Status::singular_system);
  CHECK(sol.message.find("singular") != std::string::npos);
  CHECK(std::isnan(sol.H_over_V));
  CHECK(!sol.field);
}
