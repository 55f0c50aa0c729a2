// PEGTL's grammar analysis: no rule may loop without consuming input (an infinite loop on some
// input) or recurse without consuming input (a stack overflow on some input). The analysis
// prints the offending rules when it finds any.
#include <gtest/gtest.h>

#include <tao/pegtl/contrib/analyze.hpp>

#include "lang/syntax/grammar.h"

namespace sled::lang::grammar {
namespace {

// The grammar lang::ParseValue uses for `--set NAME=VALUE`: one value and nothing else.
struct whole_value : seq<ws, value, ws, eof> {};

TEST(GrammarAnalysis, FileGrammarHasNoInfiniteLoopsOrLeftRecursion) {
  EXPECT_EQ(tao::pegtl::analyze<file>(), 0u);
}

TEST(GrammarAnalysis, ValueGrammarHasNoInfiniteLoopsOrLeftRecursion) {
  EXPECT_EQ(tao::pegtl::analyze<whole_value>(), 0u);
}

TEST(GrammarAnalysis, BlockGrammarHasNoInfiniteLoopsOrLeftRecursion) {
  EXPECT_EQ(tao::pegtl::analyze<block>(), 0u);
}

}  // namespace
}  // namespace sled::lang::grammar
