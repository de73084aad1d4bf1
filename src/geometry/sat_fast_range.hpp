#pragma once
/// The range of sat_polygon.cpp's fast path (and of the lab's quadrilateral kernels, which must
/// fall back where it does).

namespace cardemo::sat_detail {

/// Coordinates below this (relative to the pair's reference point) keep every product and key of
/// the fast path between 2^-1000 and 2^+620, given squared axis lengths above kSmallestFastLength2.
inline constexpr double kLargestFastCoordinate = 0x1p100;
/// See kLargestFastCoordinate.
inline constexpr double kSmallestFastLength2 = 0x1p-200;

}  // namespace cardemo::sat_detail
