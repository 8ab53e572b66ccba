#include "roadscale/io/pose_row_check.h"

#include <cmath>
#include <cstdio>

#include "roadscale/util/error.h"

#include <Eigen/LU>

namespace roadscale {

void CheckPoseRow(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation,
                  const std::string& path, int line) {
  if (!rotation.allFinite() || !translation.allFinite()) {
    ThrowFileError(path, line, "the pose has a value that is not a finite number");
  }
  const double orthogonality =
      (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  const double determinant = rotation.determinant();
  if (!(orthogonality <= kRotationTolerance) || !(determinant > 0.0)) {
    char text[200];
    std::snprintf(text, sizeof(text),
                  "the 3x3 part is not a rotation (max |R^T R - I| = %.3g, det(R) = %.3g; "
                  "expected below %g and det > 0)",
                  orthogonality, determinant, kRotationTolerance);
    ThrowFileError(path, line, text);
  }
  if (!(translation.cwiseAbs().maxCoeff() <= kMaxTranslationM)) {
    char text[200];
    std::snprintf(text, sizeof(text), "the position (%.3g, %.3g, %.3g) is beyond %g m",
                  translation.x(), translation.y(), translation.z(), kMaxTranslationM);
    ThrowFileError(path, line, text);
  }
}

}  // namespace roadscale
