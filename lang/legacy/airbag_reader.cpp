// D.4 and F.6: airbags (ATB's INPUT_AIRBAGS and INPUT_AIRBAG_FORCE; the model from AIRBAG and
// AIRBGG). ATB's bag is a free rigid body of weight XBM, held to its deployment point by the
// spring SPRK and pushed off its reaction panels (ellipsoids, D.4.g and D.4.h); its gas is
// polytropic, fed by a cylinder that empties through a choked throat from CYTD, and vents in
// proportion to the square root of the gauge pressure once above CYPV. sled's bag is fixed in its
// frame, balances the gas's energy, takes an inflow function and vents by isentropic orifice
// flow. The gas constants, the ambient pressure, the deployment time and the vent's area and
// discharge coefficient carry over; the rest only approximately, so a deck converts its airbags
// only when asked (--approximate-airbags), with a W0504 for each approximation.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "lang/legacy/airbag_inflow.h"
#include "lang/legacy/restraint_readers.h"

namespace sled::lang::legacy {
namespace {

constexpr int kMaxPanels = 4;

Vec3 Rotated(const Vec3& yaw_pitch_roll_deg, const Vec3& v) {
  constexpr double kRadians = std::numbers::pi / 180;
  const double y = yaw_pitch_roll_deg[0] * kRadians, p = yaw_pitch_roll_deg[1] * kRadians,
               r = yaw_pitch_roll_deg[2] * kRadians;
  const double cy = std::cos(y), sy = std::sin(y), cp = std::cos(p), sp = std::sin(p),
               cr = std::cos(r), sr = std::sin(r);
  // Yaw about z, then pitch about y, then roll about x (ATB's order 3, 2, 1).
  const double m[3][3] = {{cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr},
                          {sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr},
                          {-sp, cp * sr, cp * cr}};
  Vec3 out{};
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) out[i] += m[i][j] * v[j];
  }
  return out;
}

class AirbagReader {
 public:
  AirbagReader(DeckFields& fields, bool approximate)
      : f_(fields), r_(fields.source()), approximate_(approximate) {}

  void Read(int number) {
    const std::string bag = fmt::format("airbag {}", number);
    const Card head = r_.Next(fmt::format("D.4.a ({})", bag), {"(A20,I4)"});
    AirbagCard airbag;
    airbag.line = head.line;
    airbag.title = r_.Text(head, 1, 20);
    const int panels = r_.Integer(head, 21, 24, "NPANEL, the number of reaction panels");
    const Card shape = r_.Next(fmt::format("D.4.b ({})", bag), {"(6F12.0)"});
    airbag.semi_axes = f_.Triple(shape, 1, 12, "the bag's semi-axes");
    const Vec3 cg_offset = f_.Triple(shape, 37, 12, "the bag's C.G. offset");
    const Card place = r_.Next(fmt::format("D.4.c ({})", bag), {"(6F12.0)"});
    airbag.orientation = f_.Triple(place, 1, 12, "yaw, pitch and roll of the bag");
    const Vec3 deploy = f_.Triple(place, 37, 12, "the deployment point");
    const Card d = r_.Next(fmt::format("D.4.d ({})", bag), {"(6F12.0)"});
    airbag.cylinder_line = d.line;
    const double weight = r_.Real(d, 1, 12, "XBM, the bag's weight");
    airbag.deploy_at = r_.Real(d, 13, 24, "CYTD, the time the cylinder starts to empty");
    airbag.ambient_pressure = r_.Real(d, 25, 36, "CYPA, the ambient pressure");
    Cylinder cylinder;
    cylinder.supply_pressure = r_.Real(d, 37, 48, "CYSP, the cylinder's supply pressure");
    airbag.gas_temperature = r_.Real(d, 49, 60, "CYT0, the gas temperature");
    cylinder.volume = r_.Real(d, 61, 72, "CYV0, the cylinder's volume");
    const Card e = r_.Next(fmt::format("D.4.e ({})", bag), {"(6F12.0)"});
    cylinder.discharge = r_.Real(e, 1, 12, "CYCD, the throat's discharge coefficient");
    airbag.gamma = r_.Real(e, 13, 24, "CYK, the ratio of specific heats");
    airbag.gas_constant = r_.Real(e, 25, 36, "CYR, the gas constant");
    cylinder.throat_area = r_.Real(e, 37, 48, "CYAT, the throat's area");
    const double vent_pressure = r_.Real(e, 49, 60, "CYPV, the venting pressure");
    airbag.vent_discharge = r_.Real(e, 61, 72, "CYCD0, the vent's discharge coefficient");
    const Card f = r_.Next(fmt::format("D.4.f ({})", bag), {"(6F12.0)", 5});
    airbag.vent_area = r_.Real(f, 1, 12, "CYA0, the vent's area");
    const double spring = r_.Real(f, 13, 24, "SPRK, the deployment spring");
    r_.Real(f, 25, 36, "VSCS");
    r_.Real(f, 37, 48, "CK");
    r_.Real(f, 49, 60, "CMASS, the bag's mass factor");
    if (panels < 1 || panels > kMaxPanels) {
      f_.Invalid(head, 21, 24, fmt::format("NPANEL is {}", panels),
                 "a bag has 1 to 4 reaction panels; the first holds its deployment point");
    }
    Vec3 panel_location{}, panel_offset{}, panel_orientation{};
    for (int k = 0; k < std::clamp(panels, 0, kMaxPanels) && !r_.truncated(); ++k) {
      const std::string panel = fmt::format("{}, panel {}", bag, k + 1);
      const Card g = r_.Next(fmt::format("D.4.g ({})", panel), {"(6F12.0)"});
      const Card h = r_.Next(fmt::format("D.4.h ({})", panel), {"(6F12.0)"});
      f_.Triple(g, 1, 12, "the panel's semi-axes");
      const Vec3 offset = f_.Triple(g, 37, 12, "the panel's C.G. offset");
      const Vec3 location = f_.Triple(h, 1, 12, "the panel's location");
      const Vec3 orientation = f_.Triple(h, 37, 12, "yaw, pitch and roll of the panel");
      if (k == 0) {
        panel_location = location;
        panel_offset = offset;
        panel_orientation = orientation;
        if (approximate_) {
          f_.Approximated(g, 1, 72,
                          "the reaction panels hold ATB's free bag at its deployment point; "
                          "sled's bag is fixed there, so they are not converted");
        }
      }
    }
    if (head.line == 0 || r_.truncated()) return;
    // INPUT_AIRBAGS: the deployment point in the vehicle is the first panel's location plus its
    // C.G. offset and the point, both turned by the panel's yaw, pitch and roll.
    const Vec3 local{panel_offset[0] + deploy[0], panel_offset[1] + deploy[1],
                     panel_offset[2] + deploy[2]};
    const Vec3 turned = panel_orientation == Vec3{} ? local : Rotated(panel_orientation, local);
    airbag.deploy_point = {panel_location[0] + turned[0], panel_location[1] + turned[1],
                           panel_location[2] + turned[2]};
    cylinder.gamma = airbag.gamma;
    cylinder.gas_constant = airbag.gas_constant;
    cylinder.temperature = airbag.gas_temperature;
    cylinder.ambient_pressure = airbag.ambient_pressure;
    cylinder.g = f_.deck().g;
    if (!Valid(airbag, cylinder, shape, d, e, f) || !approximate_) return;
    if (panel_orientation != Vec3{} || airbag.orientation != Vec3{}) {
      f_.Unverified(place, 1, 72,
                    "a turned bag or reaction panel: the bag is taken to deploy along its own -x "
                    "axis (ATB's DPVCTR), its axes and the first panel's turned by yaw, pitch "
                    "and roll; ATB's DRCYPR, which builds them, is not in the reference");
    }
    if (weight != 0 || spring != 0 || cg_offset != Vec3{}) {
      f_.Approximated(f, 13, 60,
                      "ATB's bag is a free rigid body (weight XBM, C.G. offset, mass factor "
                      "CMASS) held to its deployment point by the spring SPRK, unfolding by ATB's "
                      "own law; sled's bag is fixed at the deployment point in the vehicle and "
                      "unfolds as its gas fills it (docs/runtime.md)");
    }
    const InflowTable table = TabulateCylinder(cylinder);
    if (!table.valid) {
      f_.Invalid(d, 37, 72,
                 "ATB's cylinder formula gives no finite inflow for these values (CYSP, CYV0, "
                 "CYAT, CYCD with CYK, CYR, CYT0 and A.3's G)",
                 "check the cylinder's values and their units against A.3's unit labels");
      return;
    }
    airbag.inflow = table.rows;
    f_.Approximated(d, 37, 72,
                    fmt::format("ATB's cylinder (CYSP, CYV0 and the throat's CYAT and CYCD) "
                                "delivers a gas mass of closed form from CYTD; sled takes its "
                                "flow as the inflow table, {} rows every {} s up to {:.4g} s "
                                "(99.9 % of the gas), which delivers {:.4f} % of the cylinder's "
                                "gas",
                                table.rows.size(), table.step, table.end, 100 * table.delivered));
    f_.Approximated(e, 13, 36,
                    "ATB's gas is polytropic, its pressure set by the gas it holds and the bag's "
                    "volume; sled balances the gas's energy, with the inflow at CYT0 (the "
                    "temperature is read as kelvin and the gas constant per kelvin, which leaves "
                    "every product of the two, all that ATB uses, unchanged)");
    if (airbag.vent_area > 0 && airbag.vent_discharge > 0) {
      f_.Approximated(e, 49, 72,
                      fmt::format("ATB vents in proportion to the square root of the gauge "
                                  "pressure{}; sled's vent is isentropic orifice flow through "
                                  "CYCD0 times CYA0 as soon as the pressure exceeds the ambient",
                                  vent_pressure > 0 ? " once it exceeds CYPV" : ""));
    }
    f_.deck().airbags.push_back(std::move(airbag));
  }

 private:
  bool Valid(const AirbagCard& airbag, const Cylinder& cylinder, const Card& shape, const Card& d,
             const Card& e, const Card& f) {
    bool ok = true;
    auto require = [&](bool condition, const Card& card, int first, std::string_view what,
                       std::string help) {
      if (!condition) {
        f_.Invalid(card, first, first + 11, what, std::move(help));
        ok = false;
      }
    };
    for (int i = 0; i < 3; ++i) {
      require(airbag.semi_axes[static_cast<std::size_t>(i)] > 0, shape, 1 + 12 * i,
              "a semi-axis of the bag is not positive", "give the full bag's three semi-axes");
    }
    require(airbag.deploy_at >= 0, d, 13, "CYTD is negative",
            "the cylinder starts to empty at CYTD, a time from 0 on");
    require(airbag.ambient_pressure > 0, d, 25, "CYPA is not positive",
            "give the ambient pressure in the deck's force and length units");
    require(cylinder.supply_pressure + airbag.ambient_pressure > 0, d, 37,
            "the cylinder's pressure is not positive", "CYSP is the pressure above ambient");
    require(airbag.gas_temperature > 0, d, 49, "CYT0 is not positive",
            "give the gas's absolute temperature");
    require(cylinder.volume > 0, d, 61, "CYV0 is not positive", "give the cylinder's volume");
    require(cylinder.discharge > 0, e, 1, "CYCD is not positive",
            "give the throat's discharge coefficient");
    require(airbag.gas_constant > 0, e, 25, "CYR is not positive",
            "give the gas constant (per weight: length / temperature)");
    require(cylinder.throat_area > 0, e, 37, "CYAT is not positive", "give the throat's area");
    require(airbag.vent_area >= 0, f, 1, "CYA0 is negative", "a vent's area is 0 or more");
    if (airbag.gamma <= 1 || airbag.gamma > 5.0 / 3) {
      f_.Refuse(e, 13, 24, fmt::format("CYK is {}", airbag.gamma),
                "sled's `gamma` is above 1 and at most 5/3");
      ok = false;
    }
    if (airbag.vent_discharge < 0 || airbag.vent_discharge > 1) {
      f_.Refuse(e, 61, 72, fmt::format("CYCD0 is {}", airbag.vent_discharge),
                "sled's `discharge_coefficient` is above 0 and at most 1");
      ok = false;
    }
    return ok;
  }

  DeckFields& f_;
  DeckSource& r_;
  bool approximate_;
};

}  // namespace

void ReadAirbags(DeckFields& fields, int count, bool approximate) {
  AirbagReader reader(fields, approximate);
  for (int j = 0; j < count && !fields.source().truncated(); ++j) reader.Read(j + 1);
}

void ReadAirbagContacts(DeckFields& fields, int count) {
  DeckSource& r = fields.source();
  const int segments = static_cast<int>(fields.deck().segments.size());
  for (int j = 0; j < count && !r.truncated(); ++j) {
    Card card = r.Next(fmt::format("F.6 (airbag {})", j + 1), {"(2I4,20I2)", 2});
    const int number = r.Integer(card, 1, 4, "the bag's number");
    const int pairs = fields.Count(card, 5, 8, "NK, the number of segments", 10);
    r.Extend(card, 2 * pairs);
    if (card.line == 0) return;
    if (number != j + 1) {
      fields.Invalid(card, 1, 4, fmt::format("bag {} is numbered {}", j + 1, number),
                     "the F.6 cards follow the bags' order (ATB stops: STOP 20)");
    }
    AirbagCard* airbag = static_cast<std::size_t>(j) < fields.deck().airbags.size()
                             ? &fields.deck().airbags[static_cast<std::size_t>(j)]
                             : nullptr;
    if (airbag != nullptr) airbag->contact_line = card.line;
    for (int i = 0; i < pairs; ++i) {
      const int first = 9 + 4 * i;
      const Ref segment = fields.Reference(card, first, first + 1, "a segment the bag touches");
      const int ellipsoid = r.Integer(card, first + 2, first + 3, "the segment's ellipsoid");
      if (segment.number < 1 || segment.number > segments) {
        r.Report(DiagnosticKind::kDeckCountOutOfRange, card, first, first + 1,
                 fmt::format("card {}, {}: segment {} does not exist", card.label,
                             r.Where(card, first, first + 1), segment.number),
                 fmt::format("a bag touches body segments, 1 to {}", segments));
        continue;
      }
      if (ellipsoid != segment.number) {
        fields.Refuse(card, first + 2, first + 3,
                      fmt::format("ellipsoid {} of segment {}", ellipsoid, segment.number),
                      "sled's bag touches a segment's own ellipsoids; give the segment's number "
                      "as its ellipsoid");
        continue;
      }
      if (airbag != nullptr) airbag->contacts.push_back(segment);
    }
  }
}

}  // namespace sled::lang::legacy
