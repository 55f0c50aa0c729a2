#!/usr/bin/env bash
# The standard library's body family (stdlib/humans/*.sled but male50), made from male50 by
# scripts/scale_body.py. Each body's stated inputs are published figures of the Hybrid III dummy
# of that size; the sources are written into each file's header.
#
#   scripts/body_family.sh [OUT_DIR]     (default: stdlib/humans)
#
# tests/compiler/body_family_test.cpp runs this into a temporary folder and requires the result
# to equal the files in stdlib/humans, so the files are what this script makes.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$root/stdlib/humans}"
scale() { python3 "$root/scripts/scale_body.py" "$@"; }
nhtsa_family="the family table of NHTSA's Hybrid III page"

scale --name female05 --dummy hybrid3_5f --stature 59.1in --mass 108.03lb \
  --segment-mass head=8.23lb --segment-mass neck=2.0lb --segment-mass upper_torso=26.5lb \
  --segment-mass lower_torso=29.2lb --segment-mass upper_arms=5.2lb \
  --segment-mass lower_arms=5.2lb --segment-mass upper_legs=13.8lb \
  --segment-mass lower_legs_feet=17.9lb --head-length 7.2in \
  --title "a 15-segment 5th-percentile adult female, the Hybrid III 5th female's size" \
  --source "Stature 59.1 in (1501 mm): $nhtsa_family" \
  --source "(http://www.nhtsa.gov/Research/ci.Hybrid+III+5th+Percentile+Female.print)." \
  --source "Segment weights (lb) from the same page: head 8.23, neck 2.0, upper torso 26.5," \
  --source "lower torso 29.2, upper arms 5.2, lower arms and hands 5.2, upper legs 13.8, lower" \
  --source "legs and feet 17.9; total 108.03 lb (49.00 kg; the family table rounds it to 108.0)." \
  --source "Upper torso is taken as the thorax, lower torso as abdomen and pelvis (an assumption:" \
  --source "the dummy's parts do not split where male50's segments do). Head depth 7.2 in" \
  --source "(183 mm), the same page, sizes the head." > "$out/female05.sled"

scale --name male95 --stature 188cm --mass 223lb \
  --title "a 15-segment 95th-percentile adult male, the Hybrid III 95th male's size" \
  --source "Stature 188 cm and mass 223 lb (101.2 kg; the page rounds it to 100 kg): the Hybrid III" \
  --source "95th male as https://en.wikipedia.org/wiki/Hybrid_III gives it. No segment weights of" \
  --source "this dummy were found: every segment is male50's times the mass ratio." > "$out/male95.sled"

scale --name child6 --stature 45.0in --mass 51.6lb \
  --segment-mass head=7.66lb --segment-mass neck=1.20lb --segment-mass upper_torso=12.25lb \
  --segment-mass lower_torso=13.75lb --segment-mass upper_arms=2.10lb \
  --segment-mass lower_arms=2.74lb --segment-mass upper_legs=6.40lb \
  --segment-mass lower_legs_feet=5.50lb --head-length 6.80in \
  --title "a 15-segment 6-year-old child, the Hybrid III 6-year-old's size" \
  --source "Stature 45.0 in (1143 mm), weight 51.6 lb (23.41 kg):" \
  --source "$nhtsa_family" \
  --source "(http://www.nhtsa.gov/Research/ci.HYBRID+III+6-Year+Old+Physical+Data.print)." \
  --source "Segment weights (lb) from the same page: head 7.66, neck 1.20, upper torso 12.25," \
  --source "lower torso 13.75, upper arms 2.10, lower arms and hands 2.74, upper legs 6.40, lower" \
  --source "legs and feet 5.50. Upper torso is taken as the thorax, lower torso as abdomen and" \
  --source "pelvis (an assumption). Head length 6.80 in (173 mm), the same page, sizes the head:" \
  --source "a child's head is larger for its stature than an adult's, so it is scaled apart." \
  --source "Joint characteristics are scaled adult ones; a child's ranges of motion and neck" \
  --source "stiffness differ (not modelled)." > "$out/child6.sled"

scale --name child3 --stature 37.2in --mass 34.09lb \
  --segment-mass head=5.92lb --segment-mass neck=1.65lb --segment-mass torso=14.42lb \
  --segment-mass upper_arms=1.86lb --segment-mass lower_arms=2.10lb \
  --segment-mass upper_legs=4.26lb --segment-mass lower_legs=2.68lb --segment-mass feet=1.20lb \
  --head-length 181.0mm \
  --title "a 15-segment 3-year-old child, the Hybrid III 3-year-old's size" \
  --source "Stature 37.2 in (945 mm): $nhtsa_family" \
  --source "(https://one.nhtsa.gov/Research/HYBRID-III-3%E2%80%93Year-Old-Physical-Data)." \
  --source "Segment weights (lb) from the same page: head 5.92, neck 1.65, torso with jacket" \
  --source "14.42, and per side upper arm 0.93, lower arm and hand 1.05, upper leg 2.13, lower leg" \
  --source "1.34, foot 0.60; total 34.09 lb (15.46 kg; the family table rounds it to 34.1). The" \
  --source "torso is shared between thorax, abdomen and pelvis in male50's proportions." \
  --source "Head length 181 mm: derived (no published length found) from the 20 in (508 mm) head" \
  --source "circumference Humanetics gives for this dummy, with male50's head ellipse proportions" \
  --source "(its 200 x 156 mm ellipse is 561 mm round; 200 mm x 508 / 561 = 181 mm)." \
  --source "Joint characteristics are scaled adult ones; a child's differ (not modelled)." \
  > "$out/child3.sled"
