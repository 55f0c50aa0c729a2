// `sled run --format iso-mme` on the flagship scene (cut to 30 ms) writes an ISO-MME data set; a
// reader written here, apart from the writer, reads it back and checks it against
// timeseries.csv, timeseries_filtered.csv and summary.json: the .mme file's ISO/TS 13499 fields,
// the index, the 16-character codes (the documented mapping for the channels labs look up
// first), units, sample counts, the sampling interval and every value, in SAE J211's axes (y and
// z negated), and the resultants of the accelerations. A bumper's force on a leg is coded as the
// bumper's, not as a tibia load cell.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/compiler/csv_table.h"
#include "tests/compiler/flagship_scene.h"
#include "tests/compiler/sled_process.h"

namespace sled {
namespace {

namespace fs = std::filesystem;
using testing::CsvTable;
using testing::ReadCsv;
using testing::ReadText;
using testing::SledResult;
using testing::WriteText;

// One ISO-MME file: the `Name(28 characters):value` header lines (a name may repeat), then the
// lines after the header (a channel's samples).
struct IsoFile {
  std::multimap<std::string, std::string> fields;
  std::vector<std::string> data;
  std::string Get(const std::string& name) const {
    const auto at = fields.find(name);
    return at == fields.end() ? "<missing>" : at->second;
  }
};

IsoFile ReadIsoFile(const fs::path& path) {
  IsoFile file;
  std::istringstream in(ReadText(path));
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (header && line.size() > 28 && line[28] == ':') {
      std::string name = line.substr(0, 28);
      name.erase(name.find_last_not_of(' ') + 1);
      file.fields.emplace(name, line.substr(29));
      continue;
    }
    header = false;
    file.data.push_back(line);
  }
  return file;
}

class IsoMmeExport : public testing::SledProcessTest {
 protected:
  // `sled run --format iso-mme` of the scene written as NAME.sled in the test's folder: the
  // codes its channel index lists.
  std::set<std::string> RunCodes(const std::string& name) {
    const fs::path out = temp() / "out";
    const SledResult result = Sled(
        {"run", (temp() / (name + ".sled")).string(), "-o", out.string(), "--format", "iso-mme"});
    EXPECT_EQ(result.exit_code, 0) << result.err;
    const IsoFile index = ReadIsoFile(out / "iso-mme" / "Channel" / (name + ".chn"));
    std::set<std::string> codes;
    for (const auto& [field, value] : index.fields) {
      if (field.rfind("Name of channel", 0) == 0) codes.insert(value.substr(0, 16));
    }
    return codes;
  }
};

// The unit ISO-MME writes for a CSV column's unit.
std::string IsoUnit(const std::string& csv_name) {
  std::string unit =
      csv_name.substr(csv_name.find('[') + 1, csv_name.find(']') - csv_name.find('[') - 1);
  if (unit == "m/s^2") return "m/(s*s)";
  if (unit == "rad/s^2") return "rad/(s*s)";
  if (unit == "N*m") return "Nm";
  if (unit == "m^3") return "m*m*m";
  return unit;
}

std::string WithoutUnit(const std::string& name) { return name.substr(0, name.find(" [")); }

double SummaryValue(const std::string& summary, const std::string& name) {
  std::smatch match;
  const std::regex pattern("\\{\"name\": \"" + name +
                           "\", \"variant\": \"\"[^\\n]*\"value\": ([-0-9.eE+]+)");
  return std::regex_search(summary, match, pattern) ? std::stod(match[1]) : std::nan("");
}

TEST_F(IsoMmeExport, TheFlagshipSetReadsBackWithItsCodesUnitsAndValues) {
  const std::string scene = testing::FlagshipScene("30 ms");
  ASSERT_FALSE(scene.empty());
  WriteText(temp() / "frontal sled.sled", scene);
  const fs::path out = temp() / "out";
  const SledResult result = Sled(
      {"run", (temp() / "frontal sled.sled").string(), "-o", out.string(), "--format", "iso-mme"});
  ASSERT_EQ(result.exit_code, 0) << result.err;

  // The test name is the file's stem, with the space replaced.
  const fs::path set = out / "iso-mme";
  const IsoFile mme = ReadIsoFile(set / "frontal_sled.mme");
  // The header's ISO/TS 13499 (RED A 1.6) field names, as labs' tools read them.
  EXPECT_EQ(mme.Get("Data format edition number"), "1.6");
  EXPECT_EQ(mme.Get("Laboratory test ref. number"), "frontal_sled");
  EXPECT_EQ(mme.Get("Type of the test"), "Simulation");
  EXPECT_TRUE(std::regex_match(mme.Get("Date of the test"), std::regex("\\d{4}-\\d{2}-\\d{2}")));
  EXPECT_EQ(mme.Get("Title"), "frontal sled, belted driver, 56 km/h");
  EXPECT_EQ(mme.Get("Number of test objects"), "1");
  for (const char* own : {"Data format", "Version", "Test number", "Test date", "Test type"}) {
    EXPECT_EQ(mme.Get(own), "<missing>") << own;
  }

  const CsvTable raw = ReadCsv(out / "timeseries.csv");
  const CsvTable filtered = ReadCsv(out / "timeseries_filtered.csv");
  const std::string summary = ReadText(out / "summary.json");
  ASSERT_EQ(raw.rows.size(), 301u);  // 30 ms at 0.1 ms
  ASSERT_GT(filtered.names.size(), 1u);
  std::size_t criteria = 0;  // summary.json's criterion values, one `{"name": ` each
  for (std::size_t at = summary.find("{\"name\": "); at != std::string::npos;
       at = summary.find("{\"name\": ", at + 1)) {
    ++criteria;
  }

  const IsoFile index = ReadIsoFile(set / "Channel" / "frontal_sled.chn");
  const std::size_t channels = std::stoul(index.Get("Number of channels"));
  // Every acceleration request has three components, raw and filtered, and a resultant of each.
  std::size_t accelerations = 0;
  for (const std::string& name : raw.names)
    accelerations += name.find(".acceleration.x [") != std::string::npos;
  EXPECT_EQ(channels,
            (raw.names.size() - 1) + (filtered.names.size() - 1) + 2 * accelerations + criteria);

  std::set<std::string> codes;
  std::map<std::string, std::string> code_of;  // by "name/class"
  std::size_t raw_seen = 0, filtered_seen = 0, criteria_seen = 0, resultants_seen = 0;
  for (std::size_t n = 1; n <= channels; ++n) {
    const std::string number = fmt::format("{:03}", n);
    const std::string entry = index.Get("Name of channel " + number);
    const IsoFile channel = ReadIsoFile(set / "Channel" / ("frontal_sled." + number));
    const std::string code = channel.Get("Channel code");
    SCOPED_TRACE(fmt::format("{} {}", code, entry));
    ASSERT_TRUE(std::regex_match(code, std::regex("[0-9A-Z]{16}")));
    EXPECT_TRUE(codes.insert(code).second) << "a repeated code";
    const std::string name = channel.Get("Name of the channel");
    EXPECT_EQ(entry, fmt::format("{} / {}", code, name));
    EXPECT_EQ(channel.Get("Data source"), "calculation");
    EXPECT_EQ(channel.Get("Reference channel"), "implicit");
    const char filter = code[15];
    if (filter == 'X') {  // a criterion: one sample
      ++criteria_seen;
      EXPECT_EQ(channel.Get("Number of samples"), "1");
      ASSERT_EQ(channel.data.size(), 1u);
      code_of[name] = code;
      if (name == "hic15(occupant.head)") {
        EXPECT_EQ(std::stod(channel.data[0]), SummaryValue(summary, "hic15"));
      }
      continue;
    }
    const bool is_raw = filter == 'P';
    const CsvTable& table = is_raw ? raw : filtered;
    if (name.ends_with(".resultant")) {  // the root sum of squares of the x, y, z columns
      ++resultants_seen;
      code_of[name + (is_raw ? "/raw" : "/filtered")] = code;
      EXPECT_EQ(code[14], 'R');
      const std::string stem = name.substr(0, name.size() - std::string("resultant").size());
      std::vector<std::size_t> xyz;
      for (const char* axis : {"x", "y", "z"}) {
        for (std::size_t c = 1; c < table.names.size(); ++c) {
          if (WithoutUnit(table.names[c]) == stem + axis) xyz.push_back(c);
        }
      }
      ASSERT_EQ(xyz.size(), 3u) << stem;
      ASSERT_EQ(channel.data.size(), table.rows.size());
      for (std::size_t row = 0; row < table.rows.size(); ++row) {
        const std::vector<double>& r = table.rows[row];
        const double expected =
            std::sqrt(r[xyz[0]] * r[xyz[0]] + r[xyz[1]] * r[xyz[1]] + r[xyz[2]] * r[xyz[2]]);
        ASSERT_NEAR(std::strtod(channel.data[row].c_str(), nullptr), expected,
                    1e-12 * std::max(1.0, expected))
            << "row " << row;
      }
      continue;
    }
    std::size_t column = table.names.size();
    for (std::size_t c = 1; c < table.names.size(); ++c) {
      if (WithoutUnit(table.names[c]) == name) column = c;
    }
    ASSERT_LT(column, table.names.size()) << "no CSV column for " << name;
    (is_raw ? raw_seen : filtered_seen) += 1;
    code_of[name + (is_raw ? "/raw" : "/filtered")] = code;
    EXPECT_EQ(channel.Get("Unit"), IsoUnit(table.names[column]));
    EXPECT_EQ(channel.Get("Sampling interval"), "0.0001");
    EXPECT_EQ(channel.Get("Time of first sample"), "0");
    EXPECT_EQ(channel.Get("Channel frequency class"), is_raw          ? "NOVALUE"
                                                      : filter == 'A' ? "1000"
                                                      : filter == 'B' ? "600"
                                                      : filter == 'C' ? "180"
                                                                      : "60");
    ASSERT_EQ(std::stoul(channel.Get("Number of samples")), table.rows.size());
    ASSERT_EQ(channel.data.size(), table.rows.size());
    // SAE J211's axes: a y or z component is sled's negated (its y and z point left and up).
    const char direction = code[14];
    EXPECT_TRUE(std::string("XYZR0").find(direction) != std::string::npos) << direction;
    const double sign = direction == 'Y' || direction == 'Z' ? -1.0 : 1.0;
    for (std::size_t row = 0; row < table.rows.size(); ++row) {
      // Both files hold the shortest text of the same double.
      ASSERT_EQ(std::strtod(channel.data[row].c_str(), nullptr), sign * table.rows[row][column])
          << "row " << row;
    }
  }
  EXPECT_EQ(raw_seen, raw.names.size() - 1);
  EXPECT_EQ(filtered_seen, filtered.names.size() - 1);
  EXPECT_EQ(criteria_seen, criteria);
  EXPECT_EQ(resultants_seen, 2 * accelerations);

  // The documented mapping (docs/outputs.md) for channels a crash engineer looks for first.
  // (pyisomme's Euro NCAP and UN R137 reports look them up as `?pHEAD??00??ACRA`,
  // `?pHICR0015??00RX`, `?pHEAD003C??ACRX`, `?pNECKUP00??FOZ?`.)
  EXPECT_EQ(code_of["occupant.head.acceleration.x/raw"], "11HEAD0000H3ACXP");
  EXPECT_EQ(code_of["occupant.head.acceleration.x/filtered"], "11HEAD0000H3ACXA");
  EXPECT_EQ(code_of["occupant.head.acceleration.resultant/raw"], "11HEAD0000H3ACRP");
  EXPECT_EQ(code_of["occupant.head.acceleration.resultant/filtered"], "11HEAD0000H3ACRA");
  EXPECT_EQ(code_of["occupant.thorax.acceleration.z/filtered"], "11CHST0000H3ACZA");
  EXPECT_EQ(code_of["occupant.neck_upper.joint_force.z/filtered"], "11NECKUP00H3FOZA");
  EXPECT_EQ(code_of["occupant.neck_upper.joint_torque.y/filtered"], "11NECKUP00H3MOYB");
  EXPECT_EQ(code_of["occupant.upper_leg_l.buck.knee_bolster.contact_force.normal/raw"],
            "11KNBOLE00H3FO0P");
  EXPECT_EQ(code_of["three_point.lap.belt_force.span1/raw"], "11SEBE0001H3FO0P");
  EXPECT_EQ(code_of["hic15(occupant.head)"], "11HICR0015H300RX");
  EXPECT_EQ(code_of["nij(occupant.neck_upper)"], "11NIJCIP00H300YX");
  EXPECT_EQ(code_of["head_3ms(occupant.head) cumulative"], "11HEAD003CH3ACRX");
  EXPECT_EQ(code_of["head_3ms(occupant.head) continuous"], "11HEAD003SH3ACRX");
  for (const auto& [name, code] : code_of) {
    EXPECT_EQ(code.find_first_of("123", 14), std::string::npos) << name << " " << code;
  }
}

// A pedestrian's leg struck by a bumper: the contact force is the bumper's (BUMP), on the left
// (the leg's side), never a tibia load cell (TIBI), whatever segment it acts on.
TEST_F(IsoMmeExport, ABumpersForceOnALegIsCodedAsTheBumpers) {
  WriteText(temp() / "bumper.sled", R"(scenario "bumper" {
  gravity = (0, 0, 0) m/s^2
  time { end = 5 ms  output_every = 0.1 ms }
  vehicle car { velocity = (-10, 0, 0) m/s }
  body walker {
    segment lower_leg_l {
      mass = 3 kg
      inertia = (0.04, 0.04, 0.004) kg*m^2
      ellipsoid { semi_axes = (50, 50, 200) mm }
    }
  }
  plane bumper on car { corners = (0, -1, -1) m, (0, -1, 1) m, (0, 1, -1) m }
  contact walker.lower_leg_l with bumper { force = 100 kN/m }
  initial car { position = (0.06, 0, 0) m }
  output { contact_force walker.lower_leg_l with bumper }
})");
  const std::set<std::string> codes = RunCodes("bumper");
  EXPECT_TRUE(codes.count("11BUMPLE0000FOXP")) << ::testing::PrintToString(codes);
  EXPECT_TRUE(codes.count("11BUMPLE0000FO0P")) << ::testing::PrintToString(codes);
  for (const std::string& code : codes) EXPECT_EQ(code.find("TIBI"), std::string::npos) << code;
}

// Each body's `dummy` is fine location 3 of its channels' codes and its criteria's: a THOR's
// are TH, a Hybrid III 5th female's HF, a body that names none 00.
TEST_F(IsoMmeExport, EachBodysDummyTypeIsInItsCodes) {
  WriteText(temp() / "dummies.sled", R"(scenario "dummies" {
  gravity = (0, 0, 0) m/s^2
  time { end = 5 ms  output_every = 0.1 ms }
  vehicle car { velocity = (-10, 0, 0) m/s }
  body walker {
    dummy = thor
    segment lower_leg_l {
      mass = 3 kg
      inertia = (0.04, 0.04, 0.004) kg*m^2
      ellipsoid { semi_axes = (50, 50, 200) mm }
    }
  }
  body small {
    dummy = hybrid3_5f
    segment head { mass = 4 kg  inertia = (0.02, 0.02, 0.02) kg*m^2 }
  }
  body plain {
    segment head { mass = 4 kg  inertia = (0.02, 0.02, 0.02) kg*m^2 }
  }
  plane bumper on car { corners = (0, -1, -1) m, (0, -1, 1) m, (0, 1, -1) m }
  contact walker.lower_leg_l with bumper { force = 100 kN/m }
  initial car { position = (0.06, 0, 0) m }
  initial small { position = (0, 1, 0) m }
  initial plain { position = (0, 2, 0) m }
  output {
    contact_force walker.lower_leg_l with bumper
    acceleration small.head at (0, 0, 0) mm
    acceleration plain.head at (0, 0, 0) mm
    criteria = hic15(small.head)
  }
})");
  const std::set<std::string> codes = RunCodes("dummies");
  const std::string all = ::testing::PrintToString(codes);
  EXPECT_TRUE(codes.count("11BUMPLE00THFOXP")) << all;
  EXPECT_TRUE(codes.count("12HEAD0000HFACXP")) << all;
  EXPECT_TRUE(codes.count("12HEAD0000HFACRP")) << all;
  EXPECT_TRUE(codes.count("13HEAD000000ACXP")) << all;
  EXPECT_TRUE(codes.count("12HICR0015HF00RX")) << all;
}

}  // namespace
}  // namespace sled
