#pragma once

#include <Eigen/Core>

namespace roadscale {

// dst = scale * rotation * src + translation.
struct Similarity3d {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double scale = 1.0;

  Eigen::Vector3d operator()(const Eigen::Vector3d& src) const {
    return scale * (rotation * src) + translation;
  }
};

// Least-squares alignment of corresponding points (Umeyama, "Least-squares estimation of
// transformation parameters between two point patterns", PAMI 1991): the transform
// dst_from_src minimising sum_i |dst_i - (c R src_i + t)|^2 over rotations R (det +1),
// translations t and, when `with_scale`, scales c > 0 (else c = 1). Points are the columns.
//
// Throws Error when the sets differ in size or are empty, and when a scale is asked for but
// the source points all coincide (the scale is then undefined). With fewer than three
// non-collinear points the rotation is not unique; one of the minimisers is returned.
Similarity3d UmeyamaAlignment(const Eigen::Matrix3Xd& src, const Eigen::Matrix3Xd& dst,
                              bool with_scale);

}  // namespace roadscale
