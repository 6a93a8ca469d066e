//! The size of each figure in pixels and on the printed page, and the text size that follows
//! from them: a figure drawn `w` px wide and printed `W` pt wide shows a font of `f` px at
//! `f · W / w` pt, so text of at least [`MIN_PRINTED_PT`] needs `f ≥ 9 · w / W` px. The printed
//! widths here are the ones the report's stylesheet sets ([`print_css`]); the page is A4 with
//! the side margins of its `@page` rule.

/// The smallest text a figure shows on paper: tick labels, legends, colour-bar labels (pt).
pub const MIN_PRINTED_PT: f64 = 9.0;
/// Points per millimetre (1 pt = 1/72 in, 1 in = 25.4 mm).
pub const PT_PER_MM: f64 = 72.0 / 25.4;
/// Width of an A4 page (mm).
pub const PAGE_WIDTH_MM: f64 = 210.0;
/// The left and right page margins of the report's `@page` rule (mm).
pub const PAGE_SIDE_MARGIN_MM: f64 = 14.0;
/// The width of the printed text column, the widest a figure can print (mm).
pub const TEXT_WIDTH_MM: f64 = PAGE_WIDTH_MM - 2.0 * PAGE_SIDE_MARGIN_MM;

/// The largest printed height (mm) of a figure's image that shares a page with another: two of
/// them with their captions fit one page (see `report::html::style`).
pub const FIGURE_MAX_HEIGHT_MM: f64 = 100.0;

/// The kinds of figure a report draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FigureKind {
    /// distribution.png: T(θ) and q(θ) over the wrap.
    Distribution,
    /// wrap_diagram.png (and its snapshots): the polar picture of the pulley.
    WrapDiagram,
    /// history.png: four stacked panels over time.
    History,
    /// wrap_map.png: the θ–t map of friction utilization.
    WrapMap,
    /// The stacked-panel figures outside the report's document (track.png, `[[compare]]`).
    Panels,
}

impl FigureKind {
    /// Every kind.
    pub const ALL: [FigureKind; 5] =
        [Self::Distribution, Self::WrapDiagram, Self::History, Self::WrapMap, Self::Panels];

    /// The name the stylesheet knows the kind by (`img.fig-<name>`).
    pub fn css_name(self) -> &'static str {
        match self {
            Self::Distribution => "distribution",
            Self::WrapDiagram => "wrap-diagram",
            Self::History => "history",
            Self::WrapMap => "wrap-map",
            Self::Panels => "panels",
        }
    }

    /// The kind of a figure file of a scene folder, if it is one the document shows.
    pub fn of_file(file: &str) -> Option<Self> {
        match file {
            "distribution.png" => Some(Self::Distribution),
            "history.png" => Some(Self::History),
            "wrap_map.png" => Some(Self::WrapMap),
            f if f.starts_with("wrap_diagram") && f.ends_with(".png") => Some(Self::WrapDiagram),
            _ => None,
        }
    }

    /// The image's width (px).
    pub fn width_px(self) -> u32 {
        match self {
            Self::WrapDiagram => 1000,
            _ => 1200,
        }
    }

    /// The image's height (px) as drawn (the stacked panels of track.png and `[[compare]]` vary
    /// in height and print across the text column).
    pub fn height_px(self) -> Option<u32> {
        match self {
            Self::Distribution => Some(900),
            Self::WrapDiagram => Some(1000),
            Self::History => Some(1300),
            Self::WrapMap => Some(800),
            Self::Panels => None,
        }
    }

    /// Whether two of the kind share a printed page of the appendix: every kind but the tall
    /// history, which prints across the text column on a page of its own.
    pub fn two_per_page(self) -> bool {
        !matches!(self, Self::History | Self::Panels)
    }

    /// The image's printed width (mm): the text column, or narrower where the figure would be
    /// taller than [`FIGURE_MAX_HEIGHT_MM`] and two of the kind share a page: then the width at
    /// which it is that high, its proportions kept.
    pub fn printed_width_mm(self) -> f64 {
        match self.height_px() {
            Some(h) if self.two_per_page() => {
                TEXT_WIDTH_MM.min(FIGURE_MAX_HEIGHT_MM * f64::from(self.width_px()) / f64::from(h))
            }
            _ => TEXT_WIDTH_MM,
        }
    }

    /// The font size (px) of the figure's smallest text.
    pub fn text_px(self) -> u32 {
        font_px(self.width_px(), self.printed_width_mm(), MIN_PRINTED_PT)
    }

    /// The font size (px) of axis descriptions: 1 pt above the smallest text.
    pub fn desc_px(self) -> u32 {
        font_px(self.width_px(), self.printed_width_mm(), MIN_PRINTED_PT + 1.0)
    }

    /// The font size (px) of the figure's title: 11 pt printed.
    pub fn title_px(self) -> u32 {
        font_px(self.width_px(), self.printed_width_mm(), 11.0)
    }
}

/// The smallest whole font size (px) that prints at least `printed_pt` on an image `width_px`
/// wide printed `printed_mm` wide: ⌈printed_pt · width_px / (printed_mm · 72/25.4)⌉.
pub fn font_px(width_px: u32, printed_mm: f64, printed_pt: f64) -> u32 {
    let px = printed_pt * f64::from(width_px) / (printed_mm * PT_PER_MM);
    // The 1e-9 keeps a size that is exactly whole from being rounded up by round-off.
    (px - 1e-9).ceil().max(1.0) as u32
}

/// The stylesheet's rules that print each kind of figure at its width: `img.fig-<kind>`.
pub fn print_css() -> String {
    let mut css = String::from("@media print {\n");
    for kind in FigureKind::ALL {
        css.push_str(&format!(
            "  figure img.fig-{} {{ width: {:.1}mm; max-width: 100%; }}\n",
            kind.css_name(),
            kind.printed_width_mm()
        ));
    }
    css.push_str("}\n");
    css
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The printed size (pt) of `px` pixels of text on an image `width_px` wide printed
    /// `printed_mm` wide, written out independently of [`font_px`].
    fn printed_pt(px: u32, width_px: u32, printed_mm: f64) -> f64 {
        f64::from(px) * printed_mm / 25.4 * 72.0 / f64::from(width_px)
    }

    #[test]
    fn each_figure_prints_its_smallest_text_at_nine_points_at_least() {
        // By hand: the text column is 210 − 2 × 14 = 182 mm. A figure sharing a page prints at
        // most 100 mm high, so at width min(182, 100 · w/h) mm:
        // - distribution 1200 × 900 px: 133.33 mm = 377.95 pt, 0.31496 pt/px; 9 pt needs 28.58 px
        //   → 29 px (9.13 pt), 28 px would be 8.82 pt;
        // - wrap diagram 1000 × 1000 px: 100 mm = 283.46 pt, 0.28346 pt/px; 31.75 → 32 px;
        // - wrap map 1200 × 800 px: 150 mm = 425.20 pt, 0.35433 pt/px; 25.40 → 26 px;
        // - history (a page of its own) and panels across 182 mm = 515.91 pt, 0.42992 pt/px;
        //   20.93 → 21 px (9.03 pt), 20 px would be 8.60 pt.
        assert!((TEXT_WIDTH_MM - 182.0).abs() < 1e-12);
        let hand = [
            (FigureKind::Distribution, 29),
            (FigureKind::WrapDiagram, 32),
            (FigureKind::History, 21),
            (FigureKind::WrapMap, 26),
            (FigureKind::Panels, 21),
        ];
        for (kind, px) in hand {
            assert_eq!(kind.text_px(), px, "{kind:?}");
            let (w, mm) = (kind.width_px(), kind.printed_width_mm());
            assert!(printed_pt(px, w, mm) >= 9.0, "{kind:?}");
            // The smallest such size: a pixel less prints under 9 pt.
            assert!(printed_pt(px - 1, w, mm) < 9.0, "{kind:?}");
            assert!(printed_pt(kind.desc_px(), w, mm) >= 10.0 && printed_pt(kind.title_px(), w, mm) >= 11.0);
        }
        // A size exactly whole is not rounded up: 9 pt on 1000 px printed 1000 × 25.4 / 72 mm
        // (1 px = 1 pt) is 9 px.
        assert_eq!(font_px(1000, 1000.0 / PT_PER_MM, 9.0), 9);
    }

    #[test]
    fn the_stylesheet_prints_each_figure_at_the_width_its_text_was_sized_for() {
        let css = print_css();
        assert!(css.contains("img.fig-wrap-diagram { width: 100.0mm;"), "{css}");
        assert!(css.contains("img.fig-distribution { width: 133.3mm;"), "{css}");
        assert!(css.contains("img.fig-history { width: 182.0mm;"), "{css}");
        // The page's side margins are the ones the width of the text column assumes.
        assert!(crate::report::html::style::CSS.contains("@page { size: A4; margin: 16mm 14mm 18mm;"));
        assert_eq!(FigureKind::of_file("wrap_diagram_t10s.png"), Some(FigureKind::WrapDiagram));
        assert_eq!(FigureKind::of_file("wrap_map.png"), Some(FigureKind::WrapMap));
    }
}
