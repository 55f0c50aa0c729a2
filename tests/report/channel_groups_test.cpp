// Which channels share a plot: names split into base, component and unit; bases split into the
// request and the quantity it measures.
#include "output/report/channel_groups.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace sled::report {
namespace {

using ::testing::ElementsAre;

TEST(ChannelGroups, SplitsNamesIntoBaseComponentAndUnit) {
  const ChannelName name = SplitChannelName("occupant.head.acceleration.x [m/s^2]");
  EXPECT_EQ(name.base, "occupant.head.acceleration");
  EXPECT_EQ(name.component, "x");
  EXPECT_EQ(name.unit, "m/s^2");
  const ChannelName bare = SplitChannelName("pressure");
  EXPECT_EQ(bare.base, "pressure");
  EXPECT_EQ(bare.component, "");
  EXPECT_EQ(bare.unit, "");
}

TEST(ChannelGroups, SplitsBasesBeforeTheirQuantity) {
  RequestPart belt = SplitRequest("three_point.lap.belt_force.start");
  EXPECT_EQ(belt.request, "three_point.lap");
  EXPECT_EQ(belt.quantity, "belt_force.start");
  RequestPart contact = SplitRequest("occupant.pelvis.buck.seat_pan.contact_deflection");
  EXPECT_EQ(contact.request, "occupant.pelvis.buck.seat_pan");
  EXPECT_EQ(contact.quantity, "contact_deflection");
  // `angular_acceleration` is one word, not `angular_` before `acceleration`.
  RequestPart angular = SplitRequest("occupant.head.angular_acceleration");
  EXPECT_EQ(angular.request, "occupant.head");
  EXPECT_EQ(angular.quantity, "angular_acceleration");
  // A segment named like a quantity does not confuse it: the last quantity word wins.
  RequestPart odd = SplitRequest("dummy.velocity.position");
  EXPECT_EQ(odd.request, "dummy.velocity");
  EXPECT_EQ(odd.quantity, "position");
  RequestPart unknown = SplitRequest("bag.pressure");
  EXPECT_EQ(unknown.request, "bag.pressure");
  EXPECT_EQ(unknown.quantity, "");
}

TEST(ChannelGroups, GroupsComponentsOfOneQuantityAndUnitInFileOrder) {
  const std::vector<ChannelGroup> groups = GroupChannels({
      "occupant.head.acceleration.x [m/s^2]",
      "occupant.head.acceleration.y [m/s^2]",
      "occupant.head.acceleration.z [m/s^2]",
      "three_point.lap.belt_force.span1 [N]",
      "three_point.lap.belt_force.span2 [N]",
      "three_point.lap.belt_force.start.x [N]",
      "three_point.lap.belt_force.start.y [N]",
      "pad.contact_force.normal [N]",
      "pad.contact_point.x [m]",
  });
  ASSERT_EQ(groups.size(), 5u);
  EXPECT_EQ(groups[0].base, "occupant.head.acceleration");
  EXPECT_EQ(groups[0].unit, "m/s^2");
  EXPECT_THAT(groups[0].components, ElementsAre("x", "y", "z"));
  EXPECT_EQ(groups[0].request, "occupant.head");
  EXPECT_EQ(groups[0].quantity, "acceleration");
  EXPECT_THAT(groups[1].components, ElementsAre("span1", "span2"));
  EXPECT_EQ(groups[2].base, "three_point.lap.belt_force.start");
  EXPECT_THAT(groups[2].names, ElementsAre("three_point.lap.belt_force.start.x [N]",
                                           "three_point.lap.belt_force.start.y [N]"));
  EXPECT_EQ(groups[3].quantity, "contact_force");
  EXPECT_EQ(groups[4].unit, "m");
}

}  // namespace
}  // namespace sled::report
