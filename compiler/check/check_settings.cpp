// Run settings (time, integrator, restart, settling, symmetry, gravity): SettingsChecker,
// checkers.h.
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "compiler/check/checkers.h"
#include "runtime/integrate/ode.h"

namespace sled::compiler::internal {
namespace {

// The shortest output step, as a fraction of the end time: a step then spans at least 1e10
// of the time's rounding steps.
constexpr double kTimeResolution = 1e-10;

// The default absolute tolerance, as a fraction of the relative one (1e-9 at the default 1e-6).
constexpr double kAbsoluteToleranceRatio = 1e-3;

}  // namespace

void SettingsChecker::CheckRunSettings(Scope& scope, const BoundBlock& scenario_block) {
  RunSettings& run = scenario_.run;
  if (auto gravity = ReadVector(scope, scenario_block, BlockKind::kScenario, "gravity")) {
    run.gravity = *gravity;
  }
  const ast::Statement* time = nullptr;
  for (const ast::Statement* statement : run_blocks_) {
    const std::string& keyword = statement->keyword;
    if (keyword == "time") {
      time = statement;
      const BoundBlock bound = Bind(BlockKind::kTime, statement->block.get(), statement->range);
      run.end = ReadQuantity(scope, bound, BlockKind::kTime, "end").value_or(0.0);
      run.output_every = ReadQuantity(scope, bound, BlockKind::kTime, "output_every").value_or(0);
      run.start = ReadQuantity(scope, bound, BlockKind::kTime, "start").value_or(0.0);
      if (run.end > 0 && !(run.start < run.end)) {
        Report(DiagnosticKind::kInvalidRunSettings, statement->range,
               fmt::format("the run starts at {:g} s but ends at {:g} s", run.start, run.end),
               "start not before end", "make `start` earlier than `end`, or leave it out (0 s)");
      } else if (run.output_every > 0 && run.end > 0 && run.output_every > run.end - run.start) {
        Report(DiagnosticKind::kInvalidRunSettings, One(bound, "output_every")->range,
               fmt::format("the output step {:g} s is longer than the run ({:g} s)",
                           run.output_every, run.end - run.start),
               "longer than the run", "choose an output step shorter than the run");
      } else if (run.output_every > 0 && run.end > 0 &&
                 (run.end - run.start) / run.output_every > kMaxOutputRows) {
        // Every row is kept in memory (time series, animation frames) until the run ends.
        Report(DiagnosticKind::kInvalidRunSettings, One(bound, "output_every")->range,
               fmt::format("the output step {:g} s gives {:.3g} rows over the {:g} s run, more "
                           "than the {:.0f} rows sled keeps",
                           run.output_every, (run.end - run.start) / run.output_every,
                           run.end - run.start, kMaxOutputRows),
               "too many output rows",
               fmt::format("choose an output step of at least {:g} s",
                           (run.end - run.start) / kMaxOutputRows));
      } else if (run.output_every > 0 && run.output_every < kTimeResolution * run.end) {
        // Times are doubles: at t they are resolved to about 2.2e-16 t, and output times (and
        // the integrator's smallest step, 4.4e-16 t) need that to be a small part of a step.
        Report(DiagnosticKind::kInvalidRunSettings, One(bound, "output_every")->range,
               fmt::format("the output step {:g} s is too short for times up to {:g} s, which "
                           "are resolved only to about {:.2g} s",
                           run.output_every, run.end,
                           run.end * std::numeric_limits<double>::epsilon()),
               "too short for the run's times",
               fmt::format("start the run near 0 s, or choose an output step of at least {:g} s",
                           kTimeResolution * run.end));
      }
    } else if (keyword == "integrator") {
      static const std::vector<std::string> kMethods = {"auto", "exponential", "dopri5",
                                                        "rosenbrock", "cvs"};
      if (statement->target) {
        const std::string method = statement->target->PathText();
        const auto found = std::find(kMethods.begin(), kMethods.end(), method);
        if (found == kMethods.end()) {
          Report(DiagnosticKind::kInvalidEnumValue, statement->target->range,
                 fmt::format("unknown integrator `{}`", method), "not an integrator",
                 lang::DidYouMean(method, kMethods));
        } else {
          run.method = static_cast<IntegratorMethod>(found - kMethods.begin());
        }
      }
      const BoundBlock bound =
          Bind(BlockKind::kIntegrator, statement->block.get(), statement->range);
      run.relative_tolerance =
          ReadQuantity(scope, bound, BlockKind::kIntegrator, "tolerance").value_or(1e-6);
      // The absolute tolerance follows the relative one unless it is given: a component near
      // zero (a joint angle, a velocity at rest) is then held to the same thousandth of the
      // tolerance in SI units at every tolerance, so tightening `tolerance` tightens it too.
      run.absolute_tolerance = ReadQuantity(scope, bound, BlockKind::kIntegrator, "abs_tolerance")
                                   .value_or(kAbsoluteToleranceRatio * run.relative_tolerance);
      if (run.relative_tolerance < runtime::kMinRelativeTolerance) {
        const ast::Statement* tolerance = One(bound, "tolerance");
        Report(DiagnosticKind::kToleranceBelowRounding,
               tolerance ? tolerance->range : statement->range,
               fmt::format("a tolerance of {:.3g} is tighter than a double can meet: the rounding "
                           "errors of one step are already about {:.1e} of the state",
                           run.relative_tolerance, runtime::kMinRelativeTolerance),
               "below what doubles can resolve",
               fmt::format("use a tolerance of at least {:.1e}; 1e-12 is about as tight as a "
                           "reference run needs",
                           runtime::kMinRelativeTolerance));
      }
      // (Only a given one: the default follows a relative tolerance, refused above if too tight.)
      const ast::Statement* absolute = One(bound, "abs_tolerance");
      if (absolute != nullptr && run.absolute_tolerance < runtime::kMinAbsoluteTolerance) {
        Report(DiagnosticKind::kToleranceBelowRounding, absolute->range,
               fmt::format("an abs_tolerance of {:.3g} is tighter than a double can meet: a "
                           "step's rounding errors are about {:.1e} of the terms a state "
                           "component is made of, and those are at least a thousandth of an SI "
                           "unit (a millimetre, a milliradian)",
                           run.absolute_tolerance, runtime::kMinRelativeTolerance),
               "below what doubles can resolve",
               fmt::format("use an abs_tolerance of at least {:.1e}, or leave it out (a "
                           "thousandth of `tolerance`)",
                           runtime::kMinAbsoluteTolerance));
      }
      run.min_step = ReadQuantity(scope, bound, BlockKind::kIntegrator, "min_step").value_or(1e-9);
      run.max_step = ReadQuantity(scope, bound, BlockKind::kIntegrator, "max_step");
      run.initial_step = ReadQuantity(scope, bound, BlockKind::kIntegrator, "initial_step");
      if (run.max_step && run.min_step > *run.max_step) {
        Report(DiagnosticKind::kInvalidRunSettings,
               One(bound, "min_step") ? One(bound, "min_step")->range : statement->range,
               fmt::format("min_step {:g} s exceeds max_step {:g} s", run.min_step, *run.max_step),
               "min_step above max_step", "lower `min_step` or raise `max_step`");
      }
    } else if (keyword == "restart") {
      const BoundBlock bound = Bind(BlockKind::kRestart, statement->block.get(), statement->range);
      run.checkpoint_every = ReadQuantity(scope, bound, BlockKind::kRestart, "checkpoint_every");
      if (const ast::Statement* resume = One(bound, "resume_from")) {
        if (const ast::Expr* value = SingleValue(*resume)) {
          if (value->kind == ast::ExprKind::kString) {
            run.resume_from = value->text;
          } else {
            Report(DiagnosticKind::kWrongValueKind, value->range,
                   "`resume_from` is a file name in quotes", "not a string",
                   "write the file name in double quotes");
          }
        }
      }
    } else if (keyword == "settle") {
      const BoundBlock bound = Bind(BlockKind::kSettle, statement->block.get(), statement->range);
      SettleSettings settle;
      settle.duration =
          ReadQuantity(scope, bound, BlockKind::kSettle, "duration").value_or(settle.duration);
      settle.damping =
          ReadQuantity(scope, bound, BlockKind::kSettle, "damping").value_or(settle.damping);
      settle.velocity =
          ReadQuantity(scope, bound, BlockKind::kSettle, "velocity").value_or(settle.velocity);
      settle.angular_velocity = ReadQuantity(scope, bound, BlockKind::kSettle, "angular_velocity")
                                    .value_or(settle.angular_velocity);
      settle.force_change = ReadQuantity(scope, bound, BlockKind::kSettle, "force_change")
                                .value_or(settle.force_change);
      run.settle = settle;
    } else if (keyword == "symmetry") {
      static const std::vector<std::string> kKinds = {"planar", "mirror"};
      const std::string kind = statement->target ? statement->target->PathText() : "";
      if (kind == "planar") {
        run.symmetry = Symmetry::kPlanar;
      } else if (kind == "mirror") {
        run.symmetry = Symmetry::kMirror;
      } else {
        Report(DiagnosticKind::kInvalidEnumValue,
               statement->target ? statement->target->range : statement->keyword_range,
               "symmetry is `planar` (2-D, in the xz plane) or `mirror`", "not a symmetry",
               lang::DidYouMean(kind, kKinds));
      }
      const BoundBlock bound = Bind(BlockKind::kSymmetry, statement->block.get(), statement->range);
      auto pairs = bound.attributes.find("pair");
      if (pairs != bound.attributes.end()) {
        for (const ast::Statement* pair : pairs->second) {
          if (pair->values.size() != 2) {
            Report(DiagnosticKind::kWrongValueKind, pair->range,
                   "`pair` names two segments: `pair = occupant.arm_l, occupant.arm_r`",
                   "not two names", "name the left segment, then its right twin");
            continue;
          }
          Entity* left = Resolve(scope, pair->values[0], {EntityKind::kSegment});
          Entity* right = Resolve(scope, pair->values[1], {EntityKind::kSegment});
          if (left && right && left->index == right->index) {
            Report(DiagnosticKind::kJointToItself, pair->range,
                   fmt::format("`{}` is paired with itself", pair->values[0].PathText()),
                   "the same segment twice", "a mirror pair names a left and a right segment");
          } else if (left && right) {
            run.mirror_pairs.push_back({left->index, right->index});
          }
        }
      }
      if (run.symmetry == Symmetry::kPlanar && !run.mirror_pairs.empty()) {
        Report(DiagnosticKind::kInvalidRunSettings, statement->range,
               "planar symmetry takes no mirror pairs", "pairs given",
               "remove the pairs, or use `symmetry mirror`");
      }
    }
  }
  if (!time) {
    Report(DiagnosticKind::kMissingAttribute, scenario_statement_->keyword_range,
           "a scenario needs a `time` block", "no `time` block",
           "add `time { end = 200 ms  output_every = 0.1 ms }`");
  }
}

}  // namespace sled::compiler::internal
