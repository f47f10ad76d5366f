// The ogive command line, callable in-process: run_cli({"thrust", "--eccentricity", "0.5"}, out, err).
// CSV goes to `out` only, row by row as scenes are solved; messages go to `err`. Exit status: 0 every
// scene solved (status success), 2 bad input (one line on err, nothing on out; also when no scene of
// a sweep can be made), 3 some row's status is not success (its row says which, e.g. invalid_scene
// for an impossible combination of valid options), 4 the output could not be written (one line on
// err), 1 an internal error.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace ogive::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitInternal = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitNotConverged = 3;
inline constexpr int kExitOutput = 4;

// args excludes the program name.
int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace ogive::cli
