// Parsing of numeric option values: one number, a list "a,b,c", or a range "start:stop:count"
// (count equally spaced values, both ends included). Errors throw UsageError naming the option.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace ogive::cli {

// Bad input from the user: the CLI prints what() as one line and exits with status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// At most this many values from one option, and scenes from one command.
inline constexpr std::size_t kMaxValues = 1'000'000;

// Every value must be finite; `option` (e.g. "--span") names the option in messages.
std::vector<double> parse_values(std::string_view text, std::string_view option);

// Printable form of user text for a message (one line): control bytes become '?', text past 60 bytes is cut.
std::string shown(std::string_view s);

// One finite number, the whole text; nullopt-like failure throws UsageError.
double parse_number(std::string_view text, std::string_view option);

// The double nearest to a b and to a / b, each double taken as the decimal it reads as (its shortest
// text, the number as typed): 0.1 x 7 gives 0.7 and 0.7 / 7 gives 0.1, as the decimal numbers do, so a
// length given in metres and the same length given over the span make the same scene. Plain double
// arithmetic where the decimals are out of reach (beyond 10^+-280).
double decimal_product(double a, double b);
double decimal_quotient(double a, double b);

}  // namespace ogive::cli
