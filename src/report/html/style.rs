//! The report's stylesheet: screen and print (A4, page numbers in the page margin where the
//! browser supports CSS margin boxes, each major section on a new page, no row split across
//! pages, figures two to a page).

/// The height of the text area of an A4 page with the `@page` margins of [`CSS`]:
/// 297 − 16 − 18 mm.
pub const PAGE_TEXT_HEIGHT_MM: f64 = 297.0 - 16.0 - 18.0;

/// The largest printed height of a figure's image, so that two figures with their captions fit
/// one page: 2 × (100 mm + a caption of up to 5 lines of 8 pt ≈ 18 mm + 4 mm of spacing)
/// = 244 mm ≤ [`PAGE_TEXT_HEIGHT_MM`] (263 mm).
pub const FIGURE_MAX_HEIGHT_MM: f64 = crate::report::figure_size::FIGURE_MAX_HEIGHT_MM;

/// The room a figure's caption and spacing take beside its image (mm), see
/// [`FIGURE_MAX_HEIGHT_MM`].
pub const CAPTION_ROOM_MM: f64 = 22.0;

// Two figures with their captions fit a page's text area.
const _: () = assert!(2.0 * (FIGURE_MAX_HEIGHT_MM + CAPTION_ROOM_MM) <= PAGE_TEXT_HEIGHT_MM);

/// The rules that print each figure at most [`FIGURE_MAX_HEIGHT_MM`] high, its proportions kept.
pub fn figure_css() -> String {
    format!(
        "@media print {{\n  figure.half {{ margin: 2mm 0; }}\n  figure.half img {{ max-height: {FIGURE_MAX_HEIGHT_MM}mm; width: auto; max-width: 100%; object-fit: contain; }}\n  figure.half figcaption {{ font-size: 8pt; }}\n  figure.half img.fig-history {{ max-height: none; }}\n}}\n"
    )
}

pub const CSS: &str = r#"
body { font-family: "DejaVu Sans", "Liberation Sans", Arial, sans-serif; font-size: 10pt; line-height: 1.35;
       max-width: 60em; margin: 2em auto; padding: 0 1em; color: #111; }
header { border-bottom: 2px solid #333; margin-bottom: 1em; }
.kicker { color: #555; margin: 0; }
h1 { font-size: 18pt; margin: 0.2em 0; }
h2 { font-size: 13pt; border-bottom: 1px solid #999; margin-top: 1.6em; }
h3 { font-size: 11pt; margin: 1.2em 0 0.3em; }
code, .mono { font-family: "DejaVu Sans Mono", "Liberation Mono", monospace; font-size: 9pt; }
table { border-collapse: collapse; margin: 0.5em 0 1em; width: 100%; }
th, td { border: 1px solid #bbb; padding: 2px 5px; text-align: left; vertical-align: top; }
th { background: #eee; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
table.small { font-size: 8pt; }
.overall { font-weight: bold; font-size: 12pt; }
.front table.front td:first-child { width: 24%; } .front table.front td:last-child { width: 50%; }
ul.unjudged { font-size: 8pt; margin: 0; padding-left: 1.2em; } .governing { font-size: 9pt; }
.pass { color: #146c2e; } .fail { color: #b00020; } .warning { color: #8a5a00; }
.verdict { font-weight: bold; white-space: nowrap; }
.check { border: 1px solid #ccc; padding: 0.3em 0.7em; margin: 0.6em 0; break-inside: avoid; }
.check dl { display: grid; grid-template-columns: 9em 1fr; margin: 0.2em 0; gap: 0 0.5em; }
.check dt { color: #555; } .check dd { margin: 0; }
figure { margin: 1em 0; break-inside: avoid; text-align: center; }
figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }
figcaption { font-size: 9pt; color: #333; text-align: left; margin-top: 0.3em; }
.note { color: #444; font-size: 9pt; }
nav ol { columns: 2; }
@page { size: A4; margin: 16mm 14mm 18mm;
        @bottom-right { content: "page " counter(page) " of " counter(pages); font-size: 8pt; color: #555; }
        @bottom-left { content: "wrapcalc calculation report"; font-size: 8pt; color: #555; } }
@media print {
  body { max-width: none; margin: 0; padding: 0; font-size: 9pt; }
  nav { break-after: page; }
  section#checks, section#figures, section#appendix, section#appendix-tables { break-before: page; }
  section#load-cases table.small { font-size: 7pt; line-height: 1.15; }
  table.verdicts { font-size: 7pt; line-height: 1.15; }
  table.small td, table.small th { padding: 1px 3px; }
  table.inputs td:first-child { white-space: nowrap; }
  .check { padding: 0.2em 0.6em; margin: 0.4em 0; font-size: 8.5pt; }
  .check dl { grid-template-columns: 7.5em 1fr; }
  tr, .check, figure { break-inside: avoid; }
  thead { display: table-header-group; }
  a { color: inherit; text-decoration: none; }
}
"#;
