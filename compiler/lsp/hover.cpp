#include "compiler/lsp/hover.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "compiler/lsp/tree_lookup.h"
#include "compiler/units/quantity.h"
#include "compiler/units/unit_table.h"

namespace sled::lsp {
namespace {

namespace ast = lang::ast;
using compiler::CheckedScenario;
using compiler::FormatQuantity;

std::string FormatVector(const compiler::Vec3& v, compiler::Dimension dimension) {
  const std::string unit = compiler::SiUnitSymbol(dimension);
  return fmt::format("({:g}, {:g}, {:g}){}", v[0], v[1], v[2], unit.empty() ? "" : " " + unit);
}

std::string FrameText(const CheckedScenario& scene, const compiler::FrameRef& frame) {
  using Kind = compiler::FrameRef::Kind;
  if (frame.kind == Kind::kVehicle && frame.index >= 0 &&
      frame.index < static_cast<int>(scene.vehicles.size())) {
    return "vehicle `" + scene.vehicles[static_cast<std::size_t>(frame.index)].name + "`";
  }
  if (frame.kind == Kind::kSegment && frame.index >= 0 &&
      frame.index < static_cast<int>(scene.segments.size())) {
    return "segment `" + scene.segments[static_cast<std::size_t>(frame.index)].name + "`";
  }
  return "the ground";
}

template <typename T>
const T* At(const std::vector<T>& items, int index) {
  return index >= 0 && index < static_cast<int>(items.size())
             ? &items[static_cast<std::size_t>(index)]
             : nullptr;
}

std::string_view JointTypeName(compiler::JointType type) {
  switch (type) {
    case compiler::JointType::kBall:
      return "ball";
    case compiler::JointType::kPin:
      return "pin";
    case compiler::JointType::kEuler:
      return "euler";
    case compiler::JointType::kSlip:
      return "slip";
    case compiler::JointType::kNull:
      return "null";
  }
  return "joint";
}

std::string_view FunctionKindName(compiler::Function::Kind kind) {
  switch (kind) {
    case compiler::Function::Kind::kConstant:
      return "constant";
    case compiler::Function::Kind::kTable:
      return "table";
    case compiler::Function::Kind::kPolynomial:
      return "polynomial";
  }
  return "function";
}

// What the checker made of the entity: the lines after the heading.
std::string Details(const CheckedScenario& scene, const compiler::NameReference& reference) {
  const std::string& kind = reference.kind;
  std::string out;
  if (kind == "segment") {
    if (const auto* segment = At(scene.segments, reference.index)) {
      out += fmt::format("- mass: {}\n", FormatQuantity(segment->mass, compiler::dim::kMass));
      out += fmt::format("- principal inertia: {}\n",
                         FormatVector(segment->inertia, compiler::dim::kInertia));
      if (segment->singular) out += "- massless (kept in place by constraints)\n";
      out += fmt::format("- contact ellipsoids: {}\n", segment->ellipsoids.size());
      if (const auto* body = At(scene.bodies, segment->body)) {
        out += fmt::format("- body: `{}`\n", body->name);
      }
    }
  } else if (kind == "joint") {
    if (const auto* joint = At(scene.joints, reference.index)) {
      const auto* parent = At(scene.segments, joint->parent);
      const auto* child = At(scene.segments, joint->child);
      out += fmt::format("- {} joint from `{}` to `{}`\n", JointTypeName(joint->type),
                         parent ? parent->name : "?", child ? child->name : "?");
      if (joint->stop) out += fmt::format("- stop: {:g} deg\n", *joint->stop * 180.0 / M_PI);
    }
  } else if (kind == "body") {
    if (const auto* body = At(scene.bodies, reference.index)) {
      double mass = 0.0;
      for (const int segment : body->segments) {
        if (const auto* s = At(scene.segments, segment)) mass += s->mass;
      }
      out += fmt::format("- {} segments, {} joints\n", body->segments.size(), body->joints.size());
      out += fmt::format("- total mass: {}\n", FormatQuantity(mass, compiler::dim::kMass));
    }
  } else if (kind == "function") {
    if (const auto* function = At(scene.functions, reference.index)) {
      out += fmt::format("- {} of {} giving {}\n", FunctionKindName(function->kind),
                         compiler::DescribeDimension(function->argument),
                         compiler::DescribeDimension(function->result));
      if (function->kind == compiler::Function::Kind::kTable) {
        out += fmt::format("- {} points\n", function->points.size());
      }
    }
  } else if (kind == "plane") {
    if (const auto* plane = At(scene.planes, reference.index)) {
      out += fmt::format("- fixed in {}\n", FrameText(scene, plane->frame));
    }
  } else if (kind == "ellipsoid") {
    if (const auto* ellipsoid = At(scene.ellipsoids, reference.index)) {
      out += fmt::format("- semi-axes: {}\n",
                         FormatVector(ellipsoid->semi_axes, compiler::dim::kLength));
      out += fmt::format("- fixed in {}\n", FrameText(scene, ellipsoid->frame));
    }
  } else if (kind == "parameter") {
    if (reference.value.size() == 1) {
      out += fmt::format("- value: {}\n", FormatQuantity(reference.value[0], reference.dimension));
    } else if (reference.value.size() == 3) {
      out += fmt::format("- value: {}\n",
                         FormatVector({reference.value[0], reference.value[1], reference.value[2]},
                                      reference.dimension));
    } else {
      out += "- its value did not check\n";
    }
  }
  return out;
}

// The declaration's place and first line, so an imported definition can be read in place.
std::string DeclarationSource(const lang::SourceManager& sources,
                              const compiler::NameReference& reference, lang::FileId document) {
  const lang::SourceRange& range = reference.declaration;
  if (!range.valid() || range.file.value > sources.size()) return {};
  const lang::SourceBuffer& buffer = sources.buffer(range.file);
  const lang::LineColumn at = buffer.Locate(range.begin);
  std::string where = range.file == document ? fmt::format("line {}", at.line)
                                             : fmt::format("`{}`, line {}", buffer.path(), at.line);
  std::string line(buffer.Line(at.line));
  while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.erase(0, 1);
  return fmt::format("\ndeclared at {}:\n```sled\n{}\n```\n", where, line);
}

std::optional<HoverResult> HoverName(const Analysis& analysis,
                                     const compiler::NameReference& reference) {
  HoverResult result;
  result.range = reference.use;
  result.markdown = fmt::format("**{}** `{}`\n\n", reference.kind, reference.name);
  result.markdown += Details(analysis.compiled().scenario(), reference);
  result.markdown += DeclarationSource(analysis.sources(), reference, analysis.file());
  return result;
}

std::optional<HoverResult> HoverQuantity(const ast::Expr& expr) {
  if (!expr.unit || (expr.kind != ast::ExprKind::kNumber && expr.kind != ast::ExprKind::kVector)) {
    return std::nullopt;
  }
  lang::DiagnosticCollector ignored;
  const auto unit = compiler::ResolveUnit(*expr.unit, ignored);
  if (!unit) return std::nullopt;
  HoverResult result;
  result.range = expr.range;
  std::string written;
  for (const ast::UnitFactor& factor : expr.unit->factors) {
    const compiler::UnitInfo* info = compiler::FindUnit(factor.symbol);
    if (info && !info->description.empty()) {
      written += fmt::format("- `{}`: {}\n", factor.symbol, info->description);
    }
  }
  const std::string dimension = compiler::DescribeDimension(unit->dimension);
  if (expr.kind == ast::ExprKind::kNumber) {
    result.markdown = fmt::format(
        "**{}** = {} ({})\n\n{}",
        expr.text + " " +
            [&] {
              std::string text;
              for (const ast::UnitFactor& factor : expr.unit->factors) {
                text += (text.empty() ? "" : (factor.exponent < 0 ? "/" : "*")) + factor.symbol;
                const int exponent = std::abs(factor.exponent);
                if (exponent != 1) text += fmt::format("^{}", exponent);
              }
              return text;
            }(),
        FormatQuantity(expr.number * unit->scale_to_si, unit->dimension), dimension, written);
    return result;
  }
  // A vector: each component that is a plain number, scaled.
  std::string components;
  for (const ast::Expr& component : expr.operands) {
    if (!components.empty()) components += ", ";
    if (component.kind == ast::ExprKind::kNumber) {
      components += fmt::format("{:g}", component.number * unit->scale_to_si);
    } else if (component.kind == ast::ExprKind::kUnary && component.operands.size() == 1 &&
               component.operands[0].kind == ast::ExprKind::kNumber) {
      components += fmt::format("{:g}", -component.operands[0].number * unit->scale_to_si);
    } else {
      components += "…";
    }
  }
  const std::string si = compiler::SiUnitSymbol(unit->dimension);
  result.markdown = fmt::format("**vector** = ({}){} ({})\n\n{}", components,
                                si.empty() ? "" : " " + si, dimension, written);
  return result;
}

std::optional<HoverResult> HoverKeyword(const ast::Statement& statement,
                                        std::optional<compiler::BlockKind> block) {
  HoverResult result;
  result.range = statement.keyword_range;
  if (block) {
    if (const compiler::AttributeSpec* attribute =
            compiler::FindAttribute(*block, statement.keyword)) {
      result.markdown = fmt::format("**{}** (attribute of `{}`)\n\n{}\n", attribute->name,
                                    compiler::BlockName(*block), attribute->doc);
      if (attribute->type == compiler::ValueType::kQuantity ||
          attribute->type == compiler::ValueType::kVector) {
        const std::string unit = compiler::SiUnitSymbol(attribute->dimension);
        result.markdown +=
            fmt::format("\n- dimension: {}{}\n", compiler::DescribeDimension(attribute->dimension),
                        unit.empty() ? "" : " (SI: " + unit + ")");
      }
      if (attribute->required) result.markdown += "- required\n";
      return result;
    }
    if (const compiler::DeclarationSpec* declaration =
            compiler::FindDeclaration(*block, statement.keyword)) {
      result.markdown = fmt::format("**{}**\n\n{}\n", declaration->keyword, declaration->doc);
      return result;
    }
    if (*block == compiler::BlockKind::kOutput) {
      if (const compiler::OutputSpec* output = compiler::FindOutput(statement.keyword)) {
        result.markdown = fmt::format("**{}** (output of a {})\n\n{}\n", output->keyword,
                                      output->target_kind, output->doc);
        return result;
      }
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<HoverResult> Hover(const Analysis& analysis, std::uint32_t offset) {
  if (const compiler::NameReference* reference = analysis.ReferenceAt(offset)) {
    return HoverName(analysis, *reference);
  }
  const TreeContext context = analysis.ContextAt(offset);
  if (context.statements.empty()) return std::nullopt;
  const ast::Statement& statement = *context.statements.back();
  if (Holds(statement.keyword_range, analysis.file(), offset)) {
    // The keyword belongs to the block around the statement, not to the statement's own block.
    return HoverKeyword(statement, analysis.ContextAt(statement.range.begin).block);
  }
  // The narrowest number or vector with a unit: a component of a vector shows the vector.
  for (const ast::Expr* expr : ExpressionsAt(statement, analysis.file(), offset)) {
    if (auto quantity = HoverQuantity(*expr)) return quantity;
  }
  return std::nullopt;
}

}  // namespace sled::lsp
