// Rotation matrices of ATB's yaw, pitch and roll, shared by the readers and the mapping: sled's
// `orientation` and `axes` turn a frame by Rz(yaw) Ry(pitch) Rx(roll) (ATB's default rotation
// order 3, 2, 1 in DRCYPR), and a deck may give another order (B.3.b IDYPR).
#pragma once

#include <array>
#include <optional>

#include "lang/geometry/small_vectors.h"
#include "lang/legacy/deck.h"

namespace sled::lang::legacy {

using Mat = geometry::Mat3;
using geometry::Identity;
using geometry::Multiply;
using geometry::Transpose;

// Rz(yaw) Ry(pitch) Rx(roll), angles in degrees: from the turned frame's axes to the frame's.
Mat YawPitchRoll(const Vec3& ypr);

// ATB's DRCYPR with rotation order `order` (each 1, 2 or 3 for x, y, z, negative as DRCYPR
// reads it), transposed to the same sense as YawPitchRoll: the product of the rotations about
// axes |order[0]|, |order[1]|, |order[2]| in that order, each by the angle DRCYPR pairs with
// it (yaw about z, pitch about y, roll about x for positive numbers). Empty when DRCYPR would
// index no angle.
std::optional<Mat> OrderedYawPitchRoll(const Vec3& ypr, const std::array<int, 3>& order);

// The z-y-x angles (degrees) of R = Rz(a) Ry(b) Rx(c), b in [-90, 90]; at b = +-90 degrees,
// where only a - c (or a + c) is defined, c = 0. Rounded to 1e-9 degrees, so exact turns print
// as such.
Vec3 ZyxDegrees(const Mat& r);

// The angle (degrees, in (-180, 180], rounded as ZyxDegrees) of R = Ry(angle).
double AboutYDegrees(const Mat& r);

}  // namespace sled::lang::legacy
