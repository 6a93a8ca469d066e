//! Section 8: the figures of each scene, inline as base64 PNG (read back from the report
//! directory they were just drawn into), each with a one-line caption saying what to read in it.

use super::{Context, esc};
use crate::planner::Level;
use crate::report::figure_size::FigureKind;
use base64::Engine;
use std::fmt::Write;
use std::io;

/// The figures a scene folder may hold, and what to read in each.
pub const FIGURES: [(&str, &str); 4] = [
    (
        "distribution.png",
        "Tension T(θ) and friction q(θ) within its Coulomb bounds ±μn over the wrap: read where friction is positive (dark red shade) or reverse (light blue shade) at the Coulomb limit, hatched where the rope slips, and the demarcation point (JDP).",
    ),
    (
        "wrap_diagram.png",
        "The pulley with the same state drawn round its wrap: tension as a band outside the rim, from T = 0 on the rim to 1.6 R at the highest tension (dotted circle), positive (dark red) and reverse (light blue) friction inside it against the dashed Coulomb limit, the JDP as a radial line.",
    ),
    (
        "history.png",
        "End tensions, the positive and reverse arcs with the JDP (a line where it moves with the rope or the load, dots where it jumps), and the anti-slip safety factor against the minimum that applies (static at rest, dynamic in motion), values above the axis marked off scale.",
    ),
    (
        "wrap_map.png",
        "Friction utilization |q|/μn over time (across) and the wrap (θ, up), signed by the friction's direction as its colour bar shows (positive dark red, reverse light blue, none near-white; the two apart in greyscale too); the JDP in black, a line where it moves continuously and a short mark per output step where it jumps: read how the pattern moves round the wrap.",
    ),
];

/// 8. Figures of every scene that has them.
pub fn figures(out: &mut String, ctx: &Context) -> io::Result<()> {
    let mut n = 0;
    for s in &ctx.run.scenes {
        for (file, caption) in FIGURES {
            let path = ctx.dir.join(&s.name).join(file);
            if !path.is_file() {
                continue;
            }
            n += 1;
            let png = std::fs::read(&path)?;
            let data = base64::engine::general_purpose::STANDARD.encode(png);
            let nodes = match (s.plan.level, s.nodes) {
                (Level::Dynamic4, Some(n)) => duty_cycle_accuracy(n, s.level3.is_some()),
                _ => String::new(),
            };
            let _ = writeln!(
                out,
                "<figure><img class=\"fig-{}\" alt=\"{}\" src=\"data:image/png;base64,{data}\"><figcaption><b>Figure {n}.</b> {} — {}{}</figcaption></figure>",
                FigureKind::of_file(file).unwrap_or(FigureKind::Panels).css_name(),
                esc(&format!("{}/{file}", s.name)),
                esc(&s.name),
                esc(caption),
                esc(&nodes)
            );
        }
    }
    if n == 0 {
        out.push_str("<p class=\"note\">No figures: the run was made with <code>--no-plots</code>, or no scene has a wrap distribution.</p>\n");
    }
    Ok(())
}

/// What sets the accuracy of a duty cycle's figures, for their captions: on the rigid lining
/// (level 2) the node count is only the output grid and the ropes' time step sets the error; on
/// the elastic lining (level 3) the node count is the lining's segments.
fn duty_cycle_accuracy(nodes: usize, elastic: bool) -> String {
    if elastic {
        format!(
            " On the elastic lining N = {nodes} is the number of lining segments: the friction converges at second order in their pitch (README, Speed and accuracy)."
        )
    } else {
        format!(
            " The arcs and JDP of a duty cycle do not depend on the node count (N = {nodes} is only the output grid): the ropes' time step sets their accuracy, 0.18° RMS in the arcs and 9.7e-6 in tension at the default 1 ms against a step of 0.25 ms (README, Speed and accuracy)."
        )
    }
}
