#pragma once

#include <optional>

#include "roadscale/geometry/rigid3.h"

#include <Eigen/Core>

namespace roadscale {

// THE SIGN CONVENTION OF THE SCALE MODULE (every stage uses it; it is written down only here).
//
// Points are in the previous camera's frame (KITTI: x right, y down, z forward), in units of
// the baseline: the motion cur_from_prev = (R, t̂) has |t̂| = 1, so X_cur = R X_prev + t̂.
//
// A plane is {X : n·X = h} with |n| = 1, n pointing from the camera towards the road ("down",
// n_y > 0 for a level camera) and h > 0: h is then the camera's height above the plane.
// A road that rises ahead of the camera (an uphill grade, or a camera pitched down) has
// n_z > 0: a plane of pitch a has n = (0, cos a, sin a). Pitch and roll are reported as
// pitch = atan2(n_z, n_y) and roll = atan2(-n_x, n_y) (roll > 0: the road rises to the left).
//
// The paper's eqs. (8)-(10) mix signs (a flat road gives theta_i = +90 deg but
// theta_r = -90 deg). Their geometric intent is implemented instead: both camera centres are
// the same height above a planar road, so the road normal is perpendicular to the direction
// of travel d = -R^T t̂ (the current camera centre seen from the previous camera). Of the
// normals perpendicular to d, the expected road normal is the one nearest the camera's down
// axis e_y (the camera is mounted level across the car: zero roll):
//   n_r = normalize(e_y - (e_y·d) d).
// A triangle or plane is road-like when the angle between its normal and n_r is below
// theta_0. This rejects walls on either side of the street too (their normals are
// perpendicular to d as well, but 90 degrees from n_r).
struct Plane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
  double height = 0.0;

  double SignedDistance(const Eigen::Vector3d& point) const { return normal.dot(point) - height; }
  double PitchRad() const;
  double RollRad() const;
};

// The plane through three points, its normal turned to the side of `reference_normal`.
// nullopt when the points are (nearly) collinear.
std::optional<Plane> PlaneThroughPoints(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                        const Eigen::Vector3d& c,
                                        const Eigen::Vector3d& reference_normal);

// Angle in [0, pi] between two directions (atan2 form: precise for small angles).
double AngleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

// d = -R^T t normalised: the direction of travel in the previous camera's frame. nullopt when
// the translation is zero or not finite ("no motion").
std::optional<Eigen::Vector3d> TravelDirection(const Rigid3d& cur_from_prev);

// n_r of the convention above. nullopt when the travel direction is undefined or within
// 1 degree of the camera's y axis (a camera moving straight up or down: no road is implied).
std::optional<Eigen::Vector3d> RoadNormalFromMotion(const Rigid3d& cur_from_prev);

// The road normal of a level road seen by a camera pitched down by `pitch_rad` (negative:
// pitched up), whatever the motion: (0, cos p, sin p). The paper's public code assumes this.
Eigen::Vector3d RoadNormalFromCameraPitch(double pitch_rad);

}  // namespace roadscale
