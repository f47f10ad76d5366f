// A sweep's rows: every scene of a plan solved (on one thread or several) and its rows written in the
// scenes' order, byte-identical with any number of threads.
#pragma once

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <string>

#include "columns.hpp"
#include "ogive/model/scene.hpp"
#include "scene_plan.hpp"

namespace CLI {
class App;
}

namespace ogive::cli {

// Where a scene's rows go: the writer (one thread) or the scene's slot in the reorder window.
using Emit = std::function<void(const std::string&)>;

// A valid scene's rows, emitted; returns whether they all succeeded. Called from several threads at
// once when threads > 1: it must not share mutable state between calls.
using SceneRows = std::function<bool(const SceneParameters&, const Scene&, const Emit&)>;

// Writes the header, then every scene of the plan in order: a valid scene's rows by rows_of, an
// impossible one's as a row of status invalid_scene, and so is a scene whose analysis refuses it
// (rows_of throws std::invalid_argument: the rows it emitted are dropped, up to 64 KiB of them, and
// the row's message gives the reason in the options' words); the other scenes are solved all the same.
// Returns whether every scene's rows succeeded.
// rows_per_scene, the rows a scene emits at most, bounds what waits to be written when threads > 1:
// scenes of more than kChunkRows rows are written one after another on one thread.
inline constexpr std::size_t kChunkRows = 4096;
bool write_scenes(const ScenePlan& plan, const Columns& columns, std::ostream& out, int threads,
                  const SceneRows& rows_of, std::size_t rows_per_scene = 1);

// --threads: scenes solved in parallel; `threads` becomes its default, every core.
void add_threads_option(CLI::App& cmd, int& threads);
void check_threads(int threads);

// Commands that print rows along the arch: at least two stations, at most 10^7 rows in all.
void check_stations(int stations);
void check_rows(std::size_t scenes, int stations);

}  // namespace ogive::cli
