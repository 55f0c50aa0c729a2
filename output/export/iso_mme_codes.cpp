#include "output/export/iso_mme_codes.h"

#include <algorithm>
#include <set>
#include <string_view>

#include <fmt/format.h>

#include "output/post/channel_filters.h"
#include "runtime/model/dummy_types.h"
#include "runtime/run/outputs.h"

namespace sled::runtime {
namespace {

// Name words and the main location (and fine location 1) they give, tried in this order, so a
// longer word comes before one it contains (knee_bolster before knee).
struct LocationWord {
  std::string_view word;
  std::string_view location;
  std::string_view fine = "00";
};
constexpr LocationWord kLocationWords[] = {
    {"neck_upper", "NECK", "UP"},
    {"upper_neck", "NECK", "UP"},
    {"neck_lower", "NECK", "LO"},
    {"lower_neck", "NECK", "LO"},
    {"head_restraint", "HERE"},
    {"knee_bolster", "KNBO"},
    {"seat_pan", "SEPN"},
    {"seat_back", "SEBA"},
    {"toe_board", "FOWE"},
    {"instrument_panel", "DASB"},
    {"dashboard", "DASB"},
    {"windshield", "WIND"},
    {"wheel", "STWL"},
    {"steering", "STWL"},
    {"airbag", "AIRB"},
    {"buckle", "BCKL"},
    {"seat", "SEAT"},
    {"door", "DOOR"},
    {"bumper", "BUMP"},
    {"hood", "HOOD"},
    {"bonnet", "HOOD"},
    {"fender", "FEND"},
    {"a_pillar", "APIL"},
    {"pole", "POLE"},
    {"barrier", "FBAR"},
    {"neck", "NECK"},
    {"head", "HEAD"},
    {"thorax", "CHST"},
    {"chest", "CHST"},
    {"upper_torso", "CHST"},
    {"sternum", "STRN"},
    {"abdomen", "ABDO"},
    {"lumbar", "LUSP"},
    {"spine", "SPIN"},
    {"pelvis", "PELV"},
    {"lower_torso", "PELV"},
    {"upper_leg", "FEMR"},
    {"thigh", "FEMR"},
    {"femur", "FEMR"},
    {"knee", "KNEE"},
    {"lower_leg", "TIBI"},
    {"shank", "TIBI"},
    {"tibia", "TIBI"},
    {"ankle", "ANKL"},
    {"foot", "FOOT"},
    {"shoulder", "SHLD"},
    {"upper_arm", "UPAR"},
    {"elbow", "ELBJ"},
    {"lower_arm", "FOAR"},
    {"forearm", "FOAR"},
    {"wrist", "WRIS"},
    {"sled", "SLED"},
};

struct Location {
  std::string main = "0000";
  std::string fine = "00";
};

std::vector<std::string> Words(const std::string& label) {
  std::vector<std::string> words;
  std::size_t start = 0;
  while (start <= label.size()) {
    const std::size_t dot = std::min(label.find('.', start), label.size());
    words.push_back(label.substr(start, dot - start));
    start = dot + 1;
  }
  return words;
}

// The location of a dotted label: the last word that names one, and the side from any word.
// The first `skip` words are not read, unless they are all there is (a surface's module alias
// is no location: `buck.knee_bolster` is a knee bolster, a plane `bumper` a bumper).
Location LocationOf(const std::string& label, std::size_t skip = 0) {
  Location location;
  std::vector<std::string> words = Words(label);
  skip = std::min(skip, words.size() - 1);
  words.erase(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(skip));
  bool found = false;
  for (auto word = words.rbegin(); word != words.rend() && !found; ++word) {
    for (const LocationWord& entry : kLocationWords) {
      if (word->find(entry.word) == std::string::npos) continue;
      location.main = entry.location;
      location.fine = entry.fine;
      found = true;
      break;
    }
  }
  if (location.fine == "00") {
    for (const std::string& word : words) {
      const bool left = word.ends_with("_l") || word.find("left") != std::string::npos;
      const bool right = word.ends_with("_r") || word.find("right") != std::string::npos;
      if (left != right) {
        location.fine = left ? "LE" : "RI";
        break;
      }
    }
  }
  return location;
}

// Each body's place: its first word among the segments' names, in order (1 to 9, then 0).
class Positions {
 public:
  explicit Positions(const Model& model) {
    for (std::size_t s = 0; s < model.nsegment(); ++s) {
      const std::string& name = model.segment_name[s];
      const std::string body = name.substr(0, name.find('.'));
      if (std::find(bodies_.begin(), bodies_.end(), body) != bodies_.end()) continue;
      bodies_.push_back(body);
      dummies_.emplace_back(s < model.segment_dummy.size() ? model.segment_dummy[s]
                                                           : std::string(kNoDummyCode));
    }
  }
  char Of(const std::string& label) const {
    const std::size_t at = Find(label);
    if (at == bodies_.size()) return '0';
    return at < 9 ? static_cast<char>('1' + at) : '0';
  }
  // Fine location 3: the dummy type of the label's body (00 for none, and for no body).
  std::string_view DummyOf(const std::string& label) const {
    const std::size_t at = Find(label);
    return at == bodies_.size() ? kNoDummyCode : std::string_view(dummies_[at]);
  }

 private:
  std::size_t Find(const std::string& label) const {
    const std::string first = label.substr(0, label.find('.'));
    return static_cast<std::size_t>(std::find(bodies_.begin(), bodies_.end(), first) -
                                    bodies_.begin());
  }
  std::vector<std::string> bodies_;
  std::vector<std::string> dummies_;
};

struct Quantity {
  const char* dimension;
  const char* unit;
  bool world_frame;
};

Quantity QuantityOf(Model::OutputKind kind, std::size_t mechanism) {
  switch (kind) {
    case Model::OutputKind::kAcceleration:
      return {"AC", "m/(s*s)", false};
    case Model::OutputKind::kVelocity:
      return {"VE", "m/s", true};
    case Model::OutputKind::kPosition:
      return {"DS", "m", true};
    case Model::OutputKind::kAngularAcceleration:
      return {"AA", "rad/(s*s)", false};
    case Model::OutputKind::kAngularVelocity:
      return {"AV", "rad/s", false};
    case Model::OutputKind::kOrientation:
      return {"AN", "rad", true};
    case Model::OutputKind::kJointAngle:
      return mechanism == 1 ? Quantity{"DS", "m", false} : Quantity{"AN", "rad", false};
    case Model::OutputKind::kJointTorque:
      return {"MO", "Nm", false};
    case Model::OutputKind::kJointForce:
    case Model::OutputKind::kSpringForce:
    case Model::OutputKind::kBeltForce:
      return {"FO", "N", false};
    case Model::OutputKind::kContactForce:
      return {"FO", "N", true};
    case Model::OutputKind::kContactPoint:
    case Model::OutputKind::kContactDeflection:
      return {"DS", "m", true};
    case Model::OutputKind::kAirbagPressure:
      return {"PR", "Pa", false};
    case Model::OutputKind::kAirbagForce:
      return {"FO", "N", true};
    case Model::OutputKind::kAirbagVolume:
      return {"VU", "m*m*m", false};
    case Model::OutputKind::kAirbagGasMass:
      return {"MA", "kg", false};
    case Model::OutputKind::kAirbagTemperature:
      return {"TE", "K", false};
    case Model::OutputKind::kAirbagVentFlow:
      return {"MF", "kg/s", false};
  }
  return {"00", "", false};
}

// The direction letter of a channel from its component (the last word of its name), in SAE
// J211's axes: x forward, y right, z down. sled's y and z point left and up, so the data of a y or
// z component are negated (a half turn about x, which negates rotations about y and z too).
char DirectionOf(const std::string& component) {
  if (component == "x" || component == "roll" || component == "spin") return 'X';
  if (component == "y" || component == "pitch" || component == "nutation") return 'Y';
  if (component == "z" || component == "yaw" || component == "precession") return 'Z';
  return '0';
}
double SignOf(char direction) { return direction == 'Y' || direction == 'Z' ? -1.0 : 1.0; }

// The raw channels' filter class: sampled from the model at the output step, never filtered
// ("prefiltered above CFC 1000" in ISO/TS 13499's list, as labs read simulated data).
constexpr char kRawClass = 'P';

// A channel name without its unit: `occupant.head.acceleration.x`.
std::string WithoutUnit(const std::string& name) {
  const std::size_t bracket = name.find(" [");
  return bracket == std::string::npos ? name : name.substr(0, bracket);
}

// Codes handed out so far; a taken code gets the first free ordinal in fine location 2.
class CodeBook {
 public:
  std::string Take(std::string code) {
    for (int ordinal = 1; taken_.count(code) != 0 && ordinal <= 99; ++ordinal) {
      code.replace(8, 2, fmt::format("{:02}", ordinal));
    }
    taken_.insert(code);
    return code;
  }

 private:
  std::set<std::string> taken_;
};

std::string Code(char position, const Location& location, std::string_view fine2,
                 std::string_view dummy, std::string_view dimension, char direction, char filter) {
  return fmt::format("1{}{}{}{}{}{}{}{}", position, location.main, location.fine, fine2, dummy,
                     dimension, direction, filter);
}

// Criterion values as labs' tools look them up (ISO/TS 13499 RED B 1.6.2's calculation codes,
// as pyisomme's Euro NCAP and UN reports read them): HIC from the head's resultant acceleration,
// the 3 ms value as a cumulative (3C) or single-peak (3S) clip, Nij in position (IP) with its
// quadrants in fine location 2 (Nkm's likewise), peak neck and femur forces along z.
struct CriterionCode {
  std::string_view name;
  std::string_view location;
  std::string_view fine1;
  std::string_view fine2;
  std::string_view dimension;
  char direction;
};
constexpr CriterionCode kCriterionCodes[] = {
    {"hic15", "HICR", "00", "15", "00", 'R'},
    {"hic36", "HICR", "00", "36", "00", 'R'},
    {"head_3ms", "HEAD", "00", "3C", "AC", 'R'},
    {"chest_3ms", "CHST", "00", "3C", "AC", 'R'},
    {"gsi_head", "HEAD", "SI", "00", "00", 'R'},
    {"gsi_chest", "CHSI", "00", "00", "00", 'R'},
    {"nij", "NIJC", "IP", "00", "00", 'Y'},
    {"neck_tension", "NECK", "UP", "TN", "FO", 'Z'},
    {"neck_compression", "NECK", "UP", "CO", "FO", 'Z'},
    {"femur_load", "FEMR", "00", "00", "FO", 'Z'},
    {"viscous_criterion", "VCCR", "00", "00", "VE", 'X'},
    {"nkm", "NKMC", "00", "00", "00", 'Y'},
    {"nic", "NICR", "00", "00", "00", 'X'},          // a location of our own, as for nkm
    {"tti", "TTIN", "00", "00", "00", 'Y'},          // crash-conventions §2.8
    {"tibia_index", "TIIN", "00", "00", "00", 'R'},  // as pyisomme's calculate_tibia_index names it
};

}  // namespace

char FilterClassLetter(int cfc) {
  switch (cfc) {
    case 1000:
      return 'A';
    case 600:
      return 'B';
    case 180:
      return 'C';
    case 60:
      return 'D';
    default:
      return '0';
  }
}

IsoMmeCodes MapIsoMmeCodes(const Model& model, const TimeSeries& raw, const TimeSeries& filtered,
                           const std::vector<post::CriterionValue>& criteria) {
  IsoMmeCodes codes;
  CodeBook book;
  const Positions positions(model);
  std::vector<int> column_class(raw.names.size(), 0);
  const std::vector<std::size_t> first = post::GroupColumns(model);
  std::vector<int> belt_ordinal(raw.names.size(), 0);  // span or anchor, for belt channels
  for (std::size_t k = 0; k < model.output_kind.size(); ++k) {
    const Model::OutputKind kind = model.output_kind[k];
    const std::string& label = model.output_label[k];
    const std::size_t count = ChannelCount(model, k);
    const auto index = static_cast<std::size_t>(model.output_index[k]);
    const std::size_t mechanism =
        kind == Model::OutputKind::kJointAngle && model.joint_kind[index] == JointKind::kSlip ? 1
                                                                                              : 0;
    const Quantity quantity = QuantityOf(kind, mechanism);
    const int cfc = k < model.output_filter_class.size() ? model.output_filter_class[k] : 0;
    char position = positions.Of(label);
    std::string_view dummy = positions.DummyOf(label);
    Location location = LocationOf(label);
    const bool contact = kind == Model::OutputKind::kContactForce ||
                         kind == Model::OutputKind::kContactPoint ||
                         kind == Model::OutputKind::kContactDeflection;
    const ContactTable& pairs = model.contacts;
    if (contact && index < pairs.group_first.size() && pairs.group_count[index] > 0) {
      // The force on the surface the segment touches (the group's first pair's), where that
      // surface is (a bumper's force on a leg is no tibia load cell), or nowhere (0000) when its
      // name, past its first word, gives no location; the side still from the label.
      const auto pair = static_cast<std::size_t>(
          pairs.group_pairs[static_cast<std::size_t>(pairs.group_first[index])]);
      const auto second = static_cast<std::size_t>(pairs.pair_second[pair]);
      location.main = LocationOf(pairs.pair_kind[pair] == ContactTable::PairKind::kPlaneEllipsoid
                                     ? pairs.plane_name[second]
                                     : pairs.ellipsoid_name[second],
                                 1)
                          .main;
      if (location.fine == "UP" || location.fine == "LO") location.fine = "00";
    }
    if (kind == Model::OutputKind::kBeltForce) {
      // The body the belt first wraps gives the position.
      const BeltTable& belts = model.belts;
      for (std::int32_t i = 0; i < belts.point_count[index] && position == '0'; ++i) {
        const FrameRef& frame =
            belts.point_frame[static_cast<std::size_t>(belts.first_point[index]) +
                              static_cast<std::size_t>(i)];
        if (frame.kind == FrameRef::Kind::kSegment) {
          position = positions.Of(model.segment_name[static_cast<std::size_t>(frame.index)]);
          dummy = positions.DummyOf(model.segment_name[static_cast<std::size_t>(frame.index)]);
        }
      }
    }
    for (std::size_t c = 0; c < count && first[k] + c < raw.names.size(); ++c) {
      const std::size_t column = first[k] + c;
      column_class[column] = cfc;
      const std::string name = WithoutUnit(raw.names[column]);
      const std::string component = name.substr(name.rfind('.') + 1);
      char direction = DirectionOf(component);
      std::string fine2 = "00";
      Location channel_location = location;
      if (kind == Model::OutputKind::kBeltForce) {
        const auto spans = static_cast<std::size_t>(model.belts.span_count(index));
        if (c < spans) {  // a span's tension
          channel_location = {"SEBE", location.fine};
          fine2 = fmt::format("{:02}", c + 1);
          direction = '0';
        } else {  // the force on the first or last anchor
          channel_location = {"BAFI", location.fine};
          fine2 = c < spans + 3 ? "01" : "02";
        }
      }
      IsoMmeChannel channel;
      channel.code = book.Take(
          Code(position, channel_location, fine2, dummy, quantity.dimension, direction, kRawClass));
      channel.name = name;
      channel.unit = quantity.unit;
      channel.dimension = quantity.dimension;
      channel.direction = direction;
      channel.sign = SignOf(direction);
      channel.world_frame = quantity.world_frame;
      codes.raw.push_back(channel);
    }
    // A three-axis acceleration's resultant, raw and filtered (the components filtered first,
    // as J211 orders it): the channel labs read HIC and the 3 ms value from (11HEAD0000H3ACRA).
    if (kind == Model::OutputKind::kAcceleration && count == 3 && first[k] + 2 < raw.names.size()) {
      IsoMmeChannel resultant = codes.raw[first[k]];
      resultant.code =
          book.Take(Code(position, location, "00", dummy, quantity.dimension, 'R', kRawClass));
      const std::string x = WithoutUnit(raw.names[first[k]]);
      resultant.name = x.substr(0, x.rfind('.')) + ".resultant";
      resultant.direction = 'R';
      resultant.sign = 1.0;
      resultant.components = {first[k], first[k] + 1, first[k] + 2};
      codes.raw_resultants.push_back(resultant);
      std::vector<std::size_t> filtered_columns;
      for (std::size_t c = 0; c < 3; ++c) {
        const auto at =
            std::find(filtered.names.begin(), filtered.names.end(), raw.names[first[k] + c]);
        if (at != filtered.names.end()) {
          filtered_columns.push_back(static_cast<std::size_t>(at - filtered.names.begin()));
        }
      }
      if (filtered_columns.size() == 3) {
        IsoMmeChannel smooth = resultant;
        smooth.code = book.Take(
            Code(position, location, "00", dummy, quantity.dimension, 'R', FilterClassLetter(cfc)));
        smooth.components = filtered_columns;
        codes.filtered_resultants.push_back(smooth);
      }
    }
  }
  // A filtered channel: its raw channel's code with the class letter.
  for (const std::string& name : filtered.names) {
    const auto at = std::find(raw.names.begin(), raw.names.end(), name);
    IsoMmeChannel channel;
    if (at != raw.names.end()) {
      const auto column = static_cast<std::size_t>(at - raw.names.begin());
      channel = codes.raw[column];
      channel.code[15] = FilterClassLetter(column_class[column]);
    } else {  // not a raw channel's name: the filter keeps names, so never; an undefined code
      channel.code = "100000000000000P";
      channel.name = WithoutUnit(name);
    }
    channel.code = book.Take(channel.code);
    codes.filtered.push_back(channel);
  }
  for (const post::CriterionValue& value : criteria) {
    Location location;
    std::string fine2 = "00";
    std::string_view dimension = "00";
    char direction = 'R';
    for (const CriterionCode& entry : kCriterionCodes) {
      if (entry.name != value.name) continue;
      location = {std::string(entry.location), std::string(entry.fine1)};
      fine2 = entry.fine2;
      dimension = entry.dimension;
      direction = entry.direction;
    }
    if (location.main == "FEMR") location.fine = LocationOf(value.target).fine;
    if (value.variant == "continuous") fine2 = "3S";
    // Nij's quadrant terms NTE, NTF, NCE, NCF, and Nkm's NEA, NFA, NEP, NFP, in fine location 2.
    if ((value.name == "nij" || value.name == "nkm") && value.variant.size() == 3) {
      fine2 = value.variant.substr(1);
    }
    IsoMmeChannel channel;
    channel.code = book.Take(Code(positions.Of(value.target), location, fine2,
                                  positions.DummyOf(value.target), dimension, direction, 'X'));
    channel.name = fmt::format("{}({}){}", value.name, value.target,
                               value.variant.empty() ? "" : " " + value.variant);
    channel.unit = value.unit.empty() ? "1" : value.unit;  // an index has unit one
    channel.dimension = std::string(dimension);
    channel.direction = direction;
    codes.criteria.push_back(channel);
  }
  return codes;
}

}  // namespace sled::runtime
