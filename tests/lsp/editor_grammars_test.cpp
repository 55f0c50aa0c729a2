// The editor grammars (editors/) name sled's declaration keywords and output requests, which the
// checker's schema defines: a keyword added to the schema must reach the grammars too.
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "compiler/check/schema.h"

namespace sled::lsp {
namespace {

std::string ReadSource(const std::string& relative) {
  std::ifstream in(std::filesystem::path(SLED_SOURCE_ROOT) / relative, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool HasWord(const std::string& text, std::string_view word) {
  const std::regex pattern("(^|[^A-Za-z0-9_])" + std::string(word) + "([^A-Za-z0-9_]|$)");
  return std::regex_search(text, pattern);
}

TEST(EditorGrammarsTest, NameEveryDeclarationKeywordOfTheSchema) {
  const std::string textmate = ReadSource("editors/vscode/syntaxes/sled.tmLanguage.json");
  const std::string highlights = ReadSource("editors/tree-sitter-sled/queries/highlights.scm");
  const std::string emacs = ReadSource("editors/emacs/sled-mode.el");
  ASSERT_FALSE(textmate.empty());
  ASSERT_FALSE(highlights.empty());
  ASSERT_FALSE(emacs.empty());
  for (const compiler::BlockSpec& block : compiler::AllBlockSpecs()) {
    for (const compiler::DeclarationSpec& declaration : block.declarations) {
      EXPECT_TRUE(HasWord(textmate, declaration.keyword)) << declaration.keyword;
      EXPECT_TRUE(HasWord(highlights, "\"" + std::string(declaration.keyword) + "\""))
          << declaration.keyword;
      EXPECT_TRUE(HasWord(emacs, "\"" + std::string(declaration.keyword) + "\""))
          << declaration.keyword;
    }
  }
  for (const compiler::OutputSpec& output : compiler::AllOutputSpecs()) {
    EXPECT_TRUE(HasWord(textmate, output.keyword)) << output.keyword;
  }
  for (const compiler::CriterionSpec& criterion : compiler::AllCriterionSpecs()) {
    EXPECT_TRUE(HasWord(textmate, criterion.name)) << criterion.name;
  }
}

}  // namespace
}  // namespace sled::lsp
