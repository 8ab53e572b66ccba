#pragma once

#include <optional>
#include <vector>

#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/geometry/rigid3.h"
#include "roadscale/mapping/local_window.h"

#include <Eigen/Core>

namespace roadscale {

struct LandmarkTriangulatorOptions {
  // Smallest angle (degrees) between the two rays a landmark is triangulated from: below it
  // the depth is not determined (the scale stage's min_parallax_deg, for the same reason).
  // A track that fails waits for a later keyframe with a longer baseline.
  double min_parallax_deg = 0.5;
  // Largest reprojection error (pixels) in any keyframe that observes the landmark.
  double max_reprojection_error_px = 2.0;

  // Throws Error naming the first invalid option.
  void Check() const;
};

// One view of a point: the camera pose and the observed pixel.
struct PointView {
  Rigid3d cam_from_world;
  Eigen::Vector2d pixel;
};

// The point seen in `views` (at least two): triangulated linearly from the two views with the
// widest ray angle, then checked in every view (in front of the camera, reprojection error).
// Nothing when the angle or a view fails the options.
std::optional<Eigen::Vector3d> TriangulateMultiView(const std::vector<PointView>& views,
                                                    const PinholeCamera& camera,
                                                    const LandmarkTriangulatorOptions& options);

// Makes landmarks of the tracks the newest keyframe sees that are no landmarks yet and that
// earlier keyframes of the window saw too. Returns how many were made.
int TriangulateNewLandmarks(const PinholeCamera& camera, const LandmarkTriangulatorOptions& options,
                            LocalWindow* window);

}  // namespace roadscale
