"""Published segment-parameter equations that scripts/scale_body.py builds bodies from.

Each table maps a source segment to its coefficients (b0, b1, b2) of value = b0 + b1 * mass [kg]
+ b2 * stature [cm] (a multiple regression on body mass and stature), or to a share of the body
mass in per cent (a proportion). The coefficients are the papers' published figures; the source
segments are mapped onto std.humans.male50's by MAPPING below.

Sources:
  ZATSIORSKY_1983: V. Zatsiorsky and V. Seluyanov, "The mass and inertia characteristics of the
    main segments of the human body", Biomechanics VIII-B (1983), pp. 1152-1159: segment masses
    of 100 young men (gamma-ray scanning) regressed on body mass and stature. The same sample is
    the one de Leva (1996) adjusted, from which std.humans.male50 is made.
  SHAN_BOHN_2003: G. Shan and C. Bohn, "Anthropometrical data and coefficients of regression
    related to gender and race", Applied Ergonomics 34 (2003), pp. 327-337: segment masses and
    lengths of young adults regressed on body mass and stature, by sex; the coefficient sets of
    the German (Caucasian) subjects.
  JENSEN_1989: R. K. Jensen, "Changes in segment inertia proportions between 4 and 20 years",
    Journal of Biomechanics 22 (1989), pp. 529-536: segment mass proportions of boys by age
    (elliptical zone model from photographs); the 6-year-old's.
"""

# Multiple regressions on body mass [kg] and stature [cm]: segment -> (b0, b1, b2).
# Zatsiorsky's and Shan and Bohn's "head" is the head with the neck.
ZATSIORSKY_1983_MALE_MASS = {
    "foot": (-0.829, 0.0077, 0.0073),
    "shank": (-1.592, 0.0362, 0.0121),
    "thigh": (-2.649, 0.1463, 0.0137),
    "hand": (-0.1165, 0.0036, 0.00175),
    "forearm": (0.3185, 0.01445, -0.00114),
    "arm": (0.250, 0.03012, -0.0027),
    "head": (1.296, 0.0171, 0.0143),
    "thorax": (8.2144, 0.1862, -0.0584),
    "abdomen": (7.181, 0.2234, -0.0663),
    "pelvis": (-7.498, 0.0976, 0.04896),
}

SHAN_BOHN_2003_FEMALE_MASS = {
    "head": (-2.95, 0.0359, 0.0322),
    "thorax": (25.5, 0.228, -0.16),
    "abdomen": (-1.45, 0.0975, 0.0176),
    "pelvis": (1.1, 0.104, -0.0027),
    "thigh": (-10.9, 0.213, 0.038),
    "shank": (-0.563, 0.0191, 0.0141),
    "foot": (-1.27, 0.0045, 0.0104),
    "arm": (3.05, 0.0184, -0.0164),
    "forearm": (-0.481, 0.0087, 0.0043),
    "hand": (-1.13, 0.0031, 0.0074),
}

# Segment lengths [cm].
SHAN_BOHN_2003_MALE_LENGTH = {
    "head": (1.95, 0.0535, 0.105),
    "thorax": (-30.4, -0.0156, 0.324),
    "abdomen": (-1.71, -0.0794, 0.138),
    "pelvis": (26.4, 0.0473, -0.0311),
    "thigh": (4.26, -0.0183, 0.24),
    "shank": (-16.0, 0.0218, 0.321),
    "foot": (3.8, 0.013, 0.119),
    "arm": (-15.0, 0.012, 0.229),
    "forearm": (0.143, -0.0281, 0.161),
    "hand": (-3.7, 0.0036, 0.131),
}

SHAN_BOHN_2003_FEMALE_LENGTH = {
    "head": (-8.95, -0.0057, 0.202),
    "thorax": (13.0, 0.175, 0.031),
    "abdomen": (-2.52, -0.0459, 0.116),
    "pelvis": (21.4, 0.0146, -0.005),
    "thigh": (-26.8, -0.0725, 0.436),
    "shank": (-7.21, -0.0618, 0.308),
    "foot": (7.39, 0.0311, 0.0867),
    "arm": (2.44, -0.0169, 0.146),
    "forearm": (-8.57, 0.0494, 0.18),
    "hand": (-8.96, 0.0057, 0.163),
}

# Shares of the body mass [%] at 6 years; the trunk is one segment.
JENSEN_1989_AGE6_SHARE = {
    "head": 18.2,
    "trunk": 43.0,
    "arm": 2.4,
    "forearm": 1.3,
    "hand": 0.8,
    "thigh": 8.5,
    "shank": 4.6,
    "foot": 1.9,
}

# male50's segments from the sources' (one side of each limb). Head and neck, and the trunk of a
# source without its split, are shared in male50's own proportions (scale_body.py).
MAPPING = {
    "head": ["head"],
    "neck": ["head"],
    "thorax": ["thorax", "trunk"],
    "abdomen": ["abdomen", "trunk"],
    "pelvis": ["pelvis", "trunk"],
    "upper_arm": ["arm"],
    "lower_arm": ["forearm", "hand"],
    "upper_leg": ["thigh"],
    "lower_leg": ["shank"],
    "foot": ["foot"],
}

MODELS = {
    "male": {
        "mass": ZATSIORSKY_1983_MALE_MASS,
        "length": SHAN_BOHN_2003_MALE_LENGTH,
        "citation": [
            "Segment masses: Zatsiorsky and Seluyanov (1983), The mass and inertia characteristics",
            "of the main segments of the human body, Biomechanics VIII-B, 1152-1159 (multiple",
            "regression on body mass and stature, 100 young men).",
            "Segment lengths: Shan and Bohn (2003), Anthropometrical data and coefficients of",
            "regression related to gender and race, Applied Ergonomics 34, 327-337 (male,",
            "German subjects).",
        ],
    },
    "female": {
        "mass": SHAN_BOHN_2003_FEMALE_MASS,
        "length": SHAN_BOHN_2003_FEMALE_LENGTH,
        "citation": [
            "Segment masses and lengths: Shan and Bohn (2003), Anthropometrical data and",
            "coefficients of regression related to gender and race, Applied Ergonomics 34,",
            "327-337 (female, German subjects).",
        ],
    },
    "child6": {
        "share": JENSEN_1989_AGE6_SHARE,
        "citation": [
            "Segment masses: Jensen (1989), Changes in segment inertia proportions between 4 and",
            "20 years, J. Biomech. 22, 529-536 (mass proportions at 6 years; Jensen's range is 4",
            "to 20 years). No segment lengths are published there: lengths are scaled.",
        ],
    },
}

# What the length ratios are taken against: the male equations at male50's size.
REFERENCE_MASS_KG = 78.0
REFERENCE_STATURE_CM = 175.3


def evaluate(coefficients, mass, stature_cm):
    """b0 + b1 mass + b2 stature for each source segment."""
    return {s: b0 + b1 * mass + b2 * stature_cm for s, (b0, b1, b2) in coefficients.items()}


def source_of(model, segment, table):
    """The source segments of male50's `segment` (its side stripped) present in `table`."""
    base = segment[:-2] if segment.endswith(("_l", "_r")) else segment
    return [s for s in MAPPING[base] if s in table]
