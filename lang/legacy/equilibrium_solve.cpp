// ATB's EQUILB for G.5 variables with given forces, solved at conversion (equilibrium_solve.h).
#include "lang/legacy/equilibrium_solve.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "lang/legacy/rotations.h"

namespace sled::lang::legacy {
namespace {

constexpr int kNewtonIterations = 50;
constexpr std::size_t kMaxVariables = 10;  // NVAR (INPUT_EQUILB)

using geometry::Add;
using geometry::Apply;
using geometry::Cross;
using geometry::Dot;
using geometry::Scale;
using geometry::Sub;

// The primary vehicle's pose at the start (the frame of every D.2 plane), identity without one.
struct Pose {
  Vec3 position{};
  Mat rotation = Identity();
  Vec3 ToGround(const Vec3& p) const { return Add(position, Apply(rotation, p)); }
};

Pose VehiclePose(const VehicleCard& vehicle) {
  return {vehicle.position, YawPitchRoll(vehicle.orientation)};
}

// A contact segment's ellipsoid against its plane, in the ground frame.
struct PlaneContactGeometry {
  Vec3 normal{}, origin{}, edge_u{}, edge_v{};
  double penetration = 0;  // the ellipsoid's reach past the plane along -normal
  Vec3 deepest{};          // its deepest point
  double radius = 0;       // its largest semi-axis
};

// The loading force of `function` (deck units) at penetration `d`, or none for a form whose
// value the conversion does not evaluate.
double Polynomial(const FunctionCard& function, double d) {
  double value = 0, power = 1;
  for (const double c : function.coefficients) {
    value += c * power;
    power *= d;
  }
  return value;
}

class EquilibriumSolver {
 public:
  EquilibriumSolver(DeckFields& fields, const Card& g1, const Card& g4,
                    const std::vector<EquilibriumVariable>& variables)
      : f_(fields), deck_(fields.deck()), g1_(g1), g4_(g4), variables_(variables) {
    if (!deck_.vehicles.empty()) vehicle_ = VehiclePose(deck_.vehicles.back());
  }

  void Solve(int constraints) {
    bool ok = true;
    if (constraints > 0) {
      f_.Refuse(g4_, 5, 8,
                fmt::format("NCON is {}: G.6 constraints, whose forces EQUILB_SOLVE takes as "
                            "the contact forces sought",
                            constraints),
                "the conversion solves for the forces GX written on the G.5 cards; give them "
                "there (the weight each contact carries at rest) and set NCON to 0");
      ok = false;
    }
    ok = CheckWhatEquilibRewrites() && ok;
    for (const EquilibriumVariable& variable : variables_) {
      ok = CheckVariable(variable) && ok;
    }
    if (!ok) return;
    std::vector<double> sought;
    for (const EquilibriumVariable& variable : variables_) {
      const std::optional<double> depth = SoughtPenetration(variable);
      if (!depth) return;
      sought.push_back(*depth);
    }
    const std::optional<std::vector<double>> moves = Newton(sought);
    if (!moves) {
      Set(std::vector<double>(variables_.size(), 0.0));
      return;
    }
    Set(*moves);
    Note(*moves);
    for (const EquilibriumVariable& variable : variables_) CheckClearOfEdges(variable);
  }

 private:
  // EQUILB also raises the unlock torque (B.5.a VISC(4)) of every joint locked by a negative
  // JTYPE without one to 1.5 times the torque it carries in equilibrium, and rewrites the point
  // (RK2) of every fixed-point constraint to the primary vehicle: values of the dynamics at the
  // solved state, which the conversion does not compute.
  bool CheckWhatEquilibRewrites() {
    bool ok = true;
    for (std::size_t j = 0; j < deck_.joints.size(); ++j) {
      const JointCard& joint = deck_.joints[j];
      if (joint.jtype >= 0 || joint.parent == 0 || joint.unlock_level != 0) continue;
      f_.Refuse(g1_, 31, 34,
                fmt::format("joint {} ({}) is locked by JTYPE {} without an unlock torque: "
                            "EQUILB sets its B.5.a VISC(4) to 1.5 times the torque it carries "
                            "in equilibrium",
                            j + 1, joint.name, joint.jtype),
                "that torque is a result of ATB's dynamics, not of the deck; give VISC(4) on "
                "the joint's B.5.a card (columns 19-24)");
      ok = false;
    }
    const int primary = static_cast<int>(deck_.vehicles.size()) - 1;
    for (const ConstraintCard& constraint : deck_.constraints) {
      if (constraint.kind != ConstraintCard::Kind::kFixedPoint ||
          constraint.second.kind != DeckFrame::Kind::kVehicle ||
          constraint.second.index != primary) {
        continue;
      }
      f_.Refuse(g1_, 31, 34,
                fmt::format("the D.6 fixed-point constraint of line {} holds a point to the "
                            "primary vehicle, whose RK2 EQUILB rewrites after the solve",
                            constraint.line),
                "write the constraint's point for the solved position, or position the body by "
                "hand and set I1 to 0");
      ok = false;
    }
    return ok;
  }

  bool CheckVariable(const EquilibriumVariable& v) {
    bool ok = true;
    if (!IsReference(v.segment)) {
      f_.Refuse(v.card, 9, 12,
                fmt::format("NSGE is segment {}, which hangs from a joint", v.segment),
                "the conversion moves and turns reference segments only (a jointed segment's "
                "pose follows its joints); name the body's reference segment");
      ok = false;
    }
    if (!IsReference(v.contact_segment)) {
      f_.Refuse(v.card, 33, 36,
                fmt::format("JSG is segment {}, which hangs from a joint", v.contact_segment),
                "the conversion finds the penetration of a reference segment's ellipsoid, whose "
                "pose is its G.2 and G.3.a cards'; a jointed segment's depends on the posture");
      ok = false;
    }
    for (std::size_t i = 0; i < v.moved_along.size(); ++i) {
      const int moved = v.moved_along[i];
      const int at = 41 + 4 * static_cast<int>(i);
      // A turn moves a segment's G.3.a angles from the ground (jointed segments not listed keep
      // theirs, as in ATB: the joint angles follow from them).
      if (v.kind == 2 && !TurnsFromGround(moved)) {
        f_.Refuse(v.card, at, at + 3,
                  fmt::format("KSGE is segment {}, whose G.3.a angles are not from the ground "
                              "(ID4 not 0)",
                              moved),
                  "EQUILB turns the angles as given; give the segment's G.3.a angles from the "
                  "ground (ID4 = 0)");
        ok = false;
        continue;
      }
      if (v.kind == 2 || IsReference(moved) || Root(moved) == Root(v.segment)) continue;
      f_.Refuse(v.card, at, at + 3,
                fmt::format("KSGE is segment {}, which hangs from a joint of another body", moved),
                "name the reference segment of that body: it moves the whole body");
      ok = false;
    }
    return ok && ContactOf(v) != nullptr;
  }

  // The F.1 contact of segment JSG with plane JPL (ATB stops without one).
  const ContactCard* ContactOf(const EquilibriumVariable& v) {
    for (const ContactCard& contact : deck_.contacts) {
      if (contact.with_plane && contact.segment.number == v.contact_segment &&
          contact.other.number == v.plane) {
        return &contact;
      }
    }
    f_.Invalid(
        v.card, 29, 36,
        fmt::format("no F.1 contact of segment {} with plane {}", v.contact_segment, v.plane),
        "EQUILB solves for a contact's force: name a segment and a plane of an F.1 card");
    return nullptr;
  }

  // The penetration at which the contact's loading force is GX (deck units).
  std::optional<double> SoughtPenetration(const EquilibriumVariable& v) {
    const ContactCard& contact = *ContactOf(v);
    const FunctionCard* function = nullptr;
    for (const FunctionCard& candidate : deck_.functions) {
      if (candidate.number == contact.force.number) function = &candidate;
    }
    const SegmentCard& segment = deck_.segments[static_cast<std::size_t>(v.contact_segment) - 1];
    std::string why;
    if (function == nullptr) {
      return std::nullopt;  // the mapping reports the undefined function at its card
    } else if (contact.unloading.HasRateTerms()) {
      why = "its force has rate terms";
    } else if (contact.ellipsoid.number != 0 && contact.ellipsoid.number != v.contact_segment) {
      why = "it names an extra ellipsoid";
    } else if (*std::min_element(segment.semi_axes.begin(), segment.semi_axes.end()) <= 0) {
      why = "the segment has no contact ellipsoid";
    } else if (PlaneArea(v.plane) <= 0) {
      why = "the plane's corners are on one line";
    } else if (segment.degree != 2) {
      why = "its ellipsoid is a hyper-ellipsoid";
    } else if (function->form == FunctionCard::Form::kConstant) {
      why = "its force function is a constant, the same at every penetration";
    } else if (function->form == FunctionCard::Form::kTable &&
               (function->points.empty() || function->points.front().first > 0)) {
      why = "its force table does not start at zero penetration";
    }
    if (why.empty()) {
      const double largest = *std::max_element(segment.semi_axes.begin(), segment.semi_axes.end());
      // ATB holds a function's value past |D1|, the end of its first part (EVALFD_INTEGRAL).
      const double reach = function->first_part_end > 0
                               ? std::min(2 * largest, function->first_part_end)
                               : 2 * largest;
      if (const auto depth = Inverse(*function, v.force, reach)) return depth;
      why = fmt::format(
          "its force function does not reach GX = {} {} within the ellipsoid's "
          "size and the function's first part (E.2 |D1|)",
          v.force, deck_.units.force);
    }
    f_.Refuse(v.card, 13, 20,
              fmt::format("GX of segment {}'s contact with plane {}: {}", v.contact_segment,
                          v.plane, why),
              "the conversion finds the penetration where a polynomial or tabulated loading "
              "force is GX; position the body by hand and set I1 to 0");
    return std::nullopt;
  }

  // The first penetration in [0, limit] where the loading force reaches `force`.
  static std::optional<double> Inverse(const FunctionCard& function, double force, double limit) {
    if (function.form == FunctionCard::Form::kTable) {
      const auto& points = function.points;
      for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const auto [x0, f0] = points[i];
        const auto [x1, f1] = points[i + 1];
        if (x1 <= 0 || x1 <= x0) continue;
        const double start = std::max(x0, 0.0);
        const double at_start = f0 + (f1 - f0) * (start - x0) / (x1 - x0);
        if (at_start >= force)
          return at_start == force ? std::optional<double>(start) : std::nullopt;
        if (f1 < force) continue;
        const double depth = x0 + (x1 - x0) * (force - f0) / (f1 - f0);
        return depth <= limit ? std::optional<double>(depth) : std::nullopt;
      }
      return std::nullopt;
    }
    if (Polynomial(function, 0) >= force) {
      return Polynomial(function, 0) == force ? std::optional<double>(0.0) : std::nullopt;
    }
    constexpr int kScan = 4000;
    double low = 0;
    for (int i = 1; i <= kScan; ++i) {
      const double high = limit * i / kScan;
      if (Polynomial(function, high) < force) {
        low = high;
        continue;
      }
      double a = low, b = high;
      for (int k = 0; k < 200 && b - a > 1e-15 * limit; ++k) {
        const double mid = 0.5 * (a + b);
        (Polynomial(function, mid) < force ? a : b) = mid;
      }
      return 0.5 * (a + b);
    }
    return std::nullopt;
  }

  // Newton on the penetrations' residuals, a forward-difference Jacobian: the moves of the
  // variables (a position's along its inertial axis in the deck's length, an angle's in degrees)
  // from the deck's cards. Positions enter linearly (one step), angles through the ellipsoid's
  // reach and centre.
  std::optional<std::vector<double>> Newton(const std::vector<double>& sought) {
    // NVAR is 1 to 10 (INPUT_EQUILB's STOP 2600, checked by the reader).
    const std::size_t n = std::min<std::size_t>(variables_.size(), kMaxVariables);
    double size = 0;
    for (const EquilibriumVariable& v : variables_) size = std::max(size, Geometry(v).radius);
    const double tolerance = 1e-12 * size;
    std::vector<double> x(n, 0.0);
    for (int iteration = 0; iteration < kNewtonIterations; ++iteration) {
      const std::vector<double> r = Residuals(x, sought);
      double largest = 0;
      for (const double value : r) largest = std::max(largest, std::abs(value));
      if (largest <= tolerance) return x;
      std::vector<std::vector<double>> a(n, std::vector<double>(n + 1, 0.0));
      for (std::size_t j = 0; j < n; ++j) {
        std::vector<double> shifted = x;
        const double h = variables_[j].kind == 1 ? 1e-6 * size : 1e-6;
        shifted[j] += h;
        const std::vector<double> r_shifted = Residuals(shifted, sought);
        for (std::size_t k = 0; k < n; ++k) a[k][j] = (r_shifted[k] - r[k]) / h;
      }
      for (std::size_t k = 0; k < n; ++k) a[k][n] = -r[k];
      const std::optional<std::vector<double>> step = Eliminate(a);
      if (!step) {
        f_.Refuse(g4_, 1, 4,
                  "the G.5 variables do not decide the contact forces: a move along no "
                  "contact's plane normal, or two variables that move one contact alike",
                  "give each contact one variable that moves its segment across its plane");
        return std::nullopt;
      }
      for (std::size_t j = 0; j < n; ++j) x[j] += (*step)[j];
    }
    f_.Refuse(g4_, 1, 4,
              fmt::format("the solve of the G.5 variables did not converge in {} Newton steps",
                          kNewtonIterations),
              "start the segments nearer their equilibrium on the G.2 and G.3.a cards");
    return std::nullopt;
  }

  std::vector<double> Residuals(const std::vector<double>& x, const std::vector<double>& sought) {
    Set(x);
    std::vector<double> r(variables_.size());
    for (std::size_t k = 0; k < variables_.size(); ++k) {
      r[k] = Geometry(variables_[k]).penetration - sought[k];
    }
    return r;
  }

  // Gauss-Jordan with partial pivoting on [A | b]; none when A is singular.
  static std::optional<std::vector<double>> Eliminate(std::vector<std::vector<double>>& a) {
    const std::size_t n = a.size();
    double scale = 0;
    for (const auto& row : a) {
      for (std::size_t c = 0; c < n; ++c) scale = std::max(scale, std::abs(row[c]));
    }
    for (std::size_t c = 0; c < n; ++c) {
      std::size_t pivot = c;
      for (std::size_t r = c + 1; r < n; ++r) {
        if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
      }
      if (!(std::abs(a[pivot][c]) > 1e-9 * scale)) return std::nullopt;
      std::swap(a[c], a[pivot]);
      for (std::size_t r = 0; r < n; ++r) {
        if (r == c) continue;
        const double factor = a[r][c] / a[c][c];
        for (std::size_t k = c; k <= n; ++k) a[r][k] -= factor * a[c][k];
      }
    }
    std::vector<double> x(n);
    for (std::size_t c = 0; c < n; ++c) x[c] = a[c][n] / a[c][c];
    return x;
  }

  // The deck's G.2 positions and G.3.a angles as read, moved by `x`.
  void Set(const std::vector<double>& x) {
    deck_.initial_positions = positions_;
    deck_.initial_orientations = orientations_;
    for (std::size_t j = 0; j < variables_.size(); ++j) {
      const EquilibriumVariable& v = variables_[j];
      const auto axis = static_cast<std::size_t>(v.coordinate) - 1;
      if (v.kind == 2) {
        for (std::size_t s = 0; s < deck_.initial_orientations.size(); ++s) {
          if (MovesSegment(v, static_cast<int>(s) + 1))
            deck_.initial_orientations[s].angles[axis] += x[j];
        }
        continue;
      }
      Vec3 move{};
      move[axis] = x[j];
      for (InitialCard& initial : deck_.initial_positions) {
        if (!MovesSegment(v, initial.segment)) continue;
        // A G.2 position given in a vehicle's axes (IREF4) moves by the move in those axes.
        const Vec3 in_card =
            initial.position_vehicle < 0
                ? move
                : Apply(Transpose(YawPitchRoll(
                            deck_.vehicles[static_cast<std::size_t>(initial.position_vehicle)]
                                .orientation)),
                        move);
        initial.position = Add(initial.position, in_card);
      }
    }
  }

  // A comment on each moved reference segment's `initial`: what moved, by how much, and why.
  void Note(const std::vector<double>& x) {
    for (std::size_t j = 0; j < variables_.size(); ++j) {
      const EquilibriumVariable& v = variables_[j];
      const std::string what =
          v.kind == 1 ? fmt::format("moved {:.9g} {} along the inertial {}", x[j],
                                    deck_.units.length, "xyz"[v.coordinate - 1])
                      : fmt::format("turned its G.3.a {} by {:.9g} deg",
                                    std::array{"yaw", "pitch", "roll"}[v.coordinate - 1], x[j]);
      for (InitialCard& initial : deck_.initial_positions) {
        if (initial.segment != v.segment) continue;
        initial.equilibrium_note += fmt::format(
            " G.1.a I1 = 15 (EQUILB): {} so that segment {}'s contact force on plane {} is GX = "
            "{} {} (G.5, line {}{})",
            what, v.contact_segment, v.plane, v.force, deck_.units.force, v.card.line,
            v.moved_along.empty() ? "" : "; its KSGE segments moved along");
      }
    }
  }

  // sled's plane force is the share of the footprint on the parallelogram near its edges; the
  // solve assumes the whole footprint on it.
  void CheckClearOfEdges(const EquilibriumVariable& v) {
    const PlaneContactGeometry g = Geometry(v);
    const Vec3 w = Sub(g.deepest, g.origin);
    const double uu = Dot(g.edge_u, g.edge_u), uv = Dot(g.edge_u, g.edge_v);
    const double vv = Dot(g.edge_v, g.edge_v);
    const double det = uu * vv - uv * uv;
    const double s = (vv * Dot(w, g.edge_u) - uv * Dot(w, g.edge_v)) / det;
    const double t = (uu * Dot(w, g.edge_v) - uv * Dot(w, g.edge_u)) / det;
    const double area = std::sqrt(det);
    const double width_s = area / std::sqrt(vv), width_t = area / std::sqrt(uu);
    const double inside =
        std::min({s * width_s, (1 - s) * width_s, t * width_t, (1 - t) * width_t});
    if (inside >= g.radius) return;
    f_.Refuse(v.card, 29, 32,
              fmt::format("at the solved position segment {} meets plane {} {:.6g} {} from its "
                          "edge, within its ellipsoid's size",
                          v.contact_segment, v.plane, inside, deck_.units.length),
              "near an edge sled's plane force is the share of the footprint on the plane, "
              "which the solve does not model; position the body by hand and set I1 to 0");
  }

  double PlaneArea(int number) const {
    const PlaneCard& plane = deck_.planes[static_cast<std::size_t>(number) - 1];
    const Vec3 normal =
        Cross(Sub(plane.corners[1], plane.corners[0]), Sub(plane.corners[2], plane.corners[0]));
    return std::sqrt(Dot(normal, normal));
  }

  PlaneContactGeometry Geometry(const EquilibriumVariable& v) const {
    const auto s = static_cast<std::size_t>(v.contact_segment) - 1;
    const SegmentCard& segment = deck_.segments[s];
    const InitialCard& initial = InitialOf(v.contact_segment);
    const Vec3 position =
        initial.position_vehicle < 0
            ? initial.position
            : VehiclePose(deck_.vehicles[static_cast<std::size_t>(initial.position_vehicle)])
                  .ToGround(initial.position);
    const Mat turn = s < deck_.initial_orientations.size()
                         ? YawPitchRoll(deck_.initial_orientations[s].angles)
                         : Identity();
    const Mat ellipsoid = Multiply(turn, YawPitchRoll(segment.ellipsoid_orientation));
    const Vec3 center = Add(position, Apply(turn, segment.center));
    const PlaneCard& plane = deck_.planes[static_cast<std::size_t>(v.plane) - 1];
    PlaneContactGeometry g;
    g.origin = vehicle_.ToGround(plane.corners[0]);
    g.edge_u = Apply(vehicle_.rotation, Sub(plane.corners[1], plane.corners[0]));
    g.edge_v = Apply(vehicle_.rotation, Sub(plane.corners[2], plane.corners[0]));
    const Vec3 normal = Cross(g.edge_u, g.edge_v);
    g.normal = Scale(1 / std::sqrt(Dot(normal, normal)), normal);
    // The ellipsoid's support along -n: reach sqrt(sum (a_i m_i)^2), m = R^T n.
    const Vec3 m = Apply(Transpose(ellipsoid), g.normal);
    Vec3 scaled{};
    double reach_squared = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      scaled[i] = segment.semi_axes[i] * segment.semi_axes[i] * m[i];
      reach_squared += scaled[i] * m[i];
    }
    const double reach = std::sqrt(reach_squared);
    g.penetration = reach - Dot(g.normal, Sub(center, g.origin));
    g.deepest = Sub(center, Apply(ellipsoid, Scale(1 / reach, scaled)));
    g.radius = *std::max_element(segment.semi_axes.begin(), segment.semi_axes.end());
    return g;
  }

  // Whether variable `v` moves reference segment `segment` (its own or one moved along).
  static bool MovesSegment(const EquilibriumVariable& v, int segment) {
    return v.segment == segment ||
           std::find(v.moved_along.begin(), v.moved_along.end(), segment) != v.moved_along.end();
  }

  const InitialCard& InitialOf(int segment) const {
    for (const InitialCard& initial : deck_.initial_positions) {
      if (initial.segment == segment) return initial;
    }
    return deck_.initial_positions.front();
  }

  bool IsReference(int segment) const { return Root(segment) == segment; }

  bool TurnsFromGround(int segment) const {
    const auto s = static_cast<std::size_t>(segment) - 1;
    return s < deck_.initial_orientations.size() &&
           deck_.initial_orientations[s].reference == OrientationCard::Reference::kGround;
  }

  // The reference segment of `segment`'s body: up the joints to one that starts a body.
  int Root(int segment) const {
    for (int guard = 0; segment > 1 && guard <= static_cast<int>(deck_.joints.size()); ++guard) {
      const auto joint = static_cast<std::size_t>(segment) - 2;
      if (joint >= deck_.joints.size() || deck_.joints[joint].parent == 0) return segment;
      segment = deck_.joints[joint].parent;
    }
    return segment;
  }

  DeckFields& f_;
  Deck& deck_;
  const Card& g1_;
  const Card& g4_;
  const std::vector<EquilibriumVariable>& variables_;
  Pose vehicle_;
  // The G.2 and G.3.a cards as read: every trial of the solve starts from them.
  std::vector<InitialCard> positions_ = deck_.initial_positions;
  std::vector<OrientationCard> orientations_ = deck_.initial_orientations;
};

}  // namespace

void SolveEquilibrium(DeckFields& fields, const Card& g1, const Card& g4, int constraints,
                      const std::vector<EquilibriumVariable>& variables) {
  EquilibriumSolver(fields, g1, g4, variables).Solve(constraints);
}

}  // namespace sled::lang::legacy
