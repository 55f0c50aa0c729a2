// `sled convert`: a CVS-III / ATB deck read into the same AST the .sled parser produces, ready
// for the formatter to print (docs/architecture.md). Diagnostics name the deck's line, card and
// columns.
#pragma once

#include <optional>
#include <string_view>

#include "lang/ast/ast.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/legacy/deck.h"
#include "lang/legacy/fortran_field.h"
#include "lang/source/source_manager.h"

namespace sled::lang::legacy {

// How the deck is written: fixed columns (`.ain`, the FORMATs of ATB's READ statements) or
// list-directed (`.lin`, ATB's `READ (unit, *)`).
enum class DeckFormat { kFixed, kList };

struct ConvertOptions {
  DiagnosticConsumer* diagnostics = nullptr;  // required
  DeckFormat format = DeckFormat::kFixed;
  BlankMode blanks = BlankMode::kIgnore;  // kZero: FORTRAN IV blanks-as-zeros (--blank-zero, .ain)
  // Deprecated and ignored (--approximate-airbags): D.4 airbags convert to ATB's free bag
  // (`model = atb_free`) by default; `sled convert` warns that the option does nothing.
  bool approximate_airbags = false;
};

// The format a deck's file name asks for: `.ain` fixed, `.lin` list-directed (any case); nothing
// for another extension.
std::optional<DeckFormat> DeckFormatOfPath(std::string_view path);

// The scenario of a deck. When errors were reported the tree is incomplete and must not be
// printed as a conversion.
ast::File ConvertDeck(const SourceManager& sources, FileId deck, const ConvertOptions& options);

// The mapping alone, for a deck already read: reports unresolved references (E0505, E0509) and
// unused functions (W0502) at the cards' ranges.
ast::File DeckToAst(const Deck& deck, DiagnosticConsumer& diagnostics);

}  // namespace sled::lang::legacy
