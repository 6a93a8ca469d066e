//! wrap_diagram.png: a polar picture of the pulley with the computed state drawn round its
//! wrap — the rope tension T(θ) as a band outside the rim that starts at zero on the rim (its
//! outer edge at radius R (1 + 0.6 T/T_max), so its width is proportional to T, with a dotted
//! circle at T_max), the signed friction q(θ) as bands inside it (depth 0.5 |q|/max μn; positive
//! friction dark red, reverse light blue: [`super::friction_colour`]) against the Coulomb limit
//! μn (dashed), and the JDP as a radial line.
//!
//! Geometry: the wrap is centred on the top of the pulley, θ = 0 (side 1) on the left, θ = α
//! (side 2) on the right, so a state and its mirror (sides swapped: θ → α − θ, q → −q) give
//! pictures mirrored left to right. The arcs follow the summary's rule: friction counts as
//! positive or reverse where |q| ≥ 0.001 μn, the crossings found by linear interpolation
//! between the output samples. What is drawn is built first as plain data ([`WrapDiagram`]).

use super::figure_size::FigureKind;
use super::friction_colour::{POSITIVE_END, REVERSE_END};
use super::plot::{Area, PlotError, e, font, render_sized};
use super::plot_series::legend_strip;
use super::plot_zones::{LegendEntry, Swatch};
use crate::wrap::Distribution;
use crate::wrap::contact::{ARC_THRESHOLD, NodeState};
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

const TENSION: RGBColor = RGBColor(20, 70, 160);
const POSITIVE: RGBColor = POSITIVE_END;
const REVERSE: RGBColor = REVERSE_END;
const LIMIT: RGBColor = RGBColor(110, 110, 110);
/// The tension band's fill: a neutral grey, apart in hue from the friction bands.
const BAND: RGBColor = RGBColor(218, 218, 218);
const JDP: RGBColor = RGBColor(20, 130, 60);
/// Radius of the rim the friction bands hang from (pulley radius 1).
const RIM: f64 = 0.96;
const FRICTION_DEPTH: f64 = 0.5;
/// Width of the tension band at the highest tension (pulley radii): T = 0 on the rim (radius
/// 1), T_max at radius 1 + TENSION_WIDTH.
pub const TENSION_WIDTH: f64 = 0.6;

/// A stretch of the wrap where friction has one sign, with its band (θ in degrees, unit-radius
/// picture coordinates).
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionArc {
    /// Where the stretch starts (deg from the side-1 tangent point).
    pub start_deg: f64,
    /// Where it ends (deg, ≥ `start_deg`).
    pub end_deg: f64,
    /// Positive friction (q > 0, in +θ) rather than reverse (q < 0).
    pub positive: bool,
    /// The band: along the rim from start to end, then back along |q|.
    pub polygon: Vec<(f64, f64)>,
}

/// What wrap_diagram.png shows.
#[derive(Debug, Clone, PartialEq)]
pub struct WrapDiagram {
    /// The wrap angle α (deg).
    pub wrap_angle_deg: f64,
    /// The tension curve, from θ = 0 to α: the outer edge of the band whose inner edge, the
    /// rim, is T = 0.
    pub tension: Vec<(f64, f64)>,
    /// The circle (an arc over the wrap) where the band's edge would be at the highest tension.
    pub tension_max: Vec<(f64, f64)>,
    /// The Coulomb limit μn, from θ = 0 to α.
    pub limit: Vec<(f64, f64)>,
    /// The positive and reverse stretches in +θ order, each with its band.
    pub arcs: Vec<FrictionArc>,
    /// The JDP (deg from the side-1 tangent point), drawn as a radial line, when there is one.
    pub jdp_deg: Option<f64>,
    /// The tensions at θ = 0 and θ = α (kN).
    pub end_tensions_kn: (f64, f64),
    /// The legend: the tension scale, the Coulomb limit, the arcs present and the JDP.
    pub legend: Vec<LegendEntry>,
}

impl WrapDiagram {
    /// Total measure of the positive (`true`) or reverse arcs (deg).
    pub fn arc_deg(&self, positive: bool) -> f64 {
        self.arcs.iter().filter(|a| a.positive == positive).map(|a| a.end_deg - a.start_deg).sum()
    }
}

/// The picture's angle (rad, counter-clockwise from +x) of wrap angle θ (deg) on a wrap of α.
fn screen_angle(theta_deg: f64, alpha_deg: f64) -> f64 {
    (90.0 + 0.5 * alpha_deg - theta_deg).to_radians()
}

fn polar(theta_deg: f64, r: f64, alpha_deg: f64) -> (f64, f64) {
    let phi = screen_angle(theta_deg, alpha_deg);
    (r * phi.cos(), r * phi.sin())
}

/// A sample reduced to what the picture needs: θ (deg), q, μn, and whether it is at the
/// Coulomb limit.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Point {
    theta_deg: f64,
    q: f64,
    limit: f64,
    at_limit: bool,
}

/// Sign class of friction q against the limit μn: +1 positive, −1 reverse, 0 below 0.001 μn.
fn class(q: f64, limit: f64) -> i8 {
    if q > 0.0 && q >= ARC_THRESHOLD * limit {
        1
    } else if q < 0.0 && -q >= ARC_THRESHOLD * limit {
        -1
    } else {
        0
    }
}

/// The wrap cut into stretches of one sign class each: `(from, to, class)`.
///
/// Between two samples in the same contact state friction is continuous and the crossings of
/// q = ±0.001 μn are interpolated linearly. Where the state changes, friction jumps at the
/// sample at the limit (the zone boundary, which the output grid holds exactly): the stretch
/// takes the class of the other sample.
fn stretches(points: &[Point]) -> Vec<(Point, Point, i8)> {
    let mut out = Vec::with_capacity(points.len() + 8);
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        if a.at_limit != b.at_limit {
            let inner = if a.at_limit { b } else { a };
            out.push((a, b, class(inner.q, inner.limit)));
            continue;
        }
        let mut cuts: Vec<f64> = [1.0, -1.0]
            .iter()
            .filter_map(|&s| {
                let (fa, fb) = (s * a.q - ARC_THRESHOLD * a.limit, s * b.q - ARC_THRESHOLD * b.limit);
                ((fa < 0.0) != (fb < 0.0)).then(|| fa / (fa - fb)).filter(|t| *t > 0.0 && *t < 1.0)
            })
            .collect();
        cuts.sort_by(f64::total_cmp);
        let at = |t: f64| Point {
            theta_deg: a.theta_deg + t * (b.theta_deg - a.theta_deg),
            q: a.q + t * (b.q - a.q),
            limit: a.limit + t * (b.limit - a.limit),
            at_limit: a.at_limit,
        };
        let mut from = a;
        for t in cuts.into_iter().chain([1.0]) {
            let to = if t == 1.0 { b } else { at(t) };
            let mid = at(0.5 * (from.theta_deg - a.theta_deg + to.theta_deg - a.theta_deg)
                / (b.theta_deg - a.theta_deg).max(1e-300));
            out.push((from, to, class(mid.q, mid.limit)));
            from = to;
        }
    }
    out
}

/// The friction arcs: consecutive stretches of one non-zero class joined, each with its band.
fn friction_arcs(points: &[Point], alpha: f64, depth: impl Fn(f64) -> f64) -> Vec<FrictionArc> {
    let mut arcs: Vec<FrictionArc> = Vec::new();
    let mut run: Vec<Point> = Vec::new();
    let mut close = |run: &mut Vec<Point>, sign: i8| {
        if let (true, [first, .., last]) = (sign != 0, &run[..])
            && last.theta_deg > first.theta_deg
        {
            let mut polygon: Vec<(f64, f64)> = run.iter().map(|p| polar(p.theta_deg, RIM, alpha)).collect();
            polygon.extend(run.iter().rev().map(|p| polar(p.theta_deg, depth(p.q), alpha)));
            arcs.push(FrictionArc { start_deg: first.theta_deg, end_deg: last.theta_deg, positive: sign > 0, polygon });
        }
        run.clear();
    };
    let mut current = 0i8;
    for (from, to, c) in stretches(points) {
        if c != current {
            close(&mut run, current);
            current = c;
        }
        if run.last() != Some(&from) {
            run.push(from);
        }
        run.push(to);
    }
    close(&mut run, current);
    arcs
}

/// The content of wrap_diagram.png for `dist`.
pub fn wrap_diagram(dist: &Distribution) -> WrapDiagram {
    let alpha = if dist.wrap_angle_deg.is_finite() && dist.wrap_angle_deg > 0.0 { dist.wrap_angle_deg } else { 360.0 };
    let points: Vec<Point> = dist
        .samples
        .iter()
        .filter(|s| s.theta_deg.is_finite() && s.friction_n_per_rad.is_finite() && s.normal_n_per_rad.is_finite())
        .map(|s| Point {
            theta_deg: s.theta_deg.clamp(0.0, alpha),
            q: s.friction_n_per_rad,
            limit: (dist.mu * s.normal_n_per_rad).abs(),
            at_limit: s.state != NodeState::Stick,
        })
        .collect();
    let t_hi = dist.samples.iter().map(|s| s.tension_n).filter(|t| t.is_finite()).fold(0.0, f64::max);
    let t_radius = |t: f64| if t_hi > 0.0 { 1.0 + TENSION_WIDTH * t.max(0.0) / t_hi } else { 1.0 };
    let q_ref = points.iter().map(|p| p.limit.max(p.q.abs())).fold(0.0, f64::max);
    let q_ref = if q_ref > 0.0 { q_ref } else { 1.0 };
    let depth = |q: f64| RIM - FRICTION_DEPTH * (q.abs() / q_ref).min(1.0);
    let tension = dist
        .samples
        .iter()
        .filter(|s| s.theta_deg.is_finite() && s.tension_n.is_finite())
        .map(|s| polar(s.theta_deg.clamp(0.0, alpha), t_radius(s.tension_n), alpha))
        .collect();
    let limit = points.iter().map(|p| polar(p.theta_deg, depth(p.limit), alpha)).collect();
    let tension_max = (0..=180).map(|i| polar(alpha * f64::from(i) / 180.0, 1.0 + TENSION_WIDTH, alpha)).collect();
    let arcs = friction_arcs(&points, alpha, depth);
    let jdp_deg = dist.jdp_deg.filter(|j| j.is_finite() && (0.0..=alpha).contains(j));
    let end = |s: Option<&crate::wrap::Sample>| s.map_or(f64::NAN, |s| s.tension_n / 1e3);
    let mut legend = vec![
        (Swatch::Line(TENSION, 3, false), tension_label(t_hi)),
        (Swatch::Line(LIMIT, 2, true), "Coulomb limit μn (depth inside the rim)".to_string()),
    ];
    if arcs.iter().any(|a| a.positive) {
        legend.push((Swatch::Fill(POSITIVE), "positive friction".to_string()));
    }
    if arcs.iter().any(|a| !a.positive) {
        legend.push((Swatch::Fill(REVERSE), "reverse friction".to_string()));
    }
    legend.extend(jdp_deg.map(|j| (Swatch::Line(JDP, 3, false), format!("JDP {j:.1}°"))));
    WrapDiagram {
        wrap_angle_deg: alpha,
        tension,
        tension_max,
        limit,
        arcs,
        jdp_deg,
        end_tensions_kn: (end(dist.samples.first()), end(dist.samples.last())),
        legend,
    }
}

/// The tension band's legend: its zero and its scale.
fn tension_label(t_hi: f64) -> String {
    if t_hi > 0.0 && t_hi.is_finite() {
        format!("tension T: rim at T = 0, {:.1} R at {:.1} kN (dotted)", 1.0 + TENSION_WIDTH, t_hi / 1e3)
    } else {
        "tension T".to_string()
    }
}

/// Draws wrap_diagram.png of `dist` at `path`.
pub fn plot_wrap_diagram(path: &Path, title: &str, dist: &Distribution) -> Result<(), PlotError> {
    let diagram = wrap_diagram(dist);
    let kind = FigureKind::WrapDiagram;
    render_sized(path, (kind.width_px(), kind.width_px()), kind.title_px(), title, |body| draw(body, &diagram))
}

fn draw(body: &Area, d: &WrapDiagram) -> Result<(), String> {
    let (w, _) = body.dim_in_pixel();
    let plot = legend_strip(body, &d.legend, (24, w as i32 - 24), FigureKind::WrapDiagram.text_px())?;
    let (pw, ph) = plot.dim_in_pixel();
    let half_h = 1.0;
    let half_w = half_h * f64::from(pw) / f64::from(ph.max(1));
    // 3.4 pulley radii tall: the ropes' labels below, the JDP's label (r = 1.74) above.
    let scale = 1.7;
    let mut chart = ChartBuilder::on(&plot)
        .margin(10)
        .build_cartesian_2d(-half_w * scale..half_w * scale, -1.45..2.0 * scale - 1.45)
        .map_err(e)?;
    chart.configure_mesh().disable_mesh().disable_axes().draw().map_err(e)?;
    let area = chart.plotting_area();
    let circle = |r: f64| -> Vec<(f64, f64)> {
        (0..=360).map(|i| f64::from(i).to_radians()).map(|a| (r * a.cos(), r * a.sin())).collect()
    };
    area.draw(&Polygon::new(circle(1.0), RGBColor(238, 238, 238).filled())).map_err(e)?;
    area.draw(&PathElement::new(circle(1.0), RGBColor(120, 120, 120).stroke_width(2))).map_err(e)?;
    for arc in &d.arcs {
        let color = if arc.positive { POSITIVE } else { REVERSE };
        area.draw(&Polygon::new(arc.polygon.clone(), color.filled())).map_err(e)?;
    }
    // The tension band: from the rim (T = 0) out to the curve, the ends closed along the radii.
    let rim: Vec<(f64, f64)> =
        (0..=180).map(|i| polar(d.wrap_angle_deg * f64::from(i) / 180.0, 1.0, d.wrap_angle_deg)).collect();
    let band: Vec<(f64, f64)> = d.tension.iter().copied().chain(rim.into_iter().rev()).collect();
    area.draw(&Polygon::new(band, BAND.filled())).map_err(e)?;
    area.draw(&DashedPathElement::new(d.tension_max.clone(), 3, 5, TENSION.stroke_width(1))).map_err(e)?;
    area.draw(&DashedPathElement::new(d.limit.clone(), 8, 5, LIMIT.stroke_width(2))).map_err(e)?;
    area.draw(&PathElement::new(d.tension.clone(), TENSION.stroke_width(3))).map_err(e)?;
    draw_ends(&chart, d)?;
    if let Some(j) = d.jdp_deg {
        let (a, b) = (polar(j, 0.25, d.wrap_angle_deg), polar(j, 1.62, d.wrap_angle_deg));
        area.draw(&PathElement::new(vec![a, b], JDP.stroke_width(3))).map_err(e)?;
        let style = font(FigureKind::WrapDiagram.text_px()).color(&JDP).pos(Pos::new(HPos::Center, VPos::Center));
        let label =
            EmptyElement::at(polar(j, 1.74, d.wrap_angle_deg)) + Text::new(format!("JDP {j:.1}°"), (0, 0), style);
        area.draw(&label).map_err(e)?;
    }
    Ok(())
}

/// The ropes leaving the tangent points (tangent to the pulley), labelled with their side,
/// end tension and θ.
fn draw_ends(chart: &super::plot::Chart, d: &WrapDiagram) -> Result<(), String> {
    let area = chart.plotting_area();
    let alpha = d.wrap_angle_deg;
    let ends = [(0.0, 1.0, "side 1, θ = 0", d.end_tensions_kn.0), (alpha, -1.0, "side 2, θ = α", d.end_tensions_kn.1)];
    for (theta, s, name, t_kn) in ends {
        let phi = screen_angle(theta, alpha);
        let p = (phi.cos(), phi.sin());
        // Away from the wrap along the tangent: +dp/dφ at θ = 0, −dp/dφ at θ = α.
        let dir = (-s * phi.sin(), s * phi.cos());
        let q = (p.0 + 1.1 * dir.0, p.1 + 1.1 * dir.1);
        area.draw(&PathElement::new(vec![p, q], TENSION.stroke_width(3))).map_err(e)?;
        let h = if s > 0.0 { HPos::Right } else { HPos::Left };
        let px = FigureKind::WrapDiagram.text_px();
        let style = font(px).color(&BLACK).pos(Pos::new(h, VPos::Top));
        let label = EmptyElement::at(q)
            + Text::new(name.to_string(), (-8 * s as i32, 6), style.clone())
            + Text::new(format!("T = {t_kn:.1} kN"), (-8 * s as i32, 12 + px as i32), style);
        area.draw(&label).map_err(e)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::plot_distribution::steady_distribution;
    use super::*;
    use crate::wrap::{Sample, Zone};

    /// q = Q cos(πθ/α) with μn = 2Q/… constant: positive up to the crossing of q = 0.001 μn,
    /// reverse beyond that of q = −0.001 μn, on a grid of `n` pitches; mirrored (θ → α − θ,
    /// q → −q) when `mirror`.
    fn cosine(n: u32, mirror: bool) -> Distribution {
        let (alpha, q0, lim) = (180.0, 30e3, 50e3);
        let samples = (0..=n)
            .map(|i| {
                let theta = alpha * f64::from(i) / f64::from(n);
                let x = if mirror { alpha - theta } else { theta };
                let q = q0 * (std::f64::consts::PI * x / alpha).cos() * if mirror { -1.0 } else { 1.0 };
                let tension_n = 2e5 + 1e3 * x;
                Sample {
                    theta_deg: theta,
                    tension_n,
                    normal_n_per_rad: lim / 0.25,
                    friction_n_per_rad: q,
                    utilization: q.abs() / lim,
                    state: NodeState::Stick,
                    slip_velocity_m_s: Some(0.0),
                }
            })
            .collect();
        let zones = vec![Zone { start_deg: 0.0, end_deg: alpha, state: NodeState::Stick }];
        Distribution {
            t_s: 0.0,
            mu: 0.25,
            wrap_angle_deg: alpha,
            samples,
            zones,
            jdp_deg: Some(90.0),
            gross_slip: false,
        }
    }

    #[test]
    fn the_arcs_drawn_are_the_summarys_arcs() {
        // Level 1 at rest: one positive arc, β = ln(T1/T2)/μ, ending at θ = α (at θ = 0 mirrored).
        // The jump of q sits on the zone boundary, a sample: the drawn arc is the summary's to
        // round-off (1e-9°).
        let beta = (248.5f64 / 211.9).ln().to_degrees() / 0.25;
        for mirror in [false, true] {
            let d = wrap_diagram(&steady_distribution(0.0, mirror));
            assert_eq!(d.arcs.len(), 1, "{:?}", d.arcs.iter().map(|a| (a.start_deg, a.end_deg)).collect::<Vec<_>>());
            let a = &d.arcs[0];
            assert_eq!(a.positive, !mirror);
            let want = if mirror { (0.0, beta) } else { (187.42 - beta, 187.42) };
            assert!((a.start_deg - want.0).abs() < 1e-9 && (a.end_deg - want.1).abs() < 1e-9, "{a:?} {want:?}");
            assert!((d.arc_deg(!mirror) - beta).abs() < 1e-9 && d.arc_deg(mirror) == 0.0);
        }
        // q = Q cos(πθ/α): positive up to θ₊ = (α/π) acos(0.001 μn/Q), reverse from θ₋ = α − θ₊.
        // Linear interpolation of a cosine over a 0.18° pitch errs by < 1e-6°.
        let theta_plus = 180.0 / std::f64::consts::PI * (0.001f64 * 50e3 / 30e3).acos();
        let d = wrap_diagram(&cosine(1000, false));
        assert_eq!(d.arcs.len(), 2);
        assert!(d.arcs[0].positive && !d.arcs[1].positive);
        assert!(d.arcs[0].start_deg == 0.0 && (d.arcs[0].end_deg - theta_plus).abs() < 1e-6, "{:?}", d.arcs[0].end_deg);
        assert!((d.arcs[1].start_deg - (180.0 - theta_plus)).abs() < 1e-6 && d.arcs[1].end_deg == 180.0);
        assert_eq!(d.jdp_deg, Some(90.0));
        assert!(
            d.legend.iter().any(|l| l.1 == "positive friction") && d.legend.iter().any(|l| l.1 == "reverse friction")
        );
    }

    #[test]
    fn the_tension_band_starts_at_zero_on_the_rim() {
        // cosine(): T = 200 kN + 1 kN/deg · θ over 180°, so T_max = 380 kN at θ = α. The band's
        // edge is at R (1 + 0.6 T/T_max): 1 + 0.6 · 200/380 = 1.315789… at θ = 0, 1.6 at θ = α;
        // halfway, 1 + 0.6 · 290/380 = 1.457895. T = 0 would sit on the rim, radius 1.
        let d = wrap_diagram(&cosine(100, false));
        let r = |p: (f64, f64)| p.0.hypot(p.1);
        assert!((r(d.tension[0]) - (1.0 + 0.6 * 200.0 / 380.0)).abs() < 1e-12);
        assert!((r(d.tension[50]) - (1.0 + 0.6 * 290.0 / 380.0)).abs() < 1e-12);
        assert!((r(d.tension[100]) - 1.6).abs() < 1e-12);
        assert!(d.tension_max.iter().all(|p| (r(*p) - 1.6).abs() < 1e-12));
        assert!(d.legend[0].1.contains("T = 0") && d.legend[0].1.contains("380.0 kN"), "{}", d.legend[0].1);
    }

    #[test]
    fn mirrored_inputs_give_mirrored_diagrams() {
        // θ → α − θ is a reflection of the picture in its vertical axis: x → −x.
        let near = |a: (f64, f64), b: (f64, f64)| (a.0 + b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9;
        for (d, m) in [
            (wrap_diagram(&cosine(400, false)), wrap_diagram(&cosine(400, true))),
            (wrap_diagram(&steady_distribution(0.0, false)), wrap_diagram(&steady_distribution(0.0, true))),
        ] {
            assert_eq!(d.tension.len(), m.tension.len());
            assert!(d.tension.iter().zip(m.tension.iter().rev()).all(|(a, b)| near(*a, *b)));
            assert_eq!(d.arcs.len(), m.arcs.len());
            for (a, b) in d.arcs.iter().zip(m.arcs.iter().rev()) {
                assert_eq!(a.positive, !b.positive);
                let alpha = d.wrap_angle_deg;
                assert!(
                    (a.start_deg - (alpha - b.end_deg)).abs() < 1e-9
                        && (a.end_deg - (alpha - b.start_deg)).abs() < 1e-9
                );
                // The bands are the same shapes, reflected.
                let (pa, pb) = (&a.polygon, &b.polygon);
                assert_eq!(pa.len(), pb.len());
                let reflected = |p: &(f64, f64)| pb.iter().any(|q| near(*p, *q));
                assert!(pa.iter().all(reflected));
            }
            assert!((d.end_tensions_kn.0 - m.end_tensions_kn.1).abs() < 1e-9);
        }
    }

    #[test]
    fn draws_a_diagram_or_says_why_not() {
        let dir = tempfile::tempdir().expect("temp dir");
        let path = dir.path().join("wrap_diagram.png");
        plot_wrap_diagram(&path, "cosine", &cosine(100, false)).expect("plot");
        assert!(path.is_file());
        let empty = Distribution { samples: Vec::new(), wrap_angle_deg: f64::NAN, ..cosine(4, false) };
        plot_wrap_diagram(&dir.path().join("empty.png"), "empty", &empty).expect("plot");
        assert!(plot_wrap_diagram(&dir.path().join("missing/x.png"), "x", &empty).is_err());
    }
}
