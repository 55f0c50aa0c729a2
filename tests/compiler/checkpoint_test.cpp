// `sled run --checkpoint-every` and `--resume`: a run resumed from a checkpoint writes the same
// bytes as the uninterrupted run, with every integrator; a scene that changed its end time or
// output requests may resume, one whose physics or integrator settings changed, a damaged file
// or a checkpoint step off the output rows is refused with a message.
#include <string>

#include <gtest/gtest.h>

#include "tests/compiler/flagship_scene.h"
#include "tests/compiler/sled_process.h"

namespace sled::testing {
namespace {

class CheckpointTest : public SledProcessTest {
 protected:
  // The flagship cut to `end`, with `integrator` instead of its own (auto).
  std::string Scene(const std::string& end, const std::string& integrator = "auto") {
    std::string scene = FlagshipScene(end);
    const std::string from = "integrator auto";
    const std::size_t at = scene.find(from);
    if (at != std::string::npos) scene.replace(at, from.size(), "integrator " + integrator);
    return scene;
  }
  std::string Write(const std::string& name, const std::string& text) {
    const fs::path path = temp() / name;
    WriteText(path, text);
    return path.string();
  }
  std::string Out(const std::string& name) const { return (temp() / name).string(); }
};

TEST_F(CheckpointTest, AResumedRunIsBitIdenticalToTheUninterruptedOne) {
  for (const std::string method : {"auto", "exponential", "dopri5", "rosenbrock", "cvs"}) {
    const std::string scene = Write(method + ".sled", Scene("60 ms", method));
    const SledResult full =
        Sled({"run", scene, "-o", Out(method + "-full"), "--checkpoint-every", "20ms"});
    ASSERT_EQ(full.exit_code, 0) << full.err;
    EXPECT_NE(full.err.find("2 checkpoints, the last"), std::string::npos) << full.err;
    const SledResult plain = Sled({"run", scene, "-o", Out(method + "-plain")});
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    for (const std::string at : {"0.020000", "0.040000"}) {
      const std::string resumed = Out(method + "-resumed-" + at);
      const SledResult resume = Sled({"run", scene, "-o", resumed, "--resume",
                                      Out(method + "-full") + "/checkpoint_" + at + "s.bin"});
      ASSERT_EQ(resume.exit_code, 0) << resume.err;
      for (const std::string file : {"timeseries.csv", "timeseries_filtered.csv"}) {
        EXPECT_EQ(ReadText(fs::path(resumed) / file),
                  ReadText(fs::path(Out(method + "-full")) / file))
            << method << " from " << at << ": " << file;
      }
    }
    // Taking checkpoints changes nothing either.
    EXPECT_EQ(ReadText(fs::path(Out(method + "-plain")) / "timeseries.csv"),
              ReadText(fs::path(Out(method + "-full")) / "timeseries.csv"))
        << method;
  }
}

TEST_F(CheckpointTest, ALongerRunContinuesFromTheShorterOnesCheckpoint) {
  const std::string short_scene = Write("short.sled", Scene("40 ms"));
  const std::string long_scene = Write("long.sled", Scene("60 ms"));
  ASSERT_EQ(Sled({"run", short_scene, "-o", Out("short"), "--checkpoint-every", "20ms"}).exit_code,
            0);
  ASSERT_EQ(Sled({"run", long_scene, "-o", Out("long")}).exit_code, 0);
  const SledResult resume = Sled({"run", long_scene, "-o", Out("continued"), "--resume",
                                  Out("short") + "/checkpoint_0.020000s.bin"});
  ASSERT_EQ(resume.exit_code, 0) << resume.err;
  EXPECT_EQ(ReadText(fs::path(Out("continued")) / "timeseries.csv"),
            ReadText(fs::path(Out("long")) / "timeseries.csv"));
}

TEST_F(CheckpointTest, ChangedOutputsResumeFromTheCheckpointTime) {
  const std::string scene = Write("scene.sled", Scene("40 ms"));
  ASSERT_EQ(Sled({"run", scene, "-o", Out("full"), "--checkpoint-every", "20ms"}).exit_code, 0);
  const std::string more =
      Write("more.sled", FlagshipScene("40 ms", "    position occupant.head\n"));
  const SledResult resume =
      Sled({"run", more, "-o", Out("more"), "--resume", Out("full") + "/checkpoint_0.020000s.bin"});
  ASSERT_EQ(resume.exit_code, 0) << resume.err;
  EXPECT_NE(resume.err.find("every channel's rows start at the checkpoint's time, 0.02 s"),
            std::string::npos)
      << resume.err;
  const std::string csv = ReadText(fs::path(Out("more")) / "timeseries.csv");
  EXPECT_NE(csv.find("occupant.head.position.x"), std::string::npos);
  EXPECT_NE(csv.find("\n0.02,"), std::string::npos);  // the first row is the checkpoint's time
  // The criteria saw 20 ms to 40 ms only: they are not judged.
  EXPECT_NE(resume.err.find("incomplete: over 20 ms to 40 ms of the run only"), std::string::npos)
      << resume.err;
  EXPECT_EQ(resume.err.find(": pass"), std::string::npos) << resume.err;
}

TEST_F(CheckpointTest, AMovedOutputPointRestartsTheRowsInsteadOfMixingTwoPoints) {
  // The same channel names, another point: rows before the checkpoint are of the old point.
  const std::string scene =
      Write("scene.sled", FlagshipScene("40 ms", "    position occupant.head at (0, 0, 0) mm\n"));
  ASSERT_EQ(Sled({"run", scene, "-o", Out("full"), "--checkpoint-every", "20ms"}).exit_code, 0);
  const std::string moved =
      Write("moved.sled", FlagshipScene("40 ms", "    position occupant.head at (0, 0, 100) mm\n"));
  const SledResult resume = Sled(
      {"run", moved, "-o", Out("moved"), "--resume", Out("full") + "/checkpoint_0.020000s.bin"});
  ASSERT_EQ(resume.exit_code, 0) << resume.err;
  const std::string csv = ReadText(fs::path(Out("moved")) / "timeseries.csv");
  EXPECT_EQ(csv.find("\n0,"), std::string::npos) << "rows before the checkpoint were kept";
  EXPECT_NE(csv.find("\n0.02,"), std::string::npos);
}

TEST_F(CheckpointTest, AnAddedCriterionResumesWithIncompleteCriteria) {
  const std::string scene = Write("scene.sled", Scene("40 ms"));
  ASSERT_EQ(Sled({"run", scene, "-o", Out("full"), "--checkpoint-every", "20ms"}).exit_code, 0);
  std::string text = ReadText(scene);
  const std::string criteria = "criteria = hic15(occupant.head)";
  ASSERT_NE(text.find(criteria), std::string::npos);
  text.replace(text.find(criteria), criteria.size(),
               "criteria = hic36(occupant.head), hic15(occupant.head)");
  const std::string more = Write("more.sled", text);
  const SledResult resume =
      Sled({"run", more, "-o", Out("more"), "--resume", Out("full") + "/checkpoint_0.020000s.bin"});
  ASSERT_EQ(resume.exit_code, 0) << resume.err;
  EXPECT_NE(resume.err.find("hic36(occupant.head) = "), std::string::npos) << resume.err;
  EXPECT_NE(resume.err.find("incomplete: over 20 ms to 40 ms"), std::string::npos);
}

TEST_F(CheckpointTest, AnIncompatibleSceneOrFileIsRefused) {
  const std::string scene = Write("scene.sled", Scene("40 ms"));
  ASSERT_EQ(Sled({"run", scene, "-o", Out("full"), "--checkpoint-every", "20ms"}).exit_code, 0);
  const std::string checkpoint = Out("full") + "/checkpoint_0.020000s.bin";

  SledResult result =
      Sled({"run", scene, "-o", Out("a"), "--set", "speed=50 km/h", "--resume", checkpoint});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("is not the one the checkpoint was made from"), std::string::npos)
      << result.err;

  result = Sled({"run", Write("dopri.sled", Scene("40 ms", "dopri5")), "-o", Out("b"), "--resume",
                 checkpoint});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("the integrator settings changed"), std::string::npos) << result.err;

  const std::string bytes = ReadText(checkpoint);
  WriteText(temp() / "cut.bin", bytes.substr(0, bytes.size() / 2));
  result = Sled({"run", scene, "-o", Out("c"), "--resume", (temp() / "cut.bin").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("truncated or damaged"), std::string::npos) << result.err;

  // One changed byte anywhere, here in the middle of the saved state, is found by the checksum
  // (before it, 57 of 60 random single-byte changes resumed with exit 0).
  std::string flipped = bytes;
  flipped[flipped.size() / 2] ^= 0x01;
  WriteText(temp() / "flipped.bin", flipped);
  result = Sled({"run", scene, "-o", Out("f"), "--resume", (temp() / "flipped.bin").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("its checksum does not match"), std::string::npos) << result.err;

  WriteText(temp() / "old.bin", "sled checkpoint 1\n" + bytes.substr(bytes.find('\n') + 1));
  result = Sled({"run", scene, "-o", Out("g"), "--resume", (temp() / "old.bin").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("is a checkpoint of another format (`sled checkpoint 1`)"),
            std::string::npos)
      << result.err;

  result = Sled({"run", scene, "-o", Out("d"), "--resume", scene});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("is not a sled checkpoint"), std::string::npos) << result.err;

  result = Sled({"run", scene, "-o", Out("e"), "--checkpoint-every", "0.15ms"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("not a multiple of the output step"), std::string::npos) << result.err;

  result = Sled({"run", scene, "-o", Out("f"), "--checkpoint-every", "soon"});
  EXPECT_EQ(result.exit_code, 2);
}

TEST_F(CheckpointTest, TheScenesRestartBlockWritesAndResumes) {
  // `restart { checkpoint_every }` writes checkpoints; `resume_from` (relative to the scene's
  // folder) continues from one, bit for bit.
  std::string scene = Scene("40 ms");
  const std::size_t integrator = scene.find("  integrator ");
  ASSERT_NE(integrator, std::string::npos);
  std::string writing = scene;
  writing.insert(integrator, "  restart { checkpoint_every = 20 ms }\n");
  ASSERT_EQ(Sled({"run", Write("writing.sled", writing), "-o", Out("written")}).exit_code, 0);
  EXPECT_TRUE(fs::exists(fs::path(Out("written")) / "checkpoint_0.020000s.bin"));
  std::string resuming = scene;
  resuming.insert(integrator, "  restart { resume_from = \"written/checkpoint_0.020000s.bin\" }\n");
  const SledResult resume = Sled({"run", Write("resuming.sled", resuming), "-o", Out("resumed")});
  ASSERT_EQ(resume.exit_code, 0) << resume.err;
  EXPECT_EQ(ReadText(fs::path(Out("resumed")) / "timeseries.csv"),
            ReadText(fs::path(Out("written")) / "timeseries.csv"));
}

TEST_F(CheckpointTest, ALoopOfConstraintsResumesBitForBit) {
  // The four-bar's KLU refactorizations reuse the pivots of the last fresh factorization: the
  // checkpoint keeps them.
  const std::string scene = (kSourceRoot / "examples" / "four_bar.sled").string();
  ASSERT_EQ(Sled({"run", scene, "-o", Out("full"), "--checkpoint-every", "1s"}).exit_code, 0);
  const SledResult resume = Sled(
      {"run", scene, "-o", Out("resumed"), "--resume", Out("full") + "/checkpoint_1.000000s.bin"});
  ASSERT_EQ(resume.exit_code, 0) << resume.err;
  EXPECT_EQ(ReadText(fs::path(Out("resumed")) / "timeseries.csv"),
            ReadText(fs::path(Out("full")) / "timeseries.csv"));
}

}  // namespace
}  // namespace sled::testing
