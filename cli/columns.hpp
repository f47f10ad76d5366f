// Columns: every column of every command with its unit and meaning (`--columns help` prints a
// command's as CSV; docs/cli.md's table is generated from it; a test checks that every header name is
// documented), which of a command's columns are printed, and the scene's own columns of each row.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ogive/geometry/curve.hpp"
#include "ogive/output/csv.hpp"
#include "scene_options.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace ogive::cli {

// The columns every row starts with: the scene's number and inputs.
const std::vector<std::string>& scene_columns();

// The --columns and --all-columns options of a command.
struct ColumnText {
  std::string columns;
  bool all_columns = false;
  std::string units = "N";  // --units: N or kN (force_unit)
  std::string digits;       // --digits: significant digits, 1 .. 17; empty: the shortest round-trip decimal
  const CLI::Option* option = nullptr;  // --columns, to tell an empty list from none given
  bool given() const;
};

void add_column_options(CLI::App& cmd, ColumnText& text);

// The force unit in N of --units (N: 1, kN: 1000): of the force options given (--point-load, --live-load)
// and of the force and moment columns printed. UsageError for another unit.
double force_unit(const std::string& units);

// A command's columns in their full order (the scene's, then the results), and which of them are
// printed: by default the scene number, the inputs that vary in the sweep and the command's default
// results, in the full order; `--columns a,b` prints `scene` and then a, b in the order given;
// `--all-columns` prints everything.
class Columns {
 public:
  Columns(const std::vector<std::string>& results, std::vector<std::string> defaults);
  const std::vector<std::string>& all() const { return all_; }

  // The user's --columns and --all-columns; UsageError for a column the command does not have.
  void select(const ColumnText& ct, const std::vector<std::string>& varying_inputs,
              const std::vector<std::string>& varying_solver = {});
  // What CsvRow prints of the full order, and in which order.
  const FieldSelection* keep() const { return &selection_; }
  bool selected(std::string_view name) const;
  std::string header() const;
  // --columns help: the command's columns, their units (as --units prints them) and meanings, as CSV.
  std::string help(const ColumnText& ct) const;

 private:
  std::vector<std::string> all_, defaults_;
  FieldSelection selection_;  // its divisor is set with --units kN alone
};

// A parameter that does not apply to the scene's curve is an empty field, never "nan".
void add_parameter(CsvRow& row, double value);

// The scene's columns. curve may be null (a scene whose curve could not be made): its rise is then
// the one asked for.
void add_scene_columns(CsvRow& row, const SceneParameters& p, const Curve* curve);

// A row with the scene's inputs and a few named fields (status, message, ...); every other field empty:
// an impossible scene, or a solve that produced no numbers.
std::string sparse_row(const Columns& columns, const SceneParameters& p, const Curve* curve,
                       const std::vector<std::pair<std::string_view, std::string>>& fields);

}  // namespace ogive::cli
