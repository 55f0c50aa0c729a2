// The fixed-column `.ain` source: one card per line, fields read by their columns as a Fortran
// formatted READ does. An all-blank line is a card like any other (zeros in old decks), never
// swallowed; a tab is refused (E0504), since fields are found by column.
#pragma once

#include "lang/legacy/deck_source.h"

namespace sled::lang::legacy {

class CardReader final : public DeckSource {
 public:
  using DeckSource::DeckSource;

  Card Next(std::string label, const CardSpec& spec) override;
  void Extend(Card&, int) override {}
  double Real(const Card& card, int first, int last, std::string_view what) override;
  int Integer(const Card& card, int first, int last, std::string_view what) override;
  std::string Text(const Card& card, int first, int last) override;
  SourceRange Range(const Card& card, int first, int last) const override;
  std::string Where(const Card& card, int first, int last) const override;

 private:
  std::size_t NextUnreadLine() const override { return next_; }
  std::string_view PlacementHint() const override;
  std::string_view Columns(const Card& card, int first, int last) const;

  std::size_t next_ = 0;
};

}  // namespace sled::lang::legacy
