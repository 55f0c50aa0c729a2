// The schema: for every kind of block, the attributes it takes, each with its value type,
// physical dimension, range and whether it is required. One table serves the checker's attribute
// binding, its "did you mean" hints, and the test that keeps docs/language.md complete.
//
// Declarations (segment, joint, contact, ...) are statements with a name or a target and a block;
// the schema lists which declarations each block allows and which block kind they open.
#pragma once

#include <limits>
#include <string_view>
#include <vector>

#include "compiler/units/dimension.h"

namespace sled::compiler {

enum class BlockKind {
  kFile,
  kScenario,
  kModule,
  kBody,
  kSegment,
  kSegmentEllipsoid,
  kJoint,
  kVehicle,
  kPlane,
  kEllipsoid,
  kTable,  // rows and unloading attributes of a table function
  kContact,
  kBelt,
  kHarness,
  kAirbag,
  kSpring,
  kConstraint,
  kLoad,
  kActuator,
  kWind,
  kWater,
  kInitial,
  kOutput,
  kTime,
  kIntegrator,
  kRestart,
  kSettle,
  kSymmetry,
  kOverride,
};

std::string_view BlockName(BlockKind kind);

enum class ValueType {
  kQuantity,    // one number with a unit of `dimension`
  kVector,      // (x, y, z) with a unit of `dimension`
  kPoints,      // `count` vectors separated by commas
  kBool,        // true or false
  kString,      // "text"
  kWord,        // one of `choices`
  kReference,   // a name of one of the kinds in `choices` (segment, function, ...)
  kReferences,  // one or more names, comma separated
  kFunction,    // a function name or constant(...) / table(...) / polynomial(...) of
                // `argument` -> `dimension`
  kMotion,      // half_sine(...), trapezoid(...), table(time -> acceleration [-> angular])
  kBeltPath,    // anchor -> segment -> ... -> anchor
  kLock,        // true, false, or a list of Euler axes
  kCriteria,    // hic15(segment), nij(joint), ...
  kPair,        // two names (symmetry pairs)
  kUnloading,   // atb(energy_return = R, permanent_set = G)
};

struct AttributeSpec {
  std::string_view name;
  ValueType type = ValueType::kQuantity;
  Dimension dimension{};
  bool required = false;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;
  std::string_view choices;  // space-separated words or reference kinds
  Dimension argument{};      // kFunction: dimension of the argument
  int count = 0;             // kPoints: number of points
  bool repeatable = false;
  std::string_view doc;
};

// A declaration keyword allowed in a block, and the block kind its body is checked as.
struct DeclarationSpec {
  std::string_view keyword;
  BlockKind opens;
  std::string_view doc;
};

struct BlockSpec {
  BlockKind kind;
  std::vector<AttributeSpec> attributes;
  std::vector<DeclarationSpec> declarations;
};

const BlockSpec& SpecOf(BlockKind kind);
const AttributeSpec* FindAttribute(BlockKind kind, std::string_view name);
const DeclarationSpec* FindDeclaration(BlockKind kind, std::string_view keyword);
// Every keyword a block allows, for "did you mean" hints.
std::vector<std::string> KeywordsOf(BlockKind kind);
// Blocks other than `kind` where `keyword` is allowed, for "not allowed here" messages.
std::vector<BlockKind> BlocksAllowing(std::string_view keyword);
const std::vector<BlockSpec>& AllBlockSpecs();

// The output request keywords and what they need.
struct OutputSpec {
  std::string_view keyword;
  std::string_view target_kind;  // segment, joint, belt, airbag, spring, contact
  bool takes_point = false;      // `at (x, y, z) mm`
  std::string_view doc;
};
const std::vector<OutputSpec>& AllOutputSpecs();
const OutputSpec* FindOutput(std::string_view keyword);

// The injury criteria that `criteria = ...` accepts.
struct CriterionSpec {
  std::string_view name;
  std::string_view target_kind;  // segment or joint
  std::string_view doc;
  // A second, required input given by name: `nic(occupant.head, t1 = occupant.neck_lower)`.
  std::string_view second_name = {};
  std::string_view second_kind = {};  // segment or joint
};
const std::vector<CriterionSpec>& AllCriterionSpecs();
const CriterionSpec* FindCriterion(std::string_view name);

// Names of quantities usable in function signatures: table(deflection -> force).
struct QuantityName {
  std::string_view name;
  Dimension dimension;
};
const std::vector<QuantityName>& AllQuantityNames();
const QuantityName* FindQuantityName(std::string_view name);

}  // namespace sled::compiler
