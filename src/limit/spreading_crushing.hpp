// The crushing hinges of the spreading path (spreading.hpp, Crushing), private to the limit module: where
// a hinge's blocks turn, the work its stress block dissipates, and how the hinges' places are compared.
#pragma once

#include <vector>

#include "limit/spreading_chain.hpp"
#include "ogive/limit/limit.hpp"

namespace ogive::spreading_detail {

// The points the blocks turn about at the contacts of `st` on the ring `moved`: a pin's, a face's; with
// a finite compressive strength f_c (Pa) the stress block's inner edge, N / f_c inside the face (the
// neutral axis, where the crushing block's strain rate vanishes: the flow rule of the condition
// |M| <= N (h/2 - N / (2 f_c))), while the resultant crosses at the block's centre, N / (2 f_c) inside.
std::vector<Hinge> turning_points(const Ring& moved, const ThrustState& st, double f_c);

// The work (N m/m per unit rate of d) the crushing blocks of the mechanism's face hinges dissipate:
// N^2 / (2 f_c) times each relative rotation rate's size, N the joint's normal force from `force`
// (ThrustState::force) on `moved`. 0 for an infinite f_c.
double crushing_dissipation(const Ring& moved, const Mechanism& mech, const std::vector<Vec>& force, double f_c);

// The most that a hinge of `a` lies from the same place's hinge of `b` (m; the same joints and faces).
double farthest_apart(const std::vector<Hinge>& a, const std::vector<Hinge>& b);

// Whether the hinges of b are those of a slid along the same faces, by at most `reach` (m) each.
bool slid_along(const std::vector<Hinge>& a, const std::vector<Hinge>& b, double reach);

// Where the contacts (on the ring `moved`) are the hinges of `hinges` (joints and faces, each at its own
// joint) and others, each on a hinge's face within `reach` (m, arc length along the axis of `ring0`) of
// it: the thrust line passes through the hinges and grazes the stress blocks' offset curve beside them,
// the moment its contact moves on. Then the mechanism of the hinges alone under the springings'
// velocities vL, vR (choose_mechanism, all of them open); none otherwise.
Mechanism grazed_mechanism(const Ring& ring0, const Ring& moved, const std::vector<Hinge>& hinges,
                           const std::vector<Hinge>& contacts, const Twist& vL, const Twist& vR, double reach);

}  // namespace ogive::spreading_detail
