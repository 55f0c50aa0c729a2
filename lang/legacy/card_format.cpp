#include "lang/legacy/card_format.h"

#include <cctype>
#include <functional>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace sled::lang::legacy {
namespace {

class FormatParser {
 public:
  explicit FormatParser(std::string_view text) : text_(text) {}

  std::vector<FieldSpan> Parse() {
    Skip();
    Expect('(');
    Items(')');
    return std::move(fields_);
  }

 private:
  // A list of items up to `close`: [repeat] (X | A | I | F/E/G/D width[.d] | group).
  void Items(char close) {
    while (true) {
      Skip();
      if (Peek() == close) {
        ++at_;
        return;
      }
      if (Peek() == ',') {
        ++at_;
        continue;
      }
      const int repeat = Number(1);
      Skip();
      const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(Peek())));
      if (c == '(') {
        ++at_;
        const std::size_t start = at_;
        for (int r = 0; r < repeat; ++r) {
          at_ = start;
          Items(')');
        }
        continue;
      }
      ++at_;
      if (c == 'X') {  // `nX`: the repeat count is the number of columns skipped
        column_ += repeat;
        continue;
      }
      const int width = Number(0);
      if (Peek() == '.') {
        ++at_;
        Number(0);
      }
      if (width <= 0) Fail("a field without a width");
      FieldKind kind = FieldKind::kReal;
      if (c == 'A') {
        kind = FieldKind::kText;
      } else if (c == 'I') {
        kind = FieldKind::kInteger;
      } else if (c != 'F' && c != 'E' && c != 'G' && c != 'D') {
        Fail("an edit descriptor the legacy cards do not use");
      }
      for (int r = 0; r < repeat; ++r) {
        fields_.push_back({column_, column_ + width - 1, kind});
        column_ += width;
      }
    }
  }

  int Number(int fallback) {
    if (!std::isdigit(static_cast<unsigned char>(Peek()))) return fallback;
    int value = 0;
    while (std::isdigit(static_cast<unsigned char>(Peek())))
      value = value * 10 + (text_[at_++] - '0');
    return value;
  }
  char Peek() const { return at_ < text_.size() ? text_[at_] : '\0'; }
  void Skip() {
    while (Peek() == ' ') ++at_;
  }
  void Expect(char c) {
    if (Peek() != c) Fail("a malformed FORMAT");
    ++at_;
  }
  [[noreturn]] void Fail(const char* what) const {
    // The formats are the reader's own declarations: a bad one is a programming error.
    throw std::logic_error(std::string(what) + " in " + std::string(text_));
  }

  std::string_view text_;
  std::size_t at_ = 0;
  int column_ = 1;
  std::vector<FieldSpan> fields_;
};

struct TransparentHash {
  using is_transparent = void;
  std::size_t operator()(std::string_view text) const {
    return std::hash<std::string_view>{}(text);
  }
};

}  // namespace

const std::vector<FieldSpan>& FieldsOf(std::string_view fortran) {
  thread_local std::unordered_map<std::string, std::vector<FieldSpan>, TransparentHash,
                                  std::equal_to<>>
      cache;
  const auto found = cache.find(fortran);
  if (found != cache.end()) return found->second;
  return cache.emplace(std::string(fortran), FormatParser(fortran).Parse()).first->second;
}

}  // namespace sled::lang::legacy
