// Every `success` is a guarantee (issue 10): no option makes a row say success unless its numbers are
// within rtol of the truth (within_tolerance, solve.hpp); conditioning is judged on the problem, not on
// its discretisation; output streams in whole rows, and a write error is an error.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#include "methods/bvp.hpp"
#include "cli.hpp"
#include "cli_run.hpp"
#include "ogive/geometry/curve_families.hpp"
#include "methods/shooting.hpp"
#include "ogive/solve/solve.hpp"
#include "scenes.hpp"
#include "tolerances.hpp"

using namespace ogive;
using namespace ogive::test;

namespace {

constexpr int kStations = 41;

Scene scene_of(std::shared_ptr<const Curve> curve, double t_over_L = 0.08) {
  Scene s;
  s.curve = std::move(curve);
  s.thickness = t_over_L * s.curve->span();
  return s;
}

// The truth: the closed form (exact to round-off) on circular arcs.
Solution exact(const Scene& scene) {
  Options o;
  o.method = Method::closed_form;
  o.stations = kStations;
  return solve(scene, o);
}

double true_error(const Solution& sol, const Solution& truth, const Scene& scene) {
  return std::max(thrust_error(sol.H_over_V, truth.H_over_V),
                  profile_difference(sol.profile, truth.profile, scene.thickness));
}

}  // namespace

TEST_CASE("trust: no atol - rtol - method or integrator makes a wrong row say success") {
  // atol from far below CVODE's default to absurd (1e300 switches CVODE's error control off), rtol over
  // the whole accepted range, verified and raw. The truth is the closed form.
  const std::vector<Scene> scenes = {paper_scene(0.5), paper_scene(0.0, 0.06, 2e-4)};
  int successes = 0, refused = 0;
  for (const Scene& scene : scenes) {
    const Solution truth = exact(scene);
    REQUIRE(truth.ok());
    for (double atol : {0.0, 1e-14, 1e-8, 1e-2, 1.0, 1e300})
      for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-13, 1e-14})
        for (Method m : {Method::shooting, Method::multiple_shooting, Method::quadrature, Method::automatic})
          for (Integrator integ : {Integrator::adams, Integrator::bdf})
            for (bool verify : {true, false}) {
              Options o;
              o.method = m;
              o.integrator = integ;
              o.rtol = rtol;
              o.atol = atol;
              o.verify = verify;
              o.stations = kStations;
              o.segments = 4;
              const Solution sol = solve(scene, o);
              CAPTURE(atol);
              CAPTURE(rtol);
              CAPTURE(to_string(m));
              CAPTURE(to_string(integ));
              CAPTURE(verify);
              if (sol.ok()) {
                ++successes;
                CHECK(within_tolerance(true_error(sol, truth, scene), rtol));
                CHECK(within_tolerance(sol.diagnostics.error_estimate, rtol));
              } else {
                ++refused;
                CHECK(!sol.message.empty());
              }
              // Raw CVODE is never success; the quadrature's estimate is its own, never switched off.
              if (!verify && (m == Method::shooting || m == Method::multiple_shooting))
                CHECK(sol.status != Status::success);
            }
  }
  CHECK(successes > 300);  // not vacuous: most verified rows succeed
  CHECK(refused > 300);    // raw rows, absurd atol, rtol below CVODE's floor
}

TEST_CASE("trust: a loose atol cannot fool verification - the examples of the issue") {
  for (double atol : {1e-8, 1.0, 1e300}) {
    Options o;
    o.method = Method::shooting;
    o.atol = atol;
    const Scene scene = paper_scene(0.5);
    const Solution sol = solve(scene, o);
    CAPTURE(atol);
    CHECK(sol.status == Status::tolerance_not_met);
    CHECK(sol.diagnostics.error_estimate > o.rtol);
    // The estimate is no underestimate: the raw first solve's error was what it says, or less.
    Options raw = o;
    raw.verify = false;
    const double err = thrust_error(solve(scene, raw).H_over_V, exact(scene).H_over_V);
    CHECK(err > o.rtol);
  }
  // The catenary with --atol 0.01 (auto): 1.4 % off and "success" before. auto now takes the
  // quadrature method there, which has no atol; whatever it takes, success means within rtol.
  Options o;
  o.atol = 0.01;
  const Scene catenary_scene = scene_of(make_catenary(10.0, 0.5));
  const Solution catenary = solve(catenary_scene, o);
  Options reference;
  reference.method = Method::multiple_shooting;
  reference.rtol = 1e-12;
  reference.segments = 32;
  const Solution truth = solve(catenary_scene, reference);
  REQUIRE(truth.ok());
  if (catenary.ok()) CHECK(within_tolerance(thrust_error(catenary.H_over_V, truth.H_over_V), o.rtol + 1e-12));
  o.method = Method::shooting;
  CHECK(solve(catenary_scene, o).status != Status::success);  // CVODE itself, with that atol: caught
}

TEST_CASE("trust: below CVODE's floor a verifying solve cannot be tighter - unverified, never success") {
  for (Integrator integ : {Integrator::adams, Integrator::bdf})
    for (double rtol : {1e-14, 1e-13}) {
      Options o;
      o.method = Method::shooting;
      o.integrator = integ;
      o.rtol = rtol;
      const Solution sol = solve(paper_scene(5.0), o);
      CAPTURE(to_string(integ));
      CAPTURE(rtol);
      CHECK(sol.status == Status::unverified);
      CHECK(sol.message.find("floor") != std::string::npos);
      CHECK(std::isnan(sol.diagnostics.error_estimate));
      CHECK(sol.field);  // the numbers are there, without a promise
    }
  // Where the floor leaves room (Adams at 1.6e-13 and above), the same scene is verified.
  Options o;
  o.method = Method::shooting;
  o.rtol = 2e-13;
  const Solution sol = solve(paper_scene(5.0), o);
  CHECK(sol.status != Status::unverified);
}

TEST_CASE("trust: --no-verify rows say unverified - auto always verifies") {
  const Run raw = run_command({"thrust", "--curve", "three-centred", "--method", "shooting", "--ignore-breakpoints", "--no-verify"});
  CHECK(raw.status == 3);
  CHECK(column(raw.out, "status") == "unverified");
  CHECK(column(raw.out, "error_estimate").empty());
  CHECK(column(raw.out, "message").find("not verified") != std::string::npos);
  const Run autop = run_command({"thrust", "--curve", "catenary", "--no-verify"});
  CHECK(autop.status == 0);
  CHECK(column(autop.out, "status") == "success");
  CHECK(!column(autop.out, "error_estimate").empty());
}

TEST_CASE("trust: the condition estimate is the problem's - multiple shooting with 1 .. 64 segments succeeds at rtol 1e-12") {
  const Scene scene = scene_of(make_segmental(10.0, 0.2));
  const Solution truth = exact(scene);
  REQUIRE(truth.ok());
  Options o;
  o.method = Method::shooting;
  o.rtol = 1e-12;
  const Solution single = solve(scene, o);
  REQUIRE(single.ok());
  for (int segments : {1, 2, 4, 8, 16, 32, 64}) {
    o.method = Method::multiple_shooting;
    o.segments = segments;
    const Solution sol = solve(scene, o);
    CAPTURE(segments);
    REQUIRE(sol.ok());
    CHECK(within_tolerance(thrust_error(sol.H_over_V, truth.H_over_V), o.rtol));
    // The same boundary-value problem has the same condition, whatever its discretisation (the
    // transfers differ by CVODE's error only).
    CHECK(close(sol.diagnostics.condition_estimate, single.diagnostics.condition_estimate, 1e-6));
    CHECK(close(sol.diagnostics.condition_estimate, truth.diagnostics.condition_estimate, 1e-6));
  }
  // --segments 1 under multiple shooting is single shooting (and says so): the same numbers.
  o.segments = 1;
  const Solution one = solve(scene, o);
  CHECK(one.method == Method::shooting);
  CHECK(one.diagnostics.segments == 1);
  CHECK(within_tolerance(thrust_error(one.H_over_V, single.H_over_V), o.rtol));
}

TEST_CASE("trust: a singular boundary-value system is a status - never a number") {
  const ArchModel model(paper_scene(0.5));
  // A transfer that maps every state to zero leaves the end's conditions without the unknowns: Q = 0.
  const double condition = boundary_value_condition(ReducedMatrix(ReducedMatrix::Zero(3, 3)));
  CHECK(std::isinf(condition));
  Solution sol;
  sol.model = std::make_shared<const ArchModel>(model);
  BvpSolution bvp;
  bvp.condition = condition;
  finish_solution(sol, bvp, nullptr);
  CHECK(sol.status == Status::singular_system);
  CHECK(sol.message.find("singular") != std::string::npos);
  CHECK(std::isnan(sol.H_over_V));
  CHECK(!sol.field);
}

TEST_CASE("trust: BDF with its analytic Jacobian meets rtol - and uses the Jacobian") {
  const Scene scene = paper_scene(1.0);
  const Solution truth = exact(scene);
  for (double rtol : {1e-6, 1e-9}) {
    Options o;
    o.method = Method::shooting;
    o.integrator = Integrator::bdf;
    o.rtol = rtol;
    o.stations = kStations;
    const Solution sol = solve(scene, o);
    CAPTURE(rtol);
    REQUIRE(sol.ok());
    CHECK(sol.diagnostics.jacobian_evaluations > 0);
    CHECK(within_tolerance(true_error(sol, truth, scene), rtol));
  }
}

TEST_CASE("trust: the closed form's profile is exact at any number of stations - crown moment with 3 and 999 999") {
  for (double eps : {0.0, 0.5}) {
    Options o;
    o.method = Method::closed_form;
    Solution sol = solve(paper_scene(eps), o);
    REQUIRE(sol.ok());
    sample_profile(sol, 3);
    const double few = sol.profile[1].M;
    const std::vector<ArchState> crown = sample_stations(sol, 999999, 499999, 1);
    REQUIRE(crown.size() == 1);
    CAPTURE(eps);
    CHECK(close(crown[0].M, few, 1e-14));
    CHECK(close(crown[0].s, sol.profile[1].s, 1e-14));
  }
}

TEST_CASE("trust: the residuals take part in the status") {
  Options o;
  o.method = Method::shooting;
  const Solution sol = solve(scene_of(make_catenary(10.0, 0.5)), o);
  REQUIRE(sol.ok());
  CHECK(within_tolerance(sol.diagnostics.boundary_residual, o.rtol));
  CHECK(within_tolerance(sol.diagnostics.equilibrium_residual, o.rtol));
}

TEST_CASE("trust: check on a survey - the reference's status and error printed - exit 0") {
  const Run r = run_command({"check", "--curve", "points", "--curve-file", OGIVE_DATA_DIR "/curves/catenary-survey.csv"});
  CHECK(r.status == 0);
  REQUIRE(lines(r.out).size() == 4);  // quadrature, shooting, multiple shooting
  for (std::size_t row : {1, 2, 3}) {
    CHECK(column(r.out, "within_tolerance", row) == "true");
    CHECK(column(r.out, "reference_status", row) == "success");
    CHECK(std::stod(column(r.out, "reference_error", row)) <= 1e-12);
  }
  const Run c = run_command({"check", "--curve", "catenary", "--rise-ratio", "0.3,0.6", "--rtol", "1e-9"});
  CHECK(c.status == 0);
  CHECK(lines(c.out).size() == 1 + 2 * 3);
}

TEST_CASE("trust: an impossible combination inside a sweep is a row - exit 3 - none possible is exit 2") {
  const Run r = run_command({"thrust", "--curve", "catenary", "--rise-ratio", "1e-6,0.5,2", "--thickness-ratio", "0.5"});
  CHECK(r.status == 3);
  CHECK(r.err.empty());
  REQUIRE(lines(r.out).size() == 4);
  CHECK(column(r.out, "status", 2) == "success");
  CHECK(column(r.out, "status", 3) == "invalid_scene");
  CHECK(column(r.out, "message", 3).find("--thickness-ratio") != std::string::npos);
  CHECK(column(r.out, "H_over_V", 3).empty());
  for (const auto& line : lines(r.out)) CHECK(fields(line).size() == fields(lines(r.out)[0]).size());
  // Each command writes such a row.
  for (const char* command : {"profile", "check", "curve"}) {
    const Run p = run_command({command, "--curve", "catenary", "--rise-ratio", "0.5,2", "--thickness-ratio", "0.5"});
    CAPTURE(command);
    CHECK(p.status == 3);
    CHECK(p.out.find("invalid_scene") != std::string::npos);
  }
  check_refused({"thrust", "--curve", "catenary", "--rise-ratio", "2", "--thickness-ratio", "0.5"});
  check_refused({"thrust", "--curve", "catenary", "--rise-ratio", "1.5,2", "--thickness-ratio", "0.5"});
}

namespace {

// A stream buffer that records each piece handed to it at a flush, and fails (as a full disk does)
// once more than `capacity` bytes have been written.
class RecordingBuffer : public std::streambuf {
 public:
  explicit RecordingBuffer(std::size_t capacity = std::numeric_limits<std::size_t>::max()) : capacity_(capacity) {}
  std::vector<std::string> pieces{std::string()};
  std::string all() const {
    std::string s;
    for (const auto& p : pieces) s += p;
    return s;
  }

 protected:
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (written_ + static_cast<std::size_t>(n) > capacity_) return 0;
    written_ += static_cast<std::size_t>(n);
    pieces.back().append(s, static_cast<std::size_t>(n));
    return n;
  }
  int overflow(int c) override {
    if (c == traits_type::eof()) return 0;
    const char ch = static_cast<char>(c);
    return xsputn(&ch, 1) == 1 ? c : traits_type::eof();
  }
  int sync() override {
    if (!pieces.back().empty()) pieces.emplace_back();
    return 0;
  }

 private:
  std::size_t capacity_;
  std::size_t written_ = 0;
};

}  // namespace

TEST_CASE("trust: output streams in whole rows - header and first row at once") {
  RecordingBuffer buffer;
  std::ostream out(&buffer);
  std::ostringstream err;
  // One thread: the first row on its own. (With several, the first chunk of scenes, at most 128.)
  REQUIRE(cli::run_cli({"thrust", "--eccentricity", "0:1:3001", "--threads", "1"}, out, err) == 0);
  const auto& pieces = buffer.pieces;
  REQUIRE(pieces.size() >= 4);                      // written in several pieces, not at the end
  CHECK(lines(pieces[0]).size() == 1);              // the header
  CHECK(lines(pieces[1]).size() == 1);              // the first row, on its own
  for (const auto& piece : pieces)
    if (!piece.empty()) CHECK(piece.back() == '\n');  // whole rows only
  CHECK(lines(buffer.all()).size() == 1 + 3001);
  // The same bytes as one string: streaming changes when, not what.
  const Run whole = run_command({"thrust", "--eccentricity", "0:1:3001"});
  CHECK(whole.out == buffer.all());
  // With two threads: whole rows in every piece, the first rows early (one chunk), the same bytes.
  RecordingBuffer threaded;
  std::ostream out2(&threaded);
  REQUIRE(cli::run_cli({"thrust", "--eccentricity", "0:1:3001", "--threads", "2"}, out2, err) == 0);
  REQUIRE(threaded.pieces.size() >= 4);
  CHECK(lines(threaded.pieces[1]).size() <= 128);
  for (const auto& piece : threaded.pieces)
    if (!piece.empty()) CHECK(piece.back() == '\n');
  CHECK(threaded.all() == buffer.all());
}

TEST_CASE("trust: a write error ends the run - one line on stderr - exit 4") {
  for (const char* command : {"thrust", "profile", "curve"}) {
    RecordingBuffer full(3000);  // the header and a few rows fit, then the disk is full
    std::ostream out(&full);
    std::ostringstream err;
    const int status = cli::run_cli({command, "--eccentricity", "0:1:2001"}, out, err);
    CAPTURE(command);
    CHECK(status == cli::kExitOutput);
    CHECK(lines(err.str()).size() == 1);
    CHECK(err.str().find("cannot write the output") != std::string::npos);
    const std::string written = full.all();
    CHECK(!written.empty());
    CHECK(written.back() == '\n');  // what was written is whole rows
  }
}

TEST_CASE("trust: bench and curve print what they promise") {
  const Run b = run_command({"bench", "--eccentricity", "0.5", "--methods", "closed-form,shooting,auto", "--rtols", "1e-6,1e-9",
                     "--repeats", "1"});
  REQUIRE(b.status == 0);
  const auto ls = lines(b.out);
  REQUIRE(ls.size() == 1 + 1 + 2 + 1);  // closed form once, shooting per rtol, auto (closed form) once
  for (std::size_t row = 1; row < ls.size(); ++row) {
    CAPTURE(ls[row]);
    CHECK(fields(ls[row]).size() == fields(ls[0]).size());
    CHECK(column(b.out, "status", row) == "success");
    const double rtol = column(b.out, "rtol", row).empty() ? 1e-14 : std::stod(column(b.out, "rtol", row));
    CHECK(within_tolerance(std::stod(column(b.out, "error_H_over_V", row)), rtol));
    CHECK(within_tolerance(std::stod(column(b.out, "error_profile", row)), rtol));
    CHECK(std::stod(column(b.out, "median_seconds", row)) > 0);
  }
  CHECK(column(b.out, "chosen_method", 4) == "closed-form");
  // On a circular arc under a live load the closed form does not apply: auto is CVODE shooting, one row
  // per rtol, each within its own rtol (bench printed one row, as if auto were the closed form).
  const Run live = run_command({"bench", "--curve", "semicircular", "--live-load", "5e3", "--live-load-to", "0.5",
                                "--methods", "closed-form,auto", "--rtols", "1e-6,1e-10", "--repeats", "1"});
  REQUIRE(live.status == 0);
  REQUIRE(lines(live.out).size() == 1 + 2);  // no closed-form row: not applicable
  for (std::size_t row : {1, 2}) {
    CAPTURE(row);
    CHECK(column(live.out, "method", row) == "auto");
    CHECK(column(live.out, "status", row) == "success");
    const double rtol = std::stod(column(live.out, "rtol", row));
    CHECK(within_tolerance(std::stod(column(live.out, "error_H_over_V", row)), rtol));
    CHECK(within_tolerance(std::stod(column(live.out, "error_profile", row)), rtol));
  }
  const Run c = run_command({"curve", "--curve", "parabolic", "--rise-ratio", "0.25", "--stations", "5"});
  REQUIRE(c.status == 0);
  REQUIRE(lines(c.out).size() == 1 + 5);
  // y = 4 h x (L - x) / L^2 at the stations, and the tangent's angle from its slope.
  for (std::size_t row = 1; row <= 5; ++row) {
    const double x = std::stod(column(c.out, "x", row)), y = std::stod(column(c.out, "y", row));
    CHECK(std::abs(y - 4 * 2.5 * x * (10 - x) / 100) <= kExact * 10);
    CHECK(std::abs(std::tan(std::stod(column(c.out, "theta", row))) - 4 * 2.5 * (10 - 2 * x) / 100) <= 1e-9);
  }
  CHECK(close(std::stod(column(c.out, "x", 5)), 10.0, kExact));
}

TEST_CASE("trust: profile's failure row - one row per scene - no numbers - exit 3") {
  const Run r = run_command({"profile", "--method", "shooting", "--max-steps", "3", "--eccentricity", "0,0.5", "--stations", "11",
                             "--all-columns"});
  CHECK(r.status == 3);
  REQUIRE(lines(r.out).size() == 3);
  for (std::size_t row : {1, 2}) {
    CHECK(column(r.out, "status", row) == "integrator_failure");
    CHECK(column(r.out, "message", row).find("CV_TOO_MUCH_WORK") != std::string::npos);
    for (const char* name : {"H_over_V", "s", "N", "M", "thrust_eccentricity"}) CHECK(column(r.out, name, row).empty());
  }
}

TEST_CASE("threads: the same bytes with any number of threads - invalid scenes and failures included") {
  const std::vector<std::vector<std::string>> commands = {
      {"thrust", "--curve", "catenary", "--rise-ratio", "0.3:2:40", "--thickness-ratio", "0.4"},
      {"thrust", "--eccentricity", "0:1:30", "--method", "shooting", "--max-steps", "40"},
      {"profile", "--eccentricity", "0:1:9", "--stations", "33"},
      {"check", "--curve", "parabolic", "--rise-ratio", "0.3,0.5,0.7"},
      {"curve", "--curve", "elliptical", "--rise-ratio", "0.2:0.6:5", "--stations", "9"},
  };
  for (const auto& command : commands) {
    std::vector<std::string> one = command, many = command;
    one.insert(one.end(), {"--threads", "1"});
    const Run reference = run_command(one);
    CAPTURE(command[0]);
    for (const char* threads : {"2", "3", "8"}) {
      many = command;
      many.insert(many.end(), {"--threads", threads});
      const Run r = run_command(many);
      CAPTURE(threads);
      CHECK(r.status == reference.status);
      CHECK(r.out == reference.out);
      CHECK(r.err == reference.err);
    }
  }
  check_refused({"thrust", "--threads", "0"});
  check_refused({"thrust", "--threads", "257"});
  check_refused({"thrust", "--threads", "two"});
}

TEST_CASE("threads: a write error with several threads still ends the run cleanly - exit 4") {
  RecordingBuffer full(5000);
  std::ostream out(&full);
  std::ostringstream err;
  const int status = cli::run_cli({"thrust", "--eccentricity", "0:1:3000", "--threads", "4"}, out, err);
  CHECK(status == cli::kExitOutput);
  CHECK(lines(err.str()).size() == 1);
  CHECK(full.all().back() == '\n');
}
