// The classic arch families of MODEL.md and the user's surveyed points (issue 4). To be filled in.
#pragma once

#include "ogive/curve.hpp"

namespace ogive {}
