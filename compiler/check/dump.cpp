// The stable text form of a checked scenario: SI values, names resolved, no source ranges.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compiler/check/checked_scenario.h"

namespace sled::compiler {
namespace {

std::string V(const Vec3& v) { return fmt::format("({}, {}, {})", v[0], v[1], v[2]); }

std::string FrameText(const CheckedScenario& s, const FrameRef& frame) {
  switch (frame.kind) {
    case FrameRef::Kind::kVehicle:
      return "vehicle " + s.vehicles.at(static_cast<std::size_t>(frame.index)).name;
    case FrameRef::Kind::kSegment:
      return "segment " + s.segments.at(static_cast<std::size_t>(frame.index)).name;
    case FrameRef::Kind::kGround:
      break;
  }
  return "ground";
}

std::string SurfaceText(const CheckedScenario& s, const SurfaceRef& surface) {
  return surface.kind == SurfaceRef::Kind::kPlane
             ? "plane " + s.planes.at(static_cast<std::size_t>(surface.index)).name
             : "ellipsoid " + s.ellipsoids.at(static_cast<std::size_t>(surface.index)).name;
}

std::string FunctionText(const CheckedScenario& s, FunctionId id) {
  if (id < 0) return "none";
  const Function& f = s.functions.at(static_cast<std::size_t>(id));
  std::string out = f.name.empty() ? std::string() : f.name + " ";
  out += fmt::format("[{} -> {}] ", SiUnitSymbol(f.argument), SiUnitSymbol(f.result));
  switch (f.kind) {
    case Function::Kind::kConstant:
      out += fmt::format("constant {}", f.constant);
      break;
    case Function::Kind::kTable:
      out += "table";
      for (const auto& p : f.points) out += fmt::format(" {}->{}", p[0], p[1]);
      break;
    case Function::Kind::kPolynomial:
      out += fmt::format("polynomial {}", fmt::join(f.coefficients, " "));
      break;
  }
  if (f.energy_loss != 0 || f.permanent_set != 0 || f.unload_slope) {
    out += fmt::format(" unload(energy_loss {} permanent_set {} slope {})", f.energy_loss,
                       f.permanent_set, f.unload_slope ? fmt::format("{}", *f.unload_slope) : "-");
  }
  if (f.atb_unloading) {
    out += fmt::format(" unload(atb energy_return f{} permanent_set f{})", f.energy_return,
                       f.atb_permanent_set);
    if (f.atb_spike >= 0) {
      out += fmt::format(" spike(f{} end {})", f.atb_spike, f.atb_spike_end);
    }
    if (f.atb_origin != 0) out += fmt::format(" origin({})", f.atb_origin);
  }
  return out;
}

template <typename T>
std::string Optional(const std::optional<T>& value) {
  return value ? fmt::format("{}", *value) : "-";
}

}  // namespace

std::string Dump(const CheckedScenario& s) {
  std::string out;
  auto line = [&](const std::string& text) { out += text + "\n"; };
  line(fmt::format("scenario \"{}\"", s.title));
  const RunSettings& r = s.run;
  line(
      fmt::format("run start {} end {} output_every {} method {} rtol {} atol {} min_step {} "
                  "max_step {} initial_step {} gravity {}",
                  r.start, r.end, r.output_every, static_cast<int>(r.method), r.relative_tolerance,
                  r.absolute_tolerance, r.min_step, Optional(r.max_step), Optional(r.initial_step),
                  V(r.gravity)));
  line(fmt::format("restart every {} from \"{}\" settle {} symmetry {} pairs {}",
                   Optional(r.checkpoint_every), r.resume_from,
                   r.settle ? fmt::format("{}", r.settle->duration) : std::string("-"),
                   static_cast<int>(r.symmetry), r.mirror_pairs.size()));
  for (std::size_t i = 0; i < s.functions.size(); ++i) {
    line(fmt::format("function #{} {}", i, FunctionText(s, static_cast<FunctionId>(i))));
  }
  for (const Body& b : s.bodies) {
    std::vector<std::string> references;
    for (int r_index : b.reference_segments) {
      references.push_back(s.segments.at(static_cast<std::size_t>(r_index)).name);
    }
    line(fmt::format("body {} segments {} joints {} reference {}", b.name, b.segments.size(),
                     b.joints.size(), fmt::join(references, ",")));
  }
  for (const Segment& g : s.segments) {
    line(fmt::format("segment {} mass {} inertia {} axes {} singular {} ellipsoids {}", g.name,
                     g.mass, V(g.inertia), V(g.principal_axes), g.singular, g.ellipsoids.size()));
  }
  for (const Joint& j : s.joints) {
    auto name = [&](int segment) {
      return segment < 0 ? std::string("?") : s.segments.at(static_cast<std::size_t>(segment)).name;
    };
    line(fmt::format(
        "joint {} type {} {} -> {} at {} {} axes {} {} axis {} flexure {} twist {} "
        "precession {} nutation {} spin {} viscous {} coulomb {} energy_loss {} stop "
        "{} twist_stop {} impulse {} restitution {} locked {} lock_below {} "
        "unlock_above {}",
        j.name, static_cast<int>(j.type), name(j.parent), name(j.child), V(j.location_in_parent),
        V(j.location_in_child), V(j.axes_in_parent), V(j.axes_in_child), V(j.axis),
        FunctionText(s, j.flexure), FunctionText(s, j.twist), FunctionText(s, j.precession),
        FunctionText(s, j.nutation), FunctionText(s, j.spin), j.viscous, j.coulomb, j.energy_loss,
        Optional(j.stop), Optional(j.twist_stop), j.stop_impulse, j.restitution, j.locked_axes,
        Optional(j.lock_below), Optional(j.unlock_above)));
  }
  for (const Ellipsoid& e : s.ellipsoids) {
    line(fmt::format("ellipsoid {} on {} semi_axes {} center {} orientation {} degree {}", e.name,
                     FrameText(s, e.frame), V(e.semi_axes), V(e.center), V(e.orientation),
                     e.degree));
  }
  for (const Vehicle& v : s.vehicles) {
    const Motion& m = v.motion;
    line(
        fmt::format("vehicle {} motion {} axis {} start {} delta_v {} duration {} peak {} rise {} "
                    "dwell {} fall {} table {} six_dof {} position {} orientation {} velocity {}",
                    v.name, static_cast<int>(m.kind), V(m.axis), m.start, m.delta_v, m.duration,
                    m.peak, m.rise, m.dwell, m.fall, m.table.size(), m.six_dof.size(),
                    V(v.position), V(v.orientation), V(v.velocity)));
  }
  for (const Plane& p : s.planes) {
    line(fmt::format("plane {} on {} corners {} {} {}", p.name, FrameText(s, p.frame),
                     V(p.corners[0]), V(p.corners[1]), V(p.corners[2])));
  }
  for (const Contact& c : s.contacts) {
    line(
        fmt::format("contact {} with {} force {} damping {} friction {} impulse {} "
                    "restitution {}",
                    SurfaceText(s, c.first), SurfaceText(s, c.second), FunctionText(s, c.force),
                    c.damping, c.friction, c.impulse, c.restitution));
  }
  for (const Harness& h : s.harnesses) {
    line(fmt::format("harness {} on {} belts {} friction {}", h.name, FrameText(s, h.frame),
                     h.belts.size(), h.friction));
  }
  for (const Belt& b : s.belts) {
    std::string path;
    for (const BeltPoint& p : b.path) {
      if (!path.empty()) path += " -> ";
      path += p.kind == BeltPoint::Kind::kAnchor
                  ? V(p.point)
                  : s.segments.at(static_cast<std::size_t>(p.segment)).name;
    }
    line(fmt::format("belt {} on {} path {} force {} slack {} pretension {} friction {}", b.name,
                     FrameText(s, b.frame), path, FunctionText(s, b.force), b.slack, b.pretension,
                     b.friction));
  }
  for (const Airbag& a : s.airbags) {
    line(
        fmt::format("airbag {} on {} position {} orientation {} semi_axes {} deploy_at {} inflow "
                    "{} vent_area {} ambient {} gas_temperature {} gamma {} gas_constant {} "
                    "discharge {} contacts {}",
                    a.name, FrameText(s, a.frame), V(a.position), V(a.orientation), V(a.semi_axes),
                    a.deploy_time, FunctionText(s, a.inflow), a.vent_area, a.ambient_pressure,
                    a.gas_temperature, a.gamma, a.gas_constant, a.discharge_coefficient,
                    a.contact_segments.size()));
  }
  for (const SpringDamper& k : s.springs) {
    line(fmt::format("{} {} {} {} -> {} {} stiffness {} damping {} free_length {}",
                     k.tension_only ? "tension" : "spring", k.name, FrameText(s, k.first),
                     V(k.point_in_first), FrameText(s, k.second), V(k.point_in_second),
                     FunctionText(s, k.stiffness), k.damping, Optional(k.free_length)));
  }
  for (const AppliedLoad& l : s.loads) {
    line(fmt::format("load {} {} #{} force {} direction {} point {} torque {} axis {} in {}",
                     l.name, l.across_joint ? "joint" : "segment", l.index,
                     FunctionText(s, l.force), V(l.direction), V(l.point),
                     FunctionText(s, l.torque), V(l.axis), l.in_segment ? "segment" : "ground"));
  }
  for (const Actuator& a : s.actuators) {
    line(fmt::format("actuator {} joint #{} target {} proportional {} derivative {} integral {}",
                     a.name, a.joint, FunctionText(s, a.target), FunctionText(s, a.proportional),
                     FunctionText(s, a.derivative), FunctionText(s, a.integral)));
  }
  for (const Fluid& f : s.fluids) {
    std::string segments;
    for (int segment : f.segments) segments += fmt::format(" #{}", segment);
    line(fmt::format("{} speed {} pressure {} direction {} density {} drag {} level {} segments{}",
                     f.medium == Fluid::Medium::kWind ? "wind" : "water", FunctionText(s, f.speed),
                     FunctionText(s, f.pressure), V(f.direction), f.density, f.drag, f.level,
                     segments));
  }
  for (const Constraint& c : s.constraints) {
    line(fmt::format("constraint {} kind {} {} {} -> {} {} distance {} axis {}", c.name,
                     static_cast<int>(c.kind), FrameText(s, c.first), V(c.point_in_first),
                     FrameText(s, c.second), V(c.point_in_second), Optional(c.distance),
                     V(c.axis)));
  }
  for (const InitialCondition& i : s.initial_conditions) {
    auto v = [](const std::optional<Vec3>& value) { return value ? V(*value) : "-"; };
    line(
        fmt::format("initial {} #{} position {} orientation {} velocity {} angular_velocity {} "
                    "angles {}",
                    static_cast<int>(i.kind), i.index, v(i.position), v(i.orientation),
                    v(i.velocity), v(i.angular_velocity), v(i.joint_angles)));
  }
  for (const OutputRequest& o : s.outputs) {
    std::string pairs;
    if (o.contacts.size() > 1) {
      for (int c : o.contacts) pairs += fmt::format(" #{}", c);
      pairs.insert(0, " pairs");
    }
    const std::string relative =
        o.relative_to ? fmt::format(" {} {}", o.expressed_in ? "expressed_in" : "relative_to",
                                    FrameText(s, *o.relative_to))
                      : "";
    line(fmt::format("output {} {} #{} at {}{}{}", static_cast<int>(o.kind), o.label, o.index,
                     V(o.point), pairs, relative));
  }
  for (const Criterion& c : s.criteria) {
    line(fmt::format("criterion {} segment {} joint {}", static_cast<int>(c.kind),
                     c.segment < 0 ? "-" : s.segments.at(static_cast<std::size_t>(c.segment)).name,
                     c.joint < 0 ? "-" : s.joints.at(static_cast<std::size_t>(c.joint)).name));
  }
  return out;
}

}  // namespace sled::compiler
