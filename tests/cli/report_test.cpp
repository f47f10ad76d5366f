// `ogive report` and the drawing's new parts: the page is one self-contained document (no script, no
// external reference) whose numbers are those of ogive thrust and ogive limit for the same options;
// its targets are refused as draw's are; a drawing shows its loads, fill, cracks and movements.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "support/cli_run.hpp"
#include "support/tolerances.hpp"

using namespace ogive::test;

namespace {

// The full value (data-value) of the first number after `anchor` in the page.
double value_after(const std::string& page, const std::string& anchor) {
  const std::size_t at = page.find(anchor);
  REQUIRE_MESSAGE(at != std::string::npos, "no " << anchor);
  const std::size_t v = page.find("data-value=\"", at);
  REQUIRE(v != std::string::npos);
  return std::stod(page.substr(v + 12));
}

std::vector<std::string> with(std::vector<std::string> head, const std::vector<std::string>& tail) {
  head.insert(head.end(), tail.begin(), tail.end());
  return head;
}

// The engineer's arch in ratio form: 8 m pointed (equilateral: rise 0.866 L = 6.93 m), t = 0.1 L, density 2000, fill to the crown's
// extrados, 50 kN/m at 2 m.
const std::vector<std::string> kEngineersArch = {
    "--span", "8", "--eccentricity", "0.5", "--thickness-ratio", "0.1", "--density", "2000",
    "--fill-density", "2000", "--fill-height-ratio", "0.924", "--point-load", "50000", "--point-load-at", "0.25"};

}  // namespace

TEST_CASE("report: one self-contained page whose numbers are ogive thrust's and ogive limit's") {
  const Run page = run_command(with({"report", "--output", "-"}, kEngineersArch));
  REQUIRE(page.status == 0);
  CHECK(page.err.empty());
  const std::string& html = page.out;
  CHECK(html.rfind("<!DOCTYPE html>", 0) == 0);
  for (const char* id : {"drawing", "reactions", "thrusts", "safety", "collapse", "spreading", "inputs"})
    CHECK_MESSAGE(html.find(std::string("<section id=\"") + id + "\"") != std::string::npos, id);
  // Readable with no script and no network: nothing to run, nothing fetched.
  CHECK(html.find("<script") == std::string::npos);
  CHECK(html.find("src=") == std::string::npos);
  CHECK(html.find("href=") == std::string::npos);
  CHECK(html.find("url(http") == std::string::npos);
  // The inputs as given.
  CHECK(html.find("<th>--point-load-at</th><td>0.25</td>") != std::string::npos);

  // The page's solution is draw's (the same solver options, profile of 101 stations): the same bits.
  const Run draw = run_command(with({"draw", "--output", "report_test_page.svg"}, kEngineersArch));
  std::filesystem::remove("report_test_page.svg");
  REQUIRE(draw.status == 0);
  CHECK(value_after(html, "<th>left springing</th>") == std::stod(column(draw.out, "H")));
  CHECK(value_after(html, "<th>elastic</th>") == std::stod(column(draw.out, "H")));
  // ogive thrust solves without a profile: a solution of its own, each within the default rtol of the truth.
  const Run thrust = run_command(with({"thrust", "--columns", "H"}, kEngineersArch));
  REQUIRE(thrust.status == 0);
  constexpr double kTwoSolutionsAtDefaultRtol = 2 * 1e-8;
  const double H = std::stod(column(thrust.out, "H"));
  CHECK(std::abs(value_after(html, "<th>elastic</th>") - H) <= kTwoSolutionsAtDefaultRtol * H);
  const Run limit = run_command(
      with({"limit", "--columns", "H_min,H_max,geometric_safety_factor,load_factor,thickness_min_ratio"}, kEngineersArch));
  REQUIRE(limit.status == 0);
  CHECK(value_after(html, "<th>minimum (limit analysis)</th>") == std::stod(column(limit.out, "H_min")));
  CHECK(value_after(html, "<th>maximum (limit analysis)</th>") == std::stod(column(limit.out, "H_max")));
  CHECK(value_after(html, "<th>minimum thickness") / 8.0 ==
        doctest::Approx(std::stod(column(limit.out, "thickness_min_ratio"))).epsilon(ogive::kExact));
  CHECK(value_after(html, "<th>geometric safety factor") ==
        doctest::Approx(std::stod(column(limit.out, "geometric_safety_factor"))).epsilon(ogive::kExact));
  CHECK(value_after(html, "<th>collapse load factor") == std::stod(column(limit.out, "load_factor")));
  // The drawing inside shows the load, the fill, both limit lines and the mechanism.
  for (const char* id : {"loads", "fill", "thrust-line-min", "thrust-line-max", "mechanism"})
    CHECK_MESSAGE(html.find(std::string("id=\"") + id + "\"") != std::string::npos, id);
}

TEST_CASE("report: targets refused as draw's - one line naming the option - exit 2 - nothing on stdout") {
  check_refused({"report"});
  check_refused({"report", "--output", "a.html", "--output-dir", "."});
  check_refused({"report", "--eccentricity", "0,0.5", "--output", "a.html"});
  check_refused({"report", "--output-dir", "/no/such/directory"});
}

TEST_CASE("draw: loads, fill, cracked zones and each springing's movement are drawn - titles wrapped") {
  const std::string dir = "report_test_drawings";
  std::filesystem::create_directories(dir);
  const std::string loaded = dir + "/loaded.svg", cracked = dir + "/cracked.svg";
  REQUIRE(run_command(with({"draw", "--limit", "--output", loaded}, kEngineersArch)).status == 0);
  REQUIRE(run_command({"draw", "--section", "no-tension", "--left-spread-ratio", "1e-4", "--output", cracked}).status == 0);
  auto read = [](const std::string& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string a = read(loaded), b = read(cracked);
  for (const char* id : {"id=\"loads\"", "id=\"fill\"", "P = 50 kN/m", "line of thrust jumps here", "id=\"mechanism\"",
                         "1 m of arrow = "})
    CHECK_MESSAGE(a.find(id) != std::string::npos, id);
  CHECK(b.find("cracked-section line of thrust") != std::string::npos);
  CHECK(b.find("elastic line of thrust") == std::string::npos);
  CHECK(b.find("id=\"cracks\"") != std::string::npos);
  CHECK(b.find("<path d=", b.find("id=\"cracks\"")) != std::string::npos);  // some section is cracked
  CHECK(b.find("right clamped, fixed") != std::string::npos);
  CHECK(b.find("d/L 0") == std::string::npos);
  // Every title line fits the page: the caption is broken into lines of at most ~the page's width.
  std::size_t longest = 0;
  const std::size_t title = a.find("<g id=\"title\"");
  for (std::size_t at = a.find("<text", title); at != std::string::npos && at < a.find("</g>", title);
       at = a.find("<text", at + 1)) {
    const std::size_t open = a.find('>', at) + 1;
    longest = std::max(longest, a.find("</text>", open) - open);
  }
  CHECK(longest < 110);
  std::filesystem::remove_all(dir);
}

TEST_CASE("report: the verdict comes first, in words, with the criteria and the warnings") {
  // A 12 m segmental bridge arch, rise 3 m, a 0.3 m ring filled to 3.8 m, 100 kN/m at 3 m: it cannot carry
  // the load (assess: fail, governed by the load factor).
  const std::vector<std::string> bridge = {"--curve", "segmental", "--span", "12", "--rise", "3", "--thickness", "0.3",
                                           "--fill-density", "2000", "--fill-height", "3.8", "--point-load", "1e5",
                                           "--point-load-x", "3"};
  const Run page = run_command(with({"report", "--output", "-"}, bridge));
  REQUIRE(page.status == 0);
  const std::string& html = page.out;
  const std::size_t verdict = html.find("<section id=\"verdict\" class=\"fail\">");
  REQUIRE(verdict != std::string::npos);
  CHECK(verdict < html.find("<section id=\"drawing\""));
  CHECK(html.find("<p class=\"word\">FAIL</p>") != std::string::npos);
  CHECK(html.find("Governed by the collapse load factor") != std::string::npos);
  const Run assess = run_command(with({"assess", "--columns", "load_factor,verdict,governing"}, bridge));
  REQUIRE(assess.status == 0);
  CHECK(column(assess.out, "verdict") == "fail");
  CHECK(value_after(html, "<th>collapse load factor") == std::stod(column(assess.out, "load_factor")));
  // The warnings in words: the line of thrust leaves the ring, t < t_min, a load factor below 1, and the
  // density left at its default.
  for (const char* words : {"leaves the section", "is below t_min", "is below 1", "--density not given"})
    CHECK_MESSAGE(html.find(words, verdict) != std::string::npos, words);
  CHECK(html.find("--span not given") == std::string::npos);
  for (const char* id : {"geometry", "assumptions"})
    CHECK_MESSAGE(html.find(std::string("<section id=\"") + id + "\"") != std::string::npos, id);
  // The title shows the ratio made of metres without float noise.
  CHECK(html.find("t/L 0.025,") != std::string::npos);

  // A twice as thick ring with a geometric factor of 1.5 asked passes, and says so.
  std::vector<std::string> thick = bridge;
  thick[7] = "0.6";
  const Run pass = run_command(with({"report", "--output", "-", "--require-geometric-factor", "1.5"}, thick));
  REQUIRE(pass.status == 0);
  CHECK(pass.out.find("<section id=\"verdict\" class=\"pass\">") != std::string::npos);
  check_refused(with({"report", "--output", "-", "--require-load-factor", "0"}, thick));
}
