// The rotation matrices of rotations.h.
#include "lang/legacy/rotations.h"

#include <algorithm>
#include <cmath>

#include "lang/legacy/ast_pieces.h"

namespace sled::lang::legacy {
namespace {

constexpr double kPi = 3.14159265358979323846;
using mapping::CosDegrees;
using mapping::SinDegrees;

}  // namespace

Mat YawPitchRoll(const Vec3& ypr) {
  const double cy = CosDegrees(ypr[0]), sy = SinDegrees(ypr[0]);
  const double cp = CosDegrees(ypr[1]), sp = SinDegrees(ypr[1]);
  const double cr = CosDegrees(ypr[2]), sr = SinDegrees(ypr[2]);
  return {{{cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr},
           {sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr},
           {-sp, cp * sr, cp * cr}}};
}

Vec3 ZyxDegrees(const Mat& r) {
  const double sb = std::clamp(-r[2][0], -1.0, 1.0);
  const double b = std::asin(sb);
  double a = 0, c = 0;
  if (std::fabs(sb) < 1 - 1e-12) {
    a = std::atan2(r[1][0], r[0][0]);
    c = std::atan2(r[2][1], r[2][2]);
  } else {
    a = std::atan2(-r[0][1], r[1][1]);
  }
  Vec3 angles{a * 180 / kPi, b * 180 / kPi, c * 180 / kPi};
  for (double& angle : angles) {
    angle = std::round(angle * 1e9) / 1e9;
    if (angle == 0) angle = 0;  // no -0
  }
  return angles;
}

double AboutYDegrees(const Mat& r) {
  const double angle = std::round(std::atan2(r[0][2], r[0][0]) * 180 / kPi * 1e9) / 1e9;
  return angle == 0 ? 0 : angle;  // no -0
}

std::optional<Mat> OrderedYawPitchRoll(const Vec3& ypr, const std::array<int, 3>& order) {
  const int sum = order[0] + order[1] + order[2];
  Mat r = Identity();
  for (const int id : order) {
    const int axis = id < 0 ? -id : id;
    // DRCYPR's angle for this rotation: yaw (1) about z, pitch (2) about y, roll (3) about x,
    // and for a negative number the one its sum rule names.
    const int angle = id < 0 ? sum - id - 2 : 4 - axis;
    if (axis < 1 || axis > 3 || angle < 1 || angle > 3) return std::nullopt;
    const double a = ypr[static_cast<std::size_t>(angle - 1)];
    const double c = CosDegrees(a), s = SinDegrees(a);
    Mat turn = Identity();
    const int i = axis % 3, j = (axis + 1) % 3;  // the plane the rotation turns: (y, z) for x
    turn[static_cast<std::size_t>(i)][static_cast<std::size_t>(i)] = c;
    turn[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = -s;
    turn[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)] = s;
    turn[static_cast<std::size_t>(j)][static_cast<std::size_t>(j)] = c;
    r = Multiply(r, turn);
  }
  return r;
}

}  // namespace sled::lang::legacy
