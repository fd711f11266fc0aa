#pragma once
// The involute function and its inverse.

namespace gearbench::geometry {

/// inv α = tan α − α.
double involute(double alpha);

/// α with inv α = value, for value in [0, inv(85°)]: Newton's method on
/// f(α) = tan α − α − value, f′(α) = tan²α, started from the cube-root series
/// α ≈ (3·value)^(1/3) (inv α = α³/3 + O(α⁵)), to machine precision.
double inverse_involute(double value);

}  // namespace gearbench::geometry
