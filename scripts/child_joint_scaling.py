"""How scripts/scale_body.py scales male50's joint characteristics to a child (--child-age).

The law is the dimensional analysis that the child dummies' response requirements were scaled by
(Irwin and Mertz 1997, "Biomechanical basis for the CRABI and Hybrid III child dummies"; the
adult sizes were scaled the same way by Mertz, Irwin and Melvin, SAE 890756, 1989): with a length
ratio lambda_L and an elastic-modulus ratio lambda_E (child over adult; densities equal), stresses
go as lambda_E at equal strains, so

    moment       lambda_M = lambda_E * lambda_L^3      (at the same angle: angles are strains)
    time         lambda_t = lambda_L * sqrt(1 / lambda_E)
    angle        1                                     (ranges of motion and stops kept)

and a viscous torque per angular velocity goes as lambda_M * lambda_t. The paper itself was not
read here: the form is the dimensional analysis it rests on, as the Pediatric Injury Biomechanics
archive (Crandall et al., eds., 2013, ch. 3's abstract) describes it: geometric scaling,
"accounting for the difference in Young's modulus between adult and pediatric bone (Irwin and
Mertz 1997; ...)". No child-to-adult modulus ratio could be read, so lambda_E = 1 for every joint
but the neck: there the law reduces to geometric similarity, lambda_M = lambda_L^3.

The neck takes published moment scale factors instead: Yoganandan, Pintar, Kumaresan,
Gennarelli, Sun, Kuppa, Maltese and Eppinger, "Pediatric and small female neck injury scale
factors and tolerance based on human spine biomechanical characteristics" (read at
https://doczz.net/doc/272965/pediatric-and-small-female-neck-injury-scale, its abstract), which
combine the spinal components' material properties by age with neck geometry: extension 0.19,
flexion 0.18 at 3 years; extension 0.25 at 6 years, and flexion 0.24 (that abstract is cut off
there; the 24 % is from A. Croft's summary of the same table, dynamicchiropractic.com article
18143). They are scale factors of tolerance (strength); taking them for the moment at every
angle is Irwin and Mertz's premise that response and tolerance scale alike. Lateral bending and
axial rotation have no factor there and take the mean of flexion's and extension's. The neck's
damping takes the lambda_E that the law needs to give the neck's moment factor at the neck's
length ratio, lambda_E = lambda_M / lambda_L^3, so that everywhere

    viscous      lambda_c = lambda_M * lambda_t = sqrt(lambda_M * lambda_L^5).

tests/compiler/body_family_test.cpp checks child6's and child3's tables and damping against
these formulas.
"""

import math

# Yoganandan et al.: age [years] -> the neck's moment scale factor by loading mode.
NECK_MOMENT_FACTORS = {
    3: {"flexion": 0.18, "extension": 0.19},
    6: {"flexion": 0.24, "extension": 0.25},
}

NECK_JOINTS = ("neck_lower", "neck_upper")

CITATION = [
    "Joints: Irwin and Mertz's (1997) scaling of the child dummies' responses, moment",
    "lambda_E * lambda_L^3 at the same angle, viscous damping lambda_M * lambda_t with lambda_t",
    "= lambda_L / sqrt(lambda_E) (scripts/child_joint_scaling.py). lambda_E = 1 (no child",
    "modulus could be read) but at the neck, whose moment factors are Yoganandan et al.'s",
]


def moment_factor(length_ratio, modulus_ratio=1.0):
    """lambda_M = lambda_E * lambda_L^3."""
    return modulus_ratio * length_ratio**3


def viscous_factor(moment, length_ratio):
    """lambda_M * lambda_t, with the lambda_E that gives lambda_M at lambda_L."""
    modulus = moment / length_ratio**3
    return moment * length_ratio / math.sqrt(modulus)


def neck_factors(age):
    """(flexion, extension, other) moment factors of the neck at `age`."""
    if age not in NECK_MOMENT_FACTORS:
        raise SystemExit(f"scale_body: no neck scale factors for age {age} "
                         f"(known: {', '.join(str(a) for a in NECK_MOMENT_FACTORS)})")
    f = NECK_MOMENT_FACTORS[age]
    return f["flexion"], f["extension"], (f["flexion"] + f["extension"]) / 2


def joint_factors(age, joint, role, length_ratio):
    """The factors of a joint's torque table for positive and for negative angles.

    `role` is the table's place in the joint (flexure, twist, precession, nutation, spin); the
    neck's nutation is flexion (positive, chin down) and extension (negative).
    """
    if joint in NECK_JOINTS:
        flexion, extension, other = neck_factors(age)
        if role == "nutation":
            return flexion, extension
        return other, other
    m = moment_factor(length_ratio)
    return m, m


def joint_viscous_factor(age, joint, length_ratio):
    if joint in NECK_JOINTS:
        return viscous_factor(neck_factors(age)[2], length_ratio)
    return viscous_factor(moment_factor(length_ratio), length_ratio)


def header(age):
    flexion, extension, other = neck_factors(age)
    return CITATION + [
        f"(flexion {flexion:g}, extension {extension:g} at {age} years; lateral bending and axial rotation",
        f"their mean, {other:g}). Ranges of motion and stops are male50's: the law keeps angles. A",
        "child's ranges of motion differ (not modelled).",
    ]
