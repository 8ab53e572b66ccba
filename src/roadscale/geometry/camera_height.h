#pragma once

namespace roadscale {

// h0, the camera's height above the road in metres, is the one number that makes the
// trajectory metric: every step's length is proportional to it. Cars, vans and trucks carry
// their cameras 1-4 m above the road; above this bound the number is a unit mistake
// (millimetres) or a typo, and unchecked it grows the trajectory to infinity (--h0 1e308).
inline constexpr double kMaxCameraHeightM = 100.0;
// Below a few centimetres no lens sits above a road: the number is a unit mistake (kilometres)
// or a typo, and unchecked it leaves the steps neither scaled by h0 nor refused (--h0 1e-300
// gave 0.26 m steps, every frame `ok`).
inline constexpr double kMinCameraHeightM = 0.05;

// Throws Error("invalid option OPTION: ...") unless kMinCameraHeightM <= h0 <= kMaxCameraHeightM.
void CheckCameraHeight(double h0, const char* option);

}  // namespace roadscale
