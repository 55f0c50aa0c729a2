// The contacts of a Model (CVS plane–ellipsoid and ellipsoid–ellipsoid contacts): the surfaces
// the contacts use, each fixed in a frame, and the contact pairs with their force law. Filled by
// compiler::Lower (compiler/lower/lower_contacts.cpp) with only the pairs that can touch;
// evaluated by runtime/contact/contact_forces.cpp. Semantics: docs/runtime.md, "Contacts".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "runtime/model/model_types.h"

namespace sled::runtime {

// The default of ContactTable::pair_damping_depth [m].
constexpr double kContactDampingDepth = 1e-3;

struct ContactTable {
  // --- Ellipsoids (degree 2) and hyper-ellipsoids (degree above 2), fixed in their frame.
  std::vector<std::string> ellipsoid_name;
  std::vector<FrameRef> ellipsoid_frame;
  std::vector<Vec3> ellipsoid_center;  // in the frame
  std::vector<Mat3> ellipsoid_axes;    // columns: the ellipsoid's axes in the frame
  std::vector<Vec3> ellipsoid_semi_axes;
  std::vector<double> ellipsoid_degree;
  std::vector<double> ellipsoid_radius;  // bounding sphere about the centre

  // --- Finite planes: the parallelogram origin + s edge_u + t edge_v, s and t in [0, 1].
  std::vector<std::string> plane_name;
  std::vector<FrameRef> plane_frame;
  std::vector<Vec3> plane_origin;  // P1, in the frame
  std::vector<Vec3> plane_edge_u;  // P2 - P1
  std::vector<Vec3> plane_edge_v;  // P3 - P1
  std::vector<Vec3> plane_normal;  // unit (P2 - P1) x (P3 - P1): the side contacts push towards

  // --- Pairs: the first surface is an ellipsoid; the second a plane or another ellipsoid.
  enum class PairKind : std::uint8_t { kPlaneEllipsoid, kEllipsoidEllipsoid };
  std::vector<PairKind> pair_kind;
  std::vector<std::int32_t> pair_first;     // ellipsoid
  std::vector<std::int32_t> pair_second;    // plane or ellipsoid, by pair_kind
  std::vector<std::int32_t> pair_function;  // deflection -> force, into Model::functions
  std::vector<double> pair_damping;         // [N*s/m]
  // ATB's rate-dependent force (FUNC_RATE_DEP): F2(d) F3(d') + F4(d') added to the function's
  // force, d' the deflection rate; into Model::functions, -1: none (F2 and F3 come together).
  std::vector<std::int32_t> pair_rate_scaled_force;  // deflection -> force
  std::vector<std::int32_t> pair_rate_scale;         // deflection rate -> ratio
  std::vector<std::int32_t> pair_rate_force;         // deflection rate -> force
  // The damping grows linearly from zero at first touch to full at this deflection [m], so the
  // normal force (and the friction with it) has no jump when the surfaces meet; 0: full at once.
  std::vector<double> pair_damping_depth;
  std::vector<double> pair_friction;       // Coulomb coefficient
  std::vector<std::uint8_t> pair_impulse;  // impulse with restitution at first contact
  std::vector<double> pair_restitution;
  std::vector<SourcePosition> pair_source;

  // --- Output groups: a `contact_force` request sums the pairs it names (a segment with several
  // ellipsoids gives several pairs). Model::output_index of a contact output is a group.
  std::vector<std::int32_t> group_first;  // into group_pairs
  std::vector<std::int32_t> group_count;
  std::vector<std::int32_t> group_pairs;

  std::size_t npair() const { return pair_kind.size(); }
  std::size_t nellipsoid() const { return ellipsoid_name.size(); }
  std::size_t nplane() const { return plane_name.size(); }
};

}  // namespace sled::runtime
