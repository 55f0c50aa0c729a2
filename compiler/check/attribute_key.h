// The name of an attribute as the checker reads it (`ReadQuantity(scope, bound, kind, "mass")`):
// a string literal that must be one of the schema's attribute names, checked when the checker
// compiles. A misspelt key would otherwise read as "absent" and silently drop what the user
// wrote; here it is a compile error ("call to consteval function ... is not a constant
// expression", with a note at NotAnAttributeOfTheSchema). The names are listed in
// attribute_keys.def, which a test keeps equal to the schema's. Internal to compiler/check.
#pragma once

#include <string_view>

namespace sled::compiler::internal {

// Every attribute name of the schema.
inline constexpr std::string_view kAttributeKeys[] = {
#define SLED_ATTRIBUTE_KEY(name) #name,
#include "compiler/check/attribute_keys.def"
#undef SLED_ATTRIBUTE_KEY
};

constexpr bool IsAttributeKey(std::string_view name) {
  for (const std::string_view key : kAttributeKeys) {
    if (key == name) return true;
  }
  return false;
}

// Not constexpr: a constant evaluation that reaches it fails to compile, naming it.
inline void NotAnAttributeOfTheSchema() {}

class AttributeKey {
 public:
  // Implicit, so that a call site writes the plain literal.
  consteval AttributeKey(const char* name)  // NOLINT(google-explicit-constructor)
      : name_(name) {
    if (!IsAttributeKey(name_)) NotAnAttributeOfTheSchema();
  }
  constexpr std::string_view view() const { return name_; }
  // Implicit, so that the schema lookups and messages take the key as they took the name.
  // NOLINTNEXTLINE(google-explicit-constructor)
  constexpr operator std::string_view() const { return name_; }

 private:
  std::string_view name_;
};

}  // namespace sled::compiler::internal
