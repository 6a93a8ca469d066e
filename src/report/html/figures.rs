//! Section 8 and Appendix A: the figures, inline as base64 PNG (read back from the report
//! directory they were just drawn into), each with a caption saying what to read in it. The
//! main body shows the figures that decide a check (the history and distribution of each scene
//! whose case governs one, [`by_hand::governing_scenes`]); every other figure goes to the
//! appendix, two to a printed page, which `[document] appendix_figures = false` leaves out.

use super::{Context, by_hand, esc};
use crate::model::Level;
use crate::report::figure_size::FigureKind;
use base64::Engine;
use std::fmt::Write;
use std::io;

/// The figures a scene folder may hold, and what to read in each.
pub const FIGURES: [(&str, &str); 6] = [
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
    OVERLAY,
    (
        "ropes.png",
        "Each rope's end tensions through the trip (a dash pattern per rope) and the mean rope (the solid line) that the other figures show: read how far the most loaded rope departs from the mean and where its share builds up or is relieved.",
    ),
];

/// The overlay of rigid and dynamic tensions, and its caption.
const OVERLAY: (&str, &str) = (
    "rigid_dynamic.png",
    "End tensions T1 (top) and T2 (bottom) per rope with the suspended ropes' dynamics (solid) and on rigid ropes along the same motion (dashed): read how far each change of acceleration makes the ropes ring about the rigid tensions, the dominant frequency (dots: the crossings of T − T_rigid it is measured from, its value in the legend and the title beside the first mode's closed form) and the governing instant of the checks decided by the ropes' dynamics (vertical line).",
);

/// The checks decided by the ropes' dynamics, whose governing scene's overlay joins the main body.
const ROPE_CHECKS: [&str; 2] = [crate::model::level4::ROPE_DYNAMICS_CHECK, crate::model::level0::GROSS_SLIP_CHECK];

/// The figure that decides a scene's checks: a time scene's history (its end tensions and its
/// safety factor over time against the minimum, the governing instant among them); a steady
/// scene's distribution (its one state).
fn deciding(ctx: &Context, scene: usize) -> &'static str {
    let history = ctx.run.scenes.get(scene).is_some_and(|s| ctx.dir.join(&s.name).join("history.png").is_file());
    if history { "history.png" } else { "distribution.png" }
}

/// One figure of the document: the scene (its index), the file in the scene's folder, its
/// caption, and the checks it decides (empty in the appendix).
struct Figure {
    scene: usize,
    file: &'static str,
    caption: &'static str,
    decides: Vec<&'static str>,
}

/// The figures of the main body (the one of each scene whose case governs a check, [`deciding`]),
/// and every other figure of the run, for the appendix; only files the run drew.
fn placement(ctx: &Context) -> (Vec<Figure>, Vec<Figure>) {
    let exists = |scene: usize, file: &str| {
        ctx.run.scenes.get(scene).is_some_and(|s| ctx.dir.join(&s.name).join(file).is_file())
    };
    let governing = by_hand::governing_scenes(ctx.run);
    let (mut main, mut rest) = (Vec::new(), Vec::new());
    for (i, names) in &governing {
        let file = deciding(ctx, *i);
        for (file, caption) in FIGURES.iter().filter(|(f, _)| *f == file && exists(*i, f)) {
            main.push(Figure { scene: *i, file, caption, decides: names.clone() });
        }
        // Beside the checks decided by the ropes' dynamics: the rigid and dynamic tensions overlaid.
        let rope_checks: Vec<&'static str> = names.iter().copied().filter(|n| ROPE_CHECKS.contains(n)).collect();
        if !rope_checks.is_empty() && exists(*i, OVERLAY.0) {
            main.push(Figure { scene: *i, file: OVERLAY.0, caption: OVERLAY.1, decides: rope_checks });
        }
    }
    for i in 0..ctx.run.scenes.len() {
        for (file, caption) in FIGURES {
            if exists(i, file) && !main.iter().any(|f| f.scene == i && f.file == file) {
                rest.push(Figure { scene: i, file, caption, decides: vec![] });
            }
        }
    }
    // The figures that share a page first, two to a page; those that fill a page of their own
    // (the histories) after them, so that none leaves half a page empty.
    rest.sort_by_key(|f| !FigureKind::of_file(f.file).unwrap_or(FigureKind::Panels).two_per_page());
    (main, rest)
}

/// Writes one figure, numbered `n`, inline as base64 PNG.
fn figure(out: &mut String, ctx: &Context, n: usize, f: &Figure) -> io::Result<()> {
    let s = &ctx.run.scenes[f.scene];
    let png = std::fs::read(ctx.dir.join(&s.name).join(f.file))?;
    let data = base64::engine::general_purpose::STANDARD.encode(png);
    let accuracy = match (s.plan.level, s.nodes) {
        (Level::Dynamic4, Some(n)) => duty_cycle_accuracy(n, s.level3.is_some()),
        _ => String::new(),
    };
    let decides =
        if f.decides.is_empty() { String::new() } else { format!(" Governing case of: {}.", f.decides.join("; ")) };
    let _ = writeln!(
        out,
        "<figure class=\"half\"><img class=\"fig-{}\" alt=\"{}\" src=\"data:image/png;base64,{data}\"><figcaption><b>Figure {n}.</b> {} — {}{}{}</figcaption></figure>",
        FigureKind::of_file(f.file).unwrap_or(FigureKind::Panels).css_name(),
        esc(&format!("{}/{}", s.name, f.file)),
        esc(&s.name),
        esc(f.caption),
        esc(&decides),
        esc(&accuracy)
    );
    Ok(())
}

/// 8. The figures that decide a check: those of the scenes whose cases govern one.
pub fn figures(out: &mut String, ctx: &Context) -> io::Result<()> {
    let (main, rest) = placement(ctx);
    if main.is_empty() && rest.is_empty() {
        out.push_str("<p class=\"note\">No figures: the run was made with <code>--no-plots</code>, or no scene has a wrap distribution.</p>\n");
        return Ok(());
    }
    let elsewhere = match (rest.len(), ctx.design.document.appendix_figures) {
        (0, _) => String::new(),
        (k, true) => format!(" The other {k} figures of the run are in Appendix A."),
        (k, false) => format!(
            " The other {k} figures of the run are in the scene folders of the report directory (the sheet leaves the appendix out: <code>[document] appendix_figures = false</code>)."
        ),
    };
    let _ = writeln!(
        out,
        "<p>The figure of each scene whose case governs a check (section 7): a time scene's history, a steady scene's distribution.{elsewhere}</p>"
    );
    for (n, f) in main.iter().enumerate() {
        figure(out, ctx, n + 1, f)?;
    }
    Ok(())
}

/// Whether the document has an appendix: figures beside the main body's, and the sheet's
/// `[document]` does not leave them out.
pub fn has_appendix(ctx: &Context) -> bool {
    ctx.design.document.appendix_figures && !placement(ctx).1.is_empty()
}

/// Appendix A: every figure that decides no check, two to a printed page, numbered on from the
/// main body's.
pub fn appendix(out: &mut String, ctx: &Context) -> io::Result<()> {
    let (main, rest) = placement(ctx);
    out.push_str("<p class=\"note\">Every other figure of the run, scene by scene; the checks they show are decided by the figures of section 8 and the values of section 7.</p>\n");
    for (n, f) in rest.iter().enumerate() {
        figure(out, ctx, main.len() + n + 1, f)?;
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
