//! The formula language of a rule set's limits: arithmetic on the design's own quantities, `min`,
//! `max` and a choice by a categorical key (`if(carries == "personnel", a, b)`), evaluated by the
//! `evalexpr` crate. The variables a formula may use are listed in [`VARIABLES`]; a formula that
//! names any other is refused when the rule set is read.

use evalexpr::{ContextWithMutableVariables, DefaultNumericTypes, HashMapContext, Node, Value};

/// A variable a limit's formula may use: its name, unit and meaning.
pub struct Variable {
    /// The name as written in a formula.
    pub name: &'static str,
    /// Its unit ("" for a ratio, "text" for a categorical key).
    pub unit: &'static str,
    /// What it is and which sheet key gives it.
    pub meaning: &'static str,
}

/// Every variable of the formula language.
pub const VARIABLES: &[Variable] = &[
    Variable {
        name: "H",
        unit: "m",
        meaning: "hanging length of a head rope, tangent point to conveyance at its lowest position \
                  (`requirements.hanging_length_m`, else the longer of `hoist.side1_length_m` and `hoist.side2_length_m`)",
    },
    Variable {
        name: "carries",
        unit: "text",
        meaning: "what the conveyances carry, the most demanding of the two: \"personnel\", \
                  \"personnel-and-material\" or \"material\" (`requirements.conveyance1_carries`, `conveyance2_carries`)",
    },
    Variable {
        name: "layout",
        unit: "text",
        meaning: "the hoist's layout: \"tower-with-guide-sheave\", \"tower\" or \"ground-mounted\" (`requirements.layout`)",
    },
    Variable {
        name: "rope_construction",
        unit: "text",
        meaning: "the hoisting ropes' construction: \"stranded\" or \"locked-coil\" (`requirements.rope_construction`)",
    },
    Variable { name: "d", unit: "m", meaning: "nominal diameter of a hoisting rope (`rope.diameter_m`)" },
    Variable {
        name: "F_set",
        unit: "N",
        meaning: "minimum breaking force of the hoisting rope set, n·F_min (`rope.count` × `rope.min_breaking_force_n`)",
    },
    Variable {
        name: "U_cert",
        unit: "N",
        meaning: "the maximum unbalanced load stated in the hoist's certificate, all ropes \
                  (`requirements.certified_unbalanced_load_n`)",
    },
    Variable {
        name: "v_rope",
        unit: "m/s",
        meaning: "a lift's rope speed at the traction sheave at rated speed, roping × `lift.rated_speed_m_s` (lift sheets)",
    },
    Variable {
        name: "n_ropes",
        unit: "",
        meaning: "a lift's number of suspension ropes, `lift.rope_count` (lift sheets)",
    },
];

/// The values of the variables for one design; `None` where the sheet does not give one.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Quantities {
    /// Hanging length H (m).
    pub hanging_length_m: Option<f64>,
    /// What the conveyances carry (the most demanding), as its sheet word.
    pub carries: Option<String>,
    /// The layout, as its sheet word.
    pub layout: Option<String>,
    /// The hoisting ropes' construction, as its sheet word.
    pub rope_construction: Option<String>,
    /// Nominal rope diameter d (m).
    pub rope_diameter_m: Option<f64>,
    /// Minimum breaking force of the rope set n·F_min (N).
    pub rope_set_breaking_force_n: Option<f64>,
    /// The certificate's maximum unbalanced load (N).
    pub certified_unbalanced_load_n: Option<f64>,
    /// A lift's rope speed at the sheave (m/s).
    pub rope_speed_m_s: Option<f64>,
    /// A lift's number of suspension ropes.
    pub rope_count: Option<f64>,
}

impl Quantities {
    /// The value of variable `name`, if the design has it.
    fn value(&self, name: &str) -> Option<Value<DefaultNumericTypes>> {
        match name {
            "H" => self.hanging_length_m.map(Value::Float),
            "carries" => self.carries.clone().map(Value::String),
            "layout" => self.layout.clone().map(Value::String),
            "rope_construction" => self.rope_construction.clone().map(Value::String),
            "d" => self.rope_diameter_m.map(Value::Float),
            "F_set" => self.rope_set_breaking_force_n.map(Value::Float),
            "U_cert" => self.certified_unbalanced_load_n.map(Value::Float),
            "v_rope" => self.rope_speed_m_s.map(Value::Float),
            "n_ropes" => self.rope_count.map(Value::Float),
            _ => None,
        }
    }
}

impl Quantities {
    /// `name = value unit` of each variable in `names` the design gives, for a limit's source
    /// (so that the value a formula used is shown with the result).
    pub fn describe(&self, names: &[&str]) -> Vec<String> {
        names
            .iter()
            .filter_map(|name| {
                let unit = VARIABLES.iter().find(|v| v.name == *name).map_or("", |v| v.unit);
                match self.value(name)? {
                    Value::String(s) => Some(format!("{name} = \"{s}\"")),
                    Value::Float(x) if unit.is_empty() => Some(format!("{name} = {x}")),
                    Value::Float(x) => Some(format!("{name} = {x} {unit}")),
                    _ => None,
                }
            })
            .collect()
    }
}

/// A parsed formula with the text it came from.
#[derive(Debug, Clone)]
pub struct Formula {
    /// The formula as written in the rule set.
    pub text: String,
    tree: Node<DefaultNumericTypes>,
}

/// Why a formula cannot be evaluated for a design.
#[derive(Debug, Clone, PartialEq)]
pub enum FormulaOutcome {
    /// The limit's value.
    Value(f64),
    /// The design does not give these variables.
    Missing(Vec<&'static str>),
    /// The formula gives no finite number for these values (the message says why).
    Invalid(String),
}

impl Formula {
    /// Parses `text`; refuses unknown variables and anything that is not an expression.
    pub fn parse(text: &str) -> Result<Self, String> {
        let tree = evalexpr::build_operator_tree::<DefaultNumericTypes>(text).map_err(|e| e.to_string())?;
        if let Some(v) = tree.iter_variable_identifiers().find(|v| VARIABLES.iter().all(|k| k.name != *v)) {
            let known: Vec<&str> = VARIABLES.iter().map(|k| k.name).collect();
            return Err(format!("unknown variable `{v}`; known: {}", known.join(", ")));
        }
        Ok(Self { text: text.to_string(), tree })
    }

    /// The variables the formula uses, each once, in the order of [`VARIABLES`].
    pub fn variables(&self) -> Vec<&'static str> {
        let used: Vec<&str> = self.tree.iter_variable_identifiers().collect();
        VARIABLES.iter().map(|v| v.name).filter(|n| used.contains(n)).collect()
    }

    /// The formula's value for the design's quantities `q`.
    pub fn eval(&self, q: &Quantities) -> FormulaOutcome {
        let mut ctx = HashMapContext::<DefaultNumericTypes>::new();
        let mut missing = Vec::new();
        for name in self.variables() {
            match q.value(name) {
                Some(v) => {
                    if let Err(e) = ctx.set_value(name.to_string(), v) {
                        return FormulaOutcome::Invalid(e.to_string());
                    }
                }
                None => missing.push(name),
            }
        }
        if !missing.is_empty() {
            return FormulaOutcome::Missing(missing);
        }
        match self.tree.eval_number_with_context(&ctx) {
            Ok(x) if x.is_finite() => FormulaOutcome::Value(x),
            Ok(x) => FormulaOutcome::Invalid(format!("the formula gives {x}")),
            Err(e) => FormulaOutcome::Invalid(e.to_string()),
        }
    }
}
