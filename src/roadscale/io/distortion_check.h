#pragma once

#include <vector>

#include "roadscale/geometry/pinhole_camera.h"

namespace roadscale {

// Throws Error("invalid option camera.K: ...") naming the coefficient K at fault unless the
// undistortion of `camera`'s images with `distortion` (OpenCV's model, 5 or 8 coefficients)
// is usable: along the radius, out to the undistorted image's farthest corner, the lens model
// must be one-to-one (the distorted radius growing with the ideal one, the rational model's
// denominator positive), else two parts of the image come from one part of the lens (k1: -1
// gave a path 14 % too long, every frame `ok`); and at least half of the undistorted image
// must come from inside the lens's image, else the frames are blank (k1: 1e6: 0 tracks). The
// coefficient named is the first one without which the model passes; when no single one
// does, all of them are named.
void CheckDistortionMap(const PinholeCamera& camera, const std::vector<double>& distortion);

}  // namespace roadscale
