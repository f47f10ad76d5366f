#include "ogive/curve_families.hpp"
