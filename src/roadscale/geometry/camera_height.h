#pragma once

namespace roadscale {

// h0, the camera's height above the road in metres, is the one number that makes the
// trajectory metric: every step's length is proportional to it. Cars, vans and trucks carry
// their cameras 1-4 m above the road; above this bound the number is a unit mistake
// (millimetres) or a typo, and unchecked it grows the trajectory to infinity (--h0 1e308).
inline constexpr double kMaxCameraHeightM = 100.0;

// Throws Error("invalid option OPTION: ...") unless 0 < h0 <= kMaxCameraHeightM.
void CheckCameraHeight(double h0, const char* option);

}  // namespace roadscale
