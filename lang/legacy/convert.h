// `sled convert`: a CVS-III / ATB deck read into the same AST the .sled parser produces, ready
// for the formatter to print (DESIGN.md §2). Diagnostics name the deck's line, card and columns.
#pragma once

#include "lang/ast/ast.h"
#include "lang/diagnostics/diagnostic.h"
#include "lang/legacy/deck.h"
#include "lang/legacy/fortran_field.h"
#include "lang/source/source_manager.h"

namespace sled::lang::legacy {

struct ConvertOptions {
  DiagnosticConsumer* diagnostics = nullptr;  // required
  BlankMode blanks = BlankMode::kIgnore;      // kZero: FORTRAN IV blanks-as-zeros (--blank-zero)
};

// The scenario of a fixed-column `.ain` deck. When errors were reported the tree is incomplete
// and must not be printed as a conversion.
ast::File ConvertAinDeck(const SourceManager& sources, FileId deck, const ConvertOptions& options);

// The mapping alone, for a deck already read: reports unresolved references (E0505, E0509) and
// unused functions (W0502) at the cards' ranges.
ast::File DeckToAst(const Deck& deck, DiagnosticConsumer& diagnostics);

}  // namespace sled::lang::legacy
