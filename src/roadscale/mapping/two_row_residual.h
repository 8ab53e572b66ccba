#pragma once

#include <algorithm>
#include <memory>

#include <ceres/sized_cost_function.h>

namespace roadscale {

// A one-row residual on a (pose, point) pair given a second row that is always zero: the same
// cost, Jacobian and robust loss, but every row of the bundle adjustment is then two rows tall,
// so that Ceres' Schur elimination uses its code specialised for 2-row residuals on 3-parameter
// points and 6-parameter poses instead of its general code (one 1-row road term anywhere makes
// it fall back for the whole window).
class TwoRowResidual : public ceres::SizedCostFunction<2, 6, 3> {
 public:
  // Takes ownership of `one_row`, a cost function of one residual on blocks of 6 and 3.
  explicit TwoRowResidual(ceres::CostFunction* one_row) : one_row_(one_row) {}

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    // Jacobian blocks are row-major, so the one-row cost fills the first row of each.
    if (!one_row_->Evaluate(parameters, residuals, jacobians)) return false;
    residuals[1] = 0.0;
    if (jacobians != nullptr) {
      if (jacobians[0] != nullptr) std::fill(jacobians[0] + 6, jacobians[0] + 12, 0.0);
      if (jacobians[1] != nullptr) std::fill(jacobians[1] + 3, jacobians[1] + 6, 0.0);
    }
    return true;
  }

 private:
  std::unique_ptr<ceres::CostFunction> one_row_;
};

}  // namespace roadscale
