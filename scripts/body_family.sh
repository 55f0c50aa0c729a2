#!/usr/bin/env bash
# The standard library's body family (stdlib/humans/*.sled but male50), made from male50 by
# scripts/scale_body.py. Each body's stated inputs are published figures of the Hybrid III dummy
# of that size; the segment masses and lengths come from published regression equations where
# one covers the body (scripts/segment_regressions.py). The sources are written into each
# file's header.
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

scale --name female05 --dummy hybrid3_5f --stature 59.1in --mass 108.03lb --regression female \
  --title "a 15-segment 5th-percentile adult female, the Hybrid III 5th female's size" \
  --source "Stature 59.1 in (1501 mm) and mass 108.03 lb (49.00 kg): $nhtsa_family" \
  --source "(http://www.nhtsa.gov/Research/ci.Hybrid+III+5th+Percentile+Female.print), the sum of" \
  --source "its segment weights (the family table rounds it to 108.0 lb)." > "$out/female05.sled"

scale --name male95 --stature 188cm --mass 223lb --regression male \
  --title "a 15-segment 95th-percentile adult male, the Hybrid III 95th male's size" \
  --source "Stature 188 cm and mass 223 lb (101.2 kg; the page rounds it to 100 kg): the Hybrid III" \
  --source "95th male as https://en.wikipedia.org/wiki/Hybrid_III gives it." > "$out/male95.sled"

scale --name male50_regression --dummy hybrid3_50m --stature 1753mm --mass 78kg --regression male \
  --title "a 15-segment 50th-percentile adult male made by the regressions, a variant of male50" \
  --source "Stature 1753 mm and mass 78 kg: the Hybrid III 50th male (crash-conventions.md §4)," \
  --source "male50's own size. It differs from male50 where the regressions' segment masses and" \
  --source "lengths differ from de Leva's." > "$out/male50_regression.sled"

scale --name male50_chest --dummy hybrid3_50m --stature 1753mm --mass 77.99kg --deflecting-chest \
  --title "male50 with a deflecting chest (a sternum on a slip joint), 16 segments" \
  --source "Stature and mass: male50's own (its segments add up to 77.99 kg), so every other" \
  --source "segment and joint is male50's." > "$out/male50_chest.sled"

scale --name child6 --stature 45.0in --mass 51.6lb --regression child6 --head-length 6.80in \
  --child-age 6 \
  --title "a 15-segment 6-year-old child, the Hybrid III 6-year-old's size" \
  --source "Stature 45.0 in (1143 mm), weight 51.6 lb (23.41 kg):" \
  --source "$nhtsa_family" \
  --source "(http://www.nhtsa.gov/Research/ci.HYBRID+III+6-Year+Old+Physical+Data.print)." \
  --source "Head length 6.80 in (173 mm), the same page, sizes the head: a child's head is larger" \
  --source "for its stature than an adult's, so it is scaled apart." \
  > "$out/child6.sled"

# Jensen's (1989) regressions of the segments' shares on age, at 3 years: one year below their
# sample, an extrapolation the header states.
scale --name child3 --stature 37.2in --mass 34.09lb --regression child3 --head-length 181.0mm \
  --child-age 3 \
  --title "a 15-segment 3-year-old child, the Hybrid III 3-year-old's size" \
  --source "Stature 37.2 in (945 mm) and weight 34.09 lb (15.46 kg; the family table rounds it to" \
  --source "34.1): $nhtsa_family" \
  --source "(https://one.nhtsa.gov/Research/HYBRID-III-3%E2%80%93Year-Old-Physical-Data)." \
  --source "Head length 181 mm: derived (no published length found) from the 20 in (508 mm) head" \
  --source "circumference Humanetics gives for this dummy, with male50's head ellipse proportions" \
  --source "(its 200 x 156 mm ellipse is 561 mm round; 200 mm x 508 / 561 = 181 mm)." \
  > "$out/child3.sled"
