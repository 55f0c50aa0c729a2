// The checker's shared state (CheckContext) and the entities, scopes and parameters it works
// on. The checkers of each block kind derive from CheckContext (checkers.h). Internal to
// compiler/check.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "compiler/check/attribute_key.h"
#include "compiler/check/check.h"
#include "compiler/check/schema.h"
#include "compiler/units/quantity.h"

namespace sled::compiler::internal {

namespace ast = lang::ast;
using lang::DiagnosticKind;

enum class EntityKind {
  kGround,
  kModule,
  kBody,
  kSegment,
  kJoint,
  kEllipsoid,
  kVehicle,
  kPlane,
  kFunction,
  kBelt,
  kHarness,
  kAirbag,
  kSpring,
  kConstraint,
  kLoad,
  kActuator,
  kParameter,
};

std::string_view EntityKindName(EntityKind kind);
// Parses a reference-kind word of the schema ("segment", "function", ...).
std::optional<EntityKind> EntityKindFromName(std::string_view name);

struct Scope;

struct Entity {
  EntityKind kind = EntityKind::kGround;
  int index = -1;  // into the CheckedScenario vector of its kind; parameters: into parameters_
  SourceRange range;
  Scope* inner = nullptr;  // bodies and modules: their names
  bool used = false;
};

// Names visible in a file, a body or a module. Lookups of a plain name walk up `parent`; the
// parts after the first dot of a path look only in `inner` scopes (and their `fallback`).
struct Scope {
  Scope* parent = nullptr;
  Scope* fallback = nullptr;  // a body's module, for `occupant.some_function`
  std::string prefix;         // qualified-name prefix: "occupant."
  std::string directory;      // folder of the file, for relative imports
  std::map<std::string, Entity> names;
  // The surfaces of an imported module's instance: the frame they are fixed in (the import's
  // `on` clause, resolved in `surface_frame_scope`); no clause means the ground.
  const ast::Expr* surface_frame = nullptr;
  Scope* surface_frame_scope = nullptr;
};

// A parameter or `let`: evaluated in the scope where it was declared, in declaration order
// (EvaluateParameters), or earlier when a value declared before it uses it.
struct Parameter {
  std::string name;
  const ast::Expr* expr = nullptr;
  std::optional<ast::Expr> override_expr;  // from --set
  Scope* scope = nullptr;
  enum class State { kPending, kEvaluating, kDone, kFailed } state = State::kPending;
  struct Value {
    std::vector<double> components;  // one for a scalar, three for a vector
    Dimension dimension;
    bool bare = false;  // written without any unit
  } value;
  bool is_param = true;
  SourceRange range;
};

using Value = Parameter::Value;

// A number or vector of zeros written without a unit: it fits any dimension (`0`, `(0, 0, 0)`).
inline bool IsBareZero(const Value& value) {
  for (const double component : value.components) {
    if (component != 0.0) return false;
  }
  return value.bare;
}

// A function whose signature is not written (`polynomial(0, 2.5 N*m/deg)`) gets it from its
// first use; the raw coefficients are kept until then.
struct PendingPolynomial {
  std::vector<Value> coefficients;
  std::vector<SourceRange> ranges;
  bool resolved = false;
};

// The checker's shared state and the services every block kind's checker uses: diagnostics,
// scopes and names, values, functions, attribute binding and reading, frames. The checkers of
// the block kinds (checkers.h) derive from it (virtually: they share one context), and
// Checker combines them.
class CheckContext {
 public:
  CheckContext(lang::SourceManager& sources, const CheckOptions& options);
  CheckContext(const CheckContext&) = delete;
  CheckContext& operator=(const CheckContext&) = delete;
  virtual ~CheckContext() = default;

  // --- diagnostics (check.cpp)
  // Every diagnostic says what was found (message), marks it (label) and gives a hint (help);
  // the help may be empty only when a "did you mean" search found nothing better to say.
  void Report(DiagnosticKind kind, SourceRange range, std::string message, std::string label,
              std::string help);

 protected:
  // --- scopes and names (check.cpp)
  Scope* NewScope(Scope* parent, std::string prefix, std::string directory);
  bool Declare(Scope& scope, const std::string& name, Entity entity);
  // Adds a declaration or a resolved use to scenario_.references (editor support).
  void RecordReference(SourceRange use, const Entity& entity, std::string name,
                       bool is_declaration);
  // Resolves a path; reports E0204/E0205 unless `quiet`. `kinds` empty accepts any kind.
  Entity* Resolve(Scope& scope, const ast::Expr& path, const std::vector<EntityKind>& kinds,
                  bool quiet = false);
  std::vector<std::string> NamesOfKinds(Scope& scope, const std::vector<EntityKind>& kinds);
  // For a segment where a joint belongs, the joints it hangs from and carries; for a joint where
  // a segment belongs, the segments it joins: a hint, or empty.
  std::string AttachedNames(const Entity& found, const std::vector<EntityKind>& kinds);

  // --- values (check_values.cpp)
  std::optional<Value> Evaluate(Scope& scope, const ast::Expr& expr);
  // Evaluates every parameter in the order of declaration, before anything uses them.
  void EvaluateParameters();
  std::optional<double> ExpectQuantity(Scope& scope, const ast::Expr& expr, Dimension dimension,
                                       std::string_view what);
  std::optional<Vec3> ExpectVector(Scope& scope, const ast::Expr& expr, Dimension dimension,
                                   std::string_view what);
  std::optional<bool> ExpectBool(const ast::Expr& expr, std::string_view what);
  std::optional<Vec3> ExpectDirection(Scope& scope, const ast::Expr& expr, std::string_view what);
  // A function attribute: a name, constant/table/polynomial(...), or a quantity read as a
  // constant or linear function. `rows` is the statement's block (table rows).
  std::optional<FunctionId> ExpectFunction(Scope& scope, const ast::Statement& statement,
                                           const ast::Expr& expr, Dimension argument,
                                           Dimension result, std::string_view what);
  // Fills the function reserved at `index` from `function NAME = table(...) { rows }`.
  void DefineFunction(Scope& scope, const ast::Statement& statement, int index);
  // `dummy = WORD` of a body: its ISO/TS 13499 dummy type; empty after reporting a bad word.
  std::string ReadDummy(const ast::Statement& statement);
  // Checks a declared function against the signature a use site expects.
  bool MatchSignature(FunctionId id, Dimension argument, Dimension result, SourceRange use);
  bool CheckRange(const AttributeSpec& spec, double value, SourceRange range);

  // The attributes of one block, read against the schema: unknown, misplaced, duplicate and
  // missing attributes are reported here. Declarations in the block are returned for the caller.
  struct BoundBlock {
    std::map<std::string, std::vector<const ast::Statement*>> attributes;
    std::vector<const ast::Statement*> declarations;
    std::vector<const ast::Statement*> rows;
  };
  BoundBlock Bind(BlockKind kind, const ast::Block* block, SourceRange owner_range);
  // The unloading attributes of a function's block (energy_loss, permanent_set, unload_slope)
  // into `function`: an unloading slope with either of the others is E0423.
  void ReadUnloading(Scope& scope, const BoundBlock& bound, Function& function, int index = -1);
  // `unloading = atb(energy_return = R, permanent_set = G)`: ATB's law, R and G each a number or
  // a function of the largest deflection; with the other unloading attributes E0423.
  // `index`: the function's FunctionId while the named functions are defined, whose law is
  // then read by ResolvePendingAtbLaws once they all are (a factor may name a later one).
  void ReadAtbUnloading(Scope& scope, const BoundBlock& bound, Function& function, int index);
  void ReadAtbLaw(Scope& scope, const ast::Statement& law, const ast::Expr& call,
                  Function& function);
  void ResolvePendingAtbLaws();
  // Refuses (E0424) a function with unloading attributes as attribute `name` of an element that
  // evaluates its function the same way loading and unloading (`element`: a spring-damper's
  // stiffness, a load, an airbag's inflow), rather than ignoring them.
  void RefuseUnloading(std::optional<FunctionId> id, const BoundBlock& bound, AttributeKey name,
                       std::string_view element);
  // Refuses (E0424) ATB's unloading law on an element other than a contact or a belt (a joint's
  // torque), whose force law does not take it.
  void RefuseAtbUnloading(std::optional<FunctionId> id, const BoundBlock& bound, AttributeKey name,
                          std::string_view element);
  const ast::Statement* One(const BoundBlock& bound, AttributeKey name) const;
  // A statement that must be `keyword = value` (one value, no target or clauses).
  const ast::Expr* SingleValue(const ast::Statement& statement);
  // The one value of attribute `name`, or nullptr when it is absent (or reported as malformed).
  const ast::Expr* ValueOf(const BoundBlock& bound, AttributeKey name);

  // Typed attribute readers over a bound block; absent attributes give nullopt silently. A key
  // that is no attribute of the schema does not compile (attribute_key.h); one that is not an
  // attribute of `kind` throws std::logic_error, a checker bug that any test reaching it shows.
  std::optional<double> ReadQuantity(Scope& scope, const BoundBlock& bound, BlockKind kind,
                                     AttributeKey name);
  std::optional<Vec3> ReadVector(Scope& scope, const BoundBlock& bound, BlockKind kind,
                                 AttributeKey name);
  std::optional<bool> ReadBool(const BoundBlock& bound, AttributeKey name);
  std::optional<FunctionId> ReadFunction(Scope& scope, const BoundBlock& bound, BlockKind kind,
                                         AttributeKey name);
  // The same with dimensions other than the schema's (a slip joint's `flexure` is a force against
  // a displacement, its `viscous` a force per speed); the schema's range still applies.
  std::optional<double> ReadQuantity(Scope& scope, const BoundBlock& bound, BlockKind kind,
                                     AttributeKey name, Dimension dimension);
  std::optional<FunctionId> ReadFunction(Scope& scope, const BoundBlock& bound, BlockKind kind,
                                         AttributeKey name, Dimension argument, Dimension result);

  // --- declarations, which every block kind may contain (scene: check_scene.cpp; bodies:
  // check_bodies.cpp).
  // The declarations of a file, module or body block; returns its bound attributes.
  virtual BoundBlock DeclareFileContents(Scope& scope, const ast::Block& block, BlockKind kind) = 0;
  virtual void CheckBodyDeclarations(Scope& scope, const ast::Statement& body_statement,
                                     const std::string& instance_name,
                                     SourceRange instance_range) = 0;

  // --- readers several block kinds share (check_restraints.cpp, check_scene.cpp)
  void ReadEllipsoid(Scope& scope, const BoundBlock& bound, BlockKind kind, Ellipsoid& ellipsoid);
  // `at FRAME = (x, y, z) mm` statements of a joint, spring or constraint: one point per frame.
  // Reports a frame that is neither of the two, and (when `required`) a missing one.
  std::array<std::optional<Vec3>, 2> ReadAtPoints(Scope& scope, const BoundBlock& bound,
                                                  std::string_view keyword,
                                                  const std::array<FrameRef, 2>& frames,
                                                  SourceRange owner, bool required,
                                                  bool local_names = false);
  // `: kind(A -> B)` or `: A -> B`: the two frames a joint, spring or constraint connects.
  std::optional<std::array<FrameRef, 2>> ReadConnection(Scope& scope,
                                                        const ast::Statement& statement,
                                                        const ast::Expr& arrow);
  // The frame a plane or ellipsoid is fixed in: its own `on` clause, else its module
  // instance's frame, else the ground. Nullopt after reporting.
  std::optional<FrameRef> SurfaceFrame(const ast::Statement& statement, Scope& scope);

  std::optional<FrameRef> ResolveFrame(Scope& scope, const ast::Expr& expr);
  std::string FrameName(const FrameRef& frame) const;

  lang::SourceManager& sources_;
  const CheckOptions& options_;
  // Bodies imported twice are checked twice; each problem is reported once.
  class DedupingConsumer final : public lang::DiagnosticConsumer {
   public:
    explicit DedupingConsumer(lang::DiagnosticConsumer& next) : next_(next) {}
    void Consume(lang::Diagnostic diagnostic) override;

   private:
    lang::DiagnosticConsumer& next_;
    std::set<std::tuple<std::uint32_t, std::uint32_t, std::string>> seen_;
  };

 private:
  DedupingConsumer dedupe_;

 protected:
  lang::DiagnosticConsumer& diagnostics_;
  CheckedScenario scenario_;

  std::vector<std::unique_ptr<Scope>> scopes_;
  std::vector<std::unique_ptr<Parameter>> parameters_;
  std::vector<bool> function_valid_;  // by FunctionId: false when its definition failed
  // While the named functions are defined: ATB laws read once they all are.
  struct PendingAtbLaw {
    Scope* scope;
    const ast::Statement* law;
    int index;
  };
  bool defining_functions_ = false;
  std::vector<PendingAtbLaw> pending_atb_laws_;
  Scope* scene_scope_ = nullptr;
  bool checking_module_ = false;  // the checked file is a module: no lints about unused names
  // `--set NAME=VALUE`, parsed; consumed by the scenario's `param` declarations.
  struct Override {
    std::string name;
    std::optional<ast::Expr> value;
    SourceRange range;
    bool used = false;
  };
  std::vector<Override> overrides_;

  // Work lists filled while declaring and processed once every name is known.
  struct Pending {
    const ast::Statement* statement;
    Scope* scope;
    int index;
  };
  struct PendingBody {
    const ast::Statement* statement;
    Scope* scope;  // the body's scope
    int index;
    const ast::Statement* reference = nullptr;  // `reference = segment`
    const ast::Statement* h_point = nullptr;    // `h_point = (x, y, z) mm`
    const ast::Statement* dummy = nullptr;      // `dummy = hybrid3_50m`
  };
  std::vector<PendingBody> bodies_;
  std::vector<Pending> vehicles_, planes_, ellipsoids_, contacts_, belts_, harnesses_, airbags_,
      springs_, loads_, actuators_, constraints_, initials_, outputs_, functions_, segments_,
      joints_, joint_overrides_;
  int current_body_ = -1;  // the body whose block DeclareFileContents is reading
  std::vector<const ast::Statement*> run_blocks_;  // time, integrator, restart, settle, symmetry
  const ast::Statement* scenario_statement_ = nullptr;
  BoundBlock scenario_bound_;
  std::vector<Entity*> lintable_;  // functions, surfaces and parameters, for unused checks
  // (index into scenario_.references, index into parameters_): values filled in at the end.
  std::vector<std::pair<std::size_t, int>> parameter_references_;

 private:
  // --- values and functions: what only Evaluate and ExpectFunction use (check_values.cpp,
  // check_functions.cpp).
  // Evaluate's body and the pieces it calls. The recursion goes through Evaluate, EvaluateNested,
  // EvaluatePath and ValueOf only; the others stay out of line (GCC and Clang would inline a
  // function called once), so that each level of a deep value costs a small stack frame, under
  // AddressSanitizer too.
  std::optional<Value> EvaluateNested(Scope& scope, const ast::Expr& expr);
  std::optional<Value> EvaluatePath(Scope& scope, const ast::Expr& expr);
  [[gnu::noinline]] std::optional<Value> EvaluateNumber(const ast::Expr& expr);
  [[gnu::noinline]] std::optional<Value> EvaluateVector(Scope& scope, const ast::Expr& expr);
  // A binary operation on two evaluated operands.
  [[gnu::noinline]] std::optional<Value> Combine(const ast::Expr& expr, const Value& left,
                                                 const Value& right);
  [[gnu::noinline]] std::optional<Value> ReportEvaluationTooDeep(const ast::Expr& expr);
  [[gnu::noinline]] std::optional<Value> ReportNotAQuantity(const ast::Expr& expr);
  [[gnu::noinline]] std::optional<Value> ReportCycle(const ast::Expr& expr, Parameter& parameter);
  // The value of a parameter, evaluating it if it has not been yet.
  std::optional<Value> ValueOf(Parameter& parameter);
  // Whether a `--set` value has the shape and dimension of the declared one (else reported).
  [[gnu::noinline]] bool OverrideFits(Parameter& parameter, const Value& value);
  // Builds a function from constant(...), table(...) or polynomial(...) into `function`; when
  // `expected` is given (argument, result) the signature must match. False after reporting.
  bool BuildFunction(Scope& scope, const ast::Statement& statement, const ast::Expr& call,
                     std::optional<std::pair<Dimension, Dimension>> expected, Function& function,
                     int index);
  // Evaluate's recursion: deep enough for the parser's longest expression (1,000 operations)
  // inside a few hundred chained definitions, shallow enough for the stack under ASan.
  static constexpr int kMaxEvaluationDepth = 2500;
  int evaluation_depth_ = 0;
  bool evaluation_too_deep_ = false;  // reported
  std::map<FunctionId, PendingPolynomial> pending_polynomials_;
};

}  // namespace sled::compiler::internal
