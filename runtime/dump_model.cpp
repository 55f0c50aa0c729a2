// runtime::DumpModel: a stable text form of a Model for `sled check --dump-model` and golden
// tests. One line per entity; numbers in their shortest round-trip form; rotation matrices row by
// row. Equal dumps mean equal models.
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "runtime/model.h"
#include "runtime/relative_motion.h"

namespace sled::runtime {
namespace {

std::string Text(const Vec3& v) { return fmt::format("({}, {}, {})", v.x(), v.y(), v.z()); }

std::string Text(const Mat3& m) {
  return fmt::format("[[{}, {}, {}], [{}, {}, {}], [{}, {}, {}]]", m(0, 0), m(0, 1), m(0, 2),
                     m(1, 0), m(1, 1), m(1, 2), m(2, 0), m(2, 1), m(2, 2));
}

std::string Text(const FrameRef& frame) {
  switch (frame.kind) {
    case FrameRef::Kind::kVehicle:
      return fmt::format("vehicle {}", frame.index);
    case FrameRef::Kind::kSegment:
      return fmt::format("segment {}", frame.index);
    case FrameRef::Kind::kGround:
      break;
  }
  return "ground";
}

std::string Text(const SourcePosition& source) {
  if (source.file.empty() && source.line == 0) return "-";
  return fmt::format("{}:{}:{}", source.file, source.line, source.column);
}

template <typename T>
std::string List(const std::vector<T>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    out += fmt::format("{}{}", i == 0 ? "" : ", ", values[i]);
  }
  return out + "]";
}

template <typename T>
const T& Get(const std::vector<T>& values, std::size_t i) {
  return values.at(i);
}

const char* Name(Model::ConstraintKind kind) {
  switch (kind) {
    case Model::ConstraintKind::kFixedPoint:
      return "fixed_point";
    case Model::ConstraintKind::kFixedDistance:
      return "fixed_distance";
    case Model::ConstraintKind::kRolling:
      return "rolling";
    case Model::ConstraintKind::kSliding:
      return "sliding";
  }
  return "?";
}

const char* Name(Model::OutputKind kind) {
  switch (kind) {
    case Model::OutputKind::kAcceleration:
      return "acceleration";
    case Model::OutputKind::kVelocity:
      return "velocity";
    case Model::OutputKind::kPosition:
      return "position";
    case Model::OutputKind::kAngularAcceleration:
      return "angular_acceleration";
    case Model::OutputKind::kAngularVelocity:
      return "angular_velocity";
    case Model::OutputKind::kOrientation:
      return "orientation";
    case Model::OutputKind::kJointAngle:
      return "joint_angle";
    case Model::OutputKind::kJointTorque:
      return "joint_torque";
    case Model::OutputKind::kJointForce:
      return "joint_force";
    case Model::OutputKind::kSpringForce:
      return "spring_force";
    case Model::OutputKind::kContactForce:
      return "contact_force";
    case Model::OutputKind::kContactPoint:
      return "contact_point";
    case Model::OutputKind::kContactDeflection:
      return "contact_deflection";
    case Model::OutputKind::kBeltForce:
      return "belt_force";
    case Model::OutputKind::kAirbagPressure:
      return "airbag_pressure";
    case Model::OutputKind::kAirbagVolume:
      return "airbag_volume";
    case Model::OutputKind::kAirbagGasMass:
      return "airbag_gas_mass";
    case Model::OutputKind::kAirbagTemperature:
      return "airbag_temperature";
    case Model::OutputKind::kAirbagVentFlow:
      return "airbag_vent_flow";
    case Model::OutputKind::kAirbagForce:
      return "airbag_force";
  }
  return "?";
}

std::string MotionText(const VehicleMotion& motion) {
  switch (motion.kind) {
    case VehicleMotion::Kind::kNone:
      return "none";
    case VehicleMotion::Kind::kHalfSine:
      return fmt::format("half_sine axis {} start {} delta_v {} duration {}", Text(motion.axis),
                         motion.start, motion.delta_v, motion.duration);
    case VehicleMotion::Kind::kTrapezoid:
      return fmt::format("trapezoid axis {} start {} peak {} rise {} dwell {} fall {}",
                         Text(motion.axis), motion.start, motion.peak, motion.rise, motion.dwell,
                         motion.fall);
    case VehicleMotion::Kind::kTable: {
      std::string out =
          fmt::format("table axis {} start {} rows [", Text(motion.axis), motion.start);
      for (std::size_t i = 0; i < motion.table.size(); ++i) {
        out +=
            fmt::format("{}({}, {})", i == 0 ? "" : ", ", motion.table[i][0], motion.table[i][1]);
      }
      return out + "]";
    }
    case VehicleMotion::Kind::kSixDof: {
      std::string out = fmt::format("six_dof start {} rows [", motion.start);
      for (std::size_t i = 0; i < motion.six_dof.size(); ++i) {
        const auto& r = motion.six_dof[i];
        out += fmt::format("{}({}, {}, {}, {}, {}, {}, {})", i == 0 ? "" : ", ", r[0], r[1], r[2],
                           r[3], r[4], r[5], r[6]);
      }
      return out + "]";
    }
  }
  return "?";
}

std::string FunctionText(const FunctionTable& f, std::size_t i) {
  const auto first = static_cast<std::size_t>(Get(f.first, i) < 0 ? 0 : Get(f.first, i));
  const auto count = static_cast<std::size_t>(Get(f.count, i) < 0 ? 0 : Get(f.count, i));
  std::string out;
  switch (Get(f.kind, i)) {
    case FunctionTable::Kind::kConstant:
      out = fmt::format("constant {}", Get(f.constant, i));
      break;
    case FunctionTable::Kind::kTable:
      out = "table [";
      for (std::size_t k = 0; k < count; ++k) {
        out += fmt::format("{}({}, {})", k == 0 ? "" : ", ", Get(f.points_x, first + k),
                           Get(f.points_y, first + k));
      }
      out += "]";
      break;
    case FunctionTable::Kind::kPolynomial:
      out = "polynomial [";
      for (std::size_t k = 0; k < count; ++k) {
        out += fmt::format("{}{}", k == 0 ? "" : ", ", Get(f.coefficients, first + k));
      }
      out += "]";
      break;
  }
  out += fmt::format(" energy_loss {} permanent_set {}", Get(f.energy_loss, i),
                     Get(f.permanent_set, i));
  // Only when given, so the dumps of functions without it stay as they were.
  if (i < f.unload_slope.size() && f.unload_slope[i] > 0) {
    out += fmt::format(" unload_slope {}", f.unload_slope[i]);
  }
  return out;
}

// One line per airbag and per contact ellipsoid, and the auxiliary states' initial values.
template <typename Line>
void DumpAirbags(const Model& m, Line& line) {
  const AirbagTable& bags = m.airbags;
  if (m.nw > 0) line(fmt::format("w0 {}", List(m.w0)));
  for (std::size_t b = 0; b < bags.size(); ++b) {
    line(fmt::format(
        "airbag {} {} on {} deploy_point {} axes {} semi_axes {} deploy_at {} inflow {} "
        "gas_temperature {} vent_area {} discharge {} ambient {} gamma {} gas_constant {} "
        "state {}",
        b, bags.name[b], Text(bags.frame[b]), Text(bags.deploy_point[b]), Text(bags.axes[b]),
        Text(bags.semi_axes[b]), bags.deploy_time[b], bags.inflow[b], bags.inflow_temperature[b],
        bags.vent_area[b], bags.discharge_coefficient[b], bags.ambient_pressure[b], bags.gamma[b],
        bags.gas_constant[b], bags.state_address[b]));
    const auto first = static_cast<std::size_t>(bags.first_contact[b]);
    for (std::size_t c = first; c < first + static_cast<std::size_t>(bags.contact_count[b]); ++c) {
      line(fmt::format("  touches segment {} center {} axes {} semi_axes {}",
                       bags.contact_segment[c], Text(bags.contact_center[c]),
                       Text(bags.contact_axes[c]), Text(bags.contact_semi_axes[c])));
    }
  }
}

// One line per belt and per path point, then the harnesses and their tie points.
template <typename Line>
void DumpBelts(const Model& m, Line& line) {
  const BeltTable& belts = m.belts;
  for (std::size_t b = 0; b < belts.size(); ++b) {
    line(fmt::format(
        "belt {} {} function {} slack {} pretension {} friction {} harness {} points {}", b,
        belts.name[b], Get(belts.function, b), Get(belts.slack, b), Get(belts.pretension, b),
        Get(belts.friction, b), Get(belts.harness, b), Get(belts.point_count, b)));
    const auto first = static_cast<std::size_t>(Get(belts.first_point, b));
    for (std::size_t k = first; k < first + static_cast<std::size_t>(belts.point_count[b]); ++k) {
      if (Get(belts.point_wraps, k)) {
        line(fmt::format("  wrap {} centre {} axes {} semi_axes {}",
                         Text(Get(belts.point_frame, k)), Text(Get(belts.point_position, k)),
                         Text(Get(belts.point_axes, k)), Text(Get(belts.point_semi_axes, k))));
      } else {
        line(fmt::format("  anchor {} {}", Text(Get(belts.point_frame, k)),
                         Text(Get(belts.point_position, k))));
      }
    }
  }
  for (std::size_t h = 0; h < belts.harness_name.size(); ++h) {
    line(fmt::format("harness {} {} friction {}", h, belts.harness_name[h],
                     Get(belts.harness_friction, h)));
  }
  for (std::size_t t = 0; t < belts.tie_points.size(); ++t) {
    line(fmt::format("tie {} harness {} points {} {}", t, Get(belts.tie_harness, t),
                     belts.tie_points[t][0], belts.tie_points[t][1]));
  }
}

}  // namespace

std::string DumpModel(const Model& m) {
  std::string out;
  auto line = [&out](const std::string& text) {
    out += text;
    out += '\n';
  };
  line(fmt::format("title {}", m.title));
  line(fmt::format("gravity {}", Text(m.gravity)));
  line(
      fmt::format("run start {} end {} output_every {} integrator {} relative_tolerance {} "
                  "absolute_tolerance {} min_step {} max_step {} initial_step {}",
                  m.start_time, m.end_time, m.output_every, m.integrator, m.relative_tolerance,
                  m.absolute_tolerance, m.min_step, m.max_step, m.initial_step));
  if (m.settle.duration > 0) {
    line(
        fmt::format("settle duration {} damping {} velocity {} angular_velocity {} "
                    "force_change {} check_every {}",
                    m.settle.duration, m.settle.damping, m.settle.velocity,
                    m.settle.angular_velocity, m.settle.force_change, m.settle.check_every));
  }
  line(
      fmt::format("sizes segments {} nq {} nv {} vehicles {} functions {} springs {} "
                  "constraints {} outputs {}",
                  m.nsegment(), m.nq, m.nv, m.nvehicle(), m.functions.size(), m.nspring(),
                  m.nconstraint(), m.output_kind.size()));
  for (std::size_t s = 0; s < m.nsegment(); ++s) {
    // The dummy type after the source: a checkpoint's physics fingerprint drops the source and
    // what follows it, and the dummy type only names channels (runtime/checkpoint.cpp).
    line(fmt::format("segment {} {} parent {} base {} mass {} inertia {} source {}", s,
                     m.segment_name[s], Get(m.segment_parent, s),
                     s < m.segment_base.size() ? Text(m.segment_base[s]) : std::string("-"),
                     Get(m.segment_mass, s), Text(Get(m.segment_inertia, s)),
                     Text(Get(m.segment_source, s))) +
         (s < m.segment_dummy.size() ? " dummy " + m.segment_dummy[s] : std::string()));
    const JointKind kind = Get(m.joint_kind, s);
    std::string joint =
        fmt::format("joint {} {} {} q {}+{} v {}+{}", s,
                    Get(m.joint_name, s).empty() ? "-" : Get(m.joint_name, s), JointKindName(kind),
                    Get(m.q_address, s), Get(m.q_count, s), Get(m.v_address, s), Get(m.v_count, s));
    if (kind != JointKind::kFree) {
      const auto& functions = Get(m.joint_function, s);
      joint += fmt::format(
          " point_in_parent {} frame_in_parent {} point_in_child {} frame_in_child {} axis {} "
          "functions [{}, {}, {}] viscous {} coulomb {} stop {} twist_stop {} stop_impulse {} "
          "restitution {} locked {} lock_below {} unlock_above {} source {}",
          Text(Get(m.joint_point_in_parent, s)), Text(Get(m.joint_frame_in_parent, s)),
          Text(Get(m.joint_point_in_child, s)), Text(Get(m.joint_frame_in_child, s)),
          Text(Get(m.joint_axis, s)), functions[0], functions[1], functions[2],
          Get(m.joint_viscous, s), Get(m.joint_coulomb, s), Get(m.joint_stop, s),
          Get(m.joint_twist_stop, s), Get(m.joint_stop_impulse, s), Get(m.joint_restitution, s),
          Get(m.joint_locked, s), Get(m.joint_lock_below, s), Get(m.joint_unlock_above, s),
          Text(Get(m.joint_source, s)));
    }
    line(joint);
    if (s < m.segment_mirror_twin.size() && m.segment_mirror_twin[s]) {
      line(fmt::format("  mirror_twin normal_in_parent {}", Text(m.mirror_normal[s])));
    }
    if (s < m.segment_mirror_count.size() && m.segment_mirror_count[s] == 2) {
      line("  stands_for_its_mirror_image");
    }
  }
  if (!m.segment_mirror_twin.empty()) line(fmt::format("mirror_plane y {}", m.mirror_plane_y));
  line(fmt::format("q0 {}", List(m.q0)));
  line(fmt::format("v0 {}", List(m.v0)));
  for (std::size_t v = 0; v < m.nvehicle(); ++v) {
    line(fmt::format("vehicle {} {} position {} orientation {} velocity {} motion {}", v,
                     m.vehicle_name[v], Text(Get(m.vehicle_position, v)),
                     Text(Get(m.vehicle_orientation, v)), Text(Get(m.vehicle_velocity, v)),
                     MotionText(Get(m.vehicle_motion, v))));
    const Vec3 spin =
        v < m.vehicle_angular_velocity.size() ? m.vehicle_angular_velocity[v] : Vec3::Zero();
    const std::size_t samples = v < m.vehicle_path.size() ? m.vehicle_path[v].size() : 0;
    if (!spin.isZero() || samples > 0) {
      line(fmt::format("  turning angular_velocity {} path {} samples", Text(spin), samples));
    }
  }
  for (std::size_t f = 0; f < m.functions.size(); ++f) {
    line(fmt::format("function {} {}", f, FunctionText(m.functions, f)));
  }
  for (std::size_t s = 0; s < m.nspring(); ++s) {
    line(fmt::format(
        "spring {} {} first {} {} second {} {} function {} damping {} free_length {} "
        "tension_only {}",
        s, m.spring_name[s], Text(Get(m.spring_first, s)), Text(Get(m.spring_point_first, s)),
        Text(Get(m.spring_second, s)), Text(Get(m.spring_point_second, s)),
        Get(m.spring_function, s), Get(m.spring_damping, s), Get(m.spring_free_length, s),
        Get(m.spring_tension_only, s)));
  }
  for (std::size_t k = 0; k < m.shape_name.size(); ++k) {
    line(fmt::format("shape {} {} segment {} center {} semi_axes {} degree {}", k, m.shape_name[k],
                     m.shape_segment[k], Text(m.shape_center[k]), Text(m.shape_semi_axes[k]),
                     m.shape_degree[k]));
  }
  const LoadTable& loads = m.loads;
  for (std::size_t k = 0; k < loads.size(); ++k) {
    line(
        fmt::format("load {} {} kind {} segment {} force {} direction {} point {} torque {} axis "
                    "{} in_segment {}",
                    k, loads.name[k], static_cast<int>(loads.kind[k]), loads.segment[k],
                    loads.force[k], Text(loads.direction[k]), Text(loads.point[k]), loads.torque[k],
                    Text(loads.axis[k]), loads.in_segment[k]));
  }
  for (std::size_t c = 0; c < m.nconstraint(); ++c) {
    line(fmt::format("constraint {} {} {} first {} {} second {} {} distance {} axis {}", c,
                     m.constraint_name[c], Name(Get(m.constraint_kind, c)),
                     Text(Get(m.constraint_first, c)), Text(Get(m.constraint_point_first, c)),
                     Text(Get(m.constraint_second, c)), Text(Get(m.constraint_point_second, c)),
                     Get(m.constraint_distance, c), Text(Get(m.constraint_axis, c))));
  }
  const ContactTable& contacts = m.contacts;
  for (std::size_t e = 0; e < contacts.nellipsoid(); ++e) {
    line(
        fmt::format("contact_ellipsoid {} {} on {} center {} axes {} semi_axes {} degree {} "
                    "radius {}",
                    e, contacts.ellipsoid_name[e], Text(Get(contacts.ellipsoid_frame, e)),
                    Text(Get(contacts.ellipsoid_center, e)), Text(Get(contacts.ellipsoid_axes, e)),
                    Text(Get(contacts.ellipsoid_semi_axes, e)), Get(contacts.ellipsoid_degree, e),
                    Get(contacts.ellipsoid_radius, e)));
  }
  for (std::size_t p = 0; p < contacts.nplane(); ++p) {
    line(fmt::format("contact_plane {} {} on {} origin {} edge_u {} edge_v {} normal {}", p,
                     contacts.plane_name[p], Text(Get(contacts.plane_frame, p)),
                     Text(Get(contacts.plane_origin, p)), Text(Get(contacts.plane_edge_u, p)),
                     Text(Get(contacts.plane_edge_v, p)), Text(Get(contacts.plane_normal, p))));
  }
  for (std::size_t k = 0; k < contacts.npair(); ++k) {
    const bool plane = Get(contacts.pair_kind, k) == ContactTable::PairKind::kPlaneEllipsoid;
    line(fmt::format(
        "contact {} ellipsoid {} with {} {} function {} damping {} damping_depth {} friction {} "
        "impulse {} restitution {} source {}",
        k, Get(contacts.pair_first, k), plane ? "plane" : "ellipsoid", Get(contacts.pair_second, k),
        Get(contacts.pair_function, k), Get(contacts.pair_damping, k),
        Get(contacts.pair_damping_depth, k), Get(contacts.pair_friction, k),
        Get(contacts.pair_impulse, k), Get(contacts.pair_restitution, k),
        Text(Get(contacts.pair_source, k))));
  }
  for (std::size_t g = 0; g < contacts.group_first.size(); ++g) {
    const auto first = static_cast<std::size_t>(contacts.group_first[g]);
    const auto count = static_cast<std::size_t>(Get(contacts.group_count, g));
    const std::vector<std::int32_t> pairs(contacts.group_pairs.begin() + first,
                                          contacts.group_pairs.begin() + first + count);
    line(fmt::format("contact_group {} pairs {}", g, List(pairs)));
  }
  DumpBelts(m, line);
  DumpAirbags(m, line);
  for (std::size_t o = 0; o < m.output_kind.size(); ++o) {
    const bool mirrored = o < m.output_mirrored.size() && m.output_mirrored[o] != 0;
    const int cfc = o < m.output_filter_class.size() ? m.output_filter_class[o] : 0;
    const bool iso = o < m.output_filter_iso.size() && m.output_filter_iso[o] != 0;
    std::string relative;
    if (o < m.output_relative.size() && m.output_relative[o] != 0) {
      relative = fmt::format(
          " {} {}{}", m.output_relative[o] == kExpressedIn ? "expressed_in" : "relative_to",
          Text(m.output_frame[o]), m.output_frame_mirrored[o] != 0 ? " mirrored" : "");
    }
    line(fmt::format("output {} {} {} index {} point {}{} filter {}{}{}", o, Name(m.output_kind[o]),
                     Get(m.output_label, o), Get(m.output_index, o), Text(Get(m.output_point, o)),
                     mirrored ? " mirrored" : "", cfc > 0 ? fmt::format("cfc{}", cfc) : "none",
                     iso ? " iso_6487" : "", relative));
  }
  for (std::size_t c = 0; c < m.ncriterion(); ++c) {
    const bool own_limit = c < m.criterion_limit.size() && !std::isnan(m.criterion_limit[c]);
    line(fmt::format("criterion {} {} {} output {} second_output {}{}{}", c,
                     Get(m.criterion_name, c), Get(m.criterion_target, c),
                     Get(m.criterion_output, c), Get(m.criterion_second_output, c),
                     Get(m.criterion_filter_iso, c) != 0 ? " iso_6487" : "",
                     own_limit ? fmt::format(" limit {} standard \"{}\"", m.criterion_limit[c],
                                             m.criterion_standard[c])
                               : std::string()));
  }
  return out;
}

}  // namespace sled::runtime
