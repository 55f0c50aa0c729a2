// F.8: harnesses (ATB's INPUT_HARNESS; the points' meaning from HBPLAY and HBELT). A harness belt
// is a chain of points: each lies on a segment KS (a vehicle, the ground or a body segment; KS
// above 100 is tie point KS / 100 on segment KS mod 100, shared by the belts that end there), on
// its ellipsoid KE or fixed (KE = 0). sled's harness belts run from an anchor in the harness's
// frame over body segments' ellipsoids to another anchor, and belts that end at the same anchor
// exchange webbing there: the first and last points must be anchors in one frame, the others
// wrapped body segments. A guide ring (a point between the ends fixed in the harness's frame, KE
// 0) splits the belt into two sled belts that end at the ring and are tied there: webbing passes
// through it as through a tie point.
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "lang/legacy/restraint_readers.h"

namespace sled::lang::legacy {
namespace {

constexpr int kMaxHarnesses = 5;
constexpr int kMaxHarnessBelts = 20;
constexpr int kMaxHarnessPoints = 100;
// sled joins two anchors of a harness closer than this (compiler/lower/lower_belts.cpp) [m].
constexpr double kTieDistance = 1e-6;

double MetresPer(const std::string& length_unit) {
  static const std::map<std::string, double> kMetres = {
      {"in", 0.0254}, {"ft", 0.3048}, {"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}};
  const auto found = kMetres.find(length_unit);
  return found == kMetres.end() ? 1.0 : found->second;
}

double Distance(const Vec3& a, const Vec3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

class HarnessReader {
 public:
  HarnessReader(DeckFields& fields, int bags)
      : f_(fields),
        r_(fields.source()),
        segments_(static_cast<int>(fields.deck().segments.size())),
        bags_(bags) {}

  void Read(int harnesses) {
    const Card head = r_.Next("F.8.a", {"(5I4,20X,I4,F8.0)"});
    std::vector<int> belts;
    int total = 0;
    for (int h = 0; h < kMaxHarnesses; ++h) {
      const int first = 4 * h + 1;
      const int count =
          f_.Count(head, first, first + 3, "NBLTPH, the number of belts of a harness", 20);
      if (h >= harnesses) {
        if (count != 0) {
          f_.Ignored(head, first, first + 3,
                     fmt::format("harness {} has {} belts, but D.1.a's NHRNSS is {}", h + 1, count,
                                 harnesses),
                     "ATB reads the belts of the first NHRNSS harnesses only");
        }
        continue;
      }
      belts.push_back(count);
      total += count;
    }
    if (total > kMaxHarnessBelts) {
      f_.Invalid(head, 1, 20, fmt::format("{} harness belts", total),
                 fmt::format("ATB takes {} harness belts at most", kMaxHarnessBelts));
      return;
    }
    // MAXITR and EPSDEL steer ATB's iterative rebalancing of the webbing between the points
    // (HPTURB); sled's harness is solved without it. Read for their diagnostics only.
    r_.Integer(head, 41, 44, "MAXITR, the iterations of the harness rebalancing");
    r_.Real(head, 45, 52, "EPSDEL, the tolerance of the harness rebalancing");
    for (std::size_t h = 0; h < belts.size() && !r_.truncated(); ++h) {
      if (belts[h] > 0) ReadHarness(head, static_cast<int>(h) + 1, belts[h]);
    }
  }

 private:
  // An end's frame from KS mod 100: a vehicle (0-based), -1 for the ground; nothing when it is not
  // a frame sled can anchor a harness in (reported).
  std::optional<int> AnchorFrame(const Card& card, int segment) {
    const std::optional<DeckFrame> frame =
        f_.FrameOf(card, 1, 4, segment, bags_, "KS, the point's segment");
    if (!frame) return std::nullopt;
    if (frame->kind == DeckFrame::Kind::kSegment) {
      f_.Refuse(card, 1, 4,
                fmt::format("KS is {}: the belt ends on body segment {} (a buckle or a tie point "
                            "on the body)",
                            segment, segment),
                "sled's harness belts end at anchors in the harness's frame: anchor this end in "
                "the vehicle, or convert the harness by hand");
      return std::nullopt;
    }
    return frame->kind == DeckFrame::Kind::kVehicle ? frame->index : -1;
  }

  void ReadHarness(const Card& head, int number, int belts) {
    HarnessCard harness;
    harness.line = head.line;
    const std::vector<int> points =
        f_.CountsPerItem(fmt::format("F.8.b (harness {})", number), belts, "(18I4)", 18, true,
                         "NPTSPB, the number of points of a belt", kMaxHarnessPoints);
    std::optional<int> frame;
    for (int b = 0; b < belts && !r_.truncated(); ++b) {
      const int count = points[static_cast<std::size_t>(b)];
      if (count == 0) continue;  // ATB skips a belt without points
      HarnessBeltCard belt;
      const Card card =
          r_.Next(fmt::format("F.8.c (harness {}, belt {})", number, b + 1), {"(5I4,F12.6)"});
      belt.line = card.line;
      Ref friction;
      f_.ReadFunctionNumbers(card, 1, &belt.force, &friction, &belt.unloading);
      if (belt.force.number == 0 && card.line != 0) {
        f_.Refuse(card, 1, 4, "a harness belt without a force function",
                  "give the webbing's force against strain (an E function) in columns 1-4");
      }
      if (friction.number != 0) {
        // INPUT_HARNESS stores it with the webbing's functions of each span (FDINIT), but HBELT
        // and HSETC read friction from the points' function tables (IBAR(3)) only.
        f_.Ignored(card, 17, 20,
                   fmt::format("the belt's friction function {}: ATB stores it with the "
                               "webbing's functions, but its harness (HBELT, HSETC) takes friction "
                               "from the points' functions only",
                               friction.number),
                   "give the friction at the points (F.8.d.1 columns 33-36); this one is left "
                   "out, as ATB leaves it out");
      }
      belt.slack = r_.Real(card, 21, 32, "XLONG, the reference slack");
      if (belt.slack < 0) {
        f_.Refuse(
            card, 21, 32,
            fmt::format("a reference slack of {} (webbing shorter than its path)", belt.slack),
            "sled's `slack` is zero or more; convert the pretension by hand "
            "(`pretension = ...`)");
        belt.slack = 0;
      }
      if (count < 3 && card.line != 0) {
        f_.Invalid(card, 1, 32,
                   fmt::format("harness {}, belt {} has {} points", number, b + 1, count),
                   "a harness belt runs from an anchor over at least one body segment to "
                   "another anchor: three points or more");
      }
      belt.number = b + 1;
      for (int k = 0; k < count && !r_.truncated(); ++k) {
        ReadPoint(number, b + 1, k + 1, k == 0 || k + 1 == count, belt, frame);
      }
      const double slack = belt.slack;
      if (SplitAtRings(std::move(belt), harness.belts) && slack != 0) {
        f_.Approximated(card, 21, 32,
                        "the reference slack goes to the belt's part before its first guide "
                        "ring; ATB lengthens the whole webbing, which differs where a ring's "
                        "friction holds the webbing back");
      }
    }
    harness.vehicle = frame.value_or(-1);
    CheckTiePoints(harness);
    f_.deck().harnesses.push_back(std::move(harness));
  }

  void ReadPoint(int harness, int belt, int number, bool end, HarnessBeltCard& out,
                 std::optional<int>& frame) {
    const std::string where = fmt::format("harness {}, belt {}, point {}", harness, belt, number);
    const Card card = r_.Next(fmt::format("F.8.d.1 ({})", where), {"(9I4,3F12.0)"});
    const Card more = r_.Next(fmt::format("F.8.d.2 ({})", where), {"(6F12.0)"});
    HarnessPoint point;
    point.line = card.line;
    const int ks = r_.Integer(card, 1, 4, "KS, the point's segment");
    const int ke = r_.Integer(card, 5, 8, "KE, the point's ellipsoid");
    const int npd = r_.Integer(card, 9, 12, "NPD");
    const int ndr = r_.Integer(card, 13, 16, "NDR");
    const char* names[] = {"the force-deflection function", "the inertial-spike function",
                           "the R-factor function", "the G-factor function"};
    for (int i = 0; i < 4; ++i) {
      const int first = 17 + 4 * i;
      const int value = r_.Integer(card, first, first + 3, names[i]);
      if (value != 0) {
        f_.Refuse(card, first, first + 3,
                  fmt::format("{} of a harness point is {}", names[i], value),
                  "ATB's harness uses a point's friction function only (columns 33-36); what "
                  "the others do at a point is not documented");
      }
    }
    point.friction = f_.Reference(card, 33, 36, "NF(5), the friction function");
    // A point between the ends on a vehicle or the ground (numbers past the body's): a guide ring.
    point.ring = !end && ks > segments_ && ks <= 100;
    if (point.friction.number < 0 && point.ring) {
      point.friction.number = -point.friction.number;  // a fixed ring never lets the webbing go
    } else if (point.friction.number < 0) {
      f_.Refuse(card, 33, 36,
                "a negative friction function: a point the webbing may not leave (a ring)",
                "sled's webbing leaves a segment when it lifts off; give the function's number "
                "without the sign");
      point.friction.number = -point.friction.number;
    }
    const Vec3 reference = f_.Triple(card, 37, 12, "BAR, the base reference point");
    const Vec3 offset = f_.Triple(more, 1, 12, "the offset");
    const Vec3 preferred = f_.Triple(more, 37, 12, "the preferred direction");
    if (card.line == 0) return;
    if (ks < 0) {
      f_.Refuse(card, 1, 4, fmt::format("KS is {}", ks),
                "a negative point segment is not documented; give the segment's number");
      return;
    }
    if (end) {
      // ATB stops (STOP 60, 61) on an end without NPD or NDR; it uses NPD's preferred direction
      // for the friction at the point, and sled's anchors hold the webbing.
      if (npd == 0) {
        f_.Invalid(card, 9, 12, "NPD is 0 at an end of the belt",
                   "ATB requires NPD and NDR at a belt's first and last points (STOP 60)");
      }
      if (ndr == 0) {
        f_.Invalid(card, 13, 16, "NDR is 0 at an end of the belt",
                   "ATB requires NPD and NDR at a belt's first and last points (STOP 61)");
      }
      point.tie = ks > 100 ? ks / 100 : 0;
      const std::optional<int> anchor_frame = AnchorFrame(card, ks > 100 ? ks % 100 : ks);
      if (anchor_frame) {
        if (frame && *frame != *anchor_frame) {
          f_.Refuse(card, 1, 4, "the harness's belts are anchored in two different frames",
                    "sled anchors all belts of a harness in the harness's frame; split the "
                    "harness");
        }
        frame = anchor_frame;
      }
      if (ke != 0) {
        f_.Refuse(card, 5, 8, fmt::format("KE is {}: an end on a contact surface", ke),
                  "sled's anchors are points; give the anchor's point with KE = 0");
      }
      point.anchor = {reference[0] + offset[0], reference[1] + offset[1], reference[2] + offset[2]};
      point.segment = Ref{ks, r_.Range(card, 1, 4), card.label};
      if (point.tie == 0 && point.friction.number != 0) {
        f_.Refuse(card, 33, 36,
                  "friction at an anchor that is not a tie point: ATB's HSETC gives an end with "
                  "a friction function the stick-or-slip conditions of a point (the force across "
                  "it against the friction times the force along its normal), and HBELT caps "
                  "the force the end passes on by the same law",
                  "sled's anchors hold the webbing; only tie points (KS above 100) let it pass "
                  "with the harness's friction");
      } else if (point.tie != 0 && point.friction.number != 0 && npd != 0 && preferred != Vec3{}) {
        f_.Approximated(more, 37, 72,
                        "ATB splits the friction at a tie point along this preferred direction; "
                        "sled's harness friction holds the webbing back along the belts");
      }
    } else {
      if (ks > 100) {
        f_.Refuse(card, 1, 4, "a tie point between a belt's ends",
                  "sled's harness belts exchange webbing where they end at the same anchor; "
                  "split the belt there");
        return;
      }
      if (point.ring) {
        ReadRing(card, ks, ke, npd, ndr,
                 {reference[0] + offset[0], reference[1] + offset[1], reference[2] + offset[2]},
                 frame, point);
        out.points.push_back(point);
        return;
      }
      if (ks < 1) {
        f_.Invalid(card, 1, 4, "KS is 0 at a point between the belt's ends",
                   "give the segment the webbing passes (a body segment, or a vehicle or the "
                   "ground for a guide ring)");
        return;
      }
      if (ke != ks) {
        f_.Refuse(card, 5, 8,
                  ke == 0
                      ? "KE is 0: a point fixed on the segment, off its surface"
                      : fmt::format("KE is {}: an ellipsoid that is not segment {}'s own", ke, ks),
                  "sled's webbing wraps a segment's own ellipsoid; set KE to the segment's "
                  "number");
      }
      if (npd != 0) {
        f_.Refuse(card, 9, 12, "NPD: a preferred direction of the friction at a wrapped point",
                  "sled's webbing slides along its own path; leave NPD blank");
      }
      if (ndr != 0) {
        f_.Refuse(card, 13, 16, fmt::format("NDR is {} at a point between the belt's ends", ndr),
                  "what NDR does between a belt's ends is not documented; leave it blank");
      }
      if (offset != Vec3{}) {
        f_.Ignored(more, 1, 36, "the offset of a point on an ellipsoid",
                   "ATB replaces it with the ellipsoid's centre; leave it blank");
      }
      if (preferred != Vec3{} && npd == 0) {
        f_.Ignored(more, 37, 72, "a preferred direction with NPD = 0",
                   "ATB uses it only when NPD is set; leave it blank");
      }
      f_.Approximated(card, 37, 72,
                      "ATB runs the webbing through a point fixed on the ellipsoid (this base "
                      "reference point, scaled to its surface); sled lays the webbing over the "
                      "ellipsoid where the path's geometry puts it and lets it slide");
      point.segment = Ref{ks, r_.Range(card, 1, 4), card.label};
    }
    out.points.push_back(point);
  }

  // A guide ring: KS a vehicle or the ground (the harness's frame), KE 0, the point BAR plus the
  // offset in that frame. It becomes the end of the belt's part before it and the start of the
  // part after, tied to each other (SplitAtRings).
  void ReadRing(const Card& card, int ks, int ke, int npd, int ndr, const Vec3& at,
                std::optional<int>& frame, HarnessPoint& point) {
    const std::optional<int> ring_frame = AnchorFrame(card, ks);
    if (ring_frame) {
      if (frame && *frame != *ring_frame) {
        f_.Refuse(card, 1, 4, "a guide ring in another frame than the harness's anchors",
                  "sled's harness holds its anchors and rings in one frame; split the harness");
      }
      frame = ring_frame;
    }
    if (ke != 0) {
      f_.Refuse(card, 5, 8, fmt::format("KE is {}: a guide ring on a contact surface", ke),
                "sled's guide rings are points; give the ring's point with KE = 0");
    }
    if (npd != 0 || ndr != 0) {
      f_.Refuse(card, npd != 0 ? 9 : 13, npd != 0 ? 12 : 16,
                "NPD or NDR at a guide ring (a preferred direction of its friction)",
                "sled's ring holds the webbing back along the belt; leave NPD and NDR blank");
    }
    point.anchor = at;
    point.segment = Ref{ks, r_.Range(card, 1, 4), card.label};
    point.tie = next_ring_tie_++;
  }

  // A belt with guide rings becomes one belt per stretch between them, each ending at the ring
  // it shares with the next, tied there with the ring's friction. Each stretch must pass a body
  // segment (a sled belt does); XLONG stays with the first (exact when the rings are
  // frictionless: the webbing then spreads over the parts freely).
  // Returns whether a ring has friction.
  bool SplitAtRings(HarnessBeltCard belt, std::vector<HarnessBeltCard>& belts) {
    const std::size_t n = belt.points.size();
    bool split = false;
    bool friction = false;
    for (std::size_t k = 1; k + 1 < n; ++k) {
      split = split || belt.points[k].ring;
      friction = friction || (belt.points[k].ring && belt.points[k].friction.number != 0);
    }
    if (!split) {
      belts.push_back(std::move(belt));
      return false;
    }
    std::size_t first = 0;
    int part = 1;
    for (std::size_t k = 1; k < n; ++k) {
      if (!belt.points[k].ring && k + 1 != n) continue;
      HarnessBeltCard piece = belt;
      piece.part = part++;
      piece.points.assign(belt.points.begin() + static_cast<std::ptrdiff_t>(first),
                          belt.points.begin() + static_cast<std::ptrdiff_t>(k) + 1);
      if (piece.part > 1) piece.slack = 0;
      if (piece.points.size() < 3) {
        r_.ReportAt(DiagnosticKind::kDeckNotExpressible, belt.points[k].segment.where,
                    fmt::format("card {}: no body segment between this point and the point on "
                                "line {}, one of them a guide ring",
                                belt.points[k].segment.card, belt.points[first].line),
                    "a sled belt passes at least one body segment (E0414): a ring next to an "
                    "anchor or another ring cannot be converted; anchor the belt at the ring");
      }
      belts.push_back(std::move(piece));
      first = k;
    }
    return friction;
  }

  // ATB ties the ends that share a tie number; sled ties anchors of two belts that lie within
  // kTieDistance of each other. The two must agree.
  void CheckTiePoints(const HarnessCard& harness) {
    const double metres = MetresPer(f_.deck().units.length);
    std::vector<const HarnessPoint*> ends;
    for (const HarnessBeltCard& belt : harness.belts) {
      if (belt.points.size() < 2) continue;
      ends.push_back(&belt.points.front());
      ends.push_back(&belt.points.back());
    }
    for (std::size_t i = 0; i < ends.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        const HarnessPoint& a = *ends[j];
        const HarnessPoint& b = *ends[i];
        const bool same_tie = a.tie != 0 && a.tie == b.tie;
        const bool together = Distance(a.anchor, b.anchor) * metres <= kTieDistance;
        if (same_tie && !together) {
          r_.ReportAt(DiagnosticKind::kDeckInvalidValue, b.segment.where,
                      fmt::format("card {}: tie point {} is at ({}, {}, {}) here and at ({}, {}, "
                                  "{}) on line {}",
                                  b.segment.card, b.tie, b.anchor[0], b.anchor[1], b.anchor[2],
                                  a.anchor[0], a.anchor[1], a.anchor[2], a.line),
                      "the ends of one tie point are one point: give them the same base "
                      "reference point and offset");
          return;
        }
        if (!same_tie && together) {
          r_.ReportAt(DiagnosticKind::kDeckNotExpressible, b.segment.where,
                      fmt::format("card {}: this end is where the end on line {} is, but ATB "
                                  "does not tie them (tie numbers {} and {})",
                                  b.segment.card, a.line, b.tie, a.tie),
                      "sled joins the belts of a harness that end at one anchor; give the two "
                      "ends one tie number (KS above 100) or move one of them");
          return;
        }
      }
    }
  }

  DeckFields& f_;
  DeckSource& r_;
  int segments_, bags_;
  int next_ring_tie_ = 1000;  // guide rings' tie numbers, past ATB's (KS / 100 < 1000)
};

}  // namespace

void ReadHarnesses(DeckFields& fields, int harnesses, int bags) {
  HarnessReader(fields, bags).Read(harnesses);
}

}  // namespace sled::lang::legacy
