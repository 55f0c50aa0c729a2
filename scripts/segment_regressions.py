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
    (elliptical zone model from photographs); the 6-year-old's table, and the quadratic
    regressions of each proportion on age (JENSEN_1989_AGE, below).

Moments of inertia (kg*cm^2, about the segment's centre of mass) regressed on body mass and
stature, about three axes: "ap" the antero-posterior axis (x in sled's body frame), "ml" the
medio-lateral one (y), "si" the longitudinal one (z; a foot's x). Zatsiorsky and Seluyanov (1983)
give them for the men (the same 100 subjects as the masses), Shan and Bohn (2003) for German men
and women. The coefficients were read from the tables of the public repository
wspr/body-segment-param (files data/zats-tables/zats2-male-moi-{ap,ml,si}.csv and
data/regr-mass-height/shan-bohn-{MG,FG}-moi-{ap,ml,si}.csv), whose mass tables agree with the
mass coefficients above digit for digit; they were not checked against the papers themselves.
scale_body.py uses them as ratios to the same equations at male50's size (below).
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

# Moments of inertia [kg*cm^2] on body mass [kg] and stature [cm], per axis (see the docstring).
ZATSIORSKY_1983_MALE_INERTIA = {
    "ap": {
        "foot": (-100, 0.480, 0.626),
        "shank": (-1105, 4.59, 6.63),
        "thigh": (-3557, 31.7, 18.61),
        "hand": (-19.5, 0.17, 0.116),
        "forearm": (-64, 0.95, 0.34),
        "arm": (-250.7, 1.56, 1.512),
        "head": (-78, 1.171, 1.519),
        "thorax": (81.2, 36.73, -5.97),
        "abdomen": (618.5, 39.8, -12.87),
        "pelvis": (-1568, 12, 7.741),
    },
    "ml": {
        "foot": (-97.09, 0.414, 0.614),
        "shank": (-1152, 4.594, 6.815),
        "thigh": (-3690, 32.02, 19.24),
        "hand": (-13.68, 0.088, 0.092),
        "forearm": (-67.9, 0.855, 0.376),
        "arm": (-232, 1.525, 1.343),
        "head": (-112, 1.43, 1.73),
        "thorax": (367, 18.3, -5.73),
        "abdomen": (263, 26.7, -8.0),
        "pelvis": (-934, 11.8, 3.44),
    },
    "si": {
        "foot": (-15.48, 0.144, 0.088),
        "shank": (-70.5, 1.134, 0.3),
        "thigh": (-13.5, 11.3, -2.28),
        "hand": (-6.26, 0.0762, 0.0347),
        "forearm": (5.66, 0.306, -0.088),
        "arm": (-16.9, 0.662, 0.0435),
        "head": (61.6, 1.72, 0.0814),
        "thorax": (561, 36.03, -9.98),
        "abdomen": (1501, 43.14, -19.8),
        "pelvis": (-775, 14.7, 1.685),
    },
}

SHAN_BOHN_2003_MALE_INERTIA = {
    "ap": {
        "head": (-1450, 6.29, 7.36),
        "thorax": (-3034, 40.1, 10.5),
        "abdomen": (1471, 22.7, -12.4),
        "pelvis": (1532, 30.1, -15.8),
        "thigh": (-1884, 41.4, 3.2),
        "shank": (-1504, 5.34, 8.76),
        "foot": (-23.1, 0.003, 0.155),
        "arm": (-509, 1.68, 2.82),
        "forearm": (-160, -0.0113, 1.26),
        "hand": (-20.3, -0.0284, 0.158),
    },
    "ml": {
        "head": (-1632, 6.06, 8.86),
        "thorax": (-2321, 17.7, 10.7),
        "abdomen": (440, 9.93, -3.89),
        "pelvis": (788, 23.6, -10.3),
        "thigh": (-2028, 41.2, 4.09),
        "shank": (-1389, 4.45, 8.19),
        "foot": (-105, 0.116, 0.703),
        "arm": (-471, 1.85, 2.55),
        "forearm": (-158, -0.0327, 1.23),
        "hand": (-21.3, -0.0219, 0.168),
    },
    "si": {
        "head": (-498, 3.67, 2.4),
        "thorax": (16.7, 45.8, -10.1),
        "abdomen": (2535, 31.2, -21.8),
        "pelvis": (1639, 34.2, -18.3),
        "thigh": (282, 13.8, -5.46),
        "shank": (-167, 1.73, 0.707),
        "foot": (-100, 0.119, 0.674),
        "arm": (26, 0.711, -0.309),
        "forearm": (-11.4, 0.0844, 0.0708),
        "hand": (-5.11, -0.0084, 0.0467),
    },
}

SHAN_BOHN_2003_FEMALE_INERTIA = {
    "ap": {
        "head": (-768, 2.44, 5.2),
        "thorax": (5096, 51.1, -39.3),
        "abdomen": (-1042, 14.5, 3.7),
        "pelvis": (-356, 12.4, 1.31),
        "thigh": (-6984, 40.6, 34.5),
        "shank": (-703, 2.47, 5.32),
        "foot": (-12.1, 0.03, 0.0781),
        "arm": (43.8, 1.15, -0.202),
        "forearm": (-121, 0.622, 0.71),
        "hand": (-16.3, 0.0409, 0.102),
    },
    "ml": {
        "head": (-952, 2.7, 6.5),
        "thorax": (2303, 34, -20.2),
        "abdomen": (-319, 6.4, 1.08),
        "pelvis": (-129, 11, -0.79),
        "thigh": (-6342, 35.5, 32.5),
        "shank": (-690, 1.86, 5.22),
        "foot": (-78.1, 0.181, 0.496),
        "arm": (46.1, 1.11, -0.19),
        "forearm": (-122, 0.598, 0.714),
        "hand": (-17.6, 0.0436, 0.113),
    },
    "si": {
        "head": (-540, 1.43, 3.583),
        "thorax": (5072, 37.7, -36.5),
        "abdomen": (-716, 18.4, 0.301),
        "pelvis": (-314, 17.5, -0.862),
        "thigh": (-755, 14.3, 0.766),
        "shank": (-21.5, 1.03, 0.147),
        "foot": (-73.8, 0.194, 0.465),
        "arm": (69.6, 0.384, -0.475),
        "forearm": (-4.09, 0.0841, 0.0176),
        "hand": (-2.27, 0.0148, 0.0157),
    },
}

# Jensen (1989): each segment's share of the body mass (a fraction) as a quadratic in age [years],
# share = a + b age + c age^2, fitted to boys of 4 to 20 years; one side of each limb. The
# forearm is with the hand, the calf with the foot. Coefficients as transcribed in public code
# (no table of the paper could be read here); the head's are the example the AIST human
# properties database prints for this paper
# (https://www.airc.aist.go.jp/dhrt/properties/segment/k-13.html): 0.27881 - 0.021152 age +
# 0.00053168 age^2. At 6 years they give shares within 1.1 points of the 6-year-old's table
# above (head 17.1 against 18.2 %, trunk 42.4 against 43.0 %; tests/compiler/body_family_test.cpp).
JENSEN_1989_AGE = {
    "head": (0.27881, -0.021152, 0.00053168),
    "upper_torso": (0.15837, -0.00125, 0.0),
    "lower_torso": (0.2733, 0.0, 0.0),
    "arm": (0.02344, 0.000696, 0.0),
    "forearm_hand": (0.0228, 0.000261, 0.0),
    "thigh": (0.04309, 0.0088978, -0.00027425),
    "calf_foot": (0.03512, 0.0063207, -0.00026119),
}
JENSEN_1989_AGES = (4.0, 20.0)  # the sample's ages


def jensen_shares(age):
    """Jensen's (1989) shares of the body mass [%] at `age` years."""
    return {s: 100 * (a + b * age + c * age * age) for s, (a, b, c) in JENSEN_1989_AGE.items()}


# male50's segments from the sources' (one side of each limb). Head and neck, and the trunk of a
# source without its split, are shared in male50's own proportions (scale_body.py).
MAPPING = {
    "head": ["head"],
    "neck": ["head"],
    "thorax": ["thorax", "trunk", "upper_torso"],
    "abdomen": ["abdomen", "trunk", "lower_torso"],
    "pelvis": ["pelvis", "trunk", "lower_torso"],
    "upper_arm": ["arm"],
    "lower_arm": ["forearm", "hand", "forearm_hand"],
    "upper_leg": ["thigh"],
    "lower_leg": ["shank", "calf_foot"],
    "foot": ["foot", "calf_foot"],
}

MODELS = {
    "male": {
        "mass": ZATSIORSKY_1983_MALE_MASS,
        "length": SHAN_BOHN_2003_MALE_LENGTH,
        # The moments at this size over the same equations' at male50's.
        "inertia": (ZATSIORSKY_1983_MALE_INERTIA, ZATSIORSKY_1983_MALE_INERTIA),
        "citation": [
            "Segment masses: Zatsiorsky and Seluyanov (1983), The mass and inertia characteristics",
            "of the main segments of the human body, Biomechanics VIII-B, 1152-1159 (multiple",
            "regression on body mass and stature, 100 young men).",
            "Segment lengths: Shan and Bohn (2003), Anthropometrical data and coefficients of",
            "regression related to gender and race, Applied Ergonomics 34, 327-337 (male,",
            "German subjects).",
            "Moments of inertia: Zatsiorsky and Seluyanov's (1983) regressions on body mass and",
            "stature (the same men).",
        ],
    },
    "female": {
        "mass": SHAN_BOHN_2003_FEMALE_MASS,
        "length": SHAN_BOHN_2003_FEMALE_LENGTH,
        # The women's moments at this size over the men's (same paper) at male50's.
        "inertia": (SHAN_BOHN_2003_FEMALE_INERTIA, SHAN_BOHN_2003_MALE_INERTIA),
        "citation": [
            "Segment masses and lengths: Shan and Bohn (2003), Anthropometrical data and",
            "coefficients of regression related to gender and race, Applied Ergonomics 34,",
            "327-337 (female, German subjects), moments of inertia from the same paper.",
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
    "child3": {
        "share": jensen_shares(3.0),
        "citation": [
            "Segment masses: Jensen (1989), Changes in segment inertia proportions between 4 and",
            "20 years, J. Biomech. 22, 529-536: its quadratic regressions of each segment's share",
            "of the body mass on age, at 3 years, one year below its sample (an extrapolation).",
            "The head's share is male50's head and neck, the upper torso the thorax, the lower",
            "torso the abdomen and pelvis, the forearm the lower arm (with the hand), the calf the",
            "lower leg and foot, each shared in male50's proportions. No segment lengths are",
            "published there: lengths are scaled.",
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
