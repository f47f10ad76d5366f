// What the command line refuses with one line (a sign twice, empty values, '=' without a value, an
// option or flag given twice, a range finer than its values' resolution, standard output as a file
// while it carries the CSV), what it states instead (help with other options), and the small promises:
// --output - of draw and report, a drawing's target written by two runs at once, the metre and ratio
// forms of a length making the same scene bit for bit.
#include <doctest/doctest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "support/cli_run.hpp"
#include "support/files.hpp"
#include "option_text.hpp"
#include "values.hpp"

using namespace ogive;
using namespace ogive::test;

namespace {

// Refused with one line that holds `words`.
void check_refused_saying(const std::vector<std::string>& args, const std::string& words) {
  check_refused(args);
  const Run r = run_command(args);
  CAPTURE(r.err);
  CHECK(r.err.find(words) != std::string::npos);
}

}  // namespace

TEST_CASE("refusals: a second sign, empty values, '=' without a value, an option or flag given twice") {
  check_refused_saying({"thrust", "--point-load=+-1"}, "--point-load: '+-1' is not a number");
  check_refused_saying({"thrust", "--span", "-+1"}, "is not a number");
  CHECK_THROWS_AS(cli::parse_number("+-1", "--x"), cli::UsageError);
  CHECK(cli::parse_number("+1", "--x") == 1);
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{{"thrust", "--left-support", ""},
                                             {"thrust", "--digits", ""},
                                             {"thrust", "--section", " "},
                                             {"thrust", "--span", ""},
                                             {"thrust", "--method", ""},
                                             {"limit", "--thrust-line", ""},
                                             {"spread", "--moving", ""},
                                             // options a command does not take are hidden, yet named
                                             {"spread", "--wall-lean", ""},
                                             {"limit", "--left-wall-lean", ""},
                                             {"thrust", "--columns", ""}})
    check_refused_saying(args, args[1] + ": the value must not be empty");
  check_refused_saying({"thrust", "--span=", "8"}, "--span: no value after '='");
  check_refused_saying({"thrust", "--plane-strain", "--plane-strain"}, "--plane-strain: given more than once");
  check_refused_saying({"thrust", "--crown-hinge", "--crown-hinge=false"}, "--crown-hinge: given more than once");
  check_refused_saying({"thrust", "--span", "8", "--span", "9"}, "--span: given more than once");
  check_refused_saying({"spread", "--wall-lean", "0", "--wall-lean", "0"}, "--wall-lean: given more than once");
  check_refused_saying({"spread", "--left-wall-lean", "0", "--wall-lean", "0", "--wall-lean", "0"},
                       "--wall-lean: given more than once");
  check_refused_saying({"spread", "--span", "8", "--wall-lean"}, "--wall-lean: needs a value");
  check_refused_saying({"limit", "--plane-strain=maybe"}, "--plane-strain: a flag, given alone");
  // The file options keep their own words.
  check_refused_saying({"thrust", "--curve", "points", "--curve-file", ""}, "--curve-file: the name must not be empty");
  // A value after '=' is one, and an '=' inside a value is the value's.
  CHECK(run_command({"thrust", "--span=8", "--columns=span"}).out == "scene,span\n1,8\n");
}

TEST_CASE("refusals: the library's messages in the options' words - no field name left") {
  CHECK(cli::as_option_message("live_load_to: must exceed live_load_from (0.5), got 0.3") ==
        "--live-load-to: must exceed --live-load-from (0.5), got 0.3");
  CHECK(cli::as_option_message("density, gravity, thickness and youngs_modulus: the weight per length w") ==
        "--density, --gravity, --thickness-ratio and --youngs-modulus: the weight per length w");
  CHECK(cli::as_option_message("rtol: must lie in [1e-14, 0.1], got 0") == "--rtol: must lie in [1e-14, 0.1], got 0");
  // The ring without load, as worded now, and any other message about the loads.
  CHECK(cli::as_option_message("loads: the ring carries no load (density 0, and the fills lie below the extrados)")
            .starts_with("--density: 0 leaves the ring without load"));
  CHECK(cli::as_option_message("loads: something else") ==
        "--density, --point-load, --live-load, --fill-density and --loads-file: something else");
  CHECK(cli::as_option_message("right_settlement: must be finite in units of w L^4 / EI, got 1e-300") ==
        "--density, --gravity, --thickness-ratio and --youngs-modulus: the right springing's settlement of 1e-300 m "
        "is beyond the range of a double in units of w L^4 / EI (the weight per length w too small for the bending "
        "stiffness EI)");
  // Words that are no field stay words.
  CHECK(cli::as_option_message("points: 3 points given") == "points: 3 points given");
  CHECK(cli::as_option_message("the density 0 of the fill") == "the density 0 of the fill");
}

TEST_CASE("refusals: help with other options prints the help and exits 0 - an argument no option takes is refused") {
  const Run help = run_command({"thrust", "--help", "--span", "8"});
  CHECK(help.status == 0);
  CHECK(help.out.find("Usage: ogive thrust") != std::string::npos);
  CHECK(help.err.empty());
  check_refused({"thrust", "--help", "8"});
}

TEST_CASE("refusals: a range stays within its ends - a step below its values' resolution is refused") {
  // 18 digits against 1e-18: the exact decimal arithmetic would overflow; the values stay within the ends
  // and fall from one to the other.
  const std::vector<double> values = cli::parse_values("999999999999999999:1e-18:1000", "--point-load");
  REQUIRE(values.size() == 1000);
  CHECK(values.front() == 1e18);
  CHECK(values.back() == 1e-18);
  for (std::size_t i = 1; i < values.size(); ++i) {
    CHECK(values[i] < values[i - 1]);
    CHECK(values[i] >= 1e-18);
  }
  const Run r = run_command({"thrust", "--point-load", "999999999999999999:1e-18:1000", "--columns", "point_load"});
  const auto ls = lines(r.out);
  REQUIRE(ls.size() == 1001);
  for (std::size_t row = 1; row < ls.size(); ++row) CHECK(std::stod(column(r.out, "point_load", row)) >= 1e-18);
  // Five values between neighbouring doubles cannot all differ: refused, naming the option.
  check_refused_saying({"thrust", "--span", "1:1.0000000000000002:5"}, "--span: range '1:1.0000000000000002:5' has a step below");
  check_refused_saying({"thrust", "--point-load", "1e300:1.0000000000000002e300:3"}, "has a step below");
  // Equal ends repeat by request.
  CHECK(cli::parse_values("2:2:3", "--span") == std::vector<double>{2, 2, 2});
}

TEST_CASE("refusals: draw and report --output - write the file alone on standard output, with the file's exit status") {
  TempDir dir("ogive-output-dash");
  // An arch too thin to stand without tension: status inadmissible, exit 3 whether to a file or to -.
  const std::vector<std::string> thin = {"--section", "no-tension", "--thickness-ratio", "0.04"};
  for (const char* command : {"draw", "report"}) {
    CAPTURE(command);
    const std::string file = dir / (std::string(command) + (std::string(command) == "draw" ? ".svg" : ".html"));
    std::vector<std::string> to_file = {command, "--output", file};
    to_file.insert(to_file.end(), thin.begin(), thin.end());
    std::vector<std::string> to_dash = {command, "--output", "-"};
    to_dash.insert(to_dash.end(), thin.begin(), thin.end());
    const Run f = run_command(to_file), d = run_command(to_dash);
    CHECK(f.status == 3);
    CHECK(d.status == f.status);
    CHECK(d.out == read_text(file));  // the file's bytes, and no CSV row
    const Run ok = run_command({command, "--output", "-"});
    CHECK(ok.status == 0);
    CHECK(ok.out.rfind(std::string(command) == "draw" ? "<?xml" : "<!DOCTYPE html>", 0) == 0);
  }
  // Standard output as a file name while it carries the CSV: refused, naming -.
  struct stat standard {}, null {};
  if (::fstat(STDOUT_FILENO, &standard) == 0 && ::stat("/dev/null", &null) == 0 &&
      !(standard.st_dev == null.st_dev && standard.st_ino == null.st_ino))
    check_refused_saying({"draw", "--output", "/dev/stdout"}, "is standard output, which carries the CSV rows");
}

TEST_CASE("refusals: two runs drawing one path both write it whole") {
  TempDir dir("ogive-two-draws");
  const std::string file = dir / "arch.svg";
  std::vector<int> status(2, -1);
  std::vector<std::string> errors(2);
  std::vector<std::thread> runs;
  for (int k = 0; k < 2; ++k)
    runs.emplace_back([&, k] {
      for (int i = 0; i < 5; ++i) {
        const Run r = run_command({"draw", "--output", file, "--eccentricity", k == 0 ? "0" : "0.5"});
        status[k] = std::max(status[k], r.status);
        errors[k] += r.err;
      }
    });
  for (std::thread& t : runs) t.join();
  CHECK(status == std::vector<int>{0, 0});
  CHECK(errors == std::vector<std::string>{"", ""});
  const std::string svg = read_text(file);
  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(svg.find("</svg>") != std::string::npos);
  CHECK(svg.find("</svg>") == svg.rfind("</svg>"));
  CHECK(svg.find_last_not_of("\n") + 1 == svg.find("</svg>") + 6);  // whole: nothing after its end
  // No temporary file left beside it.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path)) ++files;
  CHECK(files == 1);
}

TEST_CASE("refusals: --joints-count states its range, the settlement shares their unit and meaning") {
  for (const char* command : {"limit", "spread"}) {
    CAPTURE(command);
    CHECK(run_command({command, "--help"}).out.find("odd, in [5, 20001]") != std::string::npos);
  }
  const std::string help = run_command({"spread", "--columns", "help"}).out;
  for (const char* share : {"left_settlement_share,m/m,\"spread: the left springing's settlement",
                            "right_settlement_share,m/m,\"spread: the right springing's settlement"})
    CHECK(help.find(share) != std::string::npos);
}

TEST_CASE("metres: decimal_product and decimal_quotient round the decimal result once") {
  // Against strtod of the exact decimal product (Python's decimal) and IEEE division of exact integers,
  // both correctly rounded.
  CHECK(cli::decimal_product(0.1, 7) == 0.7);
  CHECK(0.1 * 7 != 0.7);  // what binary arithmetic gives instead
  CHECK(cli::decimal_quotient(0.7, 7) == 0.1);
  CHECK(cli::decimal_product(1.2345678901234567, 9.876543210987654) == std::stod("12.1932631137021782470659995035818"));
  CHECK(cli::decimal_product(0.05002000400080016, 13.7) == std::stod("0.685274054810962192"));
  CHECK(cli::decimal_product(-0.05002000400080016, 13.7) == -std::stod("0.685274054810962192"));
  CHECK(cli::decimal_quotient(1, 3) == 1.0 / 3);
  CHECK(cli::decimal_quotient(3e-5, 7e10) == std::stod("4.28571428571428571428571428571428571e-16"));
  CHECK(cli::decimal_quotient(-0.3, 0.7) == -3.0 / 7);
}

TEST_CASE("metres: a length in metres and its ratio make the same scene, bit for bit, at spans not binary") {
  // Each metre value is the ratio times the span, exactly in decimal: m = r L. Every column (the inputs'
  // echo in both forms included) must print the same bytes.
  const std::vector<std::pair<std::string, std::int64_t>> spans = {{"7", 70}, {"3.3", 33}, {"13.7", 137}, {"6.1", 61}};
  const std::vector<std::int64_t> thousandths = {100, 70, 150, 33, 90, 210};
  // m = (r / 1000) (L / 10) in ten-thousandths.
  const auto metres = [](std::int64_t r, std::int64_t l) {
    const std::int64_t m = r * l;
    return fmt::format("{}.{:04d}", m / 10000, m % 10000);
  };
  const auto ratio = [](std::int64_t r) { return fmt::format("0.{:03d}", r); };
  int pairs = 0;
  for (const auto& each_span : spans)
    for (std::int64_t r : thousandths) {
      // Named copies: CAPTURE's lambda cannot capture a structured binding (C++20 before P1091 in clang).
      const auto& span = each_span.first;
      const auto& l = each_span.second;
      CAPTURE(span);
      CAPTURE(r);
      const std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> cases = {
          {{"--thickness", metres(r, l)}, {"--thickness-ratio", ratio(r)}},
          {{"--curve", "segmental", "--rise", metres(r + 100, l)}, {"--curve", "segmental", "--rise-ratio", ratio(r + 100)}},
          {{"--point-load", "2e4", "--point-load-x", metres(r, l)}, {"--point-load", "2e4", "--point-load-at", ratio(r)}},
          {{"--fill-density", "1800", "--fill-height", metres(r + 300, l)},
           {"--fill-density", "1800", "--fill-height-ratio", ratio(r + 300)}},
          {{"--live-load", "5e3", "--live-load-from-x", metres(r, l), "--live-load-to-x", metres(r + 500, l)},
           {"--live-load", "5e3", "--live-load-from", ratio(r), "--live-load-to", ratio(r + 500)}},
      };
      for (const auto& each_case : cases) {
        const auto& metre = each_case.first;
        const auto& over_span = each_case.second;
        std::vector<std::string> a = {"thrust", "--span", span, "--all-columns"}, b = a;
        a.insert(a.end(), metre.begin(), metre.end());
        b.insert(b.end(), over_span.begin(), over_span.end());
        const Run ra = run_command(a), rb = run_command(b);
        CAPTURE(metre.back());
        CHECK(ra.status == rb.status);
        CHECK(ra.out == rb.out);
        ++pairs;
      }
    }
  CHECK(pairs == 120);
}
