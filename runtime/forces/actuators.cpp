#include "runtime/forces/actuators.h"

#include "runtime/dynamics/frame_motion.h"
#include "runtime/forces/applied_loads.h"
#include "runtime/forces/functions.h"
#include "runtime/model/data.h"
#include "runtime/model/model.h"

namespace sled::runtime {

double ActuatorTorque(const Model& model, Data& data, std::size_t k) {
  const ActuatorTable& table = model.actuators;
  const auto s = static_cast<std::size_t>(table.segment[k]);
  const double angle = data.q[static_cast<std::size_t>(model.q_address[s])];
  const double rate = data.v[static_cast<std::size_t>(model.v_address[s])];
  const double target = EvaluateFunction(model.functions, table.target[k], data.time);
  const double target_rate = FunctionSlope(model.functions, table.target[k], data.time);
  const double error = angle - target;
  double torque = -EvaluateFunction(model.functions, table.proportional[k], target) * error;
  if (table.derivative[k] >= 0) {
    torque -= EvaluateFunction(model.functions, table.derivative[k], target) * (rate - target_rate);
  }
  const std::int32_t address = table.state_address[k];
  if (address >= 0) {
    const auto w = static_cast<std::size_t>(address);
    torque -= EvaluateFunction(model.functions, table.integral[k], target) * data.w[w];
    data.wdot[w] = error;
  }
  return torque;
}

void AddActuatorTorques(const Model& model, Data& data) {
  const ActuatorTable& table = model.actuators;
  for (std::size_t k = 0; k < table.size(); ++k) {
    const auto s = static_cast<std::size_t>(table.segment[k]);
    const std::int32_t parent = model.segment_parent[s];
    const Mat3& parent_rotation = parent >= 0 ? data.rotation[static_cast<std::size_t>(parent)]
                                              : MotionOf(data, model.segment_base[s]).rotation;
    const Vec3 torque = ActuatorTorque(model, data, k) * (parent_rotation * table.axis[k]);
    const Vec3 joint_point = data.position[s] + data.rotation[s] * model.joint_point_in_child[s];
    AddAppliedForce(data, s, joint_point, Vec3::Zero(), torque);
    if (parent >= 0) {
      AddAppliedForce(data, static_cast<std::size_t>(parent), joint_point, Vec3::Zero(), -torque);
    }
  }
}

}  // namespace sled::runtime
