#include "roadscale/frontend/sampson_refinement.h"

#include <cmath>

#include "roadscale/geometry/rigid3.h"
#include "roadscale/util/error.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

namespace roadscale {
namespace {

// Two unit vectors that with t form an orthonormal basis: the tangent plane of the sphere.
Eigen::Matrix<double, 3, 2> TangentBasis(const Eigen::Vector3d& t) {
  const Eigen::Vector3d helper =
      std::abs(t.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d b1 = t.cross(helper).normalized();
  const Eigen::Vector3d b2 = t.cross(b1).normalized();
  Eigen::Matrix<double, 3, 2> basis;
  basis << b1, b2;
  return basis;
}

double RobustCost(double r, const SampsonRefinementOptions& options) {
  const double s = options.loss_scale_px;
  const double a = std::abs(r);
  if (options.loss == SampsonRefinementOptions::Loss::kCauchy) {
    return 0.5 * s * s * std::log1p((r / s) * (r / s));
  }
  return a <= s ? 0.5 * r * r : s * (a - 0.5 * s);
}

// The iteratively-reweighted-least-squares weight of a residual: rho'(r) / r.
double RobustWeight(double r, const SampsonRefinementOptions& options) {
  const double s = options.loss_scale_px;
  const double a = std::abs(r);
  if (options.loss == SampsonRefinementOptions::Loss::kCauchy)
    return 1.0 / (1.0 + (r / s) * (r / s));
  return a <= s ? 1.0 : s / a;
}

struct Evaluation {
  double cost = 0.0;
  double sum_squares = 0.0;
};

Evaluation Evaluate(const Eigen::Matrix3d& essential, const std::vector<Eigen::Vector2d>& prev,
                    const std::vector<Eigen::Vector2d>& cur, double focal_px,
                    const SampsonRefinementOptions& options) {
  Evaluation eval;
  for (size_t i = 0; i < prev.size(); ++i) {
    const double r = SampsonErrorPx(essential, prev[i], cur[i], focal_px);
    eval.cost += RobustCost(r, options);
    eval.sum_squares += r * r;
  }
  return eval;
}

}  // namespace

void SampsonRefinementOptions::Check() const {
  CheckOption(max_iterations >= 0, "refinement.max_iterations", "must be non-negative");
  CheckOption(std::isfinite(loss_scale_px) && loss_scale_px > 0.0, "refinement.loss_scale_px",
              "must be positive");
  CheckOption(std::isfinite(relative_tolerance) && relative_tolerance >= 0.0,
              "refinement.relative_tolerance", "must be non-negative");
}

double SampsonErrorPx(const Eigen::Matrix3d& essential, const Eigen::Vector2d& prev,
                      const Eigen::Vector2d& cur, double focal_px) {
  const Eigen::Vector3d x1 = prev.homogeneous();
  const Eigen::Vector3d x2 = cur.homogeneous();
  const Eigen::Vector3d a = essential * x1;
  const Eigen::Vector3d b = essential.transpose() * x2;
  const double g = a.x() * a.x() + a.y() * a.y() + b.x() * b.x() + b.y() * b.y();
  if (g <= 0.0) return 0.0;
  return focal_px * x2.dot(a) / std::sqrt(g);
}

SampsonRefinementResult RefineRelativePoseSampson(const Eigen::Matrix3d& rotation,
                                                  const Eigen::Vector3d& direction,
                                                  const std::vector<Eigen::Vector2d>& prev,
                                                  const std::vector<Eigen::Vector2d>& cur,
                                                  double focal_px,
                                                  const SampsonRefinementOptions& options) {
  options.Check();
  if (prev.size() != cur.size()) throw Error("Sampson refinement: point lists differ in size");
  if (!(direction.norm() > 0.0)) throw Error("Sampson refinement: zero translation direction");

  SampsonRefinementResult result;
  result.rotation = rotation;
  result.direction = direction.normalized();
  const double n = static_cast<double>(prev.size());
  Evaluation current =
      Evaluate(SkewMatrix(result.direction) * result.rotation, prev, cur, focal_px, options);
  result.initial_rms_px = n > 0 ? std::sqrt(current.sum_squares / n) : 0.0;
  result.final_rms_px = result.initial_rms_px;
  // Five unknowns need at least five equations; with fewer the problem has no unique answer.
  if (prev.size() < 5) return result;

  double lambda = 1e-4;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    const Eigen::Matrix3d& R = result.rotation;
    const Eigen::Vector3d& t = result.direction;
    const Eigen::Matrix3d E = SkewMatrix(t) * R;
    const Eigen::Matrix<double, 3, 2> basis = TangentBasis(t);
    // dE for each parameter: rotation R <- exp(w) R, direction t <- normalize(t + basis * d).
    Eigen::Matrix3d dE[5];
    for (int k = 0; k < 3; ++k) dE[k] = SkewMatrix(t) * SkewMatrix(Eigen::Vector3d::Unit(k)) * R;
    for (int k = 0; k < 2; ++k) dE[3 + k] = SkewMatrix(basis.col(k)) * R;

    Eigen::Matrix<double, 5, 5> H = Eigen::Matrix<double, 5, 5>::Zero();
    Eigen::Matrix<double, 5, 1> g = Eigen::Matrix<double, 5, 1>::Zero();
    for (size_t i = 0; i < prev.size(); ++i) {
      const Eigen::Vector3d x1 = prev[i].homogeneous();
      const Eigen::Vector3d x2 = cur[i].homogeneous();
      const Eigen::Vector3d a = E * x1;
      const Eigen::Vector3d b = E.transpose() * x2;
      const double e = x2.dot(a);
      const double gg = a.x() * a.x() + a.y() * a.y() + b.x() * b.x() + b.y() * b.y();
      if (gg <= 0.0) continue;
      const double sqrt_g = std::sqrt(gg);
      const double r = focal_px * e / sqrt_g;
      Eigen::Matrix<double, 5, 1> J;
      for (int k = 0; k < 5; ++k) {
        const Eigen::Vector3d da = dE[k] * x1;
        const Eigen::Vector3d db = dE[k].transpose() * x2;
        const double de = x2.dot(da);
        const double dg = 2.0 * (a.x() * da.x() + a.y() * da.y() + b.x() * db.x() + b.y() * db.y());
        J(k) = focal_px * (de / sqrt_g - 0.5 * e * dg / (gg * sqrt_g));
      }
      const double w = RobustWeight(r, options);
      H += w * J * J.transpose();
      g += w * J * r;
    }

    bool improved = false;
    while (!improved && lambda < 1e10) {
      Eigen::Matrix<double, 5, 5> damped = H;
      damped.diagonal() += lambda * H.diagonal().cwiseMax(1e-12);
      const Eigen::Matrix<double, 5, 1> step = damped.ldlt().solve(-g);
      if (!step.allFinite()) break;
      const Eigen::Matrix3d R_new = ExpSo3(step.head<3>()) * R;
      const Eigen::Vector3d t_new = (t + basis * step.tail<2>()).normalized();
      const Evaluation trial = Evaluate(SkewMatrix(t_new) * R_new, prev, cur, focal_px, options);
      if (trial.cost < current.cost) {
        const double decrease = (current.cost - trial.cost) / std::max(current.cost, 1e-300);
        result.rotation = R_new;
        result.direction = t_new;
        current = trial;
        lambda = std::max(lambda * 0.1, 1e-12);
        improved = true;
        result.iterations = iteration + 1;
        if (decrease < options.relative_tolerance) iteration = options.max_iterations;
      } else {
        lambda *= 10.0;
      }
    }
    if (!improved) break;
  }
  result.final_rms_px = std::sqrt(current.sum_squares / n);
  return result;
}

}  // namespace roadscale
