#!/usr/bin/env python3
"""Makes a body of another size from std.humans.male50 by length and mass scaling.

    scripts/scale_body.py --name female05 --stature 1501mm --mass 48.99kg > my_body.sled

The scaling follows how the Hybrid III family was sized: NHTSA's dummy pages call the 5th
female "a scaled down version" of the 50th male and the 6-year-old "scaled down from" it. Every
length of the reference body (joint locations, contact ellipsoids, the H-point) is multiplied by
the length ratio L that gives the stated stature, every mass by the mass ratio M, each moment of
inertia by its segment's mass ratio times its length ratio squared. Each joint's torque functions
are multiplied by M_j * L_j (M_j the ratio of the mass beyond the joint, L_j the child segment's
length ratio), so that the joint holds up what hangs beyond it at the reference's angle under
gravity (static similarity), and its viscous damping by M_j * L_j^1.5, which keeps its damping
ratio (a joint's natural frequency goes as sqrt(torque / inertia), ~ L^-0.5). Angles (ranges of
motion) are kept. The torque and damping rules are this script's engineering choice, not a
published law. With --child-age the joints follow instead the law the child dummies were scaled
by (Irwin and Mertz 1997; the neck by Yoganandan et al.'s factors): scripts/child_joint_scaling.py.

Options that bring published data in where a uniform scaling would be wrong:
  --segment-mass GROUP=KG   a published segment (group) mass, both sides together, e.g. a Hybrid
                            III dummy's segment weights; shared inside the group in the reference
                            body's proportions; the other segments take what is left of --mass in
                            the reference proportions, so the total is --mass exactly.
  --head-length MM          the published head length (glabella to back of the head): the head
                            segment is scaled by its own factor (head length / the reference's
                            200 mm), and the rest of the body by the factor that keeps --stature.

Bodies from published regression equations instead of uniform scaling:
  --regression male|female  segment masses from the regression on body mass and stature
                            (male: Zatsiorsky and Seluyanov 1983; female: Shan and Bohn 2003),
                            each male50 segment's lengths by the ratio of its Shan and Bohn
                            (2003) length at the stated size to the male length at male50's
                            (78 kg, 175.3 cm), all times the one factor that gives --stature.
  --regression child6       segment masses from Jensen's (1989) proportions at 6 years; lengths
                            scaled as without --regression (with --head-length).
  --regression child3       segment masses from Jensen's (1989) regressions of the shares on
                            age at 3 years (one year below its sample); lengths scaled.
  scripts/segment_regressions.py holds the coefficients and the citations. The regressions'
  segment masses are shared among male50's segments where a source segment covers several (head
  and neck; a whole trunk) in male50's proportions, and scaled together by the one factor that
  makes the total --mass (the header gives it: how far the regression's own sum is off). A
  regression that gives a segment a non-positive mass, or a share of the body mass or a length
  ratio far from male50's, is refused: the equations are being used outside their sample.
  Moments of inertia (male and female): male50's times the published regression's moment at
  the stated size over its moment at male50's, per axis, where that stays within INERTIA_BAND
  of the moment male50's radii of gyration give at the new mass and lengths and keeps the
  triangle inequality; otherwise (and for the children) they follow the segment's mass and
  lengths as without --regression. Centres of mass stay at male50's place along each segment.

  --child-age 3|6           a child's joints: torque tables times lambda_E * lambda_L^3
                            (lambda_E = 1), the neck's by published factors, damping by the same
                            law's time scale; angles kept (scripts/child_joint_scaling.py).
  --deflecting-chest        adds a sternum segment in front of the thorax on a slip joint `chest`
                            (x forward) with a force-deflection flexure and viscous damping, so
                            that chest deflection and the Viscous Criterion can be read; its mass
                            is taken from the thorax's (the header gives the sources).

Every stated input is written into the new file's header; tests/compiler/body_family_test.cpp
checks each body's total mass and standing height (computed from its geometry) against them.
"""
import argparse
import re
import sys
import textwrap
from pathlib import Path

import child_joint_scaling
import segment_regressions

ROOT = Path(__file__).resolve().parent.parent
REFERENCE = ROOT / "stdlib" / "humans" / "male50.sled"
REFERENCE_HEAD_LENGTH_MM = 200.0  # male50's head ellipsoid is 2 x 100 mm long (its header)

GROUPS = {
    "head": ["head"],
    "neck": ["neck"],
    "upper_torso": ["thorax"],
    "lower_torso": ["abdomen", "pelvis"],
    "torso": ["thorax", "abdomen", "pelvis"],
    "upper_arms": ["upper_arm_l", "upper_arm_r"],
    "lower_arms": ["lower_arm_l", "lower_arm_r"],
    "upper_legs": ["upper_leg_l", "upper_leg_r"],
    "lower_legs_feet": ["lower_leg_l", "lower_leg_r", "foot_l", "foot_r"],
    "lower_legs": ["lower_leg_l", "lower_leg_r"],
    "feet": ["foot_l", "foot_r"],
}

NUMBER = r"-?\d+(?:\.\d+)?(?:e-?\d+)?"
VECTOR = re.compile(r"\(\s*(" + NUMBER + r")\s*,\s*(" + NUMBER + r")\s*,\s*(" + NUMBER + r")\s*\)")


def quantity(text, unit):
    """'1501mm', '1.501 m', '48.99kg' -> the value in `unit` (mm or kg)."""
    match = re.fullmatch(r"\s*(" + NUMBER + r")\s*([a-z]*)\s*", text)
    if not match:
        raise SystemExit(f"scale_body: cannot read '{text}' as a quantity")
    value, given = float(match.group(1)), match.group(2) or unit
    factors = {"mm": {"mm": 1, "cm": 10, "m": 1000, "in": 25.4}, "kg": {"kg": 1, "g": 0.001, "lb": 0.45359237}}
    if given not in factors[unit]:
        raise SystemExit(f"scale_body: '{text}' is not a {unit} quantity")
    return value * factors[unit][given]


def fmt(value, digits=4):
    """A number with `digits` significant digits, without an exponent."""
    if value == 0:
        return "0"
    text = f"{value:.{digits}g}"
    if "e" in text:
        text = f"{float(text):f}".rstrip("0").rstrip(".")
    return text


def fmt_length(value):
    return fmt(round(value, 1), 6) if abs(value) >= 1 else fmt(round(value, 2), 3)


class Reference:
    """The reference body's segments, joints and geometry as male50.sled writes them."""

    def __init__(self, text):
        self.text = text
        self.masses = {}
        self.inertias = {}  # segment -> its principal moments about x, y, z [kg*m^2]
        self.parent = {}  # child -> (parent, at_parent, at_child)
        self.ellipsoids = {}  # segment -> [(semi_axes, center)]
        self.root = re.search(r"^\s*reference = (\w+)", text, re.M).group(1)
        segment = None
        joint = None
        for line in text.splitlines():
            s = line.strip()
            m = re.match(r"segment (\w+) \{", s)
            if m:
                segment = m.group(1)
            m = re.match(r"mass = (" + NUMBER + r") kg", s)
            if m and segment:
                self.masses[segment] = float(m.group(1))
            m = re.match(r"inertia = (.*) kg\*m\^2", s)
            if m and segment:
                self.inertias[segment] = vector(m.group(1))
            m = re.match(r"ellipsoid \{ semi_axes = (.*) mm\s+center = (.*) mm \}", s)
            if m and segment:
                self.ellipsoids.setdefault(segment, []).append(
                    (vector(m.group(1)), vector(m.group(2))))
            m = re.match(r"joint (\w+) : \w+\((\w+) -> (\w+)\)", s)
            if m:
                segment = None
                joint = [m.group(2), m.group(3), None, None]
            m = re.match(r"at (\w+) = (.*) mm", s)
            if m and joint:
                slot = 2 if m.group(1) == joint[0] else 3
                joint[slot] = vector(m.group(2))
                if joint[2] and joint[3]:
                    self.parent[joint[1]] = (joint[0], joint[2], joint[3])
                    joint = None

    def stature(self, scale_of):
        """Standing height (all joint angles zero): the top of the highest contact ellipsoid less
        the bottom of the lowest, with each segment's lengths multiplied by scale_of(segment)."""
        position = {}

        def at(segment):
            if segment not in position:
                if segment not in self.parent:
                    position[segment] = 0.0
                else:
                    parent, at_parent, at_child = self.parent[segment]
                    position[segment] = (at(parent) + at_parent[2] * scale_of(parent) -
                                         at_child[2] * scale_of(segment))
            return position[segment]

        top, bottom = -1e9, 1e9
        for segment, shapes in self.ellipsoids.items():
            for semi_axes, center in shapes:
                z = at(segment) + center[2] * scale_of(segment)
                top = max(top, z + semi_axes[2] * scale_of(segment))
                bottom = min(bottom, z - semi_axes[2] * scale_of(segment))
        return top - bottom


def vector(text):
    m = VECTOR.fullmatch(text.strip())
    if not m:
        raise SystemExit(f"scale_body: cannot read the vector '{text}'")
    return [float(m.group(i)) for i in (1, 2, 3)]


def scale_vector(m, factor, scale=fmt_length):
    """The vector matched by `m` times `factor`, one number or one per axis."""
    factors = factor if isinstance(factor, (list, tuple)) else [factor] * 3
    return "(" + ", ".join(scale(float(m.group(i)) * factors[i - 1]) for i in (1, 2, 3)) + ")"


def long_axis(segment):
    """The axis a segment's published length runs along: x for a foot, z for the others."""
    return 0 if segment.startswith("foot") else 2


# The deflecting chest of male50's size (--deflecting-chest): the sternum's place and shape in the
# thorax frame [mm], its mass [kg], the force against the deflection [mm -> N] and the damping
# [N*s/m]. Sources and estimates: CHEST_NOTES.
STERNUM_MASS = 0.45
STERNUM_AT = (105.0, 0.0, 10.0)
STERNUM_SEMI_AXES = (40.0, 110.0, 120.0)
CHEST_FORCE = [(0, 0), (25, 200), (50, 600), (70, 1500), (90, 6000), (100, 20000)]
CHEST_VISCOUS = 500.0
CHEST_NOTES = [
    "Deflecting chest: the segment `sternum` (the front of the ribcage) on the slip joint `chest`",
    "(thorax -> sternum, along x): chest deflection is `joint_angle occupant.chest` (negative in",
    "compression) and `viscous_criterion(occupant.chest)` gives VC. Give the sternum the frontal",
    "contacts (belt, wheel, panel): its ellipsoid stands 20 mm (male50's size) in front of the",
    "thorax's, which is then the back and sides of the chest.",
    "  Source of the first 25 mm: Cavanaugh, Jepsen and King (1988), Quasi-static frontal loading",
    "of the thorax of human cadavers and the Hybrid III dummy (16th International Workshop on",
    "Human Subjects for Biomechanical Research): 6 to 10 N/mm at the sternum over a 25.4 mm",
    "stroke; 8 N/mm is taken. Estimates (no source here): the stiffening beyond 25 mm to a",
    "bottoming out at 100 mm, the 500 N*s/m of damping, the sternum's 0.45 kg (taken from the",
    "thorax's mass) and its place. Other sizes: deflections times the thorax's depth ratio,",
    "forces and damping times its square (geometric similarity; an engineering choice).",
]


def chest_text(factors, mass_ratio):
    """The sternum segment, its force function and the slip joint, for a thorax whose lengths
    are male50's times `factors` (x, y, z) and whose mass is `mass_ratio` times male50's."""
    depth = factors[0]
    semi = ", ".join(fmt_length(v * f) for v, f in zip(STERNUM_SEMI_AXES, factors))
    at = ", ".join(fmt_length(v * f) for v, f in zip(STERNUM_AT, factors))
    mass = STERNUM_MASS * mass_ratio
    # A thin plate across the chest: moments of a box 2a x 2b x 2c.
    a, b, c = (v * f / 1000 for v, f in zip(STERNUM_SEMI_AXES, factors))
    inertia = ", ".join(fmt(mass * (q * q + r * r) / 3, 3) for q, r in ((b, c), (a, c), (a, b)))
    segment = ["  segment sternum {", f"    mass = {fmt(mass)} kg",
               f"    inertia = ({inertia}) kg*m^2",
               f"    ellipsoid {{ semi_axes = ({semi}) mm  center = (0, 0, 0) mm }}", "  }"]
    function = ["  // The chest's force against its deflection (the header gives the sources).",
                "  function chest_force = table(deflection -> force) {"]
    function += [f"    {fmt_length(d * depth)} mm -> {fmt(f * depth * depth, 4)} N"
                 for d, f in CHEST_FORCE]
    function += ["  }", ""]
    joint = ["", "  // Chest: the sternum slides along x against the chest's force and damping.",
             "  joint chest : slip(thorax -> sternum) {", f"    at thorax = ({at}) mm",
             "    at sternum = (0, 0, 0) mm", "    axis = x", "    flexure = chest_force",
             f"    viscous = {fmt(CHEST_VISCOUS * depth * depth, 3)} N*s/m", "  }"]
    return segment, function, joint


def regress(ref, name, stature, mass):
    """male50's segment masses and length ratios from the regression `name` at the stated size
    (scripts/segment_regressions.py); refuses a size outside what the equations can give."""
    model = segment_regressions.MODELS[name]
    stature_cm = stature / 10
    where = f"at {fmt(stature, 5)} mm and {fmt(mass, 5)} kg"
    if "mass" in model:
        table = model["mass"]
        values = segment_regressions.evaluate(table, mass, stature_cm)
    else:
        table = model["share"]
        values = {s: share / 100 * mass for s, share in table.items()}
    bad = sorted(s for s, v in values.items() if v <= 0)
    if bad:
        raise SystemExit(f"scale_body: the {name} regression gives no mass to {', '.join(bad)} "
                         f"{where}: the size is outside its sample")
    # male50's segments that one source segment covers (head and neck; a whole trunk) share its
    # mass in male50's proportions, side by side.
    groups = {}
    for segment in ref.masses:
        side = segment[-2:] if segment.endswith(("_l", "_r")) else ""
        sources = tuple(segment_regressions.source_of(name, segment, table))
        groups.setdefault((sources, side), []).append(segment)
    raw = {}
    for (sources, _), members in groups.items():
        covered = sum(ref.masses[m] for m in members)
        for m in members:
            raw[m] = sum(values[x] for x in sources) * ref.masses[m] / covered
    regression_sum = sum(raw.values())
    masses = {segment: value * mass / regression_sum for segment, value in raw.items()}
    ref_total = sum(ref.masses.values())
    # A regression far outside its sample gives shares no body has (a proportion model does not
    # extrapolate, and a child's head is rightly 2.6 times the adult's share).
    for segment, value in masses.items() if "mass" in model else ():
        share = value / mass / (ref.masses[segment] / ref_total)
        if not 0.5 <= share <= 2.0:
            raise SystemExit(f"scale_body: the {name} regression gives {segment} {share:.2f} times "
                             f"male50's share of the body mass {where}: outside its sample")
    lengths = {}
    if "length" in model:
        target = segment_regressions.evaluate(model["length"], mass, stature_cm)
        reference = segment_regressions.evaluate(
            segment_regressions.MODELS["male"]["length"], segment_regressions.REFERENCE_MASS_KG,
            segment_regressions.REFERENCE_STATURE_CM)
        overall = stature_cm / segment_regressions.REFERENCE_STATURE_CM
        for segment in ref.masses:
            sources = segment_regressions.source_of(name, segment, model["length"])
            lengths[segment] = (sum(target[x] for x in sources) /
                                sum(reference[x] for x in sources))
            if not 0.7 <= lengths[segment] / overall <= 1.4:
                raise SystemExit(f"scale_body: the {name} regression makes {segment} "
                                 f"{lengths[segment]:.2f} times male50's length {where} (the "
                                 f"stature {overall:.2f} times): outside its sample")
    return {"masses": masses, "lengths": lengths, "sum": regression_sum, "total": mass,
            "inertia": inertia_ratios(ref, name, model, mass, stature_cm),
            "citation": model["citation"]}


def inertia_axes(segment):
    """The regressions' axes for a segment's x, y and z moments: a foot's long axis is x."""
    return ("si", "ml", "ap") if segment.startswith("foot") else ("ap", "ml", "si")


def inertia_ratios(ref, name, model, mass, stature_cm):
    """Per male50 segment, its moments about x, y and z at the stated size over the same
    regressions' at male50's (78 kg, 175.3 cm), or None where the equations give a moment that is
    not positive. A segment that several source segments make up (the forearm and hand) takes
    the ratio of their sums, which leaves out the parallel-axis terms of their offsets."""
    if "inertia" not in model:
        return {}
    at_size, at_reference = (
        {axis: segment_regressions.evaluate(table[axis], m, h) for axis in table}
        for table, m, h in ((model["inertia"][0], mass, stature_cm),
                            (model["inertia"][1], segment_regressions.REFERENCE_MASS_KG,
                             segment_regressions.REFERENCE_STATURE_CM)))
    ratios = {}
    for segment in ref.masses:
        sources = segment_regressions.source_of(name, segment, at_size["ap"])
        values = [(sum(at_size[a][x] for x in sources), sum(at_reference[a][x] for x in sources))
                  for a in inertia_axes(segment)]
        ratios[segment] = None if min(min(v) for v in values) <= 0 else [v / r for v, r in values]
    return ratios


# How far a regressed moment may stray from the one male50's radii of gyration give at the new
# segment's mass and lengths: a radius of gyration within about -18 % to +22 % of male50's
# proportion. Outside it the regression is being used away from its subjects (Shan and Bohn's
# women's thigh at the 5th female's size, for one, has 0.40 of the scaled moment).
INERTIA_BAND = (0.67, 1.5)


def triangle_holds(moments):
    """Principal moments of a real body: each at most the sum of the other two."""
    return all(2 * m <= sum(moments) * (1 + 1e-9) for m in moments)


def choose_inertia(ref, segment, mass_factor, lengths, regression):
    """A segment's factors on male50's moments about x, y, z and whether they are the
    regression's: the regression's ratios (times the mass normalization) where every axis is
    inside INERTIA_BAND of the scaled moment and the moments keep the triangle inequality; else
    the scaled ones (mass ratio times the two length ratios across each axis)."""
    f = lengths
    scaled = [mass_factor * f[1] * f[2], mass_factor * f[0] * f[2], mass_factor * f[0] * f[1]]
    ratios = (regression or {}).get("inertia", {}).get(segment)
    if ratios:
        normalized = [r * mass_factor_of_sum(regression) for r in ratios]
        within = all(INERTIA_BAND[0] <= n / s <= INERTIA_BAND[1] for n, s in zip(normalized, scaled))
        moments = [n * i for n, i in zip(normalized, ref.inertias[segment])]
        if within and triangle_holds(moments):
            return normalized, True
    return scaled, False


def mass_factor_of_sum(regression):
    """The factor that made the regression's segment masses add up to the stated mass."""
    return regression["total"] / regression["sum"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--name", required=True, help="the new body's name")
    parser.add_argument("--stature", required=True, help="standing height, e.g. 1501mm")
    parser.add_argument("--mass", required=True, help="total mass, e.g. 48.99kg")
    parser.add_argument("--segment-mass", action="append", default=[], metavar="GROUP=MASS")
    parser.add_argument("--head-length", help="published head length, e.g. 172.7mm")
    parser.add_argument("--regression", choices=sorted(segment_regressions.MODELS),
                        help="segment masses (and lengths) from published regression equations")
    parser.add_argument("--deflecting-chest", action="store_true",
                        help="a sternum segment on a slip joint in front of the thorax")
    parser.add_argument("--child-age", type=int,
                        choices=sorted(child_joint_scaling.NECK_MOMENT_FACTORS),
                        help="scale the joints as a child's of this age (Irwin and Mertz's law; "
                             "scripts/child_joint_scaling.py) instead of by static similarity")
    parser.add_argument("--dummy", default="human",
                        help="the dummy the body stands for in ISO-MME codes (`dummy = ...` of a "
                             "body in docs/language.md); default human, code 00")
    parser.add_argument("--title", default="", help="what the body is, for the header")
    parser.add_argument("--source", action="append", default=[], help="a source line for the header")
    parser.add_argument("--reference", default=str(REFERENCE), help=argparse.SUPPRESS)
    args = parser.parse_args()

    if not re.fullmatch(r"[a-z_][a-z0-9_]*", args.name):
        raise SystemExit("scale_body: --name must be a lower-case identifier")
    ref = Reference(Path(args.reference).read_text())
    stature = quantity(args.stature, "mm")
    mass = quantity(args.mass, "kg")
    ref_mass = sum(ref.masses.values())
    ones = ref.stature(lambda _: 1.0)

    # Masses: from a regression, or published groups first and the rest in the reference
    # proportions.
    masses = {}
    relative = {}  # segment -> its length ratio from a regression, before the stature's factor
    regression = None
    if args.regression:
        if args.segment_mass:
            raise SystemExit("scale_body: --regression gives the segment masses; drop --segment-mass")
        regression = regress(ref, args.regression, stature, mass)
        masses = dict(regression["masses"])
        relative = regression["lengths"]
        if relative and args.head_length:
            raise SystemExit(f"scale_body: --regression {args.regression} gives the head's length; "
                             "drop --head-length")
    for item in args.segment_mass:
        group, _, value = item.partition("=")
        if group not in GROUPS:
            raise SystemExit(f"scale_body: unknown group '{group}' (known: {', '.join(GROUPS)})")
        members = GROUPS[group]
        if any(s in masses for s in members):
            raise SystemExit(f"scale_body: group '{group}' overlaps another --segment-mass")
        group_ref = sum(ref.masses[s] for s in members)
        for s in members:
            masses[s] = quantity(value, "kg") * ref.masses[s] / group_ref
    rest_ref = sum(m for s, m in ref.masses.items() if s not in masses)
    rest = mass - sum(masses.values())
    if (rest_ref > 0 and rest <= 0) or (rest_ref == 0 and abs(rest) > 1e-6 * mass):
        raise SystemExit("scale_body: the segment masses do not add up to the total --mass")
    for s, m in ref.masses.items():
        if s not in masses:
            masses[s] = m * rest / rest_ref if rest_ref > 0 else 0.0

    # Lengths: the head by its own factor when its length is given, the rest to the stature.
    head = quantity(args.head_length, "mm") / REFERENCE_HEAD_LENGTH_MM if args.head_length else None
    across = stature / ones  # the breadths of a body made from regression lengths

    def regression_scale(segment, along):
        """Per axis: a segment's regression length ratio times `along` on its long axis, the
        stature's ratio across it (the regressions give lengths, not breadths)."""
        factors = [across] * 3
        factors[long_axis(segment)] = along * relative[segment]
        return factors

    if relative:
        # Standing height is linear in the factor along the segments (the feet's heights are
        # breadths here): S = S0 + c (S1 - S0).
        s0, s1 = (ref.stature(lambda seg, c=c: regression_scale(seg, c)[2]) for c in (0.0, 1.0))
        body_scale = (stature - s0) / (s1 - s0)
    elif head is None:
        body_scale = stature / ones
    else:
        # Standing height is linear in the head's factor h and the rest's l while the head stays
        # the top and a foot the bottom: S = h * A + l * B.
        head_share = ref.stature(lambda seg: 2.0 if seg == "head" else 1.0) - ones
        body_scale = (stature - head * head_share) / (ones - head_share)
        if body_scale <= 0:
            raise SystemExit("scale_body: the head length does not fit the stature")

    def axis_scale(segment):
        """A segment's length factors along x, y and z."""
        if relative:
            return regression_scale(segment, body_scale)
        return [head if head is not None and segment == "head" else body_scale] * 3

    def length_scale(segment):
        """The factor of a segment's length: its weight's lever about the joint above it."""
        return axis_scale(segment)[long_axis(segment)]

    achieved = ref.stature(lambda segment: axis_scale(segment)[2])
    mass_ratio = mass / ref_mass

    # The masses written: a deflecting chest's sternum is taken from the thorax (the joints
    # above still hold up both).
    written = dict(masses)
    if args.deflecting_chest:
        sternum_mass = STERNUM_MASS * masses["thorax"] / ref.masses["thorax"]
        written["thorax"] -= sternum_mass
    inertia_factors = {segment: choose_inertia(ref, segment, written[segment] / ref.masses[segment],
                                               axis_scale(segment), regression)
                       for segment in ref.masses}

    # A joint's torques hold up what hangs beyond it: scaled by that mass's ratio M_j and the
    # child segment's length ratio L_j (its weight's lever), so the body stands and sits at the
    # reference's joint angles under gravity; damping by M_j * L_j^1.5 keeps the damping ratio.
    def beyond(joint_child, table):
        return table[joint_child] + sum(beyond(c, table) for c, (p, _, _) in ref.parent.items()
                                        if p == joint_child)

    def joint_length(joint, child):
        """A child joint's length ratio: the neck's for the neck joints, else its segment's."""
        return length_scale("neck" if joint in child_joint_scaling.NECK_JOINTS else child)

    def torque_factors(joint, child, role):
        """The factors of a joint's torque table for positive and for negative angles."""
        if args.child_age:
            return child_joint_scaling.joint_factors(args.child_age, joint, role,
                                                     joint_length(joint, child))
        factor = beyond(child, masses) / beyond(child, ref.masses) * length_scale(child)
        return factor, factor

    def viscous_factor(joint, child):
        if args.child_age:
            return child_joint_scaling.joint_viscous_factor(args.child_age, joint,
                                                            joint_length(joint, child))
        return beyond(child, masses) / beyond(child, ref.masses) * length_scale(child) ** 1.5

    out = []
    title = args.title or f"a body of {fmt(stature)} mm and {fmt(mass)} kg"
    out.append(f"// std.humans.{args.name}: {title}.")
    out.append("// Generated by scripts/scale_body.py from std.humans.male50; do not edit by hand:")
    command = ["scripts/scale_body.py", f"--name {args.name}", f"--stature {args.stature}",
               f"--mass {args.mass}"]
    command += [f"--segment-mass {m}" for m in args.segment_mass]
    if args.head_length:
        command.append(f"--head-length {args.head_length}")
    if args.regression:
        command.append(f"--regression {args.regression}")
    if args.deflecting_chest:
        command.append("--deflecting-chest")
    if args.child_age:
        command.append(f"--child-age {args.child_age}")
    command.append("--title ... --source ...")
    line = "//  "
    for word in command:
        if len(line) + len(word) > 96:
            out.append(line + " \\")
            line = "//    "
        line += " " + word
    out.append(line)
    out.append("//")
    out.append(f"// Stated inputs: stature {fmt(stature, 5)} mm, total mass {fmt(mass, 5)} kg.")
    for line in args.source:
        out.append(f"//   {line}")
    out.append("//")
    out.append("// Derivation (scripts/scale_body.py's header has the rules): male50 is 77.99 kg and")
    if relative:
        out.append(f"// {fmt(ones, 5)} mm tall standing (from its geometry). Breadths times {fmt(across, 5)} (the")
        out.append(f"// stature's ratio); lengths along each segment (z, a foot's x) times {fmt(body_scale, 5)}")
        out.append("// and the segment's regression length ratio (below).")
    else:
        out.append(f"// {fmt(ones, 5)} mm tall standing (from its geometry). Lengths times {fmt(body_scale, 5)}"
                   + (f", the head's times {fmt(head, 5)}." if head is not None else "."))
    if regression:
        for line in regression["citation"]:
            out.append(f"//   {line}")
        out.append(f"// The source's segment masses add up to {fmt(regression['sum'], 5)} kg; each is"
                   f" times {fmt(mass / regression['sum'], 5)},")
        out.append("// so that they add up to the stated mass.")
        if relative:
            out.append("// Regression length ratios (each segment's length at this size over the male")
            out.append("// segment's at 78 kg and 175.3 cm):")
            sides = [s for s in ref.masses if not s.endswith("_r")]
            line = "//  "
            for segment in sides:
                word = f" {segment.removesuffix('_l')} {fmt(relative[segment], 4)},"
                if len(line) + len(word) > 96:
                    out.append(line)
                    line = "//  "
                line += word
            out.append(line.rstrip(",") + ".")
    elif args.segment_mass:
        out.append("// Masses: the groups given above, each shared in male50's proportions"
                   + ("; every other" if rest_ref > 0 else "."))
        if rest_ref > 0:
            out.append(f"// segment times {fmt(rest / rest_ref, 5)} (what is left of the total).")
    else:
        out.append(f"// Masses times {fmt(mass_ratio, 5)}.")
    regressed = [s.removesuffix("_l") for s in ref.masses
                 if inertia_factors[s][1] and not s.endswith("_r")]
    others = [s.removesuffix("_l") for s in ref.masses
              if not inertia_factors[s][1] and not s.endswith("_r")]
    text = ""
    if regressed:
        text = (f"Moments of inertia of {', '.join(regressed)}: male50's times the regression's "
                "moment at this size over its moment at 78 kg and 175.3 cm, per axis, times "
                f"{fmt(mass / regression['sum'], 5)}; each is within {fmt(INERTIA_BAND[0], 2)} to "
                f"{fmt(INERTIA_BAND[1], 2)} times the moment male50's radii of gyration give at "
                "the segment's mass and lengths, and the three keep the triangle inequality. ")
    if others:
        text += ("Moments of inertia" + (f" of {', '.join(others)} (the regression's fall "
                                          "outside that band: the equations are used away from "
                                          "their subjects there)" if regressed else "")
                 + ": each about an axis times the segment's mass ratio and the length ratios "
                 "across it (male50's radii of gyration, in proportion to the segment's lengths, "
                 "kept).")
    out.extend("// " + line for line in textwrap.wrap(text, 93))
    if args.child_age:
        out.extend("// " + line for line in child_joint_scaling.header(args.child_age))
        out.append(f"// Standing height from this file's geometry: {fmt(achieved, 5)} mm. What male50's header")
        out.append("// calls an estimate is one here too.")
    else:
        out.append("// Each joint's torque tables times M_j * L_j and its viscous damping times M_j * L_j^1.5,")
        out.append("// M_j the ratio of the mass beyond the joint and L_j the child segment's length ratio:")
        out.append("// they keep male50's joint angles under gravity and its damping ratios (an engineering")
        out.append("// estimate, not measured). Ranges of motion are male50's (adult) ones. Standing height")
        out.append(f"// from this file's geometry: {fmt(achieved, 5)} mm. What male50's header calls an estimate")
        out.append("// is one here too.")
    if args.deflecting_chest:
        out.append("//")
        out.extend(f"// {line}" for line in CHEST_NOTES)
    out.append("//")
    out.append("// Frames as in male50: x forward, y left, z up, each segment frame at its centre of mass;")
    out.append("// all joint angles zero is the standing posture; the H-point is midway between the hips.")

    # The joints each torque function serves. male50 shares functions between joints (the two
    # sides; the two neck joints); a function whose joints scale apart is written once per scale,
    # named after the first joint of each (`neck_nutation_neck_lower`).
    uses = {}  # function -> [(joint, child, role)]
    for j in re.finditer(r"joint (\w+) : \w+\(\w+ -> (\w+)\) \{([^}]*)\}", ref.text):
        for f in re.finditer(r"(flexure|twist|precession|nutation|spin) = (\w+)", j.group(3)):
            uses.setdefault(f.group(2), []).append((j.group(1), j.group(2), f.group(1)))
    copies = {}  # function -> [(new name, (factor of positive angles, of negative ones))]
    renamed = {}  # (joint, function) -> new name
    for function, joints in uses.items():
        by_factor = {}
        for joint, child, role in joints:
            factors = tuple(round(f, 12) for f in torque_factors(joint, child, role))
            by_factor.setdefault(factors, []).append(joint)
        single = len(by_factor) == 1
        copies[function] = []
        for factor, group in by_factor.items():
            name = function if single else f"{function}_{group[0]}"
            copies[function].append((name, factor))
            for joint in group:
                renamed[(joint, function)] = name

    def scaled_body_lines():
        segment = None
        joint = None
        joint_child = None
        for line in ref.text.split("\n")[ref.text[:ref.text.index("\nbody ")].count("\n") + 2:]:
            s = line.strip()
            if s.startswith("//"):
                # male50's comments describe its own numbers; only the section titles stay.
                if s.startswith("// ---"):
                    yield line
                continue
            m = re.match(r"segment (\w+) \{", s)
            if m:
                segment = m.group(1)
            m = re.match(r"joint (\w+) : \w+\((\w+) -> (\w+)\)", s)
            if m:
                segment, joint, joint_child = None, m.group(1), m.group(3)
            new = line
            m = re.match(r"(\s*dummy = )\w+$", new)
            if m:
                new = m.group(1) + args.dummy
            m = re.search(r"mass = (" + NUMBER + r") kg", new)
            if m and segment:
                new = new.replace(m.group(0), f"mass = {fmt(written[segment])} kg")
            m = re.search(r"inertia = (\(.*\)) kg\*m\^2", new)
            if m and segment:
                new = new.replace(m.group(1), scale_vector(VECTOR.fullmatch(m.group(1)),
                                                           inertia_factors[segment][0],
                                                           lambda v: fmt(v, 4)))
            if re.search(r"(semi_axes|center|h_point) = ", new) and " mm" in new:
                factor = axis_scale(segment or ref.root)
                new = re.sub(r"(semi_axes|center|h_point) = (\([^)]*\)) mm",
                             lambda g: f"{g.group(1)} = "
                             + scale_vector(VECTOR.fullmatch(g.group(2)), factor) + " mm", new)
            m = re.match(r"(\s*at (\w+) = )(\(.*\)) mm", new)
            if m:
                new = m.group(1) + scale_vector(VECTOR.fullmatch(m.group(3)),
                                                axis_scale(m.group(2))) + " mm"
            m = re.match(r"(\s*(?:flexure|twist|precession|nutation|spin) = )(\w+)$", new)
            if m and joint:
                new = m.group(1) + renamed[(joint, m.group(2))]
            m = re.search(r"viscous = (" + NUMBER + r") N\*m\*s/rad", new)
            if m:
                new = new.replace(m.group(0), f"viscous = "
                                  f"{fmt(float(m.group(1)) * viscous_factor(joint, joint_child), 3)} N*m*s/rad")
            yield new

    lines = list(scaled_body_lines())
    out.append(f"body {args.name} {{")
    i = 0
    while i < len(lines):
        m = re.match(r"(\s*)function (\w+) = table", lines[i])
        if not m:
            out.append(lines[i])
            i += 1
            continue
        end = i
        while lines[end].strip() != "}":
            end += 1
        for name, (positive, negative) in copies.get(m.group(2), [(m.group(2), (1.0, 1.0))]):
            out.append(lines[i].replace(f"function {m.group(2)} ", f"function {name} "))
            for row in lines[i + 1:end + 1]:
                r = re.match(r"(\s*)(" + NUMBER + r") deg -> (" + NUMBER + r") N\*m$", row)
                factor = negative if r and float(r.group(2)) < 0 else positive
                out.append(f"{r.group(1)}{r.group(2)} deg -> {fmt(float(r.group(3)) * factor, 3)} N*m"
                           if r else row)
        i = end + 1
    while out and not out[-1].strip():
        out.pop()
    if args.deflecting_chest:
        segment, function, joint = chest_text(axis_scale("thorax"),
                                              masses["thorax"] / ref.masses["thorax"])
        thorax = out.index("  segment thorax {")
        thorax_end = out.index("  }", thorax)
        out[thorax_end + 1:thorax_end + 1] = segment
        joints = next(i for i, line in enumerate(out) if line.startswith("  // --- Joints "))
        out[joints:joints] = function
        out[-1:-1] = joint
    sys.stdout.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
