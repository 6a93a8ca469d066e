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
    let mut row = Rows::new(out);
    row.header(&DISTRIBUTION_HEADER)?;
    for d in blocks {
        for s in &d.samples {
            row.num(d.t_s).num(s.theta_deg).num(s.tension_n).num(s.normal_n_per_rad).num(s.friction_n_per_rad);
            row.num(s.utilization).text(s.state.as_str()).opt(s.slip_velocity_m_s).flag(s.sliding());
            row.end()?;
        }
    }
    row.finish()
}

/// history.csv: one row per reported time (docs/interface.md's columns), then the extension columns
/// `anchor1_n,anchor2_n,mid1_n,mid2_n` (tension per rope at the conveyance anchors and halfway down
/// each hanging rope; empty but for duty cycles with the ropes' dynamics), `demarcations_deg`, and
/// `jdp_gap_start_deg,jdp_gap_end_deg` (the ends of the stick gap whose middle the JDP is; empty
/// without a JDP).
pub fn write_history<W: Write>(
    out: W,
    rows: &[HistoryRow],
    anchors_n: &[[f64; 2]],
    midpoints_n: &[[f64; 2]],
) -> csv::Result<()> {
    let mut row = Rows::new(out);
    row.header(&HISTORY_COLUMNS.map(|(name, _)| name))?;
    for (i, r) in rows.iter().enumerate() {
        let anchors = anchors_n.get(i);
        let mids = midpoints_n.get(i);
        row.num(r.t_s).num(r.t1_n).num(r.t2_n).num(r.speed_m_s).num(r.accel_m_s2).opt(r.jdp_deg);
        row.num(r.positive_arc_deg).num(r.reverse_arc_deg).num(r.max_utilization).opt(r.safety_factor);
        row.flag(r.gross_slip).opt(anchors.map(|a| a[0])).opt(anchors.map(|a| a[1]));
        row.opt(mids.map(|a| a[0])).opt(mids.map(|a| a[1])).demarcations(&r.demarcations_deg);
        row.opt(r.jdp_gap_deg.map(|g| g[0])).opt(r.jdp_gap_deg.map(|g| g[1])).end()?;
    }
    row.finish()
}

/// track.csv: one row per element and reported time while the element is on the pulley.
pub fn write_tracks<W: Write>(out: W, tracks: &[crate::model::track::Track]) -> csv::Result<()> {
    let mut row = Rows::new(out);
    row.header(&[
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
    for track in tracks {
        for r in &track.rows {
            row.text(&track.label).num(r.t_s).num(r.theta_deg).num(r.tension_n).num(r.normal_n_per_rad);
            row.num(r.friction_n_per_rad).num(r.utilization).text(r.state.as_str()).num(r.contact_force_n);
            row.num(r.friction_force_n).num(r.impulse_n_s).end()?;
        }
    }
    row.finish()
}

/// The rows of a CSV report written straight into a buffer of [`BUFFER_BYTES`], field by
/// field, as the `csv` crate writes them: fields separated by `,`, rows ended by `\n`, a text
/// field quoted (its quotes doubled) only where it holds `,`, `"`, `\r` or `\n`, numbers as
/// [`number::display`] writes them (never quoted: digits, `.`, `-`, `inf`, `NaN`).
pub(super) struct Rows<W: Write> {
    out: std::io::BufWriter<W>,
    line: Vec<u8>,
    fields: usize,
}

impl<W: Write> Rows<W> {
    pub(super) fn new(out: W) -> Self {
        Self { out: std::io::BufWriter::with_capacity(BUFFER_BYTES, out), line: Vec::with_capacity(256), fields: 0 }
    }

    fn separate(&mut self) {
        if self.fields > 0 {
            self.line.push(b',');
        }
        self.fields += 1;
    }

    /// A number.
    pub(super) fn num(&mut self, x: f64) -> &mut Self {
        self.separate();
        number::write(x, &mut self.line);
        self
    }

    /// A number, or an empty field.
    pub(super) fn opt(&mut self, x: Option<f64>) -> &mut Self {
        match x {
            Some(x) => self.num(x),
            None => self.text(""),
        }
    }

    /// Demarcation points (deg) in one field, separated by `;` (empty without one).
    fn demarcations(&mut self, degrees: &[f64]) -> &mut Self {
        let mut field = Vec::new();
        for (i, d) in degrees.iter().enumerate() {
            if i > 0 {
                field.push(b';');
            }
            number::write(*d, &mut field);
        }
        self.text(&String::from_utf8_lossy(&field))
    }

    /// `true` or `false`.
    fn flag(&mut self, b: bool) -> &mut Self {
        self.text(if b { "true" } else { "false" })
    }

    /// A text field, quoted where it needs it.
    fn text(&mut self, s: &str) -> &mut Self {
        self.separate();
        if s.bytes().any(|b| matches!(b, b',' | b'"' | b'\r' | b'\n')) {
            self.line.push(b'"');
            for b in s.bytes() {
                if b == b'"' {
                    self.line.push(b'"');
                }
                self.line.push(b);
            }
            self.line.push(b'"');
        } else {
            self.line.extend_from_slice(s.as_bytes());
        }
        self
    }

    /// A row of text fields (a header).
    pub(super) fn header(&mut self, names: &[&str]) -> csv::Result<()> {
        for name in names {
            self.text(name);
        }
        self.end()
    }

    /// Ends the row (a row of one empty field is written `""`, as the `csv` crate does, so
    /// that it reads back as a row).
    pub(super) fn end(&mut self) -> csv::Result<()> {
        if self.fields == 1 && self.line.is_empty() {
            self.line.extend_from_slice(b"\"\"");
        }
        self.line.push(b'\n');
        self.out.write_all(&self.line)?;
        self.line.clear();
        self.fields = 0;
        Ok(())
    }

    pub(super) fn finish(mut self) -> csv::Result<()> {
        self.out.flush()?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::Rows;

    /// The rows are written byte for byte as the `csv` crate writes the same records: plain
    /// fields as they are, text holding a delimiter, a quote or a line break quoted with its
    /// quotes doubled, empty fields empty, numbers as the standard library displays them.
    #[test]
    fn rows_are_written_as_the_csv_crate_writes_them() {
        let texts = ["stick", "", "a,b", "say \"hi\"", "two\nlines", "cr\rhere", "plain-name_1.2"];
        let numbers = [0.0, -0.0, 1.5, -207670.75386600045, 1e-7, 1e21, f64::NAN, f64::INFINITY];
        let mut ours = Vec::new();
        let mut rows = Rows::new(&mut ours);
        rows.header(&["t_s", "name", "value", "flag"]).expect("header");
        for (i, t) in texts.iter().enumerate() {
            rows.num(numbers[i % numbers.len()]).text(t).opt((i % 2 == 0).then_some(0.25)).flag(i % 3 == 0);
            rows.end().expect("row");
        }
        rows.finish().expect("flush");
        let mut theirs = csv::Writer::from_writer(Vec::new());
        theirs.write_record(["t_s", "name", "value", "flag"]).expect("header");
        for (i, t) in texts.iter().enumerate() {
            let x = numbers[i % numbers.len()];
            let opt = if i % 2 == 0 { "0.25".to_string() } else { String::new() };
            let flag = if i % 3 == 0 { "true" } else { "false" };
            theirs.write_record([format!("{x}").as_str(), t, opt.as_str(), flag]).expect("row");
        }
        let theirs = theirs.into_inner().expect("flush");
        assert_eq!(String::from_utf8_lossy(&ours), String::from_utf8_lossy(&theirs));
    }
}
