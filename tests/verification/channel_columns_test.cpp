// Each output group's channel count (what the filters, the criteria and the ISO-MME codes use to
// find a group's columns) adds up to the channels the run writes, group by group: the flagship
// scene has belt outputs, whose span tensions and anchor forces come before its contact forces.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "output/post/channel_filters.h"
#include "runtime/run/outputs.h"
#include "tests/verification/compile.h"

namespace sled::verification {
namespace {

TEST(ChannelColumns, GroupCountsMatchTheChannelNamesOfTheFlagship) {
  std::ifstream in(std::filesystem::path(SLED_SOURCE_ROOT) / "examples" / "frontal_sled.sled");
  std::stringstream text;
  text << in.rdbuf();
  const Compiled compiled = CompileText(text.str());
  ASSERT_TRUE(compiled.errors.empty()) << compiled.errors;
  const runtime::Model& model = compiled.model();
  const std::vector<std::string> names = runtime::ChannelNames(model);
  const std::vector<std::size_t> first = runtime::post::GroupColumns(model);
  bool has_belt = false;
  for (std::size_t k = 0; k < model.output_kind.size(); ++k) {
    has_belt |= model.output_kind[k] == runtime::Model::OutputKind::kBeltForce;
    const std::size_t end =
        k + 1 < first.size() ? first[k + 1] : first[k] + runtime::ChannelCount(model, k);
    ASSERT_EQ(first[k] + runtime::ChannelCount(model, k), end);
    // Every column of the group starts with the group's label.
    for (std::size_t c = first[k]; c < end; ++c) {
      ASSERT_LT(c, names.size());
      EXPECT_EQ(names[c].rfind(model.output_label[k] + ".", 0), 0u)
          << names[c] << " in group " << model.output_label[k];
    }
  }
  EXPECT_TRUE(has_belt);
  EXPECT_EQ(first.back() + runtime::ChannelCount(model, first.size() - 1), names.size());
}

}  // namespace
}  // namespace sled::verification
