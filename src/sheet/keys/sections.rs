//! The registry's sections other than `[[scene]]`: the top level, `[pulley]`, `[pulley.guide]`,
//! `[rope]`, `[requirements]`, `[document]`, `[lining]`, `[hoist]`, `[[hoist.stage]]`,
//! `[load_cases]` and `[[compare]]` (`[brake]` and `[drive]`: `drive.rs`).

use super::Type::{
    Bool, Integer, Limit, Number, Numbers, Table as Sub, Tables, Text, TextOrDate, TextOrInteger, Texts,
};
use super::{Default as D, Key, Table};
use crate::design::damping::DEFAULT_ROPE_DAMPING_RATIO;
use crate::design::{DEFAULT_SAFETY_FACTOR_SOURCE, Phase, Requirements, STANDARD_GRAVITY_M_S2, compare_columns};
use crate::sheet::hoist::{DEFAULT_TIME_STEP_S, MAX_STAGES, TAIL_COUNT_MAX};
use crate::sheet::lining::DEFAULT_BENDING_RATIO;
use crate::sheet::load_cases::{DEFAULT_POSITIONS, DEFAULT_STOPS, MAX_ENTRIES};
use crate::sheet::rules::{MU_MAX, ROPE_COUNT_MAX, WRAP_ANGLE_MAX_DEG};

pub(super) fn table(path: &'static str, array: bool, meaning: &'static str, keys: Vec<Key>) -> Table {
    Table { path, array, meaning, keys, one_of: Vec::new() }
}

/// Every section but `[[scene]]`, in the order of the reference.
pub fn tables() -> Vec<Table> {
    vec![
        top(),
        pulley(),
        guide(),
        rope(),
        requirements(),
        document(),
        super::drive::brake(),
        super::drive::drive(),
        lining(),
        hoist(),
        stage(),
        load_cases(),
        compare(),
    ]
}

fn top() -> Table {
    let section = |name, ty, meaning| Key::new(name, ty, "", meaning);
    let hoist = "required in a hoist sheet (one without [lift])";
    let mut t = table(
        "",
        false,
        "The sheet's own keys and its sections. A hoist sheet needs [pulley], [rope] and at least one [[scene]] (or a [hoist] with \
         [load_cases]: the load-case matrix alone); \
         a lift sheet has [lift] and, beside it, only title and g_m_s2.",
        vec![
            Key::new("title", Text, "", "the design's title, echoed in the outputs"),
            Key::new("g_m_s2", Number, "m/s²", "gravity g")
                .default(D::Number(STANDARD_GRAVITY_M_S2))
                .positive()
                .max(30.0, true),
            section("pulley", Sub, "the friction pulley and its wrap").when(hoist),
            section("rope", Sub, "the hoisting ropes").when(hoist),
            section("requirements", Sub, "the limits of the checks, each with its source"),
            section("document", Sub, "the calculation report's title block"),
            section("brake", Sub, "the safety brake that stops the pulley in an emergency"),
            section("drive", Sub, "the drive: rotating inertia, efficiency, the motor's rating, rest between trips"),
            section("lining", Sub, "the elastic lining of level 3 (switches level 3 on)"),
            section("hoist", Sub, "the hoist that duty-cycle scenes and the load-case matrix run"),
            section("load_cases", Sub, "the load-case matrix built from the [hoist]"),
            section(
                "scene",
                Tables,
                "the scenes: states and histories to analyse (at least one, unless [hoist] and [load_cases] are given)",
            )
            .when(hoist),
            section("compare", Tables, "figures overlaying one quantity of several time scenes"),
            section("ropes", Sub, "the hoisting ropes one by one: multi-rope load sharing"),
            section("lift", Sub, "a traction lift: makes the sheet a lift sheet (EN 81-50)"),
            section("sensitivity", Sub, "the ranges of the uncertain inputs the rope-dynamics checks are rerun at"),
        ],
    );
    t.one_of = vec![vec!["pulley", "rope", "scene"], vec!["pulley", "rope", "hoist", "load_cases"], vec!["lift"]];
    t
}

fn pulley() -> Table {
    let mut t = table(
        "pulley",
        false,
        "The friction pulley: diameter, friction, the wrap angle (or [pulley.guide]) and its inertia.",
        vec![
            Key::new("diameter_m", Number, "m", "friction pulley diameter D (R = D/2)").required().positive(),
            Key::new("mu", Number, "", "friction coefficient μ rope–lining").required().positive().max(MU_MAX, true),
            Key::new("wrap_angle_deg", Number, "deg", "the wrap angle α")
                .when("required unless [pulley.guide] gives the geometry")
                .positive()
                .max(WRAP_ANGLE_MAX_DEG, true)
                .note("not with the [pulley.guide] geometry (vertical_m, horizontal_m)"),
            Key::new(
                "guide",
                Sub,
                "",
                "the guide (deflection) sheave: the wrap's geometry, or only its diameter and inertia",
            ),
            Key::new("inertia_kg_m2", Number, "kg·m²", "J of the friction pulley with motor and gear about its axis …")
                .default(D::Number(0.0))
                .non_negative()
                .note("not with equivalent_mass_kg"),
            Key::new("equivalent_mass_kg", Number, "kg", "… or J/R² at the rim")
                .default(D::Number(0.0))
                .non_negative()
                .note("not with inertia_kg_m2"),
        ],
    );
    t.one_of = vec![vec!["wrap_angle_deg"], vec!["guide"]];
    t
}

fn guide() -> Table {
    table(
        "pulley.guide",
        false,
        "The guide sheave. With vertical_m and horizontal_m it gives α = 180° + asin((R + R_g)/D_c) − atan(h_h/h_v), \
         D_c = √(h_v² + h_h²); beside a given wrap_angle_deg it carries only its diameter and inertia.",
        vec![
            Key::new("diameter_m", Number, "m", "guide sheave diameter").required().positive(),
            Key::new("vertical_m", Number, "m", "vertical distance h_v of the centres")
                .when("required for the geometry")
                .positive(),
            Key::new("horizontal_m", Number, "m", "horizontal distance h_h of the centres")
                .when("required for the geometry")
                .non_negative(),
            Key::new("side", Integer, "", "the side whose rope runs over the sheave")
                .default(D::Number(2.0))
                .min(1.0, true)
                .max(2.0, true)
                .note("required with an inertia"),
            Key::new("inertia_kg_m2", Number, "kg·m²", "J_g of the guide sheave about its axis …")
                .default(D::Number(0.0))
                .non_negative()
                .note("not with equivalent_mass_kg"),
            Key::new("equivalent_mass_kg", Number, "kg", "… or J_g/R_g² at its rim")
                .default(D::Number(0.0))
                .non_negative()
                .note("not with inertia_kg_m2"),
        ],
    )
}

fn rope() -> Table {
    table(
        "rope",
        false,
        "The hoisting ropes (all alike): count, mass, stiffness, and the data of the checks beside anti-slip.",
        vec![
            Key::new("count", Integer, "", "number of hoisting ropes n")
                .required()
                .min(1.0, true)
                .max(ROPE_COUNT_MAX as f64, true),
            Key::new("mass_per_m_kg", Number, "kg/m", "m' of one rope").required().positive(),
            Key::new("ea_n", Number, "N", "axial stiffness EA of one rope").required().positive(),
            Key::new(
                "diameter_m",
                Number,
                "m",
                "nominal rope diameter d: D/d, lining pressures; with modulus_pa, the bending stiffness",
            )
            .positive(),
            Key::new("min_breaking_force_n", Number, "N", "minimum breaking force of one rope: the rope safety factor")
                .positive(),
            Key::new("bending_stiffness_n_m2", Number, "N·m²", "EI of one rope (level 3; needs a [lining]) …")
                .default(D::Number(0.0))
                .non_negative()
                .note("not with modulus_pa"),
            Key::new("modulus_pa", Number, "Pa", "… or EI = bending_ratio·E·πd⁴/64 with diameter_m").positive(),
            Key::new("bending_ratio", Number, "", "a stranded rope's EI against a solid bar's (with modulus_pa)")
                .default(D::Number(DEFAULT_BENDING_RATIO))
                .positive()
                .max(1.0, true),
        ],
    )
}

fn requirements() -> Table {
    let d = Requirements::default();
    let limit = |name, unit, meaning: &str| {
        Key::new(name, Limit, unit, format!("{meaning} (none by default: the check is reported unjudged)")).positive()
    };
    let decel = |name, meaning: &str| limit(name, "m/s²", meaning).max(30.0, true).note("min ≤ max");
    let mut out = table(
        "requirements",
        false,
        "The limits of the checks. Each is a number or { value = …, source = \"…\" }; a bare number's source reads \
         \"the sheet (no source given)\".",
        vec![
            Key::new("static_safety_factor_min", Limit, "", "static anti-slip safety factor minimum")
                .default(D::Number(d.static_safety_factor_min))
                .positive()
                .note(format!("default source \"{DEFAULT_SAFETY_FACTOR_SOURCE}\"")),
            Key::new("dynamic_safety_factor_min", Limit, "", "dynamic anti-slip safety factor minimum")
                .default(D::Number(d.dynamic_safety_factor_min))
                .positive()
                .note(format!("default source \"{DEFAULT_SAFETY_FACTOR_SOURCE}\"")),
            Key::new(
                "dynamic_safety_factor_basis",
                Text,
                "",
                "which dynamic factor of a duty cycle decides the verdict: rigid ropes, or with the ropes' dynamics (level 4)",
            )
            .default(D::Word("code"))
            .words(&["code", "rope-dynamics"]),
            Key::new("code", Text, "", "the bundled rule set (design code) the limits come from, by id (`wrapcalc codes` lists them)")
                .note("a limit the sheet gives itself overrides the rule set's"),
            Key::new("conveyance1_carries", Text, "", "what the side-1 conveyance carries, for a rule set's limits")
                .words(&crate::sheet::codes::CARRIES),
            Key::new("conveyance2_carries", Text, "", "what the side-2 conveyance carries, for a rule set's limits")
                .words(&crate::sheet::codes::CARRIES),
            Key::new("layout", Text, "", "the hoist's layout, where a rule set distinguishes it")
                .words(&crate::sheet::codes::LAYOUTS),
            Key::new("hanging_length_m", Number, "m", "hanging length H of a head rope, for a rule set's formulas")
                .positive(),
            limit("rope_safety_factor_min", "", "rope safety factor minimum"),
            limit("pulley_d_ratio_min", "", "D/d of the friction pulley, minimum"),
            limit("guide_d_ratio_min", "", "D/d of the guide sheave, minimum"),
            limit("lining_pressure_max_pa", "Pa", "specific pressure (T1 + T2)/(D·d), maximum"),
            limit("lining_peak_pressure_max_pa", "Pa", "peak pressure max n(θ)/(R·d), maximum"),
            limit("mu_design_max", "", "design cap on μ: a warning above it"),
            limit("static_tension_max_n", "N", "largest static tension, all ropes"),
            limit("static_tension_difference_max_n", "N", "largest static tension difference, all ropes"),
            decel("emergency_decel_lift_min_m_s2", "emergency deceleration lifting side 1, minimum"),
            decel("emergency_decel_lift_max_m_s2", "emergency deceleration lifting side 1, maximum"),
            decel("emergency_decel_lower_min_m_s2", "emergency deceleration lowering side 1, minimum"),
            decel("emergency_decel_lower_max_m_s2", "emergency deceleration lowering side 1, maximum"),
            limit("lining_mu_min", "", "friction coefficient of the lining, minimum: the design μ (pulley.mu) is checked"),
            limit("lining_mu_wet_min", "", "friction coefficient of the lining with water or rope dressing, minimum")
                .note("checked on lining_mu_wet"),
            limit("tail_rope_safety_factor_min", "", "tail (balance) rope safety factor minimum"),
            limit("pulley_design_load_min_n", "N", "design load of the friction wheel with shaft and bearings, minimum")
                .note("checked on pulley_design_load_n"),
            limit("dynamic_allowance_min", "", "allowance for the dynamic loads on the static loads of the machine ratings")
                .max(1.0, true),
            // The design inputs of the rule sets' formulas and checks follow ([`code_inputs`]).
            limit(
                "brake_holding_factor_min",
                "",
                "static holding factor of the brake (its torque over the largest static out-of-balance torque), minimum",
            ),
        ],
    );
    out.keys.extend(code_inputs());
    out
}

/// The `[requirements]` keys that are design inputs of the rule sets' formulas and checks.
fn code_inputs() -> Vec<Key> {
    vec![
        Key::new("rope_construction", Text, "", "the hoisting ropes' construction, where a rule set distinguishes it")
            .words(&crate::sheet::requirements::ROPE_CONSTRUCTIONS),
        Key::new(
            "certified_unbalanced_load_n",
            Number,
            "N",
            "the maximum unbalanced load in the hoist's certificate, all ropes, for a rule set's formulas",
        )
        .positive(),
        Key::new(
            "lining_mu_wet",
            Number,
            "",
            "the lining's friction coefficient with water or rope dressing (its test report): the wet checks",
        )
        .positive()
        .max(MU_MAX, true),
        Key::new(
            "pulley_design_load_n",
            Number,
            "N",
            "the load the friction wheel with shaft and bearings is designed for at yield, all ropes",
        )
        .positive(),
    ]
}

fn document() -> Table {
    table(
        "document",
        false,
        "The calculation report's title block, echoed as given; every key optional.",
        vec![
            Key::new("project", Text, "", "project name"),
            Key::new("title", Text, "", "title of the calculation"),
            Key::new("revision", TextOrInteger, "", "revision of the document"),
            Key::new("author", Text, "", "who wrote the calculation"),
            Key::new("checker", Text, "", "who checked it"),
            Key::new("date", TextOrDate, "", "date of issue, as written (a TOML date or a text)"),
            Key::new("appendix_figures", Bool, "", "whether report.html ends with the appendix of further figures")
                .default(D::Bool(true)),
        ],
    )
}

fn lining() -> Table {
    let shear = ["thickness_m", "shear_modulus_pa", "contact_width_m"];
    let mut t = table(
        "lining",
        false,
        "The elastic lining: switches level 3 on.",
        vec![
            Key::new(
                "shear_stiffness_n_per_m2",
                Number,
                "N/m²",
                "k_s: friction force per metre of rope per metre of rope–lining displacement …",
            )
            .when("required (or the three keys below)")
            .positive()
            .note("not with the three keys below"),
            Key::new(
                "thickness_m",
                Number,
                "m",
                "… or a lining layer in simple shear, k_s = G·b/t: thickness t under the rope",
            )
            .positive(),
            Key::new("shear_modulus_pa", Number, "Pa", "the layer's shear modulus G").positive(),
            Key::new("contact_width_m", Number, "m", "the rope's contact width b").positive(),
            Key::new("rope_inertia", Bool, "", "add m'·R·a per radian to the rope's equilibrium")
                .default(D::Bool(false)),
        ],
    );
    t.one_of = vec![vec!["shear_stiffness_n_per_m2"], shear.to_vec()];
    t
}

fn hoist() -> Table {
    table(
        "hoist",
        false,
        "The hoist that duty-cycle scenes and the load-case matrix run.",
        vec![
            Key::new("conveyance1_kg", Number, "kg", "side-1 conveyance without payload").required().positive(),
            Key::new("conveyance2_kg", Number, "kg", "counterweight or side-2 conveyance").required().positive(),
            Key::new("rope_damping_ratio", Number, "", "damping ratio of the hoisting ropes' first longitudinal mode (default: the reference hoist's rope model, Guo et al. 2020; 0 runs undamped and is warned)")
                .default(D::Number(DEFAULT_ROPE_DAMPING_RATIO))
                .non_negative()
                .max(1.0, false),
            Key::new("tail_count", Integer, "", "tail (balance) ropes")
                .default(D::Number(0.0))
                .non_negative()
                .max(TAIL_COUNT_MAX as f64, true),
            Key::new("tail_mass_per_m_kg", Number, "kg/m", "mass per metre of one tail rope")
                .default(D::Number(0.0))
                .non_negative(),
            Key::new(
                "side1_length_m",
                Number,
                "m",
                "hanging length from the tangent point to the side-1 conveyance at the start",
            )
            .required()
            .positive(),
            Key::new(
                "side2_length_m",
                Number,
                "m",
                "hanging length from the tangent point to the side-2 conveyance at the start",
            )
            .required()
            .positive(),
            Key::new("tail1_length_m", Number, "m", "tail rope hanging below the side-1 conveyance at the start")
                .default(D::Number(0.0))
                .non_negative(),
            Key::new("tail2_length_m", Number, "m", "tail rope hanging below the side-2 conveyance at the start")
                .default(D::Number(0.0))
                .non_negative(),
            Key::new(
                "tail_min_breaking_force_n",
                Number,
                "N",
                "minimum breaking force of one tail rope: the tail ropes' safety factor",
            )
            .positive(),
            Key::new("stage", Tables, "", "the motion profile, lifting side 1, in order ([[hoist.stage]])")
                .required()
                .items(1, MAX_STAGES),
        ],
    )
}

fn stage() -> Table {
    let mut t = table(
        "hoist.stage",
        true,
        "One stage of the motion profile.",
        vec![
            Key::new("name", Text, "", "label").default(D::Described("stage i".into())),
            Key::new("duration_s", Number, "s", "length of the stage")
                .when("required (or until_stop = true)")
                .non_negative(),
            Key::new("until_stop", Bool, "", "the stage lasts until the speed reaches 0")
                .default(D::Bool(false))
                .note("not with duration_s"),
            Key::new(
                "accel_m_s2",
                Number,
                "m/s²",
                "acceleration at the end of the stage, side 1 upward positive, reached linearly from the previous stage's",
            )
            .required()
            .min(-9.81, true)
            .max(9.81, true),
            Key::new("step", Bool, "", "jump to accel_m_s2 at the stage's start instead of ramping").default(D::Bool(false)),
        ],
    );
    t.one_of = vec![vec!["duration_s"], vec!["until_stop"]];
    t
}

fn load_cases() -> Table {
    let phases: Vec<&'static str> = Phase::ALL.iter().map(|p| p.keyword()).collect();
    table(
        "load_cases",
        false,
        "The load-case matrix built from the [hoist] (needs a [hoist]). Repeated values are counted once.",
        vec![
            Key::new("payloads_kg", Numbers, "kg", "payloads on the side-1 conveyance")
                .required()
                .non_negative()
                .items(1, MAX_ENTRIES),
            Key::new("directions", Texts, "", "trip directions")
                .default(D::Words(vec!["lift", "lower"]))
                .words(&["lift", "lower"]),
            Key::new("positions", Numbers, "", "positions along the travel, as fractions (0: side 1 at the bottom)")
                .default(D::Numbers(DEFAULT_POSITIONS.to_vec()))
                .non_negative()
                .max(1.0, true)
                .items(1, MAX_ENTRIES),
            Key::new("rope_dynamics", Texts, "", "phases also run with the ropes' dynamics (level 4); [] for none")
                .default(D::Words(vec![crate::design::Phase::Emergency.keyword()]))
                .words(&phases)
                .note("\"emergency\" given explicitly needs a [brake] or emergency_decel_m_s2"),
            Key::new(
                "rope_dynamics_stops",
                Numbers,
                "",
                "where in the full-speed run the stops in time trip, as fractions; [] for none",
            )
            .default(D::Numbers(DEFAULT_STOPS.to_vec()))
            .non_negative()
            .max(1.0, true)
            .items(0, MAX_ENTRIES),
            Key::new(
                "emergency_decel_m_s2",
                Number,
                "m/s²",
                "an imposed emergency deceleration instead of the [brake]",
            )
            .positive()
            .max(9.81, true),
            Key::new("time_step_s", Number, "s", "integration step of the ropes' dynamics")
                .default(D::Number(DEFAULT_TIME_STEP_S))
                .positive()
                .max(0.1, true),
        ],
    )
}

fn compare() -> Table {
    let mut quantities = vec!["track"];
    quantities.extend(compare_columns());
    table(
        "compare",
        true,
        "A figure overlaying one quantity of several time scenes (compare/<name>.png).",
        vec![
            Key::new(
                "name",
                Text,
                "",
                "names the figure's file (letters, digits, '-', '_', '.'; not starting with '.'; unique)",
            )
            .required(),
            Key::new("scenes", Texts, "", "names of time scenes of the sheet to overlay").required().note("non-empty"),
            Key::new(
                "quantity",
                Text,
                "",
                "the first followed element of each scene (\"track\") or a history.csv column",
            )
            .required()
            .words(&quantities),
        ],
    )
}
