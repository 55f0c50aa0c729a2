// E.6, F.7 and F.9: ATB's wind and water (INPUT_WIND, INPUT_WIND_FORCE, INPUT_WATER,
// INPUT_WAVES, INPUT_WATER_ELLIPSOIDS, INPUT_WATER_OUTPUT). What the cards mean for the forces is
// from WINDY and WIND_AREA; the water's force routines are not in the reference, so its drag law
// is an assumption its warning states.
#include <cmath>

#include <fmt/format.h>

#include "lang/legacy/card_reader.h"
#include "lang/legacy/fluid_readers.h"

namespace sled::lang::legacy {
namespace {

constexpr int kMaxFunction = 98;
constexpr int kMaxTablePoints = 1000;
constexpr int kMaxWaterEllipsoids = 80;  // MAXELP
constexpr int kMaxFlotationDevices = 5;

// An `Fw.d` field: in a fixed-column card a number written without a decimal point is scaled by
// 10^-d, as the Fortran READ does (a `.lin` item is read as written).
double ScaledReal(DeckFields& f, const Card& card, int first, int last, int decimals,
                  std::string_view what) {
  DeckSource& r = f.source();
  const double value = r.Real(card, first, last, what);
  if (dynamic_cast<CardReader*>(&r) == nullptr || card.line == 0) return value;
  const std::string text = r.Text(card, first, last);
  if (text.find('.') != std::string::npos) return value;
  return value / std::pow(10.0, decimals);
}

}  // namespace

void ReadWindFunctions(DeckFields& f, int count) {
  DeckSource& r = f.source();
  for (int k = 0; k < count && !r.truncated(); ++k) {
    const Card head = r.Next(fmt::format("E.6.a (wind function {})", k + 1), {"(I4,4X,A20)"});
    WindFunctionCard function;
    function.line = head.line;
    function.where = r.Range(head, 1, 4);
    function.number = r.Integer(head, 1, 4, "the wind function's number");
    function.title = r.Text(head, 9, 28);
    if (function.number <= 0 || function.number > kMaxFunction) {
      f.Invalid(head, 1, 4, fmt::format("wind function number {}", function.number),
                "functions are numbered 1 to 98 (ATB's STOP 11)");
    }
    const std::string label = fmt::format("wind function {}", function.number);
    const Card b = r.Next(fmt::format("E.6.b ({})", label), {"(3F12.0,2I12)"});
    function.heat_ratio = r.Real(b, 1, 12, "RK, the ratio of specific heats");
    function.sonic_speed = r.Real(b, 13, 24, "C, the speed of sound");
    function.pressure = r.Real(b, 25, 36, "PR, the absolute pressure");
    function.moving = f.Reference(b, 37, 48, "NSV, the segment whose velocity makes the wind");
    function.reference = f.Reference(b, 49, 60, "NSR, the reference segment");
    if (function.heat_ratio != 0) {
      if (function.heat_ratio < 0 || function.sonic_speed <= 0 || function.pressure <= 0) {
        f.Invalid(b, 1, 36,
                  fmt::format("RK {}, C {}, PR {}", function.heat_ratio, function.sonic_speed,
                              function.pressure),
                  "the air's density is RK PR / C^2: give a positive ratio of specific heats, "
                  "speed of sound and pressure");
      }
    } else {
      const Card c = r.Next(fmt::format("E.6.c ({})", label), {"(I6)"});
      const int points = f.Count(c, 1, 6, "NTMPTS, the number of time points", kMaxTablePoints);
      for (int i = 0; i < points && !r.truncated(); ++i) {
        const Card row =
            r.Next(fmt::format("E.6.d ({}, point {})", label, i + 1), {"(4F12.0)", -1, i > 0});
        if (i == 0) function.table_line = row.line;
        std::array<double, 4> values{};
        for (int j = 0; j < 4; ++j) {
          values[static_cast<std::size_t>(j)] =
              r.Real(row, 12 * j + 1, 12 * j + 12, j == 0 ? "T, the time" : "the pressure");
        }
        if (!function.rows.empty() && values[0] <= function.rows.back()[0]) {
          f.Invalid(
              row, 1, 12,
              fmt::format("the time {} does not follow {}", values[0], function.rows.back()[0]),
              "a table's times increase strictly");
        }
        function.rows.push_back(values);
      }
      if (points < 1) {
        f.Invalid(c, 1, 6, fmt::format("a table of {} points", points),
                  "a wind table needs at least one point");
      }
    }
    f.deck().wind_functions.push_back(std::move(function));
  }
}

bool ReadWind(DeckFields& f) {
  DeckSource& r = f.source();
  const int segments = static_cast<int>(f.deck().segments.size());
  const std::vector<int> flags =
      f.CountsPerItem("F.7.a", segments, "(18I4)", 18, false, "MWSEG(1), whether the wind acts", 1);
  for (int s = 0; s < segments && !r.truncated(); ++s) {
    if (flags[static_cast<std::size_t>(s)] == 0) continue;
    const Card card = r.Next(fmt::format("F.7.b (segment {})", s + 1), {"(7I4)"});
    WindCard wind;
    wind.line = card.line;
    const int j = r.Integer(card, 1, 4, "MWSEG(1), the segment");
    if (std::abs(j) != s + 1 && card.line != 0) {
      f.Invalid(card, 1, 4, fmt::format("MWSEG(1) is {} on the card of segment {}", j, s + 1),
                "the F.7.b cards follow the segments flagged on F.7.a, each naming its own "
                "(ATB's STOP 21)");
    }
    wind.segment = Ref{s + 1, r.Range(card, 1, 4), card.label};
    wind.grid = j < 0;
    wind.ellipsoid = f.Reference(card, 5, 8, "MWSEG(2), the segment's ellipsoid");
    wind.plane_segment = f.Reference(card, 9, 12, "MWSEG(3), the plane's segment");
    wind.plane = f.Reference(card, 13, 16, "MWSEG(4), the plane");
    wind.force = f.Reference(card, 17, 20, "MWSEG(5), the wind function");
    wind.drag = f.Reference(card, 21, 24, "MWSEG(6), the drag-coefficient function");
    const int blocking = r.Integer(card, 25, 28, "MWSEG(7), the number of blocking ellipsoids");
    if (blocking != 0) {
      f.Refuse(card, 25, 28,
               fmt::format("MWSEG(7) is {}: ellipsoids that shade this one from the wind "
                           "(ATB's grid method)",
                           blocking),
               "sled's wind reaches every ellipsoid it names; set MWSEG(7) to 0 (the cards "
               "after this one are not read)");
      return false;
    }
    f.deck().winds.push_back(std::move(wind));
  }
  return true;
}

bool ReadWater(DeckFields& f) {
  DeckSource& r = f.source();
  Deck& deck = f.deck();
  WaterCard water;
  const Card a = r.Next("F.9.a", {"(8F10.6,I2)"});
  water.line = a.line;
  for (int i = 0; i < 3; ++i) {
    water.offset[static_cast<std::size_t>(i)] =
        ScaledReal(f, a, 10 * i + 1, 10 * i + 10, 6, "WOFSET, the water frame's origin");
    water.frame[static_cast<std::size_t>(i)] =
        ScaledReal(f, a, 10 * i + 31, 10 * i + 40, 6, "WFRAME, the water frame's angles");
  }
  water.depth = ScaledReal(f, a, 61, 70, 6, "WDEP, the water's depth");
  water.specific_weight = ScaledReal(f, a, 71, 80, 6, "WGAM, the water's specific weight");
  const int from_wind = r.Integer(a, 81, 82, "ISPD, the wave from a wind speed");
  if (water.specific_weight <= 0) {
    f.Invalid(a, 71, 80, fmt::format("WGAM is {}", water.specific_weight),
              "the water's specific weight (weight per volume) is positive");
  }
  if (from_wind != 0) {
    const Card d = r.Next("F.9.d", {"(F10.6)"});
    f.Refuse(d, 1, 10, "a wave raised by a wind speed (ISPD is not 0)",
             "sled's water is still: set ISPD to 0 and NWAVES to 0");
  } else {
    const Card b = r.Next("F.9.b", {"(I5,2F10.5)"});
    const int waves = r.Integer(b, 1, 5, "NWAVES, the number of regular waves");
    for (int w = 0; w < waves && !r.truncated() && w < 100; ++w) {
      const Card c = r.Next(fmt::format("F.9.c (wave {})", w + 1), {"(4F10.6,I2)", 4});
      if (w == 0) {
        f.Refuse(c, 1, 40, fmt::format("{} regular waves on the surface", waves),
                 "sled's water is still: set NWAVES to 0");
      }
    }
    if (waves == 0 && (r.Real(b, 6, 15, "RPH") != 0 || r.Real(b, 16, 25, "RNX") != 0)) {
      f.Ignored(b, 6, 25, "RPH and RNX, the grid of the wave calculations",
                "without waves ATB has nothing to compute on the grid; sled computes an "
                "ellipsoid's submerged volume in closed form");
    }
  }
  if (water.depth > 0) {
    f.Unverified(a, 61, 70,
                 fmt::format("WDEP is {} {}: the depth enters ATB's wave dispersion "
                             "(INPUT_WAVES), and without waves it is left out (sled's water has "
                             "no bottom); its other uses, if any, are not in the reference",
                             water.depth, deck.units.length));
  }
  const Card e1 = r.Next("F.9.e.1", {"(2I5,8F6.4)"});
  const int ellipsoids =
      f.Count(e1, 1, 5, "NUM_ELLIP_WATER_CT, the ellipsoids in the water", kMaxWaterEllipsoids);
  const int devices =
      f.Count(e1, 6, 10, "NUM_PER_FLOAT_DEV, the flotation devices", kMaxFlotationDevices);
  const double default_drag = ScaledReal(f, e1, 11, 16, 4, "BCOED, the default drag");
  const double default_lift = ScaledReal(f, e1, 17, 22, 4, "BCOEL, the default lift");
  double default_added[6];
  for (int i = 0; i < 6; ++i) {
    default_added[i] = ScaledReal(f, e1, 23 + 6 * i, 28 + 6 * i, 4, "BADDM, added mass");
  }
  const Card e2 = r.Next("F.9.e.2", {"(8F6.4)"});
  (void)e2;  // ECOED, ECOEL, EADDM: the flotation devices', which are refused below
  if (ellipsoids == 0 && devices == 0) {
    f.Invalid(e1, 1, 10, "no ellipsoid and no flotation device in the water",
              "ATB stops here (STOP 591): name the ellipsoids the water acts on");
  }
  for (int i = 0; i < ellipsoids && !r.truncated(); ++i) {
    const Card card = r.Next(fmt::format("F.9.f (ellipsoid {})", i + 1), {"(2I5,8F6.4)"});
    WaterCard::Ellipsoid ellipsoid;
    ellipsoid.line = card.line;
    ellipsoid.ellipsoid = f.Reference(card, 1, 5, "NWSE(1), the ellipsoid");
    ellipsoid.segment = f.Reference(card, 6, 10, "NWSE(2), its segment");
    const double drag = ScaledReal(f, card, 11, 16, 4, "COED, the drag coefficient");
    ellipsoid.drag = drag == 0 ? default_drag : std::max(drag, 0.0);
    const double lift = ScaledReal(f, card, 17, 22, 4, "COEL, the lift coefficient");
    if ((lift == 0 ? default_lift : std::max(lift, 0.0)) != 0) {
      f.Refuse(card, 17, 22, "a lift coefficient (COEL, or BCOEL on F.9.e.1)",
               "sled's water has drag and buoyancy, no lift; set COEL and BCOEL to 0 or a "
               "negative number (none)");
    }
    for (int k = 0; k < 6; ++k) {
      const double added = ScaledReal(f, card, 23 + 6 * k, 28 + 6 * k, 4, "CADDM");
      if ((added == 0 ? default_added[k] : std::max(added, 0.0)) != 0) {
        f.Refuse(card, 23, 58, "added-mass or added-damping coefficients (CADDM, or BADDM)",
                 "sled's water has no added mass or damping terms; set them to 0 or a negative "
                 "number (none)");
        break;
      }
    }
    water.ellipsoids.push_back(ellipsoid);
  }
  const Card g = r.Next("F.9.g", {"(2I5,3F10.6,I5)"});
  if (ellipsoids > 0) {
    const int repose = r.Integer(g, 41, 45, "NEBODY, the ellipsoid of the body's repose angle");
    bool found = false;
    for (const WaterCard::Ellipsoid& e : water.ellipsoids) found |= e.ellipsoid.number == repose;
    if (!found) {
      f.Invalid(g, 41, 45, fmt::format("NEBODY is {}, not an ellipsoid in the water", repose),
                "ATB stops here (STOP 597): name one of the F.9.f ellipsoids");
    }
  }
  f.Approximated(g, 1, 45,
                 "the mouth (MOUTHS, MOUTHE, DMOUTH) and the repose ellipsoid (NEBODY), which "
                 "ATB uses for its printed water report: sled does not print them (no value of "
                 "the run changes; `position SEGMENT at POINT` outputs the mouth's position)");
  if (devices > 0) {
    f.Refuse(e1, 6, 10, fmt::format("{} personal flotation devices", devices),
             "the layout of their cards (F.9.h to F.9.j, INPUT_PER_FLOAT_DEV) is not in the "
             "reference; model a flotation device as a segment of the body in the water (the "
             "cards after F.9.g are not read)");
    deck.water = std::move(water);
    return false;
  }
  const Card k = r.Next("F.9.k", {"(7I5)"});
  const int sequences = f.Count(k, 1, 5, "NSEQN, the water output sequences", 20);
  for (int q = 0; q < sequences && !r.truncated(); ++q) {
    const Card l = r.Next(fmt::format("F.9.l (sequence {})", q + 1), {"(I5)"});
    const int count = f.Count(l, 1, 5, "NELL, the ellipsoids of the sequence", 80);
    for (int e = 0; e < count && !r.truncated(); ++e) {
      r.Next(fmt::format("F.9.m (sequence {}, ellipsoid {})", q + 1, e + 1), {"(10I5)", 1});
    }
  }
  if (sequences > 0) {
    f.Approximated(k, 1, 35,
                   "water force outputs (the forces of buoyancy, drag and the rest by ellipsoid "
                   "sequence): sled does not write them (no value of the run changes; the "
                   "water's work is in the energy balance's applied work)");
  }
  deck.water = std::move(water);
  return true;
}

}  // namespace sled::lang::legacy
