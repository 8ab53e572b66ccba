#pragma once

#include <optional>
#include <vector>

#include "roadscale/geometry/rigid3.h"

#include <Eigen/Core>

namespace roadscale {

struct RoadModelCheckOptions {
  // Where the expected road normal comes from (see road_plane.h for the convention).
  enum class Reference {
    kMotion,      // the paper: the road is tangent to the direction of travel
    kFixedPitch,  // the paper's public code: a level road under a camera of fixed pitch
  };
  Reference reference = Reference::kMotion;
  // For kFixedPitch: the camera's pitch, positive when it looks down at the road.
  double camera_pitch_deg = 0.0;
  // theta_0 of eq. (11): largest angle between a triangle's normal and the expected road
  // normal.
  double max_angle_deg = 5.0;

  void Check() const;
};

// The expected road normal n_r for a motion under these options. nullopt only for kMotion
// when the motion gives no direction (see RoadNormalFromMotion).
std::optional<Eigen::Vector3d> ExpectedRoadNormal(const Rigid3d& cur_from_prev,
                                                  const RoadModelCheckOptions& options);

struct RoadModelCheck {
  std::vector<int> kept;  // indices of points in an accepted triangle, ascending
  int num_triangles = 0;
  int num_accepted_triangles = 0;
};

// Algorithm 2 of the paper: the Delaunay triangulation of `pixels`; for each triangle the
// plane n·X = h through its three `points` (eq. 7, n turned towards `road_normal`); the
// triangle's points are kept when the angle between n and `road_normal` is below
// max_angle_deg (eq. 11) and the camera is above the plane (h > 0). Throws Error when the
// lists differ in size.
RoadModelCheck CheckRoadModel(const std::vector<Eigen::Vector2d>& pixels,
                              const std::vector<Eigen::Vector3d>& points,
                              const Eigen::Vector3d& road_normal,
                              const RoadModelCheckOptions& options);

}  // namespace roadscale
