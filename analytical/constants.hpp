#pragma once

#include "core/units.hpp"
// Shared constants of the analytical models.

namespace polydem::analytical {

// g used throughout section 2 of the paper when a caller gives none [m/s^2]:
// the model's one g (core/units.hpp).
inline constexpr double standard_gravity = kGravity;

inline constexpr double pi = 3.14159265358979323846;

}  // namespace polydem::analytical
