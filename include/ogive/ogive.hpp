// The whole public API of ogive in one include: a scene (the arch's geometry, section, material, loads
// and supports), solve() with its Options, the Solution with its field and summary, the limit analysis,
// the arch on spreading walls, and the CSV and SVG writers. Each header below says its units, invariants
// and what each status means.
#pragma once

#include "ogive/version.hpp"

#include "ogive/geometry/curve.hpp"
#include "ogive/geometry/curve_families.hpp"

#include "ogive/model/arch_model.hpp"
#include "ogive/model/loads_file.hpp"
#include "ogive/model/scene.hpp"
#include "ogive/model/section.hpp"

#include "ogive/core/solution.hpp"
#include "ogive/core/thrust_line.hpp"
#include "ogive/core/wall_resultant.hpp"

#include "ogive/limit/limit.hpp"
#include "ogive/limit/spreading.hpp"
#include "ogive/solve/assessment.hpp"
#include "ogive/solve/model_error.hpp"
#include "ogive/solve/solve.hpp"

#include "ogive/output/csv.hpp"
#include "ogive/output/svg.hpp"
