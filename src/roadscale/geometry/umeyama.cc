#include "roadscale/geometry/umeyama.h"

#include <string>

#include "roadscale/util/error.h"

#include <Eigen/LU>
#include <Eigen/SVD>

namespace roadscale {

Similarity3d UmeyamaAlignment(const Eigen::Matrix3Xd& src, const Eigen::Matrix3Xd& dst,
                              bool with_scale) {
  if (src.cols() != dst.cols()) {
    throw Error("Umeyama alignment needs corresponding points: got " + std::to_string(src.cols()) +
                " source and " + std::to_string(dst.cols()) + " destination points");
  }
  if (src.cols() == 0) throw Error("Umeyama alignment needs at least one point pair");

  const double n = static_cast<double>(src.cols());
  // Eq. (34)-(35): centroids.
  const Eigen::Vector3d mean_src = src.rowwise().mean();
  const Eigen::Vector3d mean_dst = dst.rowwise().mean();
  const Eigen::Matrix3Xd src_centred = src.colwise() - mean_src;
  const Eigen::Matrix3Xd dst_centred = dst.colwise() - mean_dst;
  // Eq. (36): variance of the source points; eq. (38): their cross-covariance.
  const double src_variance = src_centred.squaredNorm() / n;
  const Eigen::Matrix3d covariance = dst_centred * src_centred.transpose() / n;

  // Eq. (39)-(43): with covariance = U D V^T, R = U S V^T where S flips the sign of the
  // smallest singular direction when U V^T would be a reflection. det(U) det(V) decides in
  // both of the paper's cases (full rank, and rank 2 where det(covariance) = 0).
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance,
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Vector3d s = Eigen::Vector3d::Ones();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0) s(2) = -1.0;

  Similarity3d transform;
  transform.rotation = svd.matrixU() * s.asDiagonal() * svd.matrixV().transpose();
  if (with_scale) {
    if (!(src_variance > 0.0)) {
      throw Error("Umeyama alignment cannot fit a scale: the source points all coincide");
    }
    // Eq. (42): c = tr(D S) / sigma_src^2.
    transform.scale = svd.singularValues().dot(s) / src_variance;
  }
  // Eq. (41): t = mu_dst - c R mu_src.
  transform.translation = mean_dst - transform.scale * transform.rotation * mean_src;
  return transform;
}

}  // namespace roadscale
