// The checker reads attributes by AttributeKey, which only the names of
// compiler/check/attribute_keys.def convert to (a misspelt key does not compile). These tests keep
// that list and the schema's attributes the same set, so that the list can neither miss an
// attribute the checker must read nor allow a name that no block has.
#include <algorithm>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "compiler/check/attribute_key.h"
#include "compiler/check/schema.h"

namespace sled::compiler {
namespace {

using internal::AttributeKey;
using internal::IsAttributeKey;
using internal::kAttributeKeys;

static_assert(IsAttributeKey("mass"));
static_assert(!IsAttributeKey("mas"));  // the misspelling a consteval AttributeKey rejects
static_assert(!IsAttributeKey(""));

TEST(AttributeKeys, AreExactlyTheSchemasAttributeNames) {
  std::set<std::string> schema;
  for (const BlockSpec& block : AllBlockSpecs()) {
    for (const AttributeSpec& attribute : block.attributes) {
      schema.emplace(attribute.name);
    }
  }
  const std::set<std::string> listed(std::begin(kAttributeKeys), std::end(kAttributeKeys));
  for (const std::string& name : schema) {
    EXPECT_TRUE(listed.count(name)) << "`" << name
                                    << "` is an attribute of the schema but not in "
                                       "compiler/check/attribute_keys.def";
  }
  for (const std::string& name : listed) {
    EXPECT_TRUE(schema.count(name)) << "`" << name
                                    << "` is in compiler/check/attribute_keys.def but no block "
                                       "of the schema has it";
  }
}

TEST(AttributeKeys, AreListedOnceInAlphabeticalOrder) {
  const std::vector<std::string_view> keys(std::begin(kAttributeKeys), std::end(kAttributeKeys));
  EXPECT_TRUE(std::is_sorted(keys.begin(), keys.end()));
  EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end());
}

TEST(AttributeKeys, AKeyIsTheLiteralItWasMadeFrom) {
  constexpr AttributeKey key = "semi_axes";
  EXPECT_EQ(key.view(), "semi_axes");
  EXPECT_EQ(FindAttribute(BlockKind::kEllipsoid, key)->name, "semi_axes");
}

}  // namespace
}  // namespace sled::compiler
