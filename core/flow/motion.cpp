// Finite rigid steps for the three motion models (manual/flow-math.md section 4.2).
#include "flow/motion.h"

#include <cmath>
#include <cstring>

#include "flow/named_values.h"

namespace oflab {
namespace {

// The three scalar functions of the screw motion, by series below theta = 1e-2 where the
// closed forms cancel catastrophically:
//   a = sin(theta)/w, b = (1 - cos theta)/w^2, c = (t - sin(theta)/w)/w^2, theta = w t.
struct ScrewCoefficients {
  double a, b, c;
};

ScrewCoefficients screw_coefficients(double w, double t) {
  const double theta = w * t;
  if (std::abs(theta) < 1e-2) {
    const double th2 = theta * theta;
    return {t * (1.0 - th2 / 6.0 + th2 * th2 / 120.0),
            t * t * (0.5 - th2 / 24.0 + th2 * th2 / 720.0),
            t * t * t * (1.0 / 6.0 - th2 / 120.0 + th2 * th2 / 5040.0)};
  }
  return {std::sin(theta) / w, (1.0 - std::cos(theta)) / (w * w),
          (t - std::sin(theta) / w) / (w * w)};
}

}  // namespace

namespace {

// Every model with its name, in the order of the enum.
constexpr NamedValue<MotionModel> kModelNames[] = {{MotionModel::kScrew, "screw"},
                                                   {MotionModel::kRotateThenTranslate, "rt"},
                                                   {MotionModel::kSpinAboutCentre, "centre"}};

}  // namespace

bool parse_motion_model(const char* text, MotionModel* model) {
  if (std::strcmp(text, "center") == 0) {
    *model = MotionModel::kSpinAboutCentre;
    return true;
  }
  return parse_named_value(kModelNames, text, model);
}

const char* motion_model_name(MotionModel model) {
  return name_of_value(kModelNames, model, "screw");
}

std::string motion_model_name_list(const std::string& separator) {
  return named_value_list(kModelNames, separator);
}

Vec3 eye_velocity(const RigidMotion& motion, const PlanePose& pose) {
  if (motion.model == MotionModel::kSpinAboutCentre) {
    return motion.velocity - glm::cross(motion.omega, pose.point);
  }
  return motion.velocity;
}

Vec3 acceleration_reference_velocity(const RigidMotion& motion, const PlanePose& /*pose*/) {
  switch (motion.model) {
    case MotionModel::kScrew:
      return Vec3(0.0);
    case MotionModel::kRotateThenTranslate:
    case MotionModel::kSpinAboutCentre:
      return motion.velocity;
  }
  return Vec3(0.0);
}

Mat3 rotation_matrix(const Vec3& axis_angle) {
  const double w = glm::length(axis_angle);
  const ScrewCoefficients k = screw_coefficients(w, 1.0);
  const Mat3 kw = cross_matrix(axis_angle);
  return Mat3(1.0) + k.a * kw + k.b * (kw * kw);
}

RigidStep rigid_step(const RigidMotion& motion, const PlanePose& pose, double dt) {
  const double w = glm::length(motion.omega);
  const ScrewCoefficients k = screw_coefficients(w, dt);
  const Mat3 kw = cross_matrix(motion.omega);
  const Mat3 kw2 = kw * kw;
  RigidStep step;
  step.rotation = Mat3(1.0) + k.a * kw + k.b * kw2;
  switch (motion.model) {
    case MotionModel::kScrew: {
      const Mat3 g = dt * Mat3(1.0) + k.b * kw + k.c * kw2;
      step.translation = g * motion.velocity;
      break;
    }
    case MotionModel::kRotateThenTranslate:
      step.translation = motion.velocity * dt;
      break;
    case MotionModel::kSpinAboutCentre:
      step.translation = pose.point + motion.velocity * dt - step.rotation * pose.point;
      break;
  }
  return step;
}

PlanePose advance_pose(const PlanePose& pose, const RigidStep& step) {
  PlanePose next = pose;
  next.point = step.rotation * pose.point + step.translation;
  next.normal = step.rotation * pose.normal;
  next.up = step.rotation * pose.up;
  return next;
}

}  // namespace oflab
