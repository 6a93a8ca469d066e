//! The contact zones of a distribution as the figures show them, as plain data: each stretch at
//! the Coulomb limit (u ≥ 0.999) by its friction's direction and by whether the rope slides
//! there. A stretch at the limit whose slip velocity is zero (a hoist at rest after its last
//! load change, on a rigid lining) is *at the Coulomb limit*; only where the rope moves
//! relative to the lining ([`crate::wrap::Sample::sliding`]) is it *slipping*.

use super::friction_colour::zone_color;
use crate::wrap::contact::NodeState;
use crate::wrap::{Distribution, Zone};
use plotters::style::RGBColor;

/// A legend entry's symbol: a line (colour, width in px, dashed) or a filled box.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Swatch {
    /// A line segment: colour, width (px), dashed.
    Line(RGBColor, u32, bool),
    /// A filled box (a shaded zone or band).
    Fill(RGBColor),
    /// A filled box with diagonal hatching over it (a zone where the rope slides).
    Hatched(RGBColor),
}

/// A legend entry: its symbol, drawn as the series is, and its label.
pub type LegendEntry = (Swatch, String);

/// How a stretch at the Coulomb limit is shaded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ZoneKind {
    /// Positive friction (q > 0, in +θ) at the limit, the rope not sliding on the lining.
    PositiveAtLimit,
    /// Positive friction at the limit, the rope sliding on the lining.
    PositiveSlipping,
    /// Reverse friction (q < 0) at the limit, the rope not sliding on the lining.
    ReverseAtLimit,
    /// Reverse friction at the limit, the rope sliding on the lining.
    ReverseSlipping,
}

impl ZoneKind {
    /// Every kind, in the order legends list them.
    pub const ALL: [ZoneKind; 4] =
        [ZoneKind::PositiveAtLimit, ZoneKind::PositiveSlipping, ZoneKind::ReverseAtLimit, ZoneKind::ReverseSlipping];

    /// The kind's legend text.
    pub fn label(self) -> &'static str {
        match self {
            ZoneKind::PositiveAtLimit => "positive friction at the Coulomb limit (no slip)",
            ZoneKind::PositiveSlipping => "positive friction, rope slipping",
            ZoneKind::ReverseAtLimit => "reverse friction at the Coulomb limit (no slip)",
            ZoneKind::ReverseSlipping => "reverse friction, rope slipping",
        }
    }

    /// The shade of the friction's sign ([`zone_color`]: darker red for positive, lighter
    /// blue for reverse), the same whether the rope slides or not.
    pub fn color(self) -> RGBColor {
        zone_color(matches!(self, ZoneKind::PositiveAtLimit | ZoneKind::PositiveSlipping))
    }

    /// The legend symbol: the shade, hatched where the rope slides (hatching, not a stronger
    /// colour, so that sign and sliding stay apart in greyscale).
    pub fn swatch(self) -> Swatch {
        if self.slipping() { Swatch::Hatched(self.color()) } else { Swatch::Fill(self.color()) }
    }

    /// Whether the rope slides on the lining in this kind of zone.
    pub fn slipping(self) -> bool {
        matches!(self, ZoneKind::PositiveSlipping | ZoneKind::ReverseSlipping)
    }
}

/// A shaded stretch of the wrap, in degrees.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZoneShade {
    /// Where the stretch starts (deg from the side-1 tangent point).
    pub start_deg: f64,
    /// Where it ends (deg, ≥ `start_deg`).
    pub end_deg: f64,
    /// How it is shaded.
    pub kind: ZoneKind,
}

/// Whether the rope slides anywhere in `zone`: at a sample of the zone's state inside it (its
/// ends included, to 1e-9°), else — a zone narrower than the output grid — in gross slip.
fn zone_slides(dist: &Distribution, zone: &Zone) -> bool {
    let tol = 1e-9 * zone.end_deg.abs().max(1.0);
    let inside = dist
        .samples
        .iter()
        .filter(|s| s.state == zone.state && s.theta_deg >= zone.start_deg - tol && s.theta_deg <= zone.end_deg + tol);
    let mut any = false;
    for s in inside {
        if s.sliding() {
            return true;
        }
        any = true;
    }
    !any && dist.gross_slip
}

/// The shaded stretches of a distribution: every zone at the Coulomb limit, by kind.
pub fn zone_shades(dist: &Distribution) -> Vec<ZoneShade> {
    dist.zones
        .iter()
        .filter_map(|z| {
            let slides = zone_slides(dist, z);
            let kind = match (z.state, slides) {
                (NodeState::Stick, _) => return None,
                (NodeState::SlipPositive, false) => ZoneKind::PositiveAtLimit,
                (NodeState::SlipPositive, true) => ZoneKind::PositiveSlipping,
                (NodeState::SlipNegative, false) => ZoneKind::ReverseAtLimit,
                (NodeState::SlipNegative, true) => ZoneKind::ReverseSlipping,
            };
            Some(ZoneShade { start_deg: z.start_deg, end_deg: z.end_deg, kind })
        })
        .collect()
}

/// The legend entries of the shades present, one per kind, in [`ZoneKind::ALL`]'s order.
pub fn shade_legend(shades: &[ZoneShade]) -> Vec<LegendEntry> {
    ZoneKind::ALL
        .into_iter()
        .filter(|k| shades.iter().any(|s| s.kind == *k))
        .map(|k| (k.swatch(), k.label().to_string()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wrap::Sample;

    fn sample(theta_deg: f64, state: NodeState, v: Option<f64>) -> Sample {
        Sample {
            theta_deg,
            tension_n: 1e5,
            normal_n_per_rad: 1e5,
            friction_n_per_rad: if state == NodeState::SlipNegative { -2.5e4 } else { 2.5e4 },
            utilization: if state == NodeState::Stick { 0.0 } else { 1.0 },
            state,
            slip_velocity_m_s: v,
        }
    }

    /// A wrap of 180° sticking over [0, 150] and at the limit over [150, 180], the rope at
    /// slip velocity `v` there; `mirror` swaps the sides (θ → α − θ, q → −q, v → −v).
    fn dist(v: Option<f64>, mirror: bool) -> Distribution {
        let (stick, limit) = ((0.0, 150.0), (150.0, 180.0));
        let mut samples: Vec<Sample> =
            (0..=15).map(|i| sample(10.0 * f64::from(i), NodeState::Stick, Some(0.0))).collect();
        samples.extend((0..=3).map(|i| sample(150.0 + 10.0 * f64::from(i), NodeState::SlipPositive, v)));
        let mut zones = vec![
            Zone { start_deg: stick.0, end_deg: stick.1, state: NodeState::Stick },
            Zone { start_deg: limit.0, end_deg: limit.1, state: NodeState::SlipPositive },
        ];
        if mirror {
            let flip = |s: NodeState| match s {
                NodeState::SlipPositive => NodeState::SlipNegative,
                other => other,
            };
            samples = samples
                .into_iter()
                .rev()
                .map(|s| Sample {
                    theta_deg: 180.0 - s.theta_deg,
                    slip_velocity_m_s: s.slip_velocity_m_s.map(|v| -v),
                    ..sample(0.0, flip(s.state), None)
                })
                .collect();
            zones = zones
                .into_iter()
                .rev()
                .map(|z| Zone { start_deg: 180.0 - z.end_deg, end_deg: 180.0 - z.start_deg, state: flip(z.state) })
                .collect();
        }
        Distribution {
            t_s: 0.0,
            mu: 0.25,
            wrap_angle_deg: 180.0,
            samples,
            zones,
            jdp_deg: None,
            gross_slip: v.is_none(),
        }
    }

    #[test]
    fn a_zone_at_rest_is_at_the_limit_and_a_moving_one_slips_in_both_directions() {
        // (slip velocity, the kind of the zone at the limit, unmirrored and mirrored)
        let cases = [
            (Some(0.0), ZoneKind::PositiveAtLimit, ZoneKind::ReverseAtLimit),
            (Some(1e-12), ZoneKind::PositiveAtLimit, ZoneKind::ReverseAtLimit),
            (Some(4e-3), ZoneKind::PositiveSlipping, ZoneKind::ReverseSlipping),
            (None, ZoneKind::PositiveSlipping, ZoneKind::ReverseSlipping),
        ];
        for (v, kind, mirrored) in cases {
            for (mirror, want, span) in [(false, kind, (150.0, 180.0)), (true, mirrored, (0.0, 30.0))] {
                let shades = zone_shades(&dist(v, mirror));
                assert_eq!(
                    shades,
                    vec![ZoneShade { start_deg: span.0, end_deg: span.1, kind: want }],
                    "{v:?} {mirror}"
                );
                let legend = shade_legend(&shades);
                assert_eq!(legend.len(), 1);
                assert_eq!(legend[0].1.contains("slipping"), want.slipping(), "{legend:?}");
                assert_eq!(legend[0].1.contains("at the Coulomb limit"), !want.slipping(), "{legend:?}");
            }
        }
    }
}
