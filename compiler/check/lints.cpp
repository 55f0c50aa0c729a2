// Lints: warnings about scenes that are legal but probably wrong. Unused declarations, contact
// pairs that can never touch, ellipsoids that start buried, and a maximum step too long for the
// stiffest contact or spring.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "compiler/check/checkers.h"
#include "compiler/check/initial_pose.h"

namespace sled::compiler::internal {
namespace {

// Largest slope of a function over its table, or of a polynomial near zero deflection.
double StiffnessOf(const Function& function) {
  switch (function.kind) {
    case Function::Kind::kConstant:
      return 0.0;
    case Function::Kind::kTable: {
      double slope = 0.0;
      for (std::size_t i = 1; i < function.points.size(); ++i) {
        const double dx = function.points[i][0] - function.points[i - 1][0];
        if (dx > 0) {
          slope = std::max(slope, std::abs(function.points[i][1] - function.points[i - 1][1]) / dx);
        }
      }
      return slope;
    }
    case Function::Kind::kPolynomial: {
      // The derivative at the deflections a crash contact sees (0 to 50 mm), largest of three.
      double slope = 0.0;
      for (double x : {0.0, 0.025, 0.05}) {
        double derivative = 0.0;
        for (std::size_t k = 1; k < function.coefficients.size(); ++k) {
          derivative += static_cast<double>(k) * function.coefficients[k] *
                        std::pow(x, static_cast<double>(k - 1));
        }
        slope = std::max(slope, std::abs(derivative));
      }
      return slope;
    }
  }
  return 0.0;
}

// f(0): the constant, the polynomial's c0, or the table at 0 (extended beyond its rows as the
// runtime does).
double ValueAtZero(const Function& function) {
  switch (function.kind) {
    case Function::Kind::kConstant:
      return function.constant;
    case Function::Kind::kPolynomial:
      return function.coefficients.empty() ? 0.0 : function.coefficients[0];
    case Function::Kind::kTable: {
      const auto& p = function.points;
      if (p.size() < 2) return p.empty() ? 0.0 : p[0][1];
      std::size_t i = 0;
      while (i + 2 < p.size() && p[i + 1][0] <= 0.0) ++i;
      return p[i][1] + (p[i + 1][1] - p[i][1]) / (p[i + 1][0] - p[i][0]) * (0.0 - p[i][0]);
    }
  }
  return 0.0;
}

// Two significant digits, rounded towards zero, so a suggested limit is never above the real one.
std::string RoundDown(double value) {
  if (!(value > 0)) return "0";
  const double scale = std::pow(10.0, std::floor(std::log10(value)) - 1);
  return fmt::format("{:g}", std::floor(value / scale) * scale);
}

}  // namespace

void LintChecker::RunLints() {
  // Unused declarations of the checked file itself (library modules may offer more than a scene
  // uses, so a module checked on its own reports none).
  const lang::FileId main_file{1};
  for (const auto& scope : scopes_) {
    if (checking_module_) break;
    for (const auto& [name, entity] : scope->names) {
      if (entity.used || !(entity.range.file == main_file)) continue;
      if (entity.kind == EntityKind::kFunction) {
        Report(DiagnosticKind::kUnusedFunction, entity.range,
               fmt::format("function `{}` is never used", scope->prefix + name), "unused",
               "remove it, or use it in a contact, joint, belt or spring");
      } else if (entity.kind == EntityKind::kPlane ||
                 (entity.kind == EntityKind::kEllipsoid && scope.get() == scene_scope_)) {
        Report(DiagnosticKind::kUnusedSurface, entity.range,
               fmt::format("{} `{}` is in no contact", EntityKindName(entity.kind),
                           scope->prefix + name),
               "never touched", "declare `contact SEGMENT with NAME { ... }`, or remove it");
      } else if (entity.kind == EntityKind::kParameter) {
        Report(DiagnosticKind::kUnusedParameter, entity.range,
               fmt::format("`{}` is never used", scope->prefix + name), "unused",
               "remove it, or use it in the scene");
      }
    }
  }

  const InitialPoses poses = ComputeInitialPoses(scenario_);
  auto frame_of = [&](const SurfaceRef& surface) {
    return surface.kind == SurfaceRef::Kind::kPlane
               ? scenario_.planes[static_cast<std::size_t>(surface.index)].frame
               : scenario_.ellipsoids[static_cast<std::size_t>(surface.index)].frame;
  };
  auto surface_name = [&](const SurfaceRef& surface) {
    return surface.kind == SurfaceRef::Kind::kPlane
               ? scenario_.planes[static_cast<std::size_t>(surface.index)].name
               : scenario_.ellipsoids[static_cast<std::size_t>(surface.index)].name;
  };
  for (const Contact& contact : scenario_.contacts) {
    const FrameRef a = frame_of(contact.first);
    const FrameRef b = frame_of(contact.second);
    const bool prescribed_a = a.kind != FrameRef::Kind::kSegment;
    const bool prescribed_b = b.kind != FrameRef::Kind::kSegment;
    if (a == b || (prescribed_a && prescribed_b)) {
      Report(DiagnosticKind::kContactCannotTouch, contact.range,
             fmt::format(
                 "`{}` and `{}` can never touch: {}", surface_name(contact.first),
                 surface_name(contact.second),
                 a == b ? "both are fixed in the same frame" : "both move with prescribed motion"),
             "never changes",
             "contacts act between a segment and a surface that can move relative to it");
      continue;
    }
    // Buried at the start: the ellipsoid reaches more than a millimetre past the surface.
    const double depth = InitialPenetration(scenario_, poses, contact);
    if (depth > 1e-3) {
      Report(DiagnosticKind::kStartsBuried, contact.range,
             fmt::format("`{}` starts {:.1f} mm inside `{}`", surface_name(contact.first),
                         depth * 1e3, surface_name(contact.second)),
             "buried at the start",
             "move the body with `initial ... { position = ... }` or check the surface; a buried "
             "ellipsoid starts with a large contact force");
    }
  }

  // Joint torque functions resist the angle: the runtime applies -f(angle), or -sign(angle)
  // f(|angle|) for a function of the angle's size (one that does not cover negative angles). Such a
  // function that is not zero at zero angle jumps by 2 f(0) as the angle passes zero: a
  // constant one stalls a joint at zero instead of turning it, which is what a motor was meant to
  // do. Say so, and point to the applied load.
  for (const Joint& joint : scenario_.joints) {
    const std::pair<FunctionId, const char*> slots[] = {{joint.flexure, "flexure"},
                                                        {joint.twist, "twist"},
                                                        {joint.precession, "precession"},
                                                        {joint.nutation, "nutation"},
                                                        {joint.spin, "spin"}};
    for (const auto& [id, slot] : slots) {
      if (id < 0) continue;
      const Function& function = scenario_.functions[static_cast<std::size_t>(id)];
      const double at_zero = ValueAtZero(function);
      const bool covers_negative =
          function.kind == Function::Kind::kTable && function.points.front()[0] < 0;
      if (covers_negative || at_zero == 0.0 || !std::isfinite(at_zero)) continue;
      const bool slip = joint.type == JointType::kSlip;
      const char* effort = slip ? "force" : "torque";
      const char* unit = slip ? "N" : "N*m";
      const char* coordinate = slip ? "displacement" : "angle";
      Report(DiagnosticKind::kJointTorqueNotZeroAtZero,
             function.range.valid() ? function.range : joint.range,
             fmt::format("the {} {} of joint `{}` is {:g} {} at zero {}: it resists the {}, so it "
                         "jumps from {:g} to {:g} {} as the {} passes zero",
                         slot, effort, joint.name, at_zero, unit, coordinate, coordinate, -at_zero,
                         at_zero, unit, coordinate),
             fmt::format("not zero at zero {}", coordinate),
             fmt::format("a joint's {} functions resist its {}; for a {} that drives the joint "
                         "(a motor), write `load NAME on {} {{ {} = ... }}`",
                         effort, coordinate, effort, joint.name, effort));
    }
  }

  // Step length against the stiffest contact and spring: an explicit step must resolve the
  // oscillation, roughly ten steps per period.
  if (!scenario_.run.max_step) return;
  const double max_step = *scenario_.run.max_step;
  auto mass_of = [&](const FrameRef& frame) {
    return frame.kind == FrameRef::Kind::kSegment
               ? scenario_.segments[static_cast<std::size_t>(frame.index)].mass
               : std::numeric_limits<double>::infinity();
  };
  auto check_period = [&](double stiffness, double mass_a, double mass_b, SourceRange range,
                          const std::string& what) {
    const double mass = std::isinf(mass_a)   ? mass_b
                        : std::isinf(mass_b) ? mass_a
                                             : mass_a * mass_b / (mass_a + mass_b);
    if (!(stiffness > 0) || !(mass > 0) || std::isinf(mass)) return;
    const double period = 2.0 * std::numbers::pi * std::sqrt(mass / stiffness);
    if (max_step > period / 10.0) {
      Report(DiagnosticKind::kStepTooLarge, range,
             fmt::format("max_step {:g} ms is too long for {}: its natural period is {:.3g} ms "
                         "(stiffness {:.3g} N/m against {:.3g} kg)",
                         max_step * 1e3, what, period * 1e3, stiffness, mass),
             "too stiff for the step",
             fmt::format("set `max_step` to {} ms or less (a tenth of the period)",
                         RoundDown(period * 1e2)));
    }
  };
  for (const Contact& contact : scenario_.contacts) {
    if (contact.force < 0) continue;
    const double stiffness =
        StiffnessOf(scenario_.functions[static_cast<std::size_t>(contact.force)]);
    check_period(stiffness, mass_of(frame_of(contact.first)), mass_of(frame_of(contact.second)),
                 contact.range,
                 fmt::format("the contact of `{}` with `{}`", surface_name(contact.first),
                             surface_name(contact.second)));
  }
  for (const SpringDamper& spring : scenario_.springs) {
    if (spring.stiffness < 0) continue;
    const double stiffness =
        StiffnessOf(scenario_.functions[static_cast<std::size_t>(spring.stiffness)]);
    check_period(stiffness, mass_of(spring.first), mass_of(spring.second), spring.range,
                 fmt::format("spring `{}`", spring.name));
  }
}

}  // namespace sled::compiler::internal
