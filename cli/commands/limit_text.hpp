// What limit and spread share of rigid voussoirs' text: the --weight and --joints names, and hinges as
// "x/L:face".
#pragma once

#include <map>
#include <string>
#include <vector>

#include "ogive/limit/limit.hpp"

namespace ogive::cli {

// --weight's names: voussoir (the ring's true weight at each centroid) or axis (rho g t per axis length).
const std::map<std::string, WeightModel>& weight_models();

// --joints' names: radial (normal to the axis) or vertical.
const std::map<std::string, JointOrientation>& joint_orientations();

// Hinges as "x/L:face" joined by ';' (x of the hinge point over the span, on the intrados, extrados or
// axis), e.g. "0.1129:intrados;0.5:extrados": no commas inside the CSV field. Given the ring, a hinge
// at a wall's bed is "x/L:wall-outer@y/L" (or wall-inner: the bed's edge on the wall's outer or inner
// face, y over the span from the springing line).
std::string hinge_text(const std::vector<Hinge>& hinges, double span, const Ring* ring = nullptr);

}  // namespace ogive::cli
