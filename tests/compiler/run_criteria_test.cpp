// `sled run` computes the requested injury criteria and writes them to summary.json. A head on a
// locked neck, held at the neck's centre of mass on a sled driven by a 60 g, 15 ms half-sine
// along z, moves exactly with the sled; so its HIC and 3 ms level are those of the pulse
// (crash-conventions.md §2.2: 173.4 and 57.06 g) and the neck pushes the head with m a.
#include <cmath>
#include <filesystem>
#include <regex>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/compiler/sled_process.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::ReadText;
using testing::SledResult;
using testing::WriteText;

using RunCriteria = testing::SledProcessTest;

// delta_v = 2 A T / pi for A = 60 g and T = 15 ms.
constexpr const char* kScene = R"(scenario "head on a sled" {
  gravity = (0, 0, 0) m/s^2
  time { end = 50 ms  output_every = 0.1 ms }
  vehicle sled { motion = half_sine(delta_v = 5.618796561619687 m/s, duration = 15 ms, axis = z) }
  body dummy {
    segment neck { mass = 1 kg  inertia = (0.002, 0.002, 0.002) kg*m^2 }
    segment head { mass = 4.5 kg  inertia = (0.02, 0.02, 0.02) kg*m^2 }
    joint neck_upper : pin(neck -> head) {
      at neck = (0, 0, 50) mm
      at head = (0, 0, -50) mm
      axis = y
      locked = true
    }
  }
  constraint mount : fixed_point(sled -> dummy.neck) {
    at sled = (0, 0, 1) m
    at dummy.neck = (0, 0, 0) mm
  }
  initial dummy { position = (0, 0, 1) m }
  output {
    criteria = hic15(dummy.head), hic36(dummy.head), head_3ms(dummy.head),
      neck_compression(dummy.neck_upper), neck_tension(dummy.neck_upper), nij(dummy.neck_upper)
  }
}
)";

// The summary.json line of a criterion (each sits on one line).
std::string CriterionLine(const std::string& summary, const std::string& name,
                          const std::string& variant = "") {
  const std::string key = "{\"name\": \"" + name + "\", \"variant\": \"" + variant + "\"";
  const std::size_t at = summary.find(key);
  if (at == std::string::npos) return "";
  return summary.substr(at, summary.find('\n', at) - at);
}

double Field(const std::string& line, const std::string& field) {
  std::smatch match;
  const std::regex pattern("\"" + field + "\": ([-0-9.eE+]+)");
  if (!std::regex_search(line, match, pattern)) return std::nan("");
  return std::stod(match[1]);
}

TEST_F(RunCriteria, SummaryHoldsTheCriteriaOfAKnownPulse) {
  WriteText(temp() / "pulse.sled", kScene);
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", (temp() / "pulse.sled").string(), "-o", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_THAT(result.err, ::testing::Not(HasSubstr("not computed yet")));
  const std::string summary = ReadText(out / "summary.json");

  const std::string hic15 = CriterionLine(summary, "hic15");
  ASSERT_FALSE(hic15.empty()) << summary;
  EXPECT_THAT(hic15, HasSubstr("\"target\": \"dummy.head\""));
  EXPECT_NEAR(Field(hic15, "value"), 173.4, 0.6);
  EXPECT_NEAR(Field(hic15, "window_end") - Field(hic15, "window_start"), 0.010, 2e-4);
  EXPECT_EQ(Field(hic15, "limit"), 700);
  EXPECT_THAT(hic15, HasSubstr("\"pass\": true"));
  EXPECT_NEAR(Field(CriterionLine(summary, "hic36"), "value"), 173.4, 0.6);
  for (const char* variant : {"cumulative", "continuous"}) {
    const std::string clip = CriterionLine(summary, "head_3ms", variant);
    EXPECT_NEAR(Field(clip, "value"), 57.06, 0.15) << variant;
    EXPECT_THAT(clip, HasSubstr("\"unit\": \"g\""));
  }
  // The neck pushes the 4.5 kg head with m a: 4.5 kg * 60 g at the pulse's peak (7.5 ms).
  const double push = 4.5 * 60 * 9.80665;
  const std::string compression = CriterionLine(summary, "neck_compression");
  EXPECT_NEAR(Field(compression, "value"), push, 0.002 * push);
  EXPECT_NEAR(Field(compression, "window_start"), 0.0075, 2e-4);
  // The neck never pulls; filtered, the pulse's abrupt end rings a little below zero (the
  // undershoot of the four-pole Butterworth), well under 0.2 % of the peak.
  EXPECT_NEAR(Field(CriterionLine(summary, "neck_tension"), "value"), 0.0, 2e-3 * push);
  // Pure compression: Nij = F / 6160 N.
  EXPECT_NEAR(Field(CriterionLine(summary, "nij"), "value"), push / 6160, 0.002 * push / 6160);

  // The criteria read channels the scene did not request: the lowering added them.
  const std::string csv = ReadText(out / "timeseries.csv");
  EXPECT_THAT(csv, HasSubstr("dummy.head.acceleration.x [m/s^2]"));
  EXPECT_THAT(csv, HasSubstr("dummy.neck_upper.joint_force.z [N]"));
  EXPECT_THAT(ReadText(out / "timeseries_filtered.csv"),
              HasSubstr("dummy.head.acceleration.x [m/s^2]"));
}

TEST_F(RunCriteria, ACoarseOutputStepLeavesTheCriterionUncomputedWithTheReason) {
  std::string scene = kScene;
  scene.replace(scene.find("output_every = 0.1 ms"), 21, "output_every = 1 ms");
  WriteText(temp() / "coarse.sled", scene);
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", (temp() / "coarse.sled").string(), "-o", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string hic15 = CriterionLine(ReadText(out / "summary.json"), "hic15");
  EXPECT_THAT(hic15, HasSubstr("\"value\": null"));
  EXPECT_THAT(hic15, HasSubstr("CFC 1000 needs a sample rate of at least 10000 Hz"));
  EXPECT_THAT(result.err, HasSubstr("hic15(dummy.head): not computed"));
}

TEST_F(RunCriteria, OutputRequestsCarryTheirFilterClass) {
  std::string scene = kScene;
  scene.replace(scene.find("    criteria ="), 0,
                "    acceleration dummy.head filter cfc180 as head_cfc180\n"
                "    acceleration dummy.neck filter none\n");
  WriteText(temp() / "filters.sled", scene);
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", (temp() / "filters.sled").string(), "-o", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string filtered = ReadText(out / "timeseries_filtered.csv");
  EXPECT_THAT(filtered, HasSubstr("head_cfc180.acceleration.z"));
  EXPECT_THAT(filtered, ::testing::Not(HasSubstr("dummy.neck.acceleration")));
  EXPECT_THAT(ReadText(out / "timeseries.csv"), HasSubstr("dummy.neck.acceleration.z"));
}

// A chest of two segments, the spine and the sternum, on a slip joint along x with a spring
// between them, squeezed by a constant force F across the joint from rest: the relative motion
// is that of the reduced mass mu on the spring k, so the compression is D(t) = (F / k) (1 -
// cos w t), w = sqrt(k / mu), its rate V = (F / k) w sin w t, and VC = SF V D / Dc peaks where
// (1 - cos) sin does, at w t = 2 pi / 3, at SF (F / k)^2 w (3 sqrt(3) / 4) / Dc (Hybrid III 50th
// male: SF = 1.3, Dc = 0.229 m; crash-conventions.md §2.1).
constexpr const char* kChest = R"(scenario "chest" {
  gravity = (0, 0, 0) m/s^2
  time { end = 60 ms  output_every = 0.1 ms }
  body chest {
    segment spine { mass = 20 kg  inertia = (0.2, 0.2, 0.2) kg*m^2 }
    segment sternum { mass = 0.5 kg  inertia = (0.001, 0.001, 0.001) kg*m^2 }
    joint ribcage : slip(spine -> sternum) {
      at spine = (100, 0, 0) mm
      at sternum = (0, 0, 0) mm
      axis = x
    }
  }
  spring ribs : chest.spine -> chest.sternum {
    at chest.spine = (0, 0, 0) mm
    at chest.sternum = (0, 0, 0) mm
    stiffness = 10 kN/m
  }
  load squeeze on chest.ribcage { force = -300 N }
  output { criteria = viscous_criterion(chest.ribcage) }
}
)";

TEST_F(RunCriteria, TheViscousCriterionOfASlipJointChestIsTheClosedForm) {
  WriteText(temp() / "chest.sled", kChest);
  const fs::path out = temp() / "out";
  const SledResult result = Sled({"run", (temp() / "chest.sled").string(), "-o", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const double mu = 20.0 * 0.5 / 20.5;
  const double w = std::sqrt(10000.0 / mu);
  const double amplitude = 300.0 / 10000.0;
  const double expected = 1.3 * amplitude * amplitude * w * (3.0 * std::sqrt(3.0) / 4.0) / 0.229;
  const std::string vc = CriterionLine(ReadText(out / "summary.json"), "viscous_criterion");
  ASSERT_FALSE(vc.empty()) << result.err;
  EXPECT_NEAR(Field(vc, "value"), expected, 0.005 * expected);
  EXPECT_NEAR(Field(vc, "window_start"), 2.0 * M_PI / 3.0 / w, 2e-4);
  EXPECT_THAT(vc, HasSubstr("\"unit\": \"m/s\""));
  EXPECT_EQ(Field(vc, "limit"), 1.0);
  EXPECT_THAT(vc, HasSubstr("\"limit_source\": \"UN R94/R137\""));
  EXPECT_THAT(vc, HasSubstr("\"filter_class\": 180"));
}

TEST_F(RunCriteria, TheViscousCriterionOfAJointThatDoesNotSlideIsRefused) {
  std::string scene = kChest;
  scene.replace(scene.find("slip(spine -> sternum)"), 22, "pin(spine -> sternum)");
  WriteText(temp() / "pin.sled", scene);
  const SledResult result = Sled({"check", (temp() / "pin.sled").string()});
  EXPECT_NE(result.exit_code, 0);
  EXPECT_THAT(result.out + result.err, HasSubstr("E0205"));
  EXPECT_THAT(result.out + result.err, HasSubstr("`chest.ribcage` is not a slip joint"));
}

}  // namespace
}  // namespace sled
