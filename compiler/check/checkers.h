// The checker of each block kind, over the shared CheckContext (context.h), and Checker, which
// runs them in order. Each checks what the declarations of its kind say once every name is
// known; what only it uses is private. Internal to compiler/check.
#pragma once

#include <string>

#include "compiler/check/context.h"

namespace sled::compiler::internal {

// Declarations and the scene's own elements (check_scene.cpp; imports in check.cpp): files,
// modules and their surfaces, vehicles, planes, ellipsoids, springs, constraints.
class SceneChecker : protected virtual CheckContext {
 public:
  using CheckContext::CheckContext;

 protected:
  BoundBlock DeclareFileContents(Scope& scope, const ast::Block& block, BlockKind kind) override;
  // Declares the top-level planes and ellipsoids of a module into one instance's scope, fixed
  // in `frame` (resolved in `frame_scope`; the ground when null).
  void DeclareModuleSurfaces(Scope& instance, const ast::Block& module, const ast::Expr* frame,
                             Scope& frame_scope);
  // Loads and declares an import (check.cpp).
  void Import(Scope& scope, const ast::Statement& statement);
  void CheckSceneElements();

  std::vector<std::unique_ptr<ast::File>> modules_;  // parsed imports, kept alive
  std::map<std::string, Scope*> module_scopes_;      // by file path
  std::vector<std::string> import_stack_;            // for cycle detection
};

// Bodies: segments, joints, their characteristics, the tree (check_bodies.cpp).
class BodyChecker : protected virtual CheckContext {
 public:
  using CheckContext::CheckContext;

 protected:
  void CheckBodyDeclarations(Scope& scope, const ast::Statement& body_statement,
                             const std::string& instance_name, SourceRange instance_range) override;
  void CheckBodyDetails();

 private:
  // The torque characteristics, damping, stops and locking a joint's (or an override's) block
  // states; what it does not state stays as it was.
  void ReadJointCharacteristics(Scope& scope, const BoundBlock& bound, BlockKind kind,
                                Joint& joint);
  void CheckTopology(Body& body, int body_index);
};

// Contacts, belts, harnesses and airbags (check_restraints.cpp).
class RestraintChecker : protected virtual CheckContext {
 public:
  using CheckContext::CheckContext;

 protected:
  void CheckContacts();
  void CheckRestraints();
  // ATB's rate-dependent terms of a contact (`rate_scaled_force`, `rate_scale`, `rate_force`);
  // false after a report (one of the first two without the other is E0206).
  bool ReadRateTerms(Scope& scope, const BoundBlock& bound, const ast::Statement& statement,
                     Contact& contact);
  // An airbag's `model` and the attributes of ATB's free bag (check_airbag_model.cpp).
  void CheckAirbagModel(Scope& scope, const BoundBlock& bound, Airbag& bag);
};

// Applied forces and torques (check_loads.cpp).
class LoadChecker : protected virtual CheckContext {
 public:
  using CheckContext::CheckContext;

 protected:
  void CheckLoads();
  // `actuator NAME on JOINT { ... }`: a pin joint, a target and gains (check_actuators.cpp).
  void CheckActuators();
  // Under `symmetry planar`, loads must act in the plane (after CheckRunSettings).
  void CheckLoadsInThePlane();
};

// Wind and water (check_fluids.cpp): E0425 for what the model cannot take.
class FluidChecker : protected virtual CheckContext {
 public:
  using CheckContext::CheckContext;

 protected:
  // After CheckRunSettings: water needs the gravity, and neither takes symmetry.
  void CheckFluids(Scope& scope);
};

// The scenario's run settings: time, integrator, restart, settle, symmetry (check_settings.cpp).
class SettingsChecker : protected virtual CheckContext {
 public:
  using CheckContext::CheckContext;

 protected:
  void CheckRunSettings(Scope& scope, const BoundBlock& scenario_block);
};

// Initial conditions (check_initial.cpp); E0421 for what the model cannot take.
class InitialChecker : protected virtual CheckContext {
 public:
  using CheckContext::CheckContext;

 protected:
  void CheckInitialConditions();
  // After every initial condition is read: held roots' positions and velocities.
  void CheckHeldInitialConditions();
  // Welds (check_welds.cpp): each holds one reference segment to the ground or a vehicle, once,
  // and the segment turns with its base (E0426).
  void CheckWelds();

 private:
  void RefuseUntakenInitial(const InitialCondition& initial, const BoundBlock& bound);
  void PlaceByHPoint(Scope& scope, const BoundBlock& bound, const ast::Statement& h_statement,
                     InitialCondition& initial);
};

// Output requests and injury criteria (check_outputs.cpp).
class OutputChecker : protected virtual CheckContext {
 public:
  using CheckContext::CheckContext;

 protected:
  void CheckOutputs();

 private:
  bool ReadCriterionArguments(Scope& scope, const ast::Expr& call, const CriterionSpec& spec,
                              Criterion& criterion);
  bool ReadOutputFrame(Scope& scope, const ast::Statement& request, const OutputSpec& spec,
                       OutputRequest& output);
  int ReadFilterClass(const ast::Expr& value);
  bool ReadFilterStandard(const BoundBlock& bound);
};

// Contacts, output requests and criteria given twice (errors); belts and springs along the same
// path (warnings) (duplicates.cpp).
class DuplicateChecker : protected virtual CheckContext {
 public:
  using CheckContext::CheckContext;

 protected:
  void CheckDuplicates();

 private:
  void ReportDuplicate(DiagnosticKind kind, SourceRange again, SourceRange first,
                       std::string message, std::string help);
};

// Force and torque laws of the wrong sign (check_element_laws.cpp): E0420.
class ElementLawChecker : protected virtual CheckContext {
 public:
  using CheckContext::CheckContext;

 protected:
  void CheckElementLaws();
};

// The lints: unused names, suspicious values (lints.cpp).
class LintChecker : protected virtual CheckContext {
 public:
  using CheckContext::CheckContext;

 protected:
  void RunLints();
};

// All of them over one context, run in order by Run (check.cpp).
class Checker final : SceneChecker,
                      BodyChecker,
                      RestraintChecker,
                      LoadChecker,
                      FluidChecker,
                      SettingsChecker,
                      InitialChecker,
                      OutputChecker,
                      DuplicateChecker,
                      ElementLawChecker,
                      LintChecker {
 public:
  Checker(lang::SourceManager& sources, const CheckOptions& options)
      : CheckContext(sources, options),
        SceneChecker(sources, options),
        BodyChecker(sources, options),
        RestraintChecker(sources, options),
        LoadChecker(sources, options),
        FluidChecker(sources, options),
        SettingsChecker(sources, options),
        InitialChecker(sources, options),
        OutputChecker(sources, options),
        DuplicateChecker(sources, options),
        ElementLawChecker(sources, options),
        LintChecker(sources, options) {}
  CheckedScenario Run(const ast::File& file);
};

}  // namespace sled::compiler::internal
