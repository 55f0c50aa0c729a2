#include "lang/legacy/deck_reader.h"

#include "lang/legacy/body_reader.h"
#include "lang/legacy/deck_fields.h"
#include "lang/legacy/fluid_readers.h"
#include "lang/legacy/global_graphic_reader.h"
#include "lang/legacy/initial_reader.h"
#include "lang/legacy/load_reader.h"
#include "lang/legacy/output_reader.h"
#include "lang/legacy/restraint_readers.h"
#include "lang/legacy/vehicle_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

#include <fmt/format.h>

namespace sled::lang::legacy {
namespace {

// Whether the corners P1, P2, P3 span a plane: the edges P1-P2 and P1-P3 are not parallel (their
// cross product is not negligible against their lengths).
bool Spans(const std::array<Vec3, 3>& p) {
  Vec3 a{}, b{};
  for (std::size_t i = 0; i < 3; ++i) {
    a[i] = p[1][i] - p[0][i];
    b[i] = p[2][i] - p[0][i];
  }
  const double cx = a[1] * b[2] - a[2] * b[1];
  const double cy = a[2] * b[0] - a[0] * b[2];
  const double cz = a[0] * b[1] - a[1] * b[0];
  const double cross = std::sqrt(cx * cx + cy * cy + cz * cz);
  const double lengths = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) *
                         std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  return lengths > 0 && cross > 1e-9 * lengths;
}

constexpr int kMaxPlanes = 50;
constexpr int kMaxBelts = 20;
constexpr int kMaxEllipsoids = 20;
constexpr int kMaxSprings = 20;
constexpr int kMaxFunction = 98;
constexpr int kMaxContacts = 200;
constexpr int kMaxHarnesses = 5;
constexpr int kMaxConstraints = 12;
constexpr int kMaxAirbags = 5;
// MAXELP = MAXSEG + MAXXELP: the largest D.5 ellipsoid number (V5.3.1 MODULE_STANDARD).
constexpr int kMaxEllipsoidNumber = kMaxSegments + kMaxEllipsoids;

std::string Upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

class DeckReader : public DeckFields {
 public:
  DeckReader(DeckSource& reader, Deck& deck) : DeckFields(reader, deck) {}

  Deck Read() {
    ReadA();
    ReadBody(*this);
    if (!r_.truncated()) ReadVehicles(*this);
    if (!r_.truncated()) ReadD();
    if (!r_.truncated()) ReadE();
    if (!r_.truncated()) ReadWindFunctions(*this, wind_functions_);
    if (unknown_layout_) return std::move(deck_);  // F.5 cards of unknown length follow
    if (!r_.truncated()) ReadF();
    if (unknown_layout_) return std::move(deck_);  // F.7.c or F.9.h cards of unknown layout
    if (!r_.truncated()) ReadInitialConditions(*this, bags_);
    if (!r_.truncated()) ReadOutputRequests(*this, bags_, actuators_);
    if (!r_.truncated() && !r_.OnlyBlankLinesRemain()) {
      const Card card = r_.Next("after H.10", {"(A80)"});
      r_.Report(DiagnosticKind::kDeckExtraCards, card, 1, 80,
                fmt::format("line {} follows the last card ATB V.3 reads (H.10, or H.11 with "
                            "joint actuators)",
                            card.line),
                "remove the lines after the H.10 cards, or check the H cards' counts");
    }
    return std::move(deck_);
  }

 private:
  // --- A: control --------------------------------------------------------------------------
  void ReadA() {
    const Card date = r_.Next("A.1 (date)", {"(A12)"});
    deck_.date = r_.Text(date, 1, 12);
    deck_.title = r_.Text(r_.Next("A.1 (title, line 1)", {"(A80)"}), 1, 80);
    deck_.subtitle = r_.Text(r_.Next("A.1 (title, line 2)", {"(A80)"}), 1, 80);

    const Card units = r_.Next("A.3", {"(3A4,4F12.0)"});
    deck_.units_line = units.line;
    deck_.units.length =
        Unit(units, 1, 4, "UNITL, the length unit",
             {{"IN", "in"}, {"INCH", "in"}, {"FT", "ft"}, {"M", "m"}, {"CM", "cm"}, {"MM", "mm"}});
    deck_.units.force =
        Unit(units, 5, 8, "UNITM, the weight (force) unit",
             {{"LB", "lbf"}, {"LBS", "lbf"}, {"LBF", "lbf"}, {"N", "N"}, {"KN", "kN"}});
    deck_.units.time =
        Unit(units, 9, 12, "UNITT, the time unit",
             {{"SEC", "s"}, {"S", "s"}, {"SECS", "s"}, {"MSEC", "ms"}, {"MS", "ms"}});
    deck_.gravity = Triple(units, 13, 12, "GRAVTY, the gravity vector");
    deck_.g = r_.Real(units, 49, 60, "G, the magnitude of gravity");
    if (deck_.g == 0) {
      deck_.g =
          std::sqrt(deck_.gravity[0] * deck_.gravity[0] + deck_.gravity[1] * deck_.gravity[1] +
                    deck_.gravity[2] * deck_.gravity[2]);
    }
    if (deck_.g <= 0) {
      Invalid(units, 13, 60, "both G and the gravity vector are zero",
              "segment masses are weights divided by G: give G in columns 49-60");
    }

    const Card control = r_.Next("A.4", {"(2I4,4F8.0)"});
    deck_.control_line = control.line;
    const int ndint = r_.Integer(control, 1, 4, "NDINT");
    if (ndint != 0) Unverified(control, 1, 4, "the meaning of NDINT is not documented; ignored");
    deck_.steps = r_.Integer(control, 5, 8, "NSTEPS, the number of output steps");
    deck_.dt = r_.Real(control, 9, 16, "DT, the output step");
    deck_.first_step = r_.Real(control, 17, 24, "H0, the first integration step");
    deck_.max_step = r_.Real(control, 25, 32, "HMAX, the largest integration step");
    deck_.min_step = r_.Real(control, 33, 40, "HMIN, the smallest integration step");
    if (deck_.steps <= 0) {
      Invalid(control, 5, 8, fmt::format("NSTEPS is {}", deck_.steps),
              "the run lasts NSTEPS output steps of DT: give a positive count");
    }
    if (deck_.dt <= 0) {
      Invalid(control, 9, 16, fmt::format("DT is {}", deck_.dt),
              "the output step must be positive");
    }
    const double steps[] = {deck_.first_step, deck_.max_step, deck_.min_step};
    static constexpr const char* kStepNames[] = {"H0", "HMAX", "HMIN"};
    for (int i = 0; i < 3; ++i) {
      if (steps[i] < 0) {
        Invalid(control, 17 + 8 * i, 24 + 8 * i, fmt::format("{} is {}", kStepNames[i], steps[i]),
                "an integration step is positive, or blank for sled's default");
      }
    }
    if (deck_.min_step > 0 && deck_.max_step > 0 && deck_.min_step > deck_.max_step) {
      Invalid(control, 25, 40,
              fmt::format("HMIN ({}) is larger than HMAX ({})", deck_.min_step, deck_.max_step),
              "the smallest integration step is at most the largest");
    }

    const Card print = r_.Next("A.5", {"(36I2)"});
    for (int i = 0; i < 36; ++i) {
      deck_.print_controls.push_back(r_.Integer(print, 2 * i + 1, 2 * i + 2, "NPRT"));
    }
    // NPRT(4) < 0: ATB reads the A cards and then a tape 8 of an earlier run, simulating nothing.
    if (deck_.print_controls[3] < 0) {
      Refuse(print, 7, 8,
             fmt::format("NPRT(4) is {}: a post-processing run of an earlier run's "
                         "tape 8, which simulates nothing",
                         deck_.print_controls[3]),
             "sled simulates the deck's scene; set NPRT(4) to 0 to convert it");
    }
    // The other entries choose ATB's printed report and files (VIEW, tape 8), which sled writes
    // its own way: they are read and left out, with one warning.
    bool printing = false;
    for (int i = 0; i < 36; ++i)
      printing = printing || (i != 33 && deck_.print_controls[static_cast<std::size_t>(i)] > 0);
    if (printing) {
      Ignored(print, 1, 72,
              "the print and file controls (NPRT) choose ATB's printed report, VIEW file and "
              "tape 8; sled writes its own run folder (docs/outputs.md), so they are left out",
              "nothing to do; the scene does not depend on them");
    }
    const int windows = deck_.print_controls[33];
    if (windows < 0 || windows > 3) {
      r_.Report(DiagnosticKind::kDeckCountOutOfRange, print, 67, 68,
                fmt::format("card A.5, {} (NPRT(34), the number of A.6 time windows): "
                            "{} is outside 0 to 3",
                            r_.Where(print, 67, 68), windows));
    } else {
      for (int i = 0; i < windows; ++i) {
        const Card window =
            r_.Next(fmt::format("A.6 (window {})", i + 1), {"(A1,1X,A1,1X,A1,1X,F10.3,1X,F10.3)"});
        if (window.line != 0) {
          Approximated(window, 1, 27,
                       "an output time window: ATB prints and writes only between TSTART and "
                       "TEND (with the flags of window 1); sled writes every output step of the "
                       "whole run");
        }
      }
    }
  }

  std::string Unit(const Card& card, int first, int last, std::string_view what,
                   std::initializer_list<std::pair<std::string_view, std::string_view>> known) {
    const std::string label = Upper(r_.Text(card, first, last));
    for (const auto& [name, symbol] : known) {
      if (label == name) return std::string(symbol);
    }
    std::string names;
    for (const auto& entry : known)
      names += fmt::format("{}`{}`", names.empty() ? "" : ", ", entry.first);
    r_.Report(DiagnosticKind::kDeckUnknownUnit, card, first, last,
              fmt::format("card A.3, {} ({}): `{}` is not a unit label sled knows",
                          r_.Where(card, first, last), what, label),
              fmt::format("write one of {}", names));
    return std::string(known.begin()->second);
  }

  // --- D: surfaces and restraints ----------------------------------------------------------
  void ReadD() {
    const Card d1 = r_.Next("D.1.a", {"(12I6)"});
    const int planes = Count(d1, 1, 6, "NPL, the number of planes", kMaxPlanes);
    const int belts = Count(d1, 7, 12, "NBLT, the number of belts", kMaxBelts);
    bags_ = Count(d1, 13, 18, "NBAG, the number of airbags", kMaxAirbags);
    const int ellipsoids =
        Count(d1, 19, 24, "NELP, the number of extra ellipsoids", kMaxEllipsoids);
    const int constraints = Count(d1, 25, 30, "NQ, the number of constraints", kMaxConstraints);
    const int springs = Count(d1, 31, 36, "NSD, the number of spring-dampers", kMaxSprings);
    harnesses_ = Count(d1, 37, 42, "NHRNSS, the number of harnesses", kMaxHarnesses);
    wind_functions_ = Count(d1, 43, 48, "NWINDF, the number of wind functions", kMaxFunction);
    const int loads =
        Count(d1, 55, 60, "NFORCE, the number of applied forces and torques", kMaxAppliedLoads);
    water_ = r_.Integer(d1, 61, 66, "NWATER, the water forces") != 0;
    // The F.5 cards of CVS-III and ATB-II decks, which follow the E cards when NJNTF is set: ATB
    // V.3 stops on them before reading any (INPUT_DCARDS, STOP 9), and neither its source nor the
    // CVS-III paper gives their columns, so the reading ends after the E cards.
    const int joint_functions = r_.Integer(d1, 49, 54, "NJNTF, the obsolete joint functions");
    if (joint_functions != 0) {
      Refuse(d1, 49, 54,
             fmt::format("NJNTF is {}: the deck has the obsolete joint-function cards (F.5) of "
                         "CVS-III and ATB-II, whose layout is not known: ATB V.3 stops on them "
                         "(STOP 9) without reading one, and neither its source nor the CVS-III "
                         "paper gives their columns; the cards after the E cards are not read",
                         joint_functions),
             "define each joint function as an E function (cards E.1 to E.4) and name it on its "
             "joint's B.4 card by a negative first coefficient (-n for function n), then set "
             "NJNTF to 0 and remove the F.5 cards, as ATB V.3 asks");
      unknown_layout_ = true;
    }
    actuators_ = ReadActuatorCount(*this, d1);
    for (int p = 0; p < planes; ++p) ReadPlane(p + 1);
    for (int b = 0; b < belts; ++b) ReadBelt(b + 1);
    ReadAirbags(*this, bags_);
    for (int e = 0; e < ellipsoids; ++e) ReadEllipsoid(e + 1);
    ReadConstraints(*this, constraints, bags_);
    ReadSymmetry();
    for (int s = 0; s < springs; ++s) ReadSpring(s + 1);
    ReadAppliedLoads(*this, loads);
  }

  void ReadPlane(int number) {
    const Card head = r_.Next(fmt::format("D.2 (plane {})", number), {"(I4,4X,A20)"});
    PlaneCard plane;
    plane.line = head.line;
    const int j = r_.Integer(head, 1, 4, "J, the plane's number");
    if (j != number && head.line != 0) {
      Invalid(head, 1, 4, fmt::format("plane {} is numbered {}", number, j),
              "planes are numbered in order from 1");
    }
    plane.title = r_.Text(head, 9, 28);
    if (number == 1) {
      Unverified(head, 1, 28,
                 fmt::format("planes are placed in the primary vehicle's frame (the vehicle "
                             "whose MSEG is 0), their corners in {} (UNITL) in its axes",
                             deck_.units.length));
    }
    Card last;
    for (int i = 0; i < 3; ++i) {
      last = r_.Next(fmt::format("D.2 (plane {}, P{})", number, i + 1), {"(3F12.0)"});
      plane.corners[static_cast<std::size_t>(i)] = Triple(last, 1, 12, "a corner of the plane");
    }
    if (!r_.truncated() && !Spans(plane.corners)) {
      Invalid(last, 1, 36,
              "P1, P2 and P3 lie on one line (or two of them are the same point), so they "
              "span no plane",
              "the plane is the parallelogram with edges P1-P2 and P1-P3; give three corners "
              "that are not in line");
    }
    deck_.planes.push_back(std::move(plane));
  }

  void ReadBelt(int number) {
    const Card title = r_.Next(fmt::format("D.3 (belt {}, title)", number), {"(A20)"});
    const Card anchors = r_.Next(fmt::format("D.3 (belt {}, anchors)", number), {"(6F12.0)"});
    const Card rest =
        r_.Next(fmt::format("D.3 (belt {}, reference point and slack)", number), {"(6F12.0)", 5});
    BeltCard belt;
    belt.line = title.line;
    belt.title = r_.Text(title, 1, 20);
    belt.anchor_a = Triple(anchors, 1, 12, "anchor A");
    belt.anchor_b = Triple(anchors, 37, 12, "anchor B");
    const Vec3 point = Triple(rest, 1, 12, "the belt's reference point on the segment");
    belt.slack = r_.Real(rest, 49, 60, "the slack (+) or the length (-)");
    if (point != Vec3{}) {
      Unverified(rest, 1, 36,
                 "the belt's reference point on the segment is not converted: sled lays the "
                 "webbing over the segment's ellipsoid from the anchors' geometry");
    }
    if (belt.slack < 0) {
      Refuse(rest, 49, 60, fmt::format("a belt length ({})", belt.slack),
             "sled's belts take their length from the initial geometry and a `slack`; give the "
             "slack instead of the length");
    }
    deck_.belts.push_back(std::move(belt));
  }

  void ReadEllipsoid(int number) {
    const Card card = r_.Next(fmt::format("D.5 (ellipsoid {})", number), {"(I6,9F6.0,3F4.0)"});
    const int m = r_.Integer(card, 1, 6, "M, the ellipsoid's number");
    const Vec3 semi_axes = Triple(card, 7, 6, "the semi-axes");
    const Vec3 center = Triple(card, 25, 6, "the centre");
    const Vec3 orientation = Triple(card, 43, 6, "yaw, pitch and roll");
    Vec3 exponents{};
    for (int i = 0; i < 3; ++i) {
      const int first = 61 + 4 * i;
      double& exponent = exponents[static_cast<std::size_t>(i)];
      exponent = r_.Real(card, first, first + 3, "an exponent");
      if (exponent == 0) exponent = 2;
      if (exponent < 2) {
        Invalid(card, first, first + 3, fmt::format("the exponent is {}", exponent),
                "an ellipsoid's exponent is 2 (or blank), a hyper-ellipsoid's above 2");
        exponent = 2;
      }
    }
    const int segments_now = static_cast<int>(deck_.segments.size());
    CheckSemiAxes(card, 7, semi_axes, m >= 1 && m <= segments_now);
    if (exponents[0] != exponents[1] || exponents[1] != exponents[2]) {
      Refuse(card, 61, 72, "a hyper-ellipsoid with different exponents per axis",
             "sled's `degree` is one exponent for all three axes");
    }
    const int segments = static_cast<int>(deck_.segments.size());
    const int vehicles = static_cast<int>(deck_.vehicles.size());
    if (m >= 1 && m <= segments) {
      SegmentCard& segment = deck_.segments[static_cast<std::size_t>(m - 1)];
      segment.semi_axes = semi_axes;
      segment.center = center;
      segment.ellipsoid_orientation = orientation;
      segment.degree = exponents[0];
      segment.ellipsoid_line = card.line;
    } else if (m > segments && m <= segments + vehicles) {
      deck_.vehicle_ellipsoids.push_back({card.line, m - segments, m, semi_axes, center,
                                          orientation, exponents[0], r_.Range(card, 1, 6)});
    } else if (m >= segments + vehicles + bags_ + 1 && m <= kMaxEllipsoidNumber) {
      // At or above NGRND: an extra ellipsoid, on the frames F.3.b's MS_SEG(1) or (3) name it.
      deck_.extra_ellipsoids.push_back(
          {card.line, 0, m, semi_axes, center, orientation, exponents[0], r_.Range(card, 1, 6)});
    } else {
      Invalid(card, 1, 6,
              m <= 0 || m > kMaxEllipsoidNumber
                  ? fmt::format("ellipsoid number {} (ATB stops: STOP 63)", m)
                  : fmt::format("ellipsoid number {} is an airbag's (ATB stops: STOP 64)", m),
              fmt::format("numbers 1 to {} replace a segment's ellipsoid, {} to {} a vehicle's, "
                          "and {} to {} are extra ellipsoids that F.3.b cards place",
                          segments, segments + 1, segments + vehicles,
                          segments + vehicles + bags_ + 1, kMaxEllipsoidNumber));
    }
  }

  void ReadSymmetry() {
    const int segments = static_cast<int>(deck_.segments.size());
    const int lines = std::max(1, (segments + 17) / 18);
    for (int l = 0; l < lines; ++l) {
      const Card card = r_.Next(fmt::format("D.7 (symmetry, line {})", l + 1),
                                {"(18I4)", std::min(18, std::max(1, segments - 18 * l))});
      if (l == 0) deck_.symmetry_line = card.line;
      for (int i = 0; i < 18 && l * 18 + i < segments; ++i) {
        Ref ref = Reference(card, 4 * i + 1, 4 * i + 4, "SYMMETRY, the mirror segment");
        if (ref.number < 0) {
          Refuse(card, 4 * i + 1, 4 * i + 4, "a negative (mirrored-check) symmetry entry",
                 "sled's mirror symmetry pairs segments in the xz plane only");
          ref.number = 0;
        } else if (ref.number > segments) {
          r_.Report(DiagnosticKind::kDeckCountOutOfRange, card, 4 * i + 1, 4 * i + 4,
                    fmt::format("card {}: segment {} does not exist", card.label, ref.number));
          ref.number = 0;
        }
        deck_.symmetry.push_back(std::move(ref));
      }
    }
  }

  void ReadSpring(int number) {
    const Card card = r_.Next(fmt::format("D.8 (spring {})", number), {"(2I3,11F6.0)"});
    SpringCard spring;
    spring.line = card.line;
    spring.first = Reference(card, 1, 3, "segment M");
    spring.second = Reference(card, 4, 6, "segment N");
    spring.at_first = Triple(card, 7, 6, "the attachment on M");
    spring.at_second = Triple(card, 25, 6, "the attachment on N");
    spring.free_length = r_.Real(card, 43, 48, "D0, the free length");
    spring.linear = r_.Real(card, 49, 54, "A1, the linear spring coefficient");
    spring.quadratic = r_.Real(card, 55, 60, "A2, the second spring coefficient");
    spring.damping = r_.Real(card, 61, 66, "B1, the damping coefficient");
    RefuseNonZero(card, 67, 72, r_.Real(card, 67, 72, "B2"), "B2 (a second damping coefficient)",
                  "sled's springs take one linear `damping`");
    const double lowest = spring.linear != 0 ? spring.linear : spring.quadratic;
    if (lowest < 0) {
      Invalid(card, 49, 60, fmt::format("the spring's lowest coefficient is negative ({})", lowest),
              "a spring pulls back when stretched: its lowest non-zero coefficient is positive");
    }
    if (spring.damping < 0) {
      Invalid(card, 61, 66, fmt::format("B1 is {}", spring.damping),
              "a damping coefficient is zero or positive: it resists the motion");
    }
    if (spring.free_length < 0) {
      Invalid(card, 43, 48, fmt::format("D0 is {}", spring.free_length),
              "a free length is zero (the initial length) or positive");
    }
    if (spring.quadratic != 0) {
      Unverified(card, 55, 60,
                 fmt::format("A2 is taken as the coefficient of the squared elongation, in {}/{}^2",
                             deck_.units.force, deck_.units.length));
    }
    deck_.springs.push_back(std::move(spring));
  }

  // --- E: functions ------------------------------------------------------------------------
  void ReadE() {
    for (int guard = 0; guard < 1000 && !r_.truncated(); ++guard) {
      const Card head = r_.Next("E.1", {"(I4,4X,A20)"});
      const int number = r_.Integer(head, 1, 4, "the function's number");
      if (number > kMaxFunction) return;
      FunctionCard function;
      function.line = head.line;
      function.where = r_.Range(head, 1, 4);
      function.number = number;
      function.title = r_.Text(head, 9, 28);
      const std::string label = fmt::format("function {}", number);
      if (number <= 0) {
        Invalid(head, 1, 4, fmt::format("function number {}", number),
                "functions are numbered 1 to 98; a number above 98 ends the E cards");
      }
      const Card e2 = r_.Next(fmt::format("E.2 ({})", label), {"(6F12.0)", 5});
      double d[5];
      for (int i = 0; i < 5; ++i) d[i] = r_.Real(e2, 12 * i + 1, 12 * i + 12, "D0..D4");
      // D0, D3 and D4 mean something only in some uses: the mapper judges them there.
      function.origin = d[0];
      function.d3 = d[3];
      function.d4 = d[4];
      function.origin_where = r_.Range(e2, 1, 12);
      function.d3_where = r_.Range(e2, 37, 48);
      function.d4_where = r_.Range(e2, 49, 60);
      if (d[1] == 0) {
        function.form = FunctionCard::Form::kConstant;
        function.constant = d[2];
      } else {
        function.form = d[1] > 0 ? FunctionCard::Form::kPolynomial : FunctionCard::Form::kTable;
        function.first_part_end = std::fabs(d[1]);
        ReadFunctionPart(function, d[1] > 0, label);
        const bool merged = d[2] != 0 && ReadSecondPart(function, e2, d[1], d[2], label);
        if (std::fabs(d[1]) != 1 && !merged) {
          Unverified(e2, 13, 24,
                     fmt::format("D1 is {}: ATB's integral of the function (EVALFD_INTEGRAL, the "
                                 "loading energy of an R factor) ends its first part at |D1| and "
                                 "holds the value there beyond; sled's {} goes on (EVALFD, which "
                                 "evaluates the function, is not in the reference)",
                                 d[1], d[1] > 0 ? "polynomial" : "table"));
        }
      }
      auto same = std::find_if(deck_.functions.begin(), deck_.functions.end(),
                               [&](const FunctionCard& f) { return f.number == number; });
      if (same != deck_.functions.end()) {
        *same = std::move(function);  // a repeated number replaces the earlier function
      } else {
        deck_.functions.push_back(std::move(function));
      }
    }
  }

  void ReadFunctionPart(FunctionCard& function, bool polynomial, const std::string& label) {
    if (polynomial) {
      const Card e3 = r_.Next(fmt::format("E.3 ({})", label), {"(6F12.0)"});
      for (int i = 0; i < 6; ++i) {
        function.coefficients.push_back(r_.Real(e3, 12 * i + 1, 12 * i + 12, "a coefficient"));
      }
      return;
    }
    const Card e4a = r_.Next(fmt::format("E.4.a ({})", label), {"(12I6)", 1});
    const int points = Count(e4a, 1, 6, "NPI, the number of points", 1000);
    for (int line = 0; line < (points + 2) / 3; ++line) {
      const Card e4b = r_.Next(fmt::format("E.4.b ({}, line {})", label, line + 1),
                               {"(6F12.0)", 2 * std::min(3, points - 3 * line), line > 0});
      for (int k = 0; k < 3 && line * 3 + k < points; ++k) {
        const int first = 24 * k + 1;
        const double x = r_.Real(e4b, first, first + 11, "D, the argument");
        const double y = r_.Real(e4b, first + 12, first + 23, "F(D), the value");
        if (!function.points.empty() && x <= function.points.back().first) {
          Invalid(
              e4b, first, first + 11,
              fmt::format("the argument {} does not follow {}", x, function.points.back().first),
              "a table's arguments increase strictly");
        }
        function.points.emplace_back(x, y);
      }
    }
    if (points < 2) {
      Invalid(e4a, 1, 6, fmt::format("a table of {} points", points), "a table needs two points");
    }
  }

  // E.2 D2 not 0: ATB's second part from |D1| to |D2| (EVALFD_INTEGRAL), a polynomial (D2 > 0)
  // or a table (D2 < 0). Two tables that meet at |D1| are one table: the first's rows below
  // |D1|, the value there, the second's rows above it up to |D2|; true when merged so. Any other
  // pair is refused (a sled function is one polynomial or one table).
  bool ReadSecondPart(FunctionCard& function, const Card& e2, double d1, double d2,
                      const std::string& label) {
    FunctionCard second;
    ReadFunctionPart(second, d2 > 0, label + ", second part");
    const double joint = std::fabs(d1), end = std::fabs(d2);
    std::string why;
    if (d1 > 0 || d2 > 0) {
      why =
          "a polynomial part: a sled function is one polynomial or one table; merge the parts "
          "into one table by hand";
    } else if (!(end > joint)) {
      why = fmt::format("|D2| = {} does not lie beyond |D1| = {}", end, joint);
    } else if (!Covers(function.points, joint) || second.points.empty() ||
               second.points.front().first > joint || second.points.back().first <= joint) {
      why = fmt::format("the tables do not both reach |D1| = {}, where ATB joins them", joint);
    } else {
      const double left = Interpolate(function.points, joint);
      const double right = Interpolate(second.points, joint);
      if (std::fabs(left - right) > 1e-9 * std::max(std::fabs(left), std::fabs(right))) {
        why = fmt::format(
            "the first table gives {} at |D1| = {} and the second {}: a jump, which "
            "a sled table cannot have",
            left, joint, right);
      }
    }
    if (!why.empty()) {
      Refuse(e2, 25, 36, "a second part of the function (D2 is not zero)",
             "ATB continues the function from |D1| to |D2| with a second polynomial (D2 > 0) or "
             "table (D2 < 0) (EVALFD_INTEGRAL); it converts when both parts are tables that meet "
             "at |D1|, not here: " +
                 why);
      return false;
    }
    std::vector<std::pair<double, double>> rows;
    for (const auto& row : function.points) {
      if (row.first < joint) rows.push_back(row);
    }
    rows.emplace_back(joint, Interpolate(function.points, joint));
    for (const auto& row : second.points) {
      if (row.first > joint && row.first < end) rows.push_back(row);
    }
    if (second.points.back().first >= end) rows.emplace_back(end, Interpolate(second.points, end));
    function.points = std::move(rows);
    function.first_part_end = end;
    if (function.points.back().first != end) {
      Unverified(e2, 25, 36,
                 fmt::format("the second table ends at {}, before |D2| = {}: ATB's integral of "
                             "the function (the loading energy of an R factor) stops at its "
                             "last row; sled's table goes on at its last slope",
                             function.points.back().first, end));
    }
    return true;
  }

  // The table's rows reach from at or below x to at or above it.
  static bool Covers(const std::vector<std::pair<double, double>>& rows, double x) {
    return !rows.empty() && rows.front().first <= x && rows.back().first >= x;
  }

  // The table's value at x, linear between its rows (x within them).
  static double Interpolate(const std::vector<std::pair<double, double>>& rows, double x) {
    for (std::size_t k = 1; k < rows.size(); ++k) {
      if (x > rows[k].first) continue;
      const auto& [x0, y0] = rows[k - 1];
      const auto& [x1, y1] = rows[k];
      return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
    }
    return rows.back().second;
  }

  // --- F: allowed contacts -----------------------------------------------------------------
  void ReadF() {
    const int planes = static_cast<int>(deck_.planes.size());
    const int belts = static_cast<int>(deck_.belts.size());
    const int segments = static_cast<int>(deck_.segments.size());
    if (planes > 0) {
      std::vector<int> counts = CountsPerItem("F.1.a", planes, "(18I4)", 18, false,
                                              "a number of contacts", kMaxContacts / 10);
      bool warned = false;
      for (int p = 0; p < planes; ++p) {
        for (int k = 0; k < counts[static_cast<std::size_t>(p)]; ++k) {
          const Card card =
              r_.Next(fmt::format("F.1.b (plane {}, contact {})", p + 1, k + 1), {"(9I4,4X,I4)"});
          if (!warned) {
            Unverified(card, 1, 44,
                       "the F.1 plane-contact cards are read like F.3.b (plane, segment, 2 "
                       "unused, 5 function numbers, NOUT in 41-44)");
            warned = true;
          }
          ReadContact(card, true, p + 1, planes);
        }
      }
    }
    if (belts > 0) {
      std::vector<int> counts = CountsPerItem("F.2.a", belts, "(8I4)", 8, true,
                                              "a number of contacts", kMaxContacts / 10);
      for (int b = 0; b < belts; ++b) {
        for (int k = 0; k < counts[static_cast<std::size_t>(b)]; ++k) {
          const Card card = r_.Next(fmt::format("F.2.b (belt {})", b + 1), {"(9I4)"});
          if (k > 0) {
            Refuse(card, 1, 36, "a belt over more than one segment",
                   "sled reads one F.2.b card per belt; write the belt's path by hand");
            continue;
          }
          ReadBeltContact(card, deck_.belts[static_cast<std::size_t>(b)], b + 1);
        }
      }
    }
    std::vector<int> counts = CountsPerItem("F.3.a", segments, "(18I4)", 18, false,
                                            "a number of contacts", kMaxContacts / 10);
    for (int s = 0; s < segments; ++s) {
      for (int k = 0; k < counts[static_cast<std::size_t>(s)]; ++k) {
        const Card card =
            r_.Next(fmt::format("F.3.b (segment {}, contact {})", s + 1, k + 1), {"(9I4,4X,I4)"});
        ReadContact(card, false, s + 1, segments);
      }
    }
    ReadGlobalGraphicJoints(*this, static_cast<int>(deck_.joints.size()));
    if (bags_ > 0 && !r_.truncated()) ReadAirbagContacts(*this, bags_);
    if (wind_functions_ > 0 && !r_.truncated() && !ReadWind(*this)) unknown_layout_ = true;
    if (harnesses_ > 0 && !r_.truncated() && !unknown_layout_) {
      ReadHarnesses(*this, harnesses_, bags_);
    }
    if (water_ && !r_.truncated() && !unknown_layout_ && !ReadWater(*this)) unknown_layout_ = true;
    if (actuators_ > 0 && !r_.truncated() && !unknown_layout_) ReadActuators(*this, actuators_);
  }

  void ReadContact(const Card& card, bool with_plane, int owner, int owners) {
    ContactCard contact;
    contact.line = card.line;
    contact.with_plane = with_plane;
    const int j = r_.Integer(card, 1, 4, with_plane ? "J, the plane" : "J, the segment");
    if (j != owner && card.line != 0) {
      Invalid(
          card, 1, 4,
          fmt::format("J is {} on a card for {} {}", j, with_plane ? "plane" : "segment", owner),
          "the cards follow the order of the counts on the .a card");
    }
    (void)owners;
    if (with_plane) {
      contact.other = Ref{owner, r_.Range(card, 1, 4), card.label};
      contact.segment = Reference(card, 5, 8, "MS_SEG(1), the segment");
    } else {
      contact.segment = Ref{owner, r_.Range(card, 1, 4), card.label};
      contact.ellipsoid = Reference(card, 5, 8, "MS_SEG(1), the segment's ellipsoid");
      contact.other = Reference(card, 9, 12, "MS_SEG(2), the other segment");
      contact.other_ellipsoid = Reference(card, 13, 16, "MS_SEG(3), the other's ellipsoid");
    }
    ReadFunctionNumbers(card, 17, &contact.force, &contact.friction, &contact.unloading);
    contact.output = r_.Integer(card, 41, 44, "NOUT, the output flag") != 0;
    if (contact.force.number == 0) {
      Refuse(card, 17, 20, "no force function (a rolling constraint)",
             "give the contact a force function; sled has no rolling constraint (E0422)");
      return;
    }
    deck_.contacts.push_back(std::move(contact));
  }

  void ReadBeltContact(const Card& card, BeltCard& belt, int number) {
    const int j = r_.Integer(card, 1, 4, "J, the belt");
    if (j != number && card.line != 0) {
      Invalid(card, 1, 4, fmt::format("J is {} on the card of belt {}", j, number),
              "the cards follow the belts' order");
    }
    belt.contact_line = card.line;
    if (number == 1) {
      Unverified(card, 17, 20,
                 fmt::format("a belt's force function is read as force in {} (UNITM) against "
                             "strain (elongation over length, no unit)",
                             deck_.units.force));
    }
    belt.segment = Reference(card, 5, 8, "MS_SEG(1), the segment");
    ReadFunctionNumbers(card, 17, &belt.force, &belt.friction, &belt.unloading);
    // NX and NOUT come from the next line by format reversion (9I4 for 11 items).
    const Card extra =
        r_.Next(fmt::format("F.2.b (belt {}, NX and NOUT)", number), {"(9I4)", 2, true});
    Unverified(extra, 1, 8,
               "NX and NOUT of F.2.b are read from the next line (format reversion of 9I4 "
               "for 11 items), as ATB V.3 does");
    const int nx = r_.Integer(extra, 1, 4, "NX");
    belt.output = r_.Integer(extra, 5, 8, "NOUT, the output flag") != 0;
    if (nx != 0) {
      Refuse(extra, 1, 4, fmt::format("NX is {}", nx), "the meaning of NX is not documented");
    }
  }

  bool unknown_layout_ = false;  // the deck goes on with cards whose layout is not known
  int harnesses_ = 0;            // D.1.a NHRNSS
  int wind_functions_ = 0;       // D.1.a NWINDF: E.6 cards after the E cards, then F.7
  bool water_ = false;           // D.1.a NWATER: the F.9 cards
  int bags_ = 0;                 // D.1.a NBAG
  int actuators_ = 0;            // D.1.b NRTORQ: the F.10 cards
};

}  // namespace

Deck ReadDeck(DeckSource& source) {
  Deck deck;
  return DeckReader(source, deck).Read();
}

}  // namespace sled::lang::legacy
