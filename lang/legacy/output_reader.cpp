#include "lang/legacy/output_reader.h"

#include <algorithm>
#include <string>

#include <fmt/format.h>

namespace sled::lang::legacy {
namespace {

constexpr int kMaxRequests = 20;    // MAX_HCARD_TTH: time histories of one type
constexpr int kMaxTotalBodies = 5;  // MAX_TOTAL_BODY: H.10 sets

class OutputReader {
 public:
  OutputReader(DeckFields& fields, int bags, int actuators)
      : f_(fields), r_(fields.source()), bags_(bags), actuators_(actuators) {}

  void Read() {
    constexpr OutputCard::Kind kPointKinds[] = {
        OutputCard::Kind::kAcceleration, OutputCard::Kind::kVelocity, OutputCard::Kind::kPosition};
    // Decks of versions before V.3 end with or before H.3; one that stops anywhere else is cut
    // short, and the next card's read reports it (E0501).
    if (Ended("H.1.a")) return;
    for (int k = 1; k <= 3 && !r_.truncated(); ++k) ReadPoints(k, kPointKinds[k - 1]);
    if (Ended("H.4")) return;
    for (int k = 4; k <= 9 && !r_.truncated(); ++k) {
      if (k == 7) {
        ReadJoints();
      } else {
        ReadPairs(k);
      }
    }
    if (!r_.truncated()) ReadTotalBodies();
    if (actuators_ > 0 && !r_.truncated()) ReadActuatorTorques();
  }

 private:
  // A deck that stops before its H cards or after H.3, as decks of versions before V.3 do: ATB
  // V.3 would stop at the end of the file; the rest is read as zero counts, with W0505 at the end
  // of the deck.
  bool Ended(const std::string& label) {
    if (r_.truncated()) return true;
    if (!r_.OnlyBlankLinesRemain()) return false;
    r_.ReportAt(DiagnosticKind::kDeckMissingCards, r_.EndOfDeck(),
                fmt::format("the deck ends before card {}: the output requests from there on are "
                            "read as zero counts (ATB V.3 would stop at the end of the file)",
                            label),
                "end a V.3 deck with its H.1 to H.10 cards; a blank card is a zero count");
    return true;
  }

  // H.k.a (I6,2I3,3F12.6,I6): KSG, KREF, MSG, point, NODPR; then KSG - 1 H.k.b cards
  // (I9,I3,3F12.6,I6), or the dummy (I2) when KSG <= 1.
  void ReadPoints(int k, OutputCard::Kind kind) {
    const Card head = r_.Next(fmt::format("H.{}.a", k), {"(I6,2I3,3F12.6,I6)"});
    const int count = f_.Count(head, 1, 6, "KSG, the number of requests", kMaxRequests);
    if (count >= 1) {
      ReadPoint(head, kind, 7, 9);
    } else {
      IgnoredWhenZero(head, 7, 48, "KREF, MSG and the point");
    }
    if (count <= 1) {
      const Card dummy = r_.Next(fmt::format("H.{}.b (dummy)", k), {"(I2)"});
      // ATB reads the dummy card whatever it holds; one that is not blank is often the next
      // group's card, which a deck without its dummy card loses.
      // A dummy is blank or 0; a `.lin` READ takes one item, so only that counts there.
      const bool list_directed = dummy.item_count > 0;
      const bool blank = r_.Integer(dummy, 1, 2, "the dummy") == 0 &&
                         (list_directed || dummy.text.size() <= 2 ||
                          dummy.text.find_first_not_of(' ', 2) == std::string_view::npos);
      if (dummy.line != 0 && !blank) {
        f_.Ignored(dummy, 1, 2,
                   fmt::format("with KSG = {} on H.{}.a, ATB reads this card as the dummy card "
                               "and ignores what it holds",
                               count, k),
                   "if this is the next card, the deck lacks its blank dummy card: insert one");
      }
      return;
    }
    for (int i = 1; i < count && !r_.truncated(); ++i) {
      ReadPoint(r_.Next(fmt::format("H.{}.b (request {})", k, i + 1), {"(I9,I3,3F12.6,I6)"}), kind,
                1, 9);
    }
  }

  void ReadPoint(const Card& card, OutputCard::Kind kind, int kref_first, int kref_last) {
    OutputCard output;
    output.line = card.line;
    output.kind = kind;
    output.segment = f_.Reference(card, 10, 12, "MSG, the segment");
    output.point = f_.Triple(card, 13, 12, "the point on the segment");
    const int nodes = r_.Integer(card, 49, 54, "NODPR, the node of a deformable segment");
    if (nodes != 0) {
      f_.Ignored(card, 49, 54, fmt::format("NODPR is {}: a node of a deformable segment", nodes),
                 "the deck has no deformable segments (B.1's NFBOD is refused); leave it blank");
    }
    if (output.segment.number < 0 && kind == OutputCard::Kind::kAcceleration) {
      // Before ATB IV.3 a negative MSG asked for a "0 G" accelerometer; V.3 prints a note and
      // outputs the same acceleration as for the positive number.
      f_.Ignored(card, 10, 12, "a negative MSG (the 0 G accelerometer of ATB before IV.3)",
                 "ATB V.3 outputs the segment's acceleration as for a positive MSG");
      output.segment.number = -output.segment.number;
    }
    if (!ReadFrame(card, kref_first, kref_last, output)) return;
    f_.deck().outputs.push_back(std::move(output));
  }

  // KREF: 0 is the card's default frame; otherwise a body segment, a vehicle or the ground.
  bool ReadFrame(const Card& card, int first, int last, OutputCard& output) {
    output.reference = f_.Reference(card, first, last, "KREF, the reference segment");
    if (output.reference.number == 0) return true;
    output.frame = f_.FrameOf(card, first, last, output.reference.number, bags_,
                              "KREF, the reference segment");
    return output.frame.has_value();
  }

  // With a zero count ATB reads the rest of the card and uses none of it.
  void IgnoredWhenZero(const Card& card, int first, int last, std::string_view what) {
    if (card.line == 0) return;
    const bool list_directed = card.item_count > 0;
    if (list_directed) return;  // a `.lin` READ stops after the count
    const auto from = static_cast<std::size_t>(first) - 1;
    if (card.text.size() <= from) return;
    const std::string_view rest = card.text.substr(
        from, static_cast<std::size_t>(last) - static_cast<std::size_t>(first) + 1);
    if (rest.find_first_not_of(" 0.") == std::string_view::npos) return;
    f_.Ignored(card, first, last, fmt::format("the count is 0, so ATB ignores {}", what),
               "leave these columns blank, or set the count");
  }

  // H.4, H.5, H.6, H.8 and H.9: (I6,22I3,/,(I9,21I3)): KSG, then KSG pairs (KREF, MSG) in one
  // READ, eleven pairs on the first card and on each further one.
  void ReadPairs(int k) {
    Card card = r_.Next(fmt::format("H.{}", k), {"(I6,22I3)", 1});
    const int count = f_.Count(card, 1, 6, "KSG, the number of requests", kMaxRequests);
    if (count > 0 && k == 8) {
      f_.Approximated(card, 1, 6,
                      fmt::format("KSG is {}: the wind forces on segments, which sled does not "
                                  "write (no value of the run changes; the wind's work is in "
                                  "the energy balance's applied work)",
                                  count));
    }
    r_.Extend(card, 2 * std::min(count, 11));
    for (int i = 0; i < count && !r_.truncated(); ++i) {
      const int on_card = i % 11;
      if (i > 0 && on_card == 0) {
        const int items = 2 * std::min(count - i, 11);
        card = r_.Next(fmt::format("H.{} (line {})", k, i / 11 + 1), {"(I9,21I3)", items, true});
      }
      // The first card holds KSG in columns 1-6 and the pairs from column 7; a further card
      // starts with its first KREF in columns 1-9. Either way a pair ends at column 12 + 6 p.
      const int msg_first = 10 + 6 * on_card;
      const int kref_first = (i >= 11 && on_card == 0) ? 1 : msg_first - 3;
      const int kref_last = msg_first - 1;
      if (k == 8) continue;  // not written, warned above
      OutputCard output;
      output.line = card.line;
      output.kind = k == 4   ? OutputCard::Kind::kAngularAcceleration
                    : k == 5 ? OutputCard::Kind::kAngularVelocity
                    : k == 6 ? OutputCard::Kind::kOrientation
                             : OutputCard::Kind::kJointForce;
      output.segment = f_.Reference(card, msg_first, msg_first + 2,
                                    k == 9 ? "MSG, the joint" : "MSG, the segment");
      if (k == 9) {
        const int kref = r_.Integer(card, kref_first, kref_last, "KREF, the reference segment");
        if (kref != 0) {
          f_.Approximated(card, kref_first, kref_last,
                          fmt::format("KREF is {}: sled's joint forces and torques are in the "
                                      "joint's child segment's axes, not in segment {}'s",
                                      kref, kref));
        }
      } else if (!ReadFrame(card, kref_first, kref_last, output)) {
        continue;
      }
      f_.deck().outputs.push_back(std::move(output));
    }
  }

  // H.7 (12I6,/,(I12,10I6)): KSG, then KSG joint numbers in one READ.
  void ReadJoints() {
    Card card = r_.Next("H.7", {"(12I6)", 1});
    const int count = f_.Count(card, 1, 6, "KSG, the number of joints", kMaxRequests);
    r_.Extend(card, std::min(count, 11));
    for (int i = 0; i < count && !r_.truncated(); ++i) {
      const int on_card = i % 11;
      if (i > 0 && on_card == 0) {
        card = r_.Next(fmt::format("H.7 (line {})", i / 11 + 1),
                       {"(I12,10I6)", std::min(count - i, 11), true});
      }
      const int first = i < 11 ? 7 + 6 * on_card : (on_card == 0 ? 1 : 13 + 6 * (on_card - 1));
      const int last = (i >= 11 && on_card == 0) ? 12 : first + 5;
      OutputCard output;
      output.line = card.line;
      output.kind = OutputCard::Kind::kJointParameters;
      output.segment = f_.Reference(card, first, last, "the joint");
      f_.deck().outputs.push_back(std::move(output));
    }
  }

  // H.10.a (I6) MCG; per set H.10.b (24I3) the reference segment, N and N segments, and H.10.c
  // (6F10.0,4I2) the origin, axes and rotation sequence. sled has no total-body output: the cards
  // are read (so the deck stays aligned) and each set is left out with a W0504 that names it; an
  // output changes no value of the run.
  void ReadTotalBodies() {
    const Card head = r_.Next("H.10.a", {"(I6)"});
    const int sets = f_.Count(head, 1, 6, "MCG, the number of total-body sets", kMaxTotalBodies);
    for (int s = 0; s < sets && !r_.truncated(); ++s) {
      Card set = r_.Next(fmt::format("H.10.b (set {})", s + 1), {"(24I3)", 2});
      const int members = f_.Count(set, 4, 6, "N, the number of segments", 22);
      r_.Extend(set, members);
      std::string segments;
      for (int m = 0; m < members; ++m) {
        const int at = 7 + 3 * m;
        const int segment = r_.Integer(set, at, at + 2, "a segment of the set");
        if (segment < 1 || segment > static_cast<int>(f_.deck().segments.size())) {
          f_.Invalid(set, at, at + 2, fmt::format("segment {} is not a body segment", segment),
                     "a total-body set lists body segments (1 to NSEG)");
        }
        segments += fmt::format("{}{}", m == 0 ? "" : ", ", segment);
      }
      r_.Next(fmt::format("H.10.c (set {})", s + 1), {"(6F10.0,4I2)"});
      f_.Approximated(set, 1, 6 + 3 * members,
                      fmt::format("the centre of gravity of segments {} (H.10 set {}) is not "
                                  "written: sled has no total-body output (no value of the run "
                                  "changes; request `position` of each segment and weigh them by "
                                  "their masses for it)",
                                  segments, s + 1));
    }
  }

  // H.11 (INPUT_H11_CARDS, only when D.1.b's NRTORQ is not 0): (12I6, /, (I12, 10I6)) KSG and
  // KSG actuator numbers, whose torque histories ATB prints. KSG below 1 stops ATB (STOP 741,
  // 742). sled writes no actuator output: each request is left out with a W0504 (no value of
  // the run changes).
  void ReadActuatorTorques() {
    Card head = r_.Next("H.11", {"(12I6)", 1});
    const int count = f_.Count(head, 1, 6, "KSG, the number of actuator torques", kMaxRequests);
    if (count < 1) {
      f_.Invalid(head, 1, 6,
                 "KSG is 0: ATB stops on an H.11 card without an actuator (STOP 741, 742)",
                 "list at least one actuator's number, 1 to NRTORQ");
      return;
    }
    const int on_first = std::min(count, 11);
    r_.Extend(head, on_first);
    std::string listed;
    for (int k = 0; k < on_first; ++k) {
      listed += fmt::format("{}{}", k == 0 ? "" : ", ",
                            r_.Integer(head, 7 + 6 * k, 12 + 6 * k, "an actuator's number"));
    }
    if (count > on_first) {
      const Card more = r_.Next("H.11 (continued)", {"(I12,10I6)", count - on_first, true});
      for (int k = 0; k < count - on_first; ++k) {
        const int first = k == 0 ? 1 : 13 + 6 * (k - 1);
        const int last = k == 0 ? 12 : first + 5;
        listed += fmt::format(", {}", r_.Integer(more, first, last, "an actuator's number"));
      }
    }
    f_.Approximated(head, 1, 6 + 6 * on_first,
                    fmt::format("the torque histories of actuators {} (H.11) are not written: "
                                "sled has no actuator output (no value of the run changes; "
                                "request `joint_angle` of the driven joints to follow them)",
                                listed));
  }

  DeckFields& f_;
  DeckSource& r_;
  int bags_;
  int actuators_;
};

}  // namespace

void ReadOutputRequests(DeckFields& fields, int bags, int actuators) {
  OutputReader(fields, bags, actuators).Read();
}

}  // namespace sled::lang::legacy
