// A loads file: several loads for one scene, as CSV (the CLI's --loads-file).
//
// Format (UTF-8 or ASCII, CRLF accepted, spaces or tabs around fields, blank lines ignored):
//   line 1: the header kind,value,a,b (case-insensitive)
//   then one load a line:
//     point,P,a,        a vertical point load P (N per metre of vault width, downwards) at x = a L
//     live,q,a,b        a uniform load q per horizontal length (N/m^2, downwards) over a L <= x <= b L
//     fill,rho_f,a,     fill of density rho_f (kg/m^3, >= 0) up to the level h_f = a L above the left
//                       springing (a > 0)
//   a and b are ratios of the span within [0, 1] (a fill's level: > 0, at most 100); the fourth field
//   is empty but for live loads. Numbers: decimal, finite; at most 1000 loads, 4096 characters a line.
// Errors throw std::invalid_argument "FILE:LINE: rule" (the header is line 1), or "FILE: rule" for a
// file that cannot be read. The same rules as Scene::validate, checked here so that the message names
// the line.
#pragma once

#include <iosfwd>
#include <string>

#include "ogive/model/scene.hpp"

namespace ogive {

inline constexpr std::size_t kMaxLoadsInFile = 1000;

Loads read_loads_file(const std::string& path);
Loads parse_loads(std::istream& in, const std::string& name_for_messages);

}  // namespace ogive
