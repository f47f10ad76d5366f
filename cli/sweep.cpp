#include "sweep.hpp"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "option_text.hpp"
#include "row_writer.hpp"
#include "values.hpp"

namespace ogive::cli {
namespace {

// The status of a row whose options are each valid but make no scene together (Scene::validate or the
// curve's factory refused the combination), or whose analysis refused the scene (the library throws
// std::invalid_argument for input it cannot take, e.g. a ring that carries no load); its message says
// why. Not a library Status.
constexpr std::string_view kInvalidScene = "invalid_scene";

// What a scene's rows may hold back before they pass on: an analysis that refuses the scene then leaves
// no row of it but the invalid_scene row. A scene of more rows (a long profile) passes them on in pieces
// of this size, the writer's (so that what waits stays bounded), and such a refusal follows the rows
// already passed on.
constexpr std::size_t kHeldBytes = std::size_t{1} << 16;

std::string invalid_row(const Columns& columns, const SceneParameters& p, const Curve* curve,
                        const std::string& problem) {
  return sparse_row(columns, p, curve, {{"status", std::string(kInvalidScene)}, {"message", problem}});
}

// One scene's rows, and whether they succeeded.
bool scene_rows(const ScenePlan& plan, const Columns& columns, const SceneRows& rows_of, std::size_t index,
                const Emit& emit) {
  const SceneParameters p = plan.parameters(index);
  ScenePlan::Built built = plan.build(p);
  if (!built.scene) {
    emit(invalid_row(columns, p, built.curve.get(), built.problem));
    return false;
  }
  std::string held;
  const Emit hold = [&](const std::string& text) {
    held += text;
    if (held.size() < kHeldBytes) return;
    emit(held);
    held.clear();
  };
  try {
    const bool ok = rows_of(p, *built.scene, hold);
    emit(held);
    return ok;
  } catch (const std::invalid_argument& e) {
    emit(invalid_row(columns, p, built.curve.get(), plan.problem_words(e.what())));
    return false;
  }
}

// Scenes solved in parallel (each thread keeps its own SUNDIALS objects) and written in order: a thread
// takes the next chunk of consecutive scenes (so that locking costs little against scenes of a
// few microseconds) only while it lies within a window of 4 x threads chunks of the next one to be
// written, so the output is byte-identical to one thread's. A chunk holds at most kChunkRows rows, so
// what waits in the window stays within 5 x threads x kChunkRows rows whatever the sweep.
class OrderedSweep {
 public:
  using OneScene = std::function<bool(std::size_t index, const Emit& emit)>;

  OrderedSweep(std::size_t scenes, int threads, std::size_t rows_per_scene, OneScene one)
      : n_(scenes),
        threads_(threads),
        // Chunks of up to 128 scenes and kChunkRows rows, but at least 16 per thread so that a short
        // sweep is shared out too.
        chunk_(std::clamp<std::size_t>(scenes / (16 * static_cast<std::size_t>(threads)), 1,
                                       std::clamp<std::size_t>(kChunkRows / std::max<std::size_t>(rows_per_scene, 1),
                                                               1, 128))),
        chunks_((scenes + chunk_ - 1) / chunk_),
        window_(4 * static_cast<std::size_t>(threads)),
        slots_(window_),
        one_(std::move(one)) {}

  // Every chunk's rows to the writer, in order; whether every scene succeeded.
  bool run(RowWriter& writer);

 private:
  struct Slot {
    std::string text;
    bool ok = true, done = false;
  };
  void work();
  // Solves the chunk into its slot of the window; false (failure_ set, every thread told to stop) if a
  // scene threw.
  bool solve_chunk(std::size_t chunk);
  // Whether a chunk is left to take within the window (under mutex_).
  bool can_take() const { return next_to_take_ < chunks_ && next_to_take_ < next_to_write_ + window_; }
  void stop_workers();

  const std::size_t n_;
  const int threads_;
  const std::size_t chunk_, chunks_, window_;
  std::vector<Slot> slots_;
  const OneScene one_;
  std::mutex mutex_;
  std::condition_variable solved_, space_;
  std::size_t next_to_take_ = 0, next_to_write_ = 0;
  bool stop_ = false;
  std::exception_ptr failure_;
};

bool OrderedSweep::solve_chunk(std::size_t chunk) {
  Slot result;
  try {
    const Emit into_slot = [&](const std::string& text) { result.text += text; };
    for (std::size_t scene = chunk * chunk_; scene < std::min(n_, (chunk + 1) * chunk_); ++scene)
      result.ok = one_(scene, into_slot) && result.ok;
  } catch (...) {
    std::lock_guard lock(mutex_);
    if (!failure_) failure_ = std::current_exception();
    stop_ = true;
    solved_.notify_all();
    space_.notify_all();
    return false;
  }
  result.done = true;
  std::lock_guard lock(mutex_);
  slots_[chunk % window_] = std::move(result);
  solved_.notify_all();
  return true;
}

void OrderedSweep::work() {
  for (;;) {
    std::size_t i;
    {
      std::unique_lock lock(mutex_);
      space_.wait(lock, [&] { return stop_ || next_to_take_ >= chunks_ || can_take(); });
      if (stop_ || next_to_take_ >= chunks_) return;
      i = next_to_take_++;
    }
    if (!solve_chunk(i)) return;
  }
}

void OrderedSweep::stop_workers() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  space_.notify_all();
}

bool OrderedSweep::run(RowWriter& writer) {
  std::vector<std::thread> pool;
  // Stops and joins the workers on every way out, an exception from the writer included.
  struct Joiner {
    OrderedSweep& sweep;
    std::vector<std::thread>& pool;
    ~Joiner() {
      sweep.stop_workers();
      for (std::thread& t : pool) t.join();
    }
  } joiner{*this, pool};
  // The calling thread writes the chunks in order and, while the next one to write is still being
  // solved, solves chunks itself: threads - 1 workers beside it, so that no thread waits on a core
  // another one needs (three threads on two cores ran 1.8 times one thread's speed).
  for (int t = 1; t < threads_; ++t) pool.emplace_back([this] { work(); });
  bool all_ok = true;
  for (std::size_t w = 0; w < chunks_; ++w) {
    Slot slot;
    for (;;) {
      std::size_t mine = 0;
      {
        std::unique_lock lock(mutex_);
        if (failure_) std::rethrow_exception(failure_);
        if (slots_[w % window_].done) {
          slot = std::move(slots_[w % window_]);
          slots_[w % window_] = Slot{};
          ++next_to_write_;
          break;
        }
        if (!can_take()) {
          // Chunk w is a worker's: wait for it.
          solved_.wait(lock, [&] { return slots_[w % window_].done || failure_; });
          continue;
        }
        mine = next_to_take_++;
      }
      solve_chunk(mine);  // on failure, failure_ is set: rethrown above
    }
    space_.notify_all();
    all_ok = slot.ok && all_ok;
    writer.write(slot.text);
  }
  return all_ok;
}

}  // namespace

bool write_scenes(const ScenePlan& plan, const Columns& columns, std::ostream& out, int threads,
                  const SceneRows& rows_of, std::size_t rows_per_scene) {
  RowWriter writer(out);
  writer.write(columns.header());
  const auto one = [&](std::size_t i, const Emit& emit) { return scene_rows(plan, columns, rows_of, i, emit); };
  const std::size_t n = plan.size();
  bool all_ok = true;
  if (threads <= 1 || n <= 1 || rows_per_scene > kChunkRows) {
    const Emit to_writer = [&](const std::string& text) { writer.write(text); };
    for (std::size_t i = 0; i < n; ++i) all_ok = one(i, to_writer) && all_ok;
  } else {
    all_ok = OrderedSweep(n, threads, rows_per_scene, one).run(writer);
  }
  writer.flush();
  return all_ok;
}

void add_threads_option(CLI::App& cmd, int& threads) {
  // Sweeps use every core by default; the rows come out in the same order, byte for byte, with any N.
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = cores;
  cmd.add_option("--threads", threads,
                 fmt::format("scenes solved in parallel, 1 .. 256 (default: every core, {} here); the output "
                             "is the same with any number",
                             cores))
      ->check(whole_count());
}

void check_threads(int threads) {
  if (threads < 1 || threads > 256) throw UsageError(fmt::format("--threads: must lie in [1, 256], got {}", threads));
}

void check_stations(int stations) {
  if (stations < 2 || stations > 1000000)
    throw UsageError(fmt::format("--stations: must lie in [2, 1000000], got {}", stations));
}

void check_rows(std::size_t scenes, int stations) {
  if (scenes * static_cast<std::size_t>(stations) > 10 * kMaxValues)
    throw UsageError(
        fmt::format("--stations: {} scenes x {} stations exceed {} rows", scenes, stations, 10 * kMaxValues));
}

}  // namespace ogive::cli

