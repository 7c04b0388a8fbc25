#pragma once
// Shared constants of the analytical models.

namespace polydem::analytical {

// g used throughout section 2 of the paper when a caller gives none [m/s^2].
inline constexpr double standard_gravity = 9.81;

inline constexpr double pi = 3.14159265358979323846;

}  // namespace polydem::analytical
