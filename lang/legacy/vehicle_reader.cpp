// C cards (INPUT_VEHICLE): the vehicles, the body segments whose motion a card prescribes (MSEG),
// and the checks of IVFLG, IVREF and MSEG that ATB stops on (STOPs 6, 7, 263 to 266).
#include "lang/legacy/vehicle_reader.h"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "lang/legacy/body_reader.h"

namespace sled::lang::legacy {
namespace {

constexpr int kMaxVehicles = 6;

// C.2.a 67-70: IVFLG (-2 to 2) and IVREF (0 to MAXSEG), ATB's STOPs 263, 265 and 266. IVREF 0
// with |IVFLG| = 2 is the ground (VINITL and VEHPOS then take the card's motion as absolute,
// as for IVFLG 0); motion relative to another frame is refused.
void ReadReference(DeckFields& f, const Card& card, int ivflg, int ivref) {
  if (ivflg < -2 || ivflg > 2) {
    f.Invalid(card, 67, 68, fmt::format("IVFLG is {}", ivflg),
              "IVFLG is -2 to 2 (ATB: STOP 263 in INPUT_VEHICLE)");
  } else if (ivref < 0 || ivref > kMaxSegments) {
    f.Invalid(card, 69, 70, fmt::format("IVREF is {}", ivref),
              fmt::format("IVREF is a segment number, 0 to {} (ATB: STOP 265)", kMaxSegments));
  } else if (ivref != 0 && ivflg == 0) {
    f.Invalid(card, 69, 70, fmt::format("IVREF is {} with IVFLG 0", ivref),
              "a reference segment needs IVFLG 1 or 2 (ATB: STOP 266)");
  } else if (ivref != 0) {
    f.Refuse(
        card, 67, 70,
        fmt::format("IVFLG {} with IVREF {}: motion relative to segment {}", ivflg, ivref, ivref),
        "sled's vehicles move relative to the ground; with IVREF 0 and IVFLG 2 the motion "
        "is the ground's");
  } else if (ivflg == 1 || ivflg == -1) {
    f.Refuse(card, 67, 68,
             fmt::format("IVFLG {}: the ground's motion seen from the vehicle", ivflg),
             "VINITL and VEHPOS reverse the card's motion, and VINO12, which gives its "
             "direction, is not in the reference; write the vehicle's own motion with IVFLG 0");
  }
}

// C.2.a 71-72, MSEG: 0 ends the list with the primary vehicle; above NSEG, the next vehicle
// segment (ATB's STOP 6 when out of order); 1 to NSEG, a body segment whose motion the card
// prescribes. False after the primary vehicle.
bool PlaceVehicle(DeckFields& f, const Card& card, VehicleCard vehicle) {
  Deck& deck = f.deck();
  const int segments = static_cast<int>(deck.segments.size());
  const int mseg = vehicle.segment;
  if (mseg == 0) {
    deck.vehicles.push_back(std::move(vehicle));
    return false;
  }
  if (mseg < 0 || mseg > kMaxSegments - 1) {
    f.Invalid(card, 71, 72, fmt::format("MSEG is {}", mseg),
              fmt::format("MSEG is 0 (the primary vehicle), a body segment 1 to {} or the next "
                          "vehicle segment (ATB: STOP 264)",
                          segments));
    return false;  // read on as after the primary vehicle: no cascade from the D cards
  }
  if (mseg <= segments) {
    const auto joint = static_cast<std::size_t>(mseg - 2);
    const auto earlier =
        std::find_if(deck.prescribed_segments.begin(), deck.prescribed_segments.end(),
                     [&](const VehicleCard& other) { return other.segment == mseg; });
    if (earlier != deck.prescribed_segments.end()) {
      f.Refuse(card, 71, 72,
               fmt::format("MSEG is {}: segment {} is prescribed by the C card of line {} too",
                           mseg, mseg, earlier->line),
               "ATB's VEHPOS gives the segment the later card's acceleration over the earlier "
               "one's; keep one card for it");
    } else if (mseg > 1 && joint < deck.joints.size() && deck.joints[joint].parent != 0) {
      f.Refuse(card, 71, 72,
               fmt::format("MSEG is {}: segment {} hangs from joint {}, and its motion is "
                           "prescribed",
                           mseg, mseg, mseg - 1),
               "sled prescribes the motion of a reference segment (segment 1, or one that a "
               "B.3.a JNT of 0 starts), welded to a vehicle of the card's motion; number the "
               "body from the prescribed segment");
    } else {
      f.Unverified(card, 71, 72,
                   fmt::format("MSEG is {}: segment {} moves with the card's motion, welded to a "
                               "vehicle placed at X0 with the card's yaw, pitch and roll, as "
                               "INPUT_VEHICLE's initial state for it says; its G.2 and G.3.a "
                               "cards are not used",
                               mseg, mseg));
      deck.prescribed_segments.push_back(std::move(vehicle));
    }
  } else if (const int next = segments + static_cast<int>(deck.vehicles.size()) + 1; mseg != next) {
    f.Invalid(card, 71, 72, fmt::format("MSEG is {}", mseg),
              fmt::format("a vehicle segment takes the next number, {} (ATB: STOP 6)", next));
  } else {
    deck.vehicles.push_back(std::move(vehicle));
  }
  return true;
}

}  // namespace

void ReadVehicles(DeckFields& f) {
  DeckSource& r = f.source();
  Deck& deck = f.deck();
  std::optional<Card> last;
  for (int v = 0; v < kMaxVehicles && !r.truncated(); ++v) {
    const Card title = r.Next(fmt::format("C.1 (vehicle {})", v + 1), {"(A80)"});
    const Card card = r.Next(fmt::format("C.2.a (vehicle {})", v + 1), {"(8F6.0,I6,2F6.0,3I2)"});
    VehicleCard vehicle;
    vehicle.line = card.line;
    vehicle.title = r.Text(title, 1, 80);
    vehicle.orientation = f.Triple(card, 1, 6, "yaw, pitch and roll of the vehicle");
    vehicle.speed = r.Real(card, 19, 24, "VIPS, the initial speed in mph");
    vehicle.duration = r.Real(card, 25, 30, "VTIME, the pulse duration");
    vehicle.position = f.Triple(card, 31, 6, "X0, the initial position");
    const int points = r.Integer(card, 49, 54, "NATAB, the number of table points");
    r.Real(card, 55, 60, "AT0, the table's start time");
    r.Real(card, 61, 66, "ADT, the table's spacing");
    const int ivflg = r.Integer(card, 67, 68, "IVFLG, the reference flag");
    const int ivref = r.Integer(card, 69, 70, "IVREF, the reference segment");
    vehicle.segment = r.Integer(card, 71, 72, "MSEG, the vehicle segment");
    if (points != 0) {
      f.Refuse(card, 49, 54, fmt::format("NATAB is {}: a tabulated pulse", points),
               "the layout of the C.3 table cards is not in the reference (VINO12 and VINO34, "
               "which read them, are not; VEHPOS shows only that NATAB > 0 is one deceleration "
               "in G every ADT from AT0 and NATAB < 0 six tables); convert the pulse into a "
               "`motion = table(...)` by hand");
    } else {
      f.Unverified(card, 19, 30,
                   fmt::format("a half-sine pulse: VIPS is read in mph (the V.3 input "
                               "description's unit, 1 mph = 0.44704 m/s) and VTIME in {} "
                               "(UNITT); its direction AX and frequency come from VINO12, which "
                               "the reference does not have; sled assumes an initial velocity "
                               "VIPS along the vehicle's x axis (turned by its yaw and pitch) "
                               "and a half-sine of duration VTIME along its -x that brings it "
                               "to rest",
                               deck.units.time));
    }
    ReadReference(f, card, ivflg, ivref);
    if (vehicle.duration <= 0 && points == 0) {
      f.Invalid(card, 25, 30, fmt::format("VTIME is {}", vehicle.duration),
                "a half-sine pulse needs a positive duration");
    }
    if (!PlaceVehicle(f, card, std::move(vehicle))) return;
    last = card;
  }
  if (last && !r.truncated()) {
    f.Invalid(
        *last, 71, 72,
        fmt::format("{} C cards and none with MSEG 0, the primary vehicle", kMaxVehicles),
        fmt::format("ATB reads at most {} C cards, the last with MSEG 0 (STOP 7)", kMaxVehicles));
  }
}

}  // namespace sled::lang::legacy
