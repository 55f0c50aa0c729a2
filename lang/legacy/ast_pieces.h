// The pieces of the scenario tree that DeckMapper (deck_mapper.h) builds from a deck: numbers in
// the deck's units, vectors, paths, calls, statements, card comments and names from deck labels.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "lang/ast/ast.h"
#include "lang/legacy/deck.h"

namespace sled::lang::legacy::mapping {

// A unit written as sled source (`lbf*in/deg^2`) as the tree holds it.
ast::Unit MakeUnit(std::string_view text);
ast::Expr Number(double value, std::string_view unit = {});
ast::Expr Vector(const Vec3& v, std::string_view unit);
ast::Expr Path(const std::string& dotted);
ast::Expr String(std::string text);
ast::Expr Boolean(bool value);
ast::Expr Call(std::string callee, std::vector<std::pair<std::string, ast::Expr>> arguments);
ast::Statement Attribute(std::string keyword, ast::Expr value);
ast::Statement Declaration(std::string keyword, ast::Expr target, std::string comment = {});
void Add(ast::Statement& parent, ast::Statement child);
ast::Statement Row(ast::Expr from, ast::Expr to);
std::string CardComment(std::string_view card, std::uint32_t line);
bool IsZero(const Vec3& v);

// The cosine and sine of an angle in degrees, exact at multiples of 90 degrees (a vehicle pitched
// -90 degrees moves along z, not along z plus 1e-17 of x).
std::optional<double> ExactCos(double degrees);
double CosDegrees(double degrees);
double SinDegrees(double degrees);
// The x axis turned by `yaw` about z, then by `pitch` about the turned y (degrees): the first row
// of ATB's direction-cosine matrix for yaw, pitch and roll (a roll turns x about itself).
Vec3 TurnedX(double yaw, double pitch);

// A deck label as a sled name: lower case, words joined by `_`, never a word the grammar or the
// frames reserve, unique among `taken`. A name something else already has takes the `kind` of
// what it names (a function titled like a plane, `knee_bolster`, becomes `knee_bolster_force`),
// and a number only if that is taken too.
std::string NameOf(std::string_view label, std::string_view fallback, std::set<std::string>& taken,
                   std::string_view kind = {});

}  // namespace sled::lang::legacy::mapping
