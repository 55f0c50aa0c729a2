// What the lowering tests share (tests/compiler/lower_test.cpp, lower_scene_test.cpp): a scene
// compiled through sled::Compile, and comparisons of the runtime's vectors and matrices.
#pragma once

#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "runtime/model/model.h"
#include "sled/compile.h"

namespace sled::compiler::lower_test {

inline const std::filesystem::path kRoot = SLED_SOURCE_ROOT;
inline constexpr double kDeg = std::numbers::pi / 180.0;

struct Result {
  Compilation compilation;
  std::string errors;  // compact diagnostics, when the scene does not compile

  const CheckedScenario& scenario() const { return compilation.scenario(); }
  const runtime::Model& model() const { return compilation.model(); }
  // The lowering's notes (N04xx), compact.
  std::vector<std::string> notes() const { return compilation.Notes(); }
  // The Model index of a segment by its qualified name; -1 when absent.
  int Segment(const std::string& name) const {
    for (std::size_t s = 0; s < model().nsegment(); ++s) {
      if (model().segment_name[s] == name) return static_cast<int>(s);
    }
    return -1;
  }
};

// Compiles text through sled::Compile; `path` names the buffer (relative to the working
// directory).
inline Result LowerText(const std::string& text, const std::string& path = "test.sled",
                        const std::string& stdlib = (kRoot / "stdlib").string()) {
  CompileOptions options;
  options.stdlib = stdlib;
  Result result{Compile(Source::Text(text, path), options), {}};
  if (!result.compilation.ok()) result.errors = result.compilation.Render();
  return result;
}

inline std::string Scene(const std::string& body) {
  return "scenario \"t\" {\n  time { end = 100 ms  output_every = 1 ms }\n" + body + "\n}\n";
}

#define ASSERT_CHECKED(result) ASSERT_EQ((result).errors, "") << "the scene does not check"

inline void ExpectNear(const runtime::Mat3& actual, const runtime::Mat3& expected,
                       double tolerance) {
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), tolerance) << "actual:\n"
                                                                  << actual << "\nexpected:\n"
                                                                  << expected;
}

inline void ExpectNear(const runtime::Vec3& actual, const runtime::Vec3& expected,
                       double tolerance) {
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), tolerance)
      << "actual " << actual.transpose() << ", expected " << expected.transpose();
}

inline const std::string kUnitInertia = "mass = 1 kg  inertia = (0.01, 0.01, 0.01) kg*m^2";

}  // namespace sled::compiler::lower_test
