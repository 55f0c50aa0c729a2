#include "output/export/state_dump.h"

#include <fmt/format.h>

#include "output/atomic_file.h"
#include "runtime/dynamics/constraints.h"
#include "runtime/dynamics/joint.h"
#include "runtime/forces/forces.h"

namespace sled::runtime {
namespace {

std::string V(const Vec3& v) {
  return fmt::format("({:.9g}, {:.9g}, {:.9g})", v.x(), v.y(), v.z());
}

std::string FrameName(const Model& model, const FrameRef& frame) {
  switch (frame.kind) {
    case FrameRef::Kind::kGround:
      return "ground";
    case FrameRef::Kind::kVehicle:
      return model.vehicle_name[static_cast<std::size_t>(frame.index)];
    case FrameRef::Kind::kSegment:
      return model.segment_name[static_cast<std::size_t>(frame.index)];
  }
  return "?";
}

std::string Values(std::span<const double> values) {
  std::string out = "(";
  for (std::size_t i = 0; i < values.size(); ++i) {
    out += fmt::format("{}{:.9g}", i == 0 ? "" : ", ", values[i]);
  }
  return out + ")";
}

void DumpState(const Model& model, const Data& data, std::string& out) {
  out += fmt::format("\n== generalized coordinates: nq = {}, nv = {}\n", model.nq, model.nv);
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const auto qa = static_cast<std::size_t>(model.q_address[s]);
    const auto va = static_cast<std::size_t>(model.v_address[s]);
    const auto nq = static_cast<std::size_t>(model.q_count[s]);
    const auto nv = static_cast<std::size_t>(model.v_count[s]);
    const std::span<const double> q(data.q), v(data.v), vdot(data.vdot),
        tau(data.generalized_force);
    out += fmt::format("{} ({} joint{}{})\n", model.segment_name[s],
                       JointKindName(model.joint_kind[s]),
                       model.joint_name[s].empty() ? "" : " " + model.joint_name[s],
                       data.locked[s] != 0 ? fmt::format(", lock mask {}", data.locked[s]) : "");
    out += fmt::format("  {:<12}= {}\n", fmt::format("q[{}..{}]", qa, qa + nq - 1),
                       Values(q.subspan(qa, nq)));
    out += fmt::format("  {:<12}= {}\n", fmt::format("v[{}..{}]", va, va + nv - 1),
                       Values(v.subspan(va, nv)));
    out += fmt::format("  {:<12}= {}\n", "vdot", Values(vdot.subspan(va, nv)));
    out += fmt::format("  {:<12}= {}  (generalized: springs, damping, stops)\n", "joint force",
                       Values(tau.subspan(va, nv)));
  }
}

void DumpVehicles(const Model& model, const Data& data, std::string& out) {
  if (model.nvehicle() == 0) return;
  out += "\n== vehicles (world frame)\n";
  for (std::size_t v = 0; v < model.nvehicle(); ++v) {
    const VehicleState& state = data.vehicle[v];
    const Eigen::Quaterniond rotation(state.rotation);
    out += fmt::format("{}\n", model.vehicle_name[v]);
    out += fmt::format("  position             [m]       = {}\n", V(state.position));
    out += fmt::format("  orientation (w,x,y,z)          = ({:.9g}, {:.9g}, {:.9g}, {:.9g})\n",
                       rotation.w(), rotation.x(), rotation.y(), rotation.z());
    out += fmt::format("  velocity             [m/s]     = {}\n", V(state.velocity));
    out += fmt::format("  acceleration         [m/s^2]   = {}\n", V(state.acceleration));
    out += fmt::format("  angular velocity     [rad/s]   = {}\n", V(state.angular_velocity));
    out += fmt::format("  angular acceleration [rad/s^2] = {}\n", V(state.angular_acceleration));
  }
}

void DumpSegments(const Model& model, const Data& data, std::string& out) {
  out +=
      "\n== segments: centre of mass in the world frame; angular quantities in the segment "
      "frame; applied wrench at the centre of mass, segment frame\n";
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    const Mat3& R = data.rotation[s];
    const Vec3 w = data.velocity[s].head<3>();
    const Vec3 v = data.velocity[s].tail<3>();
    const Vec3 alpha = data.acceleration[s].head<3>();
    const Vec3 a = data.acceleration[s].tail<3>() + w.cross(v);  // classical, of the CoM
    const Eigen::Quaterniond rotation(R);
    out += fmt::format("{} (mass {:.9g} kg)\n", model.segment_name[s], model.segment_mass[s]);
    out += fmt::format("  position             [m]       = {}\n", V(data.position[s]));
    out += fmt::format("  orientation (w,x,y,z)          = ({:.9g}, {:.9g}, {:.9g}, {:.9g})\n",
                       rotation.w(), rotation.x(), rotation.y(), rotation.z());
    for (int row = 0; row < 3; ++row) {
      out += fmt::format("  {} [{:12.9f} {:12.9f} {:12.9f}]\n",
                         row == 0 ? "rotation to world   " : "                    ", R(row, 0),
                         R(row, 1), R(row, 2));
    }
    out += fmt::format("  velocity             [m/s]     = {}\n", V(R * v));
    out += fmt::format("  acceleration         [m/s^2]   = {}\n", V(R * a));
    out += fmt::format("  angular velocity     [rad/s]   = {}\n", V(w));
    out += fmt::format("  angular acceleration [rad/s^2] = {}\n", V(alpha));
    out += fmt::format("  applied torque       [N*m]     = {}\n", V(data.external[s].head<3>()));
    out += fmt::format("  applied force        [N]       = {}\n", V(data.external[s].tail<3>()));
  }
}

void DumpJoints(const Model& model, const Data& data, std::string& out) {
  out +=
      "\n== joints: angles; the force and torque the parent transmits to the child, in the "
      "child's frame, about the joint point\n";
  for (std::size_t s = 0; s < model.nsegment(); ++s) {
    if (model.joint_name[s].empty()) continue;
    const auto qa = static_cast<std::size_t>(model.q_address[s]);
    out +=
        fmt::format("{} ({}: {} -> {})\n", model.joint_name[s], JointKindName(model.joint_kind[s]),
                    model.segment_parent[s] >= 0
                        ? model.segment_name[static_cast<std::size_t>(model.segment_parent[s])]
                        : FrameName(model, model.segment_base[s]),
                    model.segment_name[s]);
    switch (model.joint_kind[s]) {
      case JointKind::kBall: {
        const SwingTwist angles = DecomposeSwingTwist(QuaternionAt(data.q, qa).normalized());
        out += fmt::format("  flexure, twist       [rad]     = ({:.9g}, {:.9g})\n", angles.flexure,
                           angles.twist);
        break;
      }
      case JointKind::kEuler:
        out += fmt::format("  precession, nutation, spin [rad] = ({:.9g}, {:.9g}, {:.9g})\n",
                           data.q[qa], data.q[qa + 1], data.q[qa + 2]);
        break;
      case JointKind::kSlip:
        out += fmt::format("  displacement         [m]       = {:.9g}\n", data.q[qa]);
        break;
      case JointKind::kPin:
        out += fmt::format("  angle                [rad]     = {:.9g}\n", data.q[qa]);
        break;
      default:
        break;
    }
    const Vec6& wrench = data.joint_wrench[s];
    const Vec3 torque = wrench.head<3>() - model.joint_point_in_child[s].cross(wrench.tail<3>());
    out += fmt::format("  torque               [N*m]     = {}\n", V(torque));
    out += fmt::format("  force                [N]       = {}\n", V(wrench.tail<3>()));
  }
}

void DumpSprings(const Model& model, const Data& data, std::string& out) {
  if (model.nspring() == 0) return;
  out += "\n== springs and dampers (force positive in tension)\n";
  for (std::size_t k = 0; k < model.nspring(); ++k) {
    out += fmt::format("{} ({} -> {}): length {:.9g} m, force {:.9g} N\n", model.spring_name[k],
                       FrameName(model, model.spring_first[k]),
                       FrameName(model, model.spring_second[k]), data.spring_length[k],
                       data.spring_force[k]);
  }
}

void DumpContacts(const Model& model, const Data& data, std::string& out) {
  const ContactTable& table = model.contacts;
  if (table.npair() == 0) return;
  out += "\n== contacts: world frame; the force acts on the first surface\n";
  for (std::size_t p = 0; p < table.npair(); ++p) {
    const auto first = static_cast<std::size_t>(table.pair_first[p]);
    const auto second = static_cast<std::size_t>(table.pair_second[p]);
    const std::string& other = table.pair_kind[p] == ContactTable::PairKind::kPlaneEllipsoid
                                   ? table.plane_name[second]
                                   : table.ellipsoid_name[second];
    const ContactState& state = data.contacts;
    out += fmt::format("{} with {}\n", table.ellipsoid_name[first], other);
    out += fmt::format("  deflection           [m]       = {:.9g}\n", state.deflection[p]);
    out += fmt::format("  gap                  [m]       = {:.9g}\n", state.gap[p]);
    out += fmt::format("  normal force         [N]       = {:.9g}\n", state.normal_force[p]);
    out += fmt::format("  force                [N]       = {}\n", V(state.force[p]));
    out += fmt::format("  point                [m]       = {}\n", V(state.point[p]));
    out += fmt::format("  normal                         = {}\n", V(state.normal[p]));
  }
}

void DumpBelts(const Model& model, const Data& data, std::string& out) {
  const BeltTable& table = model.belts;
  if (table.size() == 0) return;
  const BeltState& state = data.belts;
  out += "\n== belts: spans (world frame), anchor forces in the anchor's frame\n";
  for (std::size_t b = 0; b < table.size(); ++b) {
    out += fmt::format("{}\n", table.name[b]);
    for (std::int32_t i = 0; i < table.span_count(b); ++i) {
      const auto span = static_cast<std::size_t>(table.first_span(b) + i);
      out += fmt::format(
          "  span {}: tension {:.9g} N, length {:.9g} m, webbing {:.9g} m, from {} to {}\n", i + 1,
          state.tension[span], state.length[span], state.rest_length[span], V(state.start[span]),
          V(state.end[span]));
    }
    for (std::int32_t i = 0; i < table.point_count[b]; ++i) {
      const auto k = static_cast<std::size_t>(table.first_point[b] + i);
      if (table.point_wraps[k] == 0) continue;
      out += fmt::format("  over {}: entry {}, exit {}, arc {:.9g} m{}\n",
                         FrameName(model, table.point_frame[k]), V(state.entry[k]),
                         V(state.exit[k]), state.arc[k], state.contact[k] ? "" : " (not touching)");
    }
    out += fmt::format("  force on the first anchor [N] = {}\n", V(state.start_anchor_force[b]));
    out += fmt::format("  force on the last anchor  [N] = {}\n", V(state.end_anchor_force[b]));
  }
}

void DumpConstraints(const Model& model, const Data& data, std::string& out) {
  if (model.nconstraint() == 0 || !data.constraints) return;
  const ConstraintWorkspace& workspace = *data.constraints;
  out += "\n== loop-closing constraints: world force on the first frame at its point\n";
  for (std::size_t c = 0; c < model.nconstraint(); ++c) {
    out += fmt::format("{} ({} -> {}): force {} N at {}, position error {:.3g} m\n",
                       model.constraint_name[c], FrameName(model, model.constraint_first[c]),
                       FrameName(model, model.constraint_second[c]), V(workspace.force_first[c]),
                       V(workspace.point_first[c]), workspace.error[c]);
  }
}

}  // namespace

std::string StateDump(const Model& model, const Data& data) {
  std::string out = fmt::format("# {}\n# complete state at t = {:.9g} s\n", model.title, data.time);
  DumpState(model, data, out);
  DumpVehicles(model, data, out);
  DumpSegments(model, data, out);
  DumpJoints(model, data, out);
  DumpSprings(model, data, out);
  DumpContacts(model, data, out);
  DumpBelts(model, data, out);
  DumpConstraints(model, data, out);
  return out;
}

std::string StateDumpFileName(double t) { return fmt::format("dump_{}.txt", t); }

bool WriteStateDump(const std::string& path, const Model& model, const Data& data,
                    std::string* error) {
  return ReplaceFile(path, StateDump(model, data), error);
}

}  // namespace sled::runtime
