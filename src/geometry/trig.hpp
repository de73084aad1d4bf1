#pragma once
/// Trigonometry whose bits depend only on the argument: the simulation's sin, cos, tan, atan and
/// atan2. glibc's libm picks an FMA or an SSE2 build of these at load time, by CPU, and the two
/// differ in the last bit for about one argument in 1,500, which changes a long replay's hash on a
/// CPU without FMA (docs/architecture.md, "Determinism"). These use only IEEE additions,
/// multiplications and divisions, so with -ffp-contract=off they round the same on every x86-64.

namespace cardemo::trig {

/// cos and sin of one angle.
struct CosSin {
  double cos;  ///< cos of the angle.
  double sin;  ///< sin of the angle.
};

/// cos and sin of `radians`: within about one ulp for |radians| <= 2^19, NaN for a NaN or an
/// infinity. Beyond 2^19 the argument is first reduced exactly modulo the double nearest 2 pi
/// (std::remainder), which is deterministic but no longer close to the true period.
[[nodiscard]] CosSin cosSin(double radians);

/// (cos, sin) of the angle of `unit` plus `quarters` right angles (0 to 3): exact, a swap and
/// signs.
[[nodiscard]] CosSin turnedByQuarters(CosSin unit, int quarters);

/// tan of `radians`, as sin / cos of cosSin (within about two ulps).
[[nodiscard]] double tan(double radians);

/// Arc tangent in [-pi/2, pi/2], within about one ulp.
[[nodiscard]] double atan(double x);

/// Angle of the point (x, y) in [-pi, pi], with the signed zeros and infinities of C's atan2.
[[nodiscard]] double atan2(double y, double x);

}  // namespace cardemo::trig
