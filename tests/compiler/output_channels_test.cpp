// Output channel groups: ChannelCount, by which the filters and the criteria find each group's
// columns, agrees with ChannelNames for every kind of group, those that name their channels
// themselves (belts, airbag forces) included. Checked on the flagship with an airbag, which has
// groups of every family after its belts.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "runtime/run/outputs.h"
#include "tests/verification/compile.h"

namespace sled::compiler {
namespace {

TEST(OutputChannels, EveryGroupCountsTheChannelsItNames) {
  const std::filesystem::path root = SLED_SOURCE_ROOT;
  const verification::Compiled compiled =
      verification::CompileFile(root / "examples" / "frontal_sled_airbag.sled");
  ASSERT_EQ(compiled.errors, "");
  const runtime::Model& model = compiled.model();
  const std::vector<std::string> names = runtime::ChannelNames(model);
  std::size_t column = 0;
  bool saw_belt = false, saw_airbag_force = false;
  for (std::size_t k = 0; k < model.output_kind.size(); ++k) {
    const std::size_t count = runtime::ChannelCount(model, k);
    ASSERT_GT(count, 0u) << model.output_label[k];
    for (std::size_t c = column; c < column + count; ++c) {
      ASSERT_LT(c, names.size());
      EXPECT_EQ(names[c].rfind(model.output_label[k] + ".", 0), 0u)
          << names[c] << " is not of group " << model.output_label[k];
    }
    column += count;
    saw_belt = saw_belt || model.output_kind[k] == runtime::Model::OutputKind::kBeltForce;
    saw_airbag_force =
        saw_airbag_force || model.output_kind[k] == runtime::Model::OutputKind::kAirbagForce;
  }
  EXPECT_EQ(column, names.size());
  EXPECT_TRUE(saw_belt);
  EXPECT_TRUE(saw_airbag_force);
}

}  // namespace
}  // namespace sled::compiler
