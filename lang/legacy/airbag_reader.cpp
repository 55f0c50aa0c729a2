// D.4 and F.6: airbags (ATB's INPUT_AIRBAGS and INPUT_AIRBAG_FORCE; the model from AIRBAG,
// AIRBGG and AIRBG3), converted to sled's `model = atb_free` bag. ATB's bag unfolds with its
// vehicle until the cylinder's gas fills it, then is a free rigid body of weight XBM (times CMASS
// with its gas), held to its deployment point by the spring SPRK and pushed off its reaction
// panels (ellipsoids, D.4.g and D.4.h); its gas is polytropic, fed by a cylinder that empties
// through a choked throat from CYTD, and vents as the square root of the gauge pressure once
// above CYPV. The full bag's gas law and vent convert exactly; the cylinder, the unfolding, the
// panels and the bag's rotation with a W0504 each that says by how much they differ.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "lang/legacy/airbag_inflow.h"
#include "lang/legacy/restraint_readers.h"
#include "lang/legacy/rotations.h"

namespace sled::lang::legacy {
namespace {

constexpr int kMaxPanels = 4;

class AirbagReader {
 public:
  explicit AirbagReader(DeckFields& fields) : f_(fields), r_(fields.source()) {}

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
    airbag.bag_weight = r_.Real(d, 1, 12, "XBM, the bag's weight");
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
    airbag.vent_pressure = r_.Real(e, 49, 60, "CYPV, the venting pressure");
    airbag.vent_discharge = r_.Real(e, 61, 72, "CYCD0, the vent's discharge coefficient");
    const Card f = r_.Next(fmt::format("D.4.f ({})", bag), {"(6F12.0)", 5});
    airbag.vent_area = r_.Real(f, 1, 12, "CYA0, the vent's area");
    airbag.spring = r_.Real(f, 13, 24, "SPRK, the deployment spring");
    const double viscous = r_.Real(f, 25, 36, "VSCS");
    const double ck = r_.Real(f, 37, 48, "CK");
    airbag.mass_factor = r_.Real(f, 49, 60, "CMASS, the bag's mass factor");
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
        f_.Approximated(g, 1, 72,
                        "ATB pushes its full bag off the reaction panels (the gauge pressure on "
                        "the area each cuts, their volume taken from the gas) and pulls it by "
                        "SPRK only while it does not cut the first; sled's free bag has no "
                        "panels: SPRK holds it at all times and the panels take no volume (not "
                        "measured: the panels' volume depends on the bag's motion)");
      }
    }
    if (head.line == 0 || r_.truncated()) return;
    // INPUT_AIRBAGS: the deployment point in the vehicle is the first panel's location plus its
    // C.G. offset and the point, both turned by the panel's yaw, pitch and roll.
    const Vec3 local{panel_offset[0] + deploy[0], panel_offset[1] + deploy[1],
                     panel_offset[2] + deploy[2]};
    const Vec3 turned = panel_orientation == Vec3{}
                            ? local
                            : geometry::Apply(YawPitchRoll(panel_orientation), local);
    airbag.deploy_point = {panel_location[0] + turned[0], panel_location[1] + turned[1],
                           panel_location[2] + turned[2]};
    cylinder.gamma = airbag.gamma;
    cylinder.gas_constant = airbag.gas_constant;
    cylinder.temperature = airbag.gas_temperature;
    cylinder.ambient_pressure = airbag.ambient_pressure;
    cylinder.g = f_.deck().g;
    if (!Valid(airbag, cylinder, shape, d, e, f)) return;
    if (panel_orientation != Vec3{} || airbag.orientation != Vec3{}) {
      f_.Unverified(place, 1, 72,
                    "a turned bag or reaction panel: the bag is taken to deploy along its own -x "
                    "axis (ATB's DPVCTR), its axes and the first panel's turned by yaw, pitch "
                    "and roll; ATB's DRCYPR, which builds them, is not in the reference");
    }
    if (cg_offset != Vec3{}) {
      f_.Approximated(shape, 37, 72,
                      "ATB's bag turns about its C.G. offset from the ellipsoid's centre; sled's "
                      "free bag does not turn, so the offset is not used");
    }
    f_.Approximated(f, 13, 24,
                    "ATB's full bag is a rigid body that also turns under the pressure's torque "
                    "(moments of inertia CMASS (gas + 2/3 XBM) / G times its semi-axes' "
                    "(b^2 + c^2) / 5); sled's free bag translates with that mass and keeps the "
                    "vehicle's axes (not measured)");
    if (viscous != 0 || ck != 0) {
      f_.Approximated(f, 25, 48,
                      "VSCS and CK enter ATB's contact of the bag (BGG), which is not in the "
                      "reference; sled's bag pushes with the gauge pressure times the contact "
                      "area only, so they are not converted");
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
    FillBag(airbag, cylinder, e);
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
    require(airbag.bag_weight >= 0, d, 1, "XBM is negative", "give the bag's weight, 0 or more");
    require(airbag.vent_pressure >= 0, e, 49, "CYPV is negative",
            "the vent opens at a gauge pressure, 0 or more");
    require(airbag.spring >= 0, f, 13, "SPRK is negative",
            "give the spring's stiffness, 0 or more");
    require(airbag.mass_factor > 0, f, 49, "CMASS is not positive",
            "ATB divides by the bag's mass, CMASS times its gas and fabric weight over G");
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

  // The full bag's polytropic law and vent, exact to ATB: the reference temperature that gives
  // ATB's SWITCH, and the vent's coefficient at the density ATB vents at (the ambient pressure
  // over R CYT0, against sled's over R T_ref).
  void FillBag(AirbagCard& airbag, const Cylinder& cylinder, const Card& e) {
    const double volume = 4.0 / 3.0 * std::numbers::pi * airbag.semi_axes[0] * airbag.semi_axes[1] *
                          airbag.semi_axes[2];
    const BagFill fill = FillFreeBag(cylinder, volume);
    airbag.reference_temperature = fill.reference_temperature;
    airbag.vent_discharge *= std::sqrt(fill.reference_temperature / airbag.gas_temperature);
    if (!fill.fills) {
      f_.Approximated(e, 13, 36,
                      "the cylinder's whole gas takes less than the bag's volume at CYPA: the "
                      "bag never fills, in ATB as in sled; the gas's reference temperature is "
                      "CYT0 / CYK, which gives it ATB's volume at the ambient pressure");
      return;
    }
    f_.Approximated(
        e, 13, 36,
        fmt::format("the full bag's polytropic law is ATB's (the reference "
                    "temperature {:.6g} K gives ATB's SWITCH at the fill); while it "
                    "unfolds, ATB's envelope holds the volume the delivered gas takes "
                    "at CYPA by the cylinder's law, sled's a volume proportional to "
                    "the gas's mass: they differ by at most {:.3g} % of the bag's "
                    "volume, and meet at the fill",
                    fill.reference_temperature, 100 * fill.largest_unfolding_difference));
  }

  DeckFields& f_;
  DeckSource& r_;
};

}  // namespace

void ReadAirbags(DeckFields& fields, int count) {
  AirbagReader reader(fields);
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
