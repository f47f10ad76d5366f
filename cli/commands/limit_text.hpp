// What limit and spread share of rigid voussoirs' text: the --weight and --joints names, and hinges as
// "x/L:face".
#pragma once

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "ogive/limit/limit.hpp"

namespace CLI {
class App;
}

namespace ogive::cli {

// --compressive-strength f_c of the rigid voussoirs (limit, draw, report, assess) and of the stress
// ratio (thrust, profile): the text as given, in Pa or with a unit of stress (3.92MPa, 3920kPa, 3.92N/mm2;
// not scaled by --units).
void add_compressive_strength_option(CLI::App& cmd, std::string& text, const char* what);
// The strength in Pa: infinity when the option is not given (Heyman's infinite strength); UsageError
// naming the option for a value that is not a finite number > 0.
double compressive_strength_of(const std::string& text, const CLI::App& cmd);
// --friction-model associative|non-associative (limit, assess): the sliding's flow rule with --friction.
void add_friction_model_option(CLI::App& cmd, std::string& text);
// The model named; UsageError naming the option for another name, or when given without --friction.
FrictionModel friction_model_of(const std::string& text, const CLI::App& cmd);
// The friction model's column: its name with friction, empty without (no sliding check).
std::string friction_model_text(const LimitOptions& o);
// A compressive stress (Pa) over f_c; NaN (an empty field) at infinite strength or without a stress.
inline double stress_ratio(double stress, double compressive_strength) {
  return std::isfinite(compressive_strength) ? stress / compressive_strength : std::numeric_limits<double>::quiet_NaN();
}

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
