#include <doctest/doctest.h>
#include "ogive/curve_families.hpp"
