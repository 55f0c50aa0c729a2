#include "runtime/restraint/belt_wrap.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace sled::runtime {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
constexpr double kTwoPi = 2 * std::numbers::pi;

// 16-point Gauss-Legendre on [-1, 1]: the positive nodes and their weights.
constexpr double kNodes[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274,
                              0.6178762444026438, 0.7554044083550030, 0.8656312023878318,
                              0.9445750230732326, 0.9894009349916499};
constexpr double kWeights[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025,
                                0.1495959888165767, 0.1246289712555339, 0.0951585116824928,
                                0.0622535239386479, 0.0271524594117541};

Vec2 QuarterTurn(const Vec2& a) { return {-a.y(), a.x()}; }
double WrapAngle(double angle) {
  angle = std::fmod(angle, kTwoPi);
  return angle < 0 ? angle + kTwoPi : angle;
}

// The section of the ellipsoid in the plane (u, w), as the map y = L^T x that makes it the unit
// circle (B = L L^T, L lower triangular with a positive diagonal, so orientation is kept).
struct Section {
  double l00, l10, l11;
  Vec2 ToCircle(const Vec2& x) const { return {l00 * x.x() + l10 * x.y(), l11 * x.y()}; }
  Vec2 FromCircle(const Vec2& y) const {
    const double w = y.y() / l11;
    return {(y.x() - l10 * w) / l00, w};
  }
  // The derivative of the point at angle phi when phi decreases (the clockwise traversal).
  Vec2 Clockwise(double phi) const { return Clockwise(std::sin(phi), std::cos(phi)); }
  // The same from phi's sine and cosine.
  Vec2 Clockwise(double sine, double cosine) const {
    const Vec2 dy(sine, -cosine);
    return {(dy.x() - l10 * dy.y() / l11) / l00, dy.y() / l11};
  }
};

// The length of the section's arc from angle `from` to angle `to` (clockwise when from > to),
// signed: |dx/dphi| by 16-point Gauss-Legendre.
double SectionArc(const Section& section, double from, double to) {
  const double half = 0.5 * (from - to), mid = to + half;
  // The nodes mid +- half x_k in pairs, by the angle sum: one sine and cosine per pair.
  const double sin_mid = std::sin(mid), cos_mid = std::cos(mid);
  double arc = 0.0;
  for (int k = 0; k < 8; ++k) {
    const double sin_k = std::sin(half * kNodes[k]), cos_k = std::cos(half * kNodes[k]);
    const double ahead_sin = sin_mid * cos_k + cos_mid * sin_k;
    const double ahead_cos = cos_mid * cos_k - sin_mid * sin_k;
    const double back_sin = sin_mid * cos_k - cos_mid * sin_k;
    const double back_cos = cos_mid * cos_k + sin_mid * sin_k;
    arc += kWeights[k] * (section.Clockwise(ahead_sin, ahead_cos).norm() +
                          section.Clockwise(back_sin, back_cos).norm());
  }
  return arc * half;
}

// The tangent point of the unit circle from p: on the circle's right of p -> point (`from` side)
// or of point -> p (`to` side); the nearest point along the ray when p is inside.
Vec2 TangentPoint(const Vec2& p, bool from_side) {
  const double r2 = p.squaredNorm();
  if (r2 <= 1.0) return r2 > 0 ? Vec2(p / std::sqrt(r2)) : Vec2(0, 1);
  const double k = std::sqrt(r2 - 1.0);
  return (p + (from_side ? -k : k) * QuarterTurn(p)) / r2;
}

}  // namespace

Wrap WrapOver(const WrapSurface& surface, const Vec3& from, const Vec3& to, const Vec3& side_hint,
              bool measure_arc) {
  Wrap wrap;
  const Vec3& c = surface.centre;
  Vec3 along = to - from;
  const double chord = along.norm();
  along = chord > 0 ? Vec3(along / chord) : side_hint.unitOrthogonal();
  // The side: across the line, toward the centre or away from it, as the hint says.
  const Vec3 to_centre = (c - from) - (c - from).dot(along) * along;
  const double scale = std::max(surface.semi_axes.maxCoeff(), 1e-9);
  Vec3 side;
  if (to_centre.norm() > 1e-12 * scale) {
    side = to_centre.normalized();
    if (side.dot(side_hint) < 0) side = -side;
  } else {
    side = side_hint - side_hint.dot(along) * along;
    side = side.norm() > 1e-12 ? Vec3(side.normalized()) : along.unitOrthogonal();
  }
  wrap.side = side;

  if (surface.semi_axes.minCoeff() <= 0.0) {
    // A fixed point of the segment: the webbing passes through it.
    wrap.entry = wrap.exit = wrap.middle = c;
    wrap.contact = true;
    wrap.reach = 1.0;
    const Vec3 in = c - from, out = to - c;
    if (in.norm() > 0 && out.norm() > 0) {
      wrap.turning = std::acos(std::clamp(in.normalized().dot(out.normalized()), -1.0, 1.0));
    }
    wrap.tangent = along;
    return wrap;
  }

  // The section: B = [e_i^T A e_j] with A = axes diag(1/a^2) axes^T.
  const Eigen::Matrix3d a = surface.axes *
                            surface.semi_axes.cwiseInverse().cwiseAbs2().asDiagonal() *
                            surface.axes.transpose();
  const double b00 = along.dot(a * along), b01 = along.dot(a * side), b11 = side.dot(a * side);
  Section section;
  section.l00 = std::sqrt(b00);
  section.l10 = b01 / section.l00;
  section.l11 = std::sqrt(std::max(b11 - section.l10 * section.l10, 1e-300));
  auto plane = [&](const Vec3& x) { return Vec2((x - c).dot(along), (x - c).dot(side)); };
  auto world = [&](const Vec2& x) -> Vec3 { return c + x.x() * along + x.y() * side; };
  const Vec2 p = plane(from), q = plane(to);

  // Contact while the ellipse reaches across the line toward `side`: its support in that
  // direction, sqrt((B^-1)_11), beyond the line's offset.
  const double support = std::sqrt(b00 / (b00 * b11 - b01 * b01));
  wrap.reach = support - p.y();
  if (!(support > p.y())) {
    // Straight: entry and exit where the body's support point in direction `side`,
    // B^-1 w / sqrt(w^T B^-1 w) with w = (0, 1), projects onto the line (between the ends).
    const double det = b00 * b11 - b01 * b01;
    const Vec2 support_point = Vec2(-b01 / det, b00 / det) / support;
    const double u = std::clamp(support_point.x(), std::min(p.x(), q.x()), std::max(p.x(), q.x()));
    wrap.entry = wrap.exit = wrap.middle = world(Vec2(u, p.y()));
    wrap.tangent = along;
    return wrap;
  }
  wrap.contact = true;
  const Vec2 entry = TangentPoint(section.ToCircle(p), true);
  const Vec2 exit = TangentPoint(section.ToCircle(q), false);
  const double phi_entry = std::atan2(entry.y(), entry.x());
  const double phi_exit = std::atan2(exit.y(), exit.x());
  double sweep = WrapAngle(phi_entry - phi_exit);  // clockwise from entry to exit
  if (sweep > kTwoPi - 1e-9) sweep = 0.0;          // tangent points that just met, past by rounding
  wrap.entry = world(section.FromCircle(entry));
  wrap.exit = world(section.FromCircle(exit));
  const double mid = phi_exit + 0.5 * sweep;
  if (measure_arc) wrap.arc = SectionArc(section, phi_exit + sweep, phi_exit);
  // Turning: from the tangent at the entry to the tangent at the exit, clockwise. A linear map
  // keeps a half turn a half turn, so a sweep under pi turns under pi (rounding aside).
  const Vec2 t_in = section.Clockwise(phi_entry), t_out = section.Clockwise(phi_exit);
  double turning = WrapAngle(std::atan2(t_in.y(), t_in.x()) - std::atan2(t_out.y(), t_out.x()));
  if (sweep <= std::numbers::pi && turning > std::numbers::pi) turning = 0.0;
  wrap.turning = turning;
  wrap.middle = world(section.FromCircle(Vec2(std::cos(mid), std::sin(mid))));
  const Vec2 t_mid = section.Clockwise(mid);
  wrap.tangent = (t_mid.x() * along + t_mid.y() * side).normalized();
  wrap.section = {
      true, c, along, side, section.l00, section.l10, section.l11, mid, phi_exit + sweep, phi_exit};
  return wrap;
}

double WrapArc(const WrapSection& s) {
  if (!s.valid) return 0.0;
  return SectionArc(Section{s.l00, s.l10, s.l11}, s.phi_entry, s.phi_exit);
}

double ArcFromMiddle(const WrapSection& s, const Vec3& point) {
  if (!s.valid) return 0.0;
  const Section section{s.l00, s.l10, s.l11};
  const Vec2 y =
      section.ToCircle(Vec2((point - s.centre).dot(s.along), (point - s.centre).dot(s.side)));
  if (!(y.squaredNorm() > 0)) return 0.0;
  // Ahead of the middle (toward `to`) is clockwise: a smaller angle, by less than half a turn.
  const double ahead = std::remainder(s.phi_middle - std::atan2(y.y(), y.x()), kTwoPi);
  return SectionArc(section, s.phi_middle, s.phi_middle - ahead);
}

}  // namespace sled::runtime
