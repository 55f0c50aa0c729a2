// Where webbing lies on an ellipsoid it wraps: the geometry of one wrapped segment between the
// points the webbing comes from and goes to.
//
// The webbing is a taut string from `from` to `to` that passes over the ellipsoid on one side,
// `side`. It is computed in the plane through `from`, `to` and the ellipsoid's centre, where the
// ellipsoid's section is an ellipse:
//
//   from -> entry (the tangent point of a line from `from`) -> along the ellipse -> exit (the
//   tangent point of a line to `to`) -> to,
//
// with the ellipse on the right of the path as it turns over the `side` of the body. In the
// coordinates y = L^T x that make the section a unit circle (B = L L^T), the tangent points from
// a point p outside are (p -+ sqrt(|p|^2 - 1) J p) / |p|^2 (J: a quarter turn), and the arc
// between them is an integral over the circle's angle (16-point Gauss-Legendre). For a sphere the
// plane through the centre holds the shortest path, so the wrap is exact; for an ellipsoid it is
// the shortest path within that plane.
//
// The webbing touches the body only while the ellipse reaches across the straight line from
// `from` to `to` toward `side`; otherwise it runs straight (entry = exit on that line, arc 0,
// turning angle 0), and as the body comes up to the line the tangent points meet, so lengths and
// forces stay continuous when contact is made or lost. A point inside the ellipse (an anchor
// buried in the body) uses the nearest point of the ellipse along the ray from the centre.
#pragma once

#include <Eigen/Core>

namespace sled::runtime {

struct WrapSurface {
  Eigen::Vector3d centre;
  Eigen::Matrix3d axes;       // columns: the ellipsoid's axes (world)
  Eigen::Vector3d semi_axes;  // all zero: a fixed point of the segment, no surface
};

// The ellipsoid's section in the webbing's plane, in the coordinates WrapOver uses: for
// measuring lengths along the surface (ArcFromMiddle). Empty (no surface) for a fixed point or
// a webbing that runs straight.
struct WrapSection {
  bool valid = false;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d along = Eigen::Vector3d::UnitX();  // unit: the line from `from` to `to`
  Eigen::Vector3d side = Eigen::Vector3d::UnitY();   // unit: across it, toward the body's side
  double l00 = 1.0, l10 = 0.0, l11 = 1.0;            // the section is the unit circle of y = L^T x
  double phi_middle = 0.0;                           // the arc's middle, as an angle on that circle
  double phi_entry = 0.0, phi_exit = 0.0;  // the arc: clockwise from phi_entry to phi_exit
};

struct Wrap {
  Eigen::Vector3d entry;  // where the webbing from `from` meets the surface
  Eigen::Vector3d exit;   // where it leaves toward `to`
  double arc = 0.0;       // length along the surface from entry to exit [m]
  double turning = 0.0;   // how far the webbing turns over the surface [rad]
  bool contact = false;   // the webbing presses on the body
  // How far the body reaches across the straight line from `from` to `to` toward `side` [m]:
  // contact while positive; continuous, so where contact is made or lost can be located.
  double reach = 0.0;
  Eigen::Vector3d side;     // unit: the side of the body the webbing lies on
  Eigen::Vector3d middle;   // the arc's middle point (entry when there is no arc)
  Eigen::Vector3d tangent;  // unit direction of the webbing (from -> to) at `middle`
  WrapSection section;
};

// `side_hint`: the side the webbing lay on before (any vector with a positive component toward
// it); it decides which way round the body the webbing goes, and the plane when the centre lies
// on the line from `from` to `to`. Without `measure_arc`, `arc` is left 0 (WrapArc measures it
// from the section): a caller that moves the ends until the tangent points settle needs the arc
// of the last wrap only.
Wrap WrapOver(const WrapSurface& surface, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
              const Eigen::Vector3d& side_hint, bool measure_arc = true);

// The length along the surface from entry to exit of the wrap whose section this is (Wrap::arc,
// bit for bit); 0 without a section.
double WrapArc(const WrapSection& section);

// The length along the section from the wrap's middle to `point` projected onto the section's
// plane and seen from its centre (positive ahead, toward `to`): how far a body point has moved
// along the webbing. 0 without a section.
double ArcFromMiddle(const WrapSection& section, const Eigen::Vector3d& point);

}  // namespace sled::runtime
