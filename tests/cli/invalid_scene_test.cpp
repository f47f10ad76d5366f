// A scene that cannot be solved is a row, not the end of the sweep: a scene whose analysis refuses it
// (the library throws std::invalid_argument) prints one invalid_scene row, its reason in the options'
// words, every other scene is solved, the bytes are the same with any number of threads, and the exit
// status is 3. And an interrupted run ends with whole rows.
#include <doctest/doctest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <system_error>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "columns.hpp"
#include "scene_plan.hpp"
#include "support/cli_run.hpp"
#include "support/files.hpp"
#include "sweep.hpp"

using namespace ogive;
using namespace ogive::test;

namespace {

// Lines whose status column says invalid_scene.
std::size_t invalid_rows(const std::string& csv) {
  std::size_t n = 0;
  const auto ls = lines(csv);
  for (std::size_t r = 1; r < ls.size(); ++r) n += column(csv, "status", r) == "invalid_scene" ? 1 : 0;
  return n;
}

// Every invalid_scene row's message names an option ("--name: ...") and no field of the library
// (snake_case words such as live_load_from, left_spread).
void check_invalid_messages(const std::string& csv) {
  const auto ls = lines(csv);
  for (std::size_t r = 1; r < ls.size(); ++r) {
    if (column(csv, "status", r) != "invalid_scene") continue;
    const std::string message = column(csv, "message", r);
    CAPTURE(message);
    CHECK(message.rfind("--", 0) == 0);
    for (const char* internal : {"left_spread", "right_spread", "live_load_from", "loads:", "_ratio", "youngs_modulus"})
      CHECK(message.find(internal) == std::string::npos);
  }
}

// The same command with --threads 1, 2 and 7: the same status, bytes and stderr.
Run same_with_any_threads(const std::vector<std::string>& command) { return same_with_threads(command, {"2", "7"}); }

}  // namespace

TEST_CASE("invalid scene: any analysis that refuses its scene is a row - the rows it began are dropped - any threads") {
  // The mechanism itself, with an analysis that refuses every third scene after emitting part of its rows.
  CLI::App app;
  cli::SceneOptions options;
  cli::add_scene_options(app, options);
  std::vector<const char*> argv = {"test", "--eccentricity", "0:1:40", "--thickness-ratio", "0.05,0.1"};
  app.parse(static_cast<int>(argv.size()), argv.data());
  const cli::ScenePlan plan(options, app);
  REQUIRE(plan.size() == 80);
  cli::Columns columns({"status", "message"}, {"status", "message"});
  columns.select(cli::ColumnText{}, plan.varying_inputs());
  const cli::SceneRows rows = [&](const cli::SceneParameters& p, const Scene&, const cli::Emit& emit) {
    emit(cli::sparse_row(columns, p, nullptr, {{"status", "success"}}));
    if (p.scene % 3 == 0) throw std::invalid_argument("live_load_to: must exceed live_load_from (0.5), got 0.25");
    emit(cli::sparse_row(columns, p, nullptr, {{"status", "success"}}));
    return true;
  };
  std::string reference;
  for (int threads : {1, 2, 7}) {
    std::ostringstream out;
    CHECK_FALSE(cli::write_scenes(plan, columns, out, threads, rows));
    CAPTURE(threads);
    const auto ls = lines(out.str());
    REQUIRE(ls.size() == 1 + 80 * 2 - 26);  // 26 refused scenes print one row each, the others two
    CHECK(invalid_rows(out.str()) == 26);
    CHECK(column(out.str(), "message", 5) == "--live-load-to: must exceed --live-load-from (0.5), got 0.25");
    if (threads == 1) reference = out.str();
    CHECK(out.str() == reference);
  }
}

TEST_CASE("invalid scene: limit of a ring without load is a row - the sweep goes on - the same bytes for 1, 2, 7 threads") {
  // The lowest fills lie below the extrados over the whole span: with --density 0 those rings carry no
  // load. Whatever the analysis makes of them, every scene has its row and the threads agree.
  const Run r = same_with_any_threads(
      {"limit", "--density", "0", "--fill-density", "1800", "--fill-height-ratio", "0.5:0.001:60"});
  CHECK(lines(r.out).size() == 61);
  CHECK(r.err.empty());
  check_invalid_messages(r.out);
  CHECK(r.status == (invalid_rows(r.out) > 0 ? 3 : 0));
  CHECK(column(r.out, "status", 1) == "success");
}

TEST_CASE("invalid scene: spread --path of a weightless arch is a row - its reason in the options' words - exit 3") {
  // A self-weight of 1e-308 kg/m^3 is too small for the rigid voussoirs' arithmetic (the squares of its
  // forces underflow): the mechanism's analysis refuses it, naming the options.
  const Run r = same_with_any_threads({"spread", "--path", "--density", "1e-308,2348", "--columns", "status,message"});
  CHECK(r.status == 3);
  CHECK(r.err.empty());
  CHECK(column(r.out, "status", 1) == "invalid_scene");
  CHECK(column(r.out, "message", 1).rfind("--density, --fill-density: the ring's loads total ", 0) == 0);
  CHECK(lines(r.out).size() > 10);  // the second scene's whole path
  CHECK(column(r.out, "status", 2) == "success");
  check_invalid_messages(r.out);
}

TEST_CASE("invalid scene: every sweeping command prints the other scenes - a live load that ends before it starts") {
  // A live load from 0.6 L to 0.3 L makes no scene: for every command that takes several scenes.
  const std::vector<std::vector<std::string>> commands = {
      {"thrust"}, {"profile", "--stations", "3"}, {"check"}, {"limit"}, {"spread"}, {"spread", "--path"},
      {"bench", "--repeats", "1", "--methods", "shooting", "--rtols", "1e-6"}};
  for (const auto& command : commands) {
    std::vector<std::string> args = command;
    args.insert(args.end(), {"--live-load", "1e3", "--live-load-from", "0.6", "--live-load-to", "0.3,0.9", "--columns",
                             "status,message"});
    CAPTURE(command[0]);
    const Run r = run_command(args);
    CHECK(r.status == 3);
    CHECK(column(r.out, "status", 1) == "invalid_scene");
    CHECK(column(r.out, "message", 1) == "--live-load-to: must exceed --live-load-from (0.6), got 0.3");
    CHECK(lines(r.out).size() > 2);
  }
  // In metres, as given.
  const Run metres = run_command({"thrust", "--live-load", "1e3", "--live-load-from-x", "6", "--live-load-to-x", "3,9",
                                  "--columns", "status,message"});
  CHECK(column(metres.out, "message", 1) == "--live-load-to-x: must exceed --live-load-from-x (6 m), got 3 m");
  // draw and report with --output-dir: no file for the invalid scene, a row that says why.
  TempDir dir("ogive-invalid-scene");
  for (const char* command : {"draw", "report"}) {
    const Run r = run_command({command, "--live-load", "1e3", "--live-load-from", "0.6", "--live-load-to", "0.3,0.9",
                               "--output-dir", dir.path.string(), "--columns", "status,file"});
    CAPTURE(command);
    CHECK(r.status == 3);
    CHECK(column(r.out, "status", 1) == "invalid_scene");
    CHECK(column(r.out, "file", 1).empty());
    CHECK(column(r.out, "status", 2) == "success");
  }
}

#ifdef OGIVE_PROGRAM
TEST_CASE("interrupt: SIGINT ends a sweep written to a file with whole rows and exit status 130") {
  TempDir dir("ogive-interrupt");
  const std::string csv = dir / "rows.csv";
  int whole = 0;
  for (int attempt = 0; attempt < 10; ++attempt) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, csv.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<std::string> args = {OGIVE_PROGRAM, "thrust", "--eccentricity", "0:1:1000000", "--method",
                                     "closed-form", "--all-columns", "--threads", "2"};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    // SIGINT as a terminal delivers it, whatever the test runner ignores.
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t defaults;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGINT);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
    pid_t pid = 0;
    REQUIRE(posix_spawn(&pid, OGIVE_PROGRAM, &actions, &attributes, argv.data(), environ) == 0);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    // Some way into the sweep, while pieces of 64 KiB are being written (the plan of a million scenes
    // takes a while before the first).
    const auto start = std::chrono::steady_clock::now();
    std::error_code ec;
    while (std::filesystem::file_size(csv, ec) < 200000 && std::chrono::steady_clock::now() - start < std::chrono::seconds(20))
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    std::this_thread::sleep_for(std::chrono::milliseconds(7 * attempt));
    kill(pid, SIGINT);
    int status = 0;
    REQUIRE(waitpid(pid, &status, 0) == pid);
    CAPTURE(attempt);
    const std::string text = read_text(csv);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) continue;  // done before the signal: nothing to check
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 130);
    REQUIRE_FALSE(text.empty());
    CHECK(text.back() == '\n');
    // Every line as wide as the header.
    const auto ls = lines(text);
    const std::size_t width = fields(ls.front()).size();
    for (const std::string& line : ls) REQUIRE(fields(line).size() == width);
    ++whole;
  }
  CHECK(whole > 0);
}
#endif
