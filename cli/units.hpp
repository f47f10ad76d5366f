// Values with units, as engineers write them: `--thickness 600mm`, `--point-load 100kN`,
// `--density 2.2t/m3`, `--youngs-modulus 15GPa`. Every unit ogive takes is a power of ten of the
// option's own (m, N/m, N/m^2, kg/m^3, Pa, m/s^2), so a value with a unit is rewritten as the same decimal
// number with its exponent moved: "600mm" reads as "600e-3", the very double that "0.6" reads as. A bare
// number keeps the option's own unit.
#pragma once

#include <string>
#include <string_view>

namespace ogive::cli {

// `text` (a value, a list a,b,c or a range start:stop:count, as values.hpp reads them) with each value's
// unit suffix replaced by the power of ten that brings it to the option's own unit; force units relative
// to --units (force_exponent: 0 for N, 3 for kN). The text unchanged for an option that takes no unit
// or a value without one. UsageError, naming the option and the units it takes, for a unit that does not
// fit the option (or a count with a unit).
std::string with_units_resolved(std::string_view text, std::string_view option, int force_exponent);

// The units an option takes, for its --help ("" for none).
std::string units_taken(std::string_view option);

}  // namespace ogive::cli
