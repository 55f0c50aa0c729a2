#include "runtime/model/model.h"

namespace sled::runtime {

const char* JointKindName(JointKind kind) {
  switch (kind) {
    case JointKind::kBall:
      return "ball";
    case JointKind::kPin:
      return "pin";
    case JointKind::kSlip:
      return "slip";
    case JointKind::kEuler:
      return "euler";
    case JointKind::kPlanar:
      return "planar";
    case JointKind::kFree:
      break;
  }
  return "free";
}

int PositionCount(JointKind kind) {
  switch (kind) {
    case JointKind::kFree:
      return 7;
    case JointKind::kBall:
      return 4;
    case JointKind::kEuler:
    case JointKind::kPlanar:
      return 3;
    case JointKind::kPin:
    case JointKind::kSlip:
      return 1;
  }
  return 0;
}

int VelocityCount(JointKind kind) {
  switch (kind) {
    case JointKind::kFree:
      return 6;
    case JointKind::kBall:
    case JointKind::kEuler:
    case JointKind::kPlanar:
      return 3;
    case JointKind::kPin:
    case JointKind::kSlip:
      return 1;
  }
  return 0;
}

void AppendPlainJointCharacteristics(Model& model) {
  model.joint_function.push_back({-1, -1, -1});
  model.joint_viscous.push_back(0.0);
  model.joint_coulomb.push_back(0.0);
  model.joint_stop.push_back(0.0);
  model.joint_twist_stop.push_back(0.0);
  model.joint_stop_impulse.push_back(0);
  model.joint_restitution.push_back(0.0);
  model.joint_locked.push_back(0);
  model.joint_lock_below.push_back(-1.0);
  model.joint_unlock_above.push_back(-1.0);
}

}  // namespace sled::runtime
