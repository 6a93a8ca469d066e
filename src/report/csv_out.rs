//! CSV reports: summary.csv (one row per scene), `<scene>/distribution.csv` and `<scene>/history.csv`.

use super::number;
use super::summary::Summary;
use crate::design::HISTORY_COLUMNS;
use crate::model::history::HistoryRow;
use crate::wrap::Distribution;
use std::io::Write;

/// Bytes a CSV writer gathers before it writes: a scene's distribution or history (a few hundred
/// kB) in a few writes rather than one every 8 kB.
const BUFFER_BYTES: usize = 1 << 18;

/// A CSV writer on `out` with a [`BUFFER_BYTES`] buffer.
fn writer<W: Write>(out: W) -> csv::Writer<W> {
    csv::WriterBuilder::new().buffer_capacity(BUFFER_BYTES).from_writer(out)
}

/// summary.csv: the scalar fields of every scene (empty where null).
pub fn write_summary<W: Write>(out: W, summary: &Summary) -> csv::Result<()> {
    let mut w = writer(out);
    for scene in &summary.scenes {
        w.serialize(&scene.summary)?;
    }
    w.flush()?;
    Ok(())
}

/// distribution.csv header (the columns of docs/interface.md §3, then the extension column `sliding`:
/// `true` where the rope moves relative to the lining, [`crate::wrap::Sample::sliding`]).
pub const DISTRIBUTION_HEADER: [&str; 9] = [
    "t_s",
    "theta_deg",
    "tension_n",
    "normal_n_per_rad",
    "friction_n_per_rad",
    "utilization",
    "state",
    "slip_velocity_m_s",
    "sliding",
];

/// distribution.csv: one block of rows per reported time.
pub fn write_distribution<W: Write>(out: W, blocks: &[&Distribution]) -> csv::Result<()> {
    let mut w = writer(out);
    w.write_record(DISTRIBUTION_HEADER)?;
    let mut row = Row::default();
    for d in blocks {
        for s in &d.samples {
            row.num(d.t_s).num(s.theta_deg).num(s.tension_n).num(s.normal_n_per_rad).num(s.friction_n_per_rad);
            row.num(s.utilization).text(s.state.as_str()).opt(s.slip_velocity_m_s).flag(s.sliding());
            row.write(&mut w)?;
        }
    }
    w.flush()?;
    Ok(())
}

/// history.csv: one row per reported time (docs/interface.md's columns), then the extension columns
/// `anchor1_n,anchor2_n,mid1_n,mid2_n` (tension per rope at the conveyance anchors and halfway down
/// each hanging rope; empty but for duty cycles with the ropes' dynamics).
pub fn write_history<W: Write>(
    out: W,
    rows: &[HistoryRow],
    anchors_n: &[[f64; 2]],
    midpoints_n: &[[f64; 2]],
) -> csv::Result<()> {
    let mut w = writer(out);
    w.write_record(HISTORY_COLUMNS.map(|(name, _)| name))?;
    let mut row = Row::default();
    for (i, r) in rows.iter().enumerate() {
        let anchors = anchors_n.get(i);
        let mids = midpoints_n.get(i);
        row.num(r.t_s).num(r.t1_n).num(r.t2_n).num(r.speed_m_s).num(r.accel_m_s2).opt(r.jdp_deg);
        row.num(r.positive_arc_deg).num(r.reverse_arc_deg).num(r.max_utilization).opt(r.safety_factor);
        row.flag(r.gross_slip).opt(anchors.map(|a| a[0])).opt(anchors.map(|a| a[1]));
        row.opt(mids.map(|a| a[0])).opt(mids.map(|a| a[1])).write(&mut w)?;
    }
    w.flush()?;
    Ok(())
}

/// track.csv: one row per element and reported time while the element is on the pulley.
pub fn write_tracks<W: Write>(out: W, tracks: &[crate::model::track::Track]) -> csv::Result<()> {
    let mut w = writer(out);
    w.write_record([
        "element",
        "t_s",
        "theta_deg",
        "tension_n",
        "normal_n_per_rad",
        "friction_n_per_rad",
        "utilization",
        "state",
        "contact_force_n",
        "friction_force_n",
        "impulse_n_s",
    ])?;
    let mut row = Row::default();
    for track in tracks {
        for r in &track.rows {
            row.text(&track.label).num(r.t_s).num(r.theta_deg).num(r.tension_n).num(r.normal_n_per_rad);
            row.num(r.friction_n_per_rad).num(r.utilization).text(r.state.as_str()).num(r.contact_force_n);
            row.num(r.friction_force_n).num(r.impulse_n_s).write(&mut w)?;
        }
    }
    w.flush()?;
    Ok(())
}

/// A row of a CSV report built field by field into one reused record: numbers are written as
/// [`number::display`] writes them, without an allocation per field.
#[derive(Default)]
struct Row {
    record: csv::ByteRecord,
    scratch: String,
}

impl Row {
    /// A number.
    fn num(&mut self, x: f64) -> &mut Self {
        self.scratch.clear();
        number::write(x, &mut self.scratch);
        self.record.push_field(self.scratch.as_bytes());
        self
    }

    /// A number, or an empty field.
    fn opt(&mut self, x: Option<f64>) -> &mut Self {
        match x {
            Some(x) => self.num(x),
            None => self.text(""),
        }
    }

    /// `true` or `false`.
    fn flag(&mut self, b: bool) -> &mut Self {
        self.text(if b { "true" } else { "false" })
    }

    /// A text field (quoted by the writer where it needs it).
    fn text(&mut self, s: &str) -> &mut Self {
        self.record.push_field(s.as_bytes());
        self
    }

    /// Writes the row and starts the next.
    fn write<W: Write>(&mut self, w: &mut csv::Writer<W>) -> csv::Result<()> {
        w.write_byte_record(&self.record)?;
        self.record.clear();
        Ok(())
    }
}
