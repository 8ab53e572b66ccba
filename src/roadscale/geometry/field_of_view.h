#pragma once

namespace roadscale {

// A focal length in pixels is physical only against the image side it spans: the field of view
// 2 atan(side / (2 f)). A pinhole image cannot show 180 degrees, and below half a degree no car
// camera sees the road; outside that range the number is a unit or typing mistake (calib
// fx = 1e308 or camera fx: 7.2e7 gave an identity trajectory with only the generic UNSCALED
// warning).
inline constexpr double kMinFieldOfViewDeg = 0.5;
inline constexpr double kMaxFieldOfViewDeg = 170.0;

// Throws Error("invalid option OPTION: ...") unless `focal_px` over `side_px` pixels gives a
// field of view in [kMinFieldOfViewDeg, kMaxFieldOfViewDeg].
void CheckFocalLength(double focal_px, int side_px, const char* option);

}  // namespace roadscale
