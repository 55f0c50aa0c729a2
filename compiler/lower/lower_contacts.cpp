// Contacts: the surfaces the contacts use and the pairs that can touch. A pair is left out, with
// a note, when its surfaces can be shown never to touch: both fixed in one rigid frame (the same
// segment, segments joined by joints locked for good, or prescribed frames), adjacent segments
// whose joint keeps the ellipsoids apart, and a segment held at a point of the frame of the other
// surface that cannot reach it.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "compiler/lower/lowering.h"
#include "runtime/contact/contact_geometry.h"

namespace sled::compiler::lowering {
namespace {

using runtime::ContactTable;
using runtime::Model;
using RuntimeFrame = runtime::FrameRef;

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

bool SameFrame(const RuntimeFrame& a, const RuntimeFrame& b) {
  return a.kind == b.kind && a.index == b.index;
}

// A joint locked on all its axes with no level to unlock it: child and parent move as one.
bool LockedForGood(const Model& model, std::size_t s) {
  return model.segment_parent[s] >= 0 && model.joint_unlock_above[s] < 0 &&
         (model.joint_locked[s] & 7u) == 7u;
}

// The segment at the top of the rigid group a segment belongs to (joints locked for good).
std::size_t RigidRoot(const Model& model, std::size_t s) {
  while (LockedForGood(model, s)) s = static_cast<std::size_t>(model.segment_parent[s]);
  return s;
}

// Where a surface is fixed, up to rigid groups: a segment stands for its rigid group.
RuntimeFrame RigidFrame(const Model& model, RuntimeFrame frame) {
  if (frame.kind == RuntimeFrame::Kind::kSegment) {
    frame.index =
        static_cast<std::int32_t>(RigidRoot(model, static_cast<std::size_t>(frame.index)));
  }
  return frame;
}

// How far a point fixed in segment s can be from the point where its tree is held to its base
// frame, whatever the joint angles: the sum of the link lengths up the tree. Unbounded for a
// floating tree or across a slip joint.
double ReachFromBase(const Model& model, std::size_t s, const runtime::Vec3& point) {
  double reach = 0.0;
  runtime::Vec3 x = point;
  while (true) {
    if (model.joint_kind[s] == runtime::JointKind::kFree ||
        model.joint_kind[s] == runtime::JointKind::kSlip) {
      return kUnbounded;
    }
    reach += (x - model.joint_point_in_child[s]).norm();
    if (model.segment_parent[s] < 0) return reach;
    x = model.joint_point_in_parent[s];
    s = static_cast<std::size_t>(model.segment_parent[s]);
  }
}

std::size_t TreeRoot(const Model& model, std::size_t s) {
  while (model.segment_parent[s] >= 0) s = static_cast<std::size_t>(model.segment_parent[s]);
  return s;
}

// A surface of a contact, in the Model's terms.
struct Surface {
  RuntimeFrame frame;
  bool plane = false;
  runtime::Vec3 center = runtime::Vec3::Zero();   // ellipsoid centre, or the plane's P1
  runtime::Vec3 normal = runtime::Vec3::UnitZ();  // plane only
  double radius = 0.0;                            // ellipsoid only: bounding sphere
  std::string name;
};

Surface Describe(Lowering& lowering, const SurfaceRef& ref) {
  const CheckedScenario& scenario = lowering.scenario();
  Surface out;
  const auto i = static_cast<std::size_t>(ref.index);
  if (ref.kind == SurfaceRef::Kind::kPlane) {
    const Plane& plane = scenario.planes.at(i);
    out.frame = lowering.Frame(plane.frame);
    out.plane = true;
    out.center = ToEigen(plane.corners[0]);
    out.normal = (ToEigen(plane.corners[1]) - out.center)
                     .cross(ToEigen(plane.corners[2]) - out.center)
                     .normalized();
    out.name = plane.name;
    return out;
  }
  const Ellipsoid& e = scenario.ellipsoids.at(i);
  out.frame = lowering.Frame(e.frame);
  out.center = ToEigen(e.center);
  out.radius = runtime::BoundingRadius(ToEigen(e.semi_axes), e.degree);
  out.name = e.name;
  return out;
}

// Why two surfaces can never touch, or nothing when they might.
std::optional<std::string> NeverTouch(const Model& model, const Surface& a, const Surface& b) {
  const bool prescribed_a = a.frame.kind != RuntimeFrame::Kind::kSegment;
  const bool prescribed_b = b.frame.kind != RuntimeFrame::Kind::kSegment;
  if (prescribed_a && prescribed_b) return "both move with prescribed motion";
  if (SameFrame(a.frame, b.frame)) return "both are fixed in the same frame";
  if (SameFrame(RigidFrame(model, a.frame), RigidFrame(model, b.frame))) {
    return "their segments are joined rigidly by joints locked for good";
  }
  // Adjacent segments: a rotational joint keeps the child's centre at a fixed distance from
  // the joint point, so the centres are at least | |c_parent - j| - |c_child - j| | apart.
  if (!prescribed_a && !prescribed_b && !a.plane && !b.plane) {
    for (int order = 0; order < 2; ++order) {
      const Surface& child = order == 0 ? a : b;
      const Surface& parent = order == 0 ? b : a;
      const auto c = static_cast<std::size_t>(child.frame.index);
      if (model.segment_parent[c] != parent.frame.index) continue;
      if (model.joint_kind[c] == runtime::JointKind::kSlip) continue;
      const double from_parent = (parent.center - model.joint_point_in_parent[c]).norm();
      const double from_child = (child.center - model.joint_point_in_child[c]).norm();
      if (std::abs(from_parent - from_child) > parent.radius + child.radius) {
        return fmt::format("joint `{}` keeps them apart", model.joint_name[c]);
      }
    }
  }
  // A segment whose tree is held at a point of the other surface's frame stays within its reach
  // of that point.
  for (int order = 0; order < 2; ++order) {
    const Surface& moving = order == 0 ? a : b;
    const Surface& fixed = order == 0 ? b : a;
    if (moving.frame.kind != RuntimeFrame::Kind::kSegment || moving.plane) continue;
    const auto s = static_cast<std::size_t>(moving.frame.index);
    const std::size_t root = TreeRoot(model, s);
    if (!SameFrame(model.segment_base[root], fixed.frame)) continue;
    const double reach = ReachFromBase(model, s, moving.center) + moving.radius;
    const runtime::Vec3& held = model.joint_point_in_parent[root];
    const double distance = fixed.plane ? std::abs(fixed.normal.dot(held - fixed.center))
                                        : (held - fixed.center).norm() - fixed.radius;
    if (distance > reach) {
      return fmt::format("`{}` is held {:.3g} m from it and reaches {:.3g} m", moving.name,
                         distance, reach);
    }
  }
  return std::nullopt;
}

// The Model's index of a checked ellipsoid or plane, adding it on first use.
class SurfaceMap {
 public:
  explicit SurfaceMap(Lowering& lowering)
      : lowering_(lowering),
        ellipsoids_(lowering.scenario().ellipsoids.size(), -1),
        planes_(lowering.scenario().planes.size(), -1) {}

  std::int32_t Ellipsoid(int checked) {
    std::int32_t& id = ellipsoids_.at(static_cast<std::size_t>(checked));
    if (id >= 0) return id;
    const compiler::Ellipsoid& e =
        lowering_.scenario().ellipsoids[static_cast<std::size_t>(checked)];
    ContactTable& table = lowering_.model().contacts;
    id = static_cast<std::int32_t>(table.nellipsoid());
    table.ellipsoid_name.push_back(e.name);
    table.ellipsoid_frame.push_back(lowering_.Frame(e.frame));
    table.ellipsoid_center.push_back(ToEigen(e.center));
    table.ellipsoid_axes.push_back(RotationMatrix(e.orientation));
    table.ellipsoid_semi_axes.push_back(ToEigen(e.semi_axes));
    table.ellipsoid_degree.push_back(e.degree);
    table.ellipsoid_radius.push_back(runtime::BoundingRadius(ToEigen(e.semi_axes), e.degree));
    return id;
  }

  std::int32_t Plane(int checked) {
    std::int32_t& id = planes_.at(static_cast<std::size_t>(checked));
    if (id >= 0) return id;
    const compiler::Plane& p = lowering_.scenario().planes[static_cast<std::size_t>(checked)];
    ContactTable& table = lowering_.model().contacts;
    id = static_cast<std::int32_t>(table.nplane());
    const runtime::Vec3 origin = ToEigen(p.corners[0]);
    const runtime::Vec3 u = ToEigen(p.corners[1]) - origin;
    const runtime::Vec3 v = ToEigen(p.corners[2]) - origin;
    table.plane_name.push_back(p.name);
    table.plane_frame.push_back(lowering_.Frame(p.frame));
    table.plane_origin.push_back(origin);
    table.plane_edge_u.push_back(u);
    table.plane_edge_v.push_back(v);
    table.plane_normal.push_back(u.cross(v).normalized());
    return id;
  }

 private:
  Lowering& lowering_;
  std::vector<std::int32_t> ellipsoids_;
  std::vector<std::int32_t> planes_;
};

}  // namespace

void LowerContacts(Lowering& lowering) {
  const CheckedScenario& scenario = lowering.scenario();
  Model& model = lowering.model();
  ContactTable& table = model.contacts;
  SurfaceMap surfaces(lowering);
  lowering.contact_pair.assign(scenario.contacts.size(), -1);
  for (std::size_t i = 0; i < scenario.contacts.size(); ++i) {
    const Contact& contact = scenario.contacts[i];
    if (contact.first.kind != SurfaceRef::Kind::kEllipsoid || contact.force < 0) {
      throw std::logic_error(fmt::format(
          "compiler::Lower: contact {} has no first ellipsoid or no force function", i));
    }
    // Mirror symmetry: a right segment's contact is its left twin's, mirrored.
    auto frame_of = [&](const SurfaceRef& ref) -> const FrameRef& {
      const auto k = static_cast<std::size_t>(ref.index);
      return ref.kind == SurfaceRef::Kind::kPlane ? scenario.planes.at(k).frame
                                                  : scenario.ellipsoids.at(k).frame;
    };
    if (lowering.Dropped(frame_of(contact.first)) || lowering.Dropped(frame_of(contact.second))) {
      lowering.AddNote(lang::DiagnosticKind::kReducedBySymmetry, contact.range,
                       "mirror symmetry: this contact acts on a right segment; "
                       "its left twin's contact stands for it");
      continue;
    }
    const Surface first = Describe(lowering, contact.first);
    const Surface second = Describe(lowering, contact.second);
    if (const auto reason = NeverTouch(model, first, second)) {
      lowering.AddNote(lang::DiagnosticKind::kLeftOutOfModel, contact.range,
                       fmt::format("contact between `{}` and `{}` is left out: they can never "
                                   "touch ({})",
                                   first.name, second.name, *reason));
      continue;
    }
    const bool plane = contact.second.kind == SurfaceRef::Kind::kPlane;
    lowering.contact_pair[i] = static_cast<int>(table.npair());
    table.pair_kind.push_back(plane ? ContactTable::PairKind::kPlaneEllipsoid
                                    : ContactTable::PairKind::kEllipsoidEllipsoid);
    table.pair_first.push_back(surfaces.Ellipsoid(contact.first.index));
    table.pair_second.push_back(plane ? surfaces.Plane(contact.second.index)
                                      : surfaces.Ellipsoid(contact.second.index));
    table.pair_function.push_back(lowering.Function(contact.force));
    table.pair_damping.push_back(contact.damping);
    table.pair_rate_scaled_force.push_back(lowering.Function(contact.rate_scaled_force));
    table.pair_rate_scale.push_back(lowering.Function(contact.rate_scale));
    table.pair_rate_force.push_back(lowering.Function(contact.rate_force));
    table.pair_damping_depth.push_back(runtime::kContactDampingDepth);
    table.pair_friction.push_back(contact.friction);
    table.pair_impulse.push_back(contact.impulse ? 1 : 0);
    table.pair_restitution.push_back(contact.restitution);
    table.pair_source.push_back(lowering.Position(contact.range));
  }
}

void LowerContactOutput(Lowering& lowering, const OutputRequest& output) {
  Model& model = lowering.model();
  ContactTable& table = model.contacts;
  std::vector<int> checked = output.contacts;
  if (checked.empty() && output.index >= 0) checked.push_back(output.index);
  const auto first = static_cast<std::int32_t>(table.group_pairs.size());
  for (int c : checked) {
    const int pair = lowering.contact_pair.at(static_cast<std::size_t>(c));
    if (pair >= 0) table.group_pairs.push_back(pair);
  }
  const auto count = static_cast<std::int32_t>(table.group_pairs.size()) - first;
  if (count == 0) {
    lowering.AddNote(lang::DiagnosticKind::kLeftOutOfModel, output.range,
                     fmt::format("output `contact_force {}` is left out: its contact can never "
                                 "touch",
                                 output.label));
    return;
  }
  const auto group = static_cast<std::int32_t>(table.group_first.size());
  table.group_first.push_back(first);
  table.group_count.push_back(count);
  for (const Model::OutputKind kind :
       {Model::OutputKind::kContactForce, Model::OutputKind::kContactPoint,
        Model::OutputKind::kContactDeflection}) {
    lowering.AddOutput({kind, output.label, group, runtime::Vec3::Zero(), false,
                        FilterClassOf(output, kind), output.iso_filter, std::nullopt, false, 0});
  }
}

}  // namespace sled::compiler::lowering
