//! sweep.csv: one row per (point, scene), in point order then sheet scene order.
//!
//! Columns: `point,point_count,<key1>[,<key2>],scene,kind,level,` then the scalar results of
//! [`RESULT_COLUMNS`]. Numbers are Rust's shortest round-trip form, empty where a value does not
//! exist (e.g. no JDP); no run times, so the same sweep always gives the same bytes. A shard
//! file is the same header and its slice of the rows; reading and rewriting a row reproduces
//! its bytes, which is what lets `merge` rebuild a single run's file.

use super::grid::KEYS;
use crate::design::Requirements;
use crate::model::Level;
use crate::report::summary::SceneSummary;
use std::io::Write;
use std::path::Path;

/// A result cell: a number (empty when absent) or a yes/no.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cell {
    /// A number; `None` writes an empty cell.
    Num(Option<f64>),
    /// A yes/no.
    Flag(bool),
}

/// How a result column is taken from a scene's summary.
pub enum Get {
    /// A number from the summary and the sheet's requirements.
    Num(fn(&SceneSummary, &Requirements) -> Option<f64>),
    /// A yes/no from the summary.
    Flag(fn(&SceneSummary) -> bool),
}

/// The safety-factor minimum that applies to a scene's reported factor: the dynamic one when the
/// state accelerates, else the static one (as the checks and history plots use them).
fn required_min(s: &SceneSummary, r: &Requirements) -> f64 {
    if s.dynamic_safety_factor.is_some() { r.dynamic_safety_factor_min } else { r.static_safety_factor_min }
}

/// The result columns after `level`, from [`SceneSummary`] (docs/interface.md §3: names and units).
pub const RESULT_COLUMNS: &[(&str, Get)] = &[
    ("t_s", Get::Num(|s, _| s.t_s)),
    ("t1_n", Get::Num(|s, _| Some(s.t1_n))),
    ("t2_n", Get::Num(|s, _| Some(s.t2_n))),
    ("speed_m_s", Get::Num(|s, _| Some(s.speed_m_s))),
    ("accel_m_s2", Get::Num(|s, _| Some(s.accel_m_s2))),
    ("mu", Get::Num(|s, _| Some(s.mu))),
    ("wrap_angle_deg", Get::Num(|s, _| Some(s.wrap_angle_deg))),
    ("euler_limit", Get::Num(|s, _| Some(s.euler_limit))),
    ("tension_ratio", Get::Num(|s, _| Some(s.tension_ratio))),
    ("safety_factor", Get::Num(|s, _| s.safety_factor)),
    ("safety_factor_min", Get::Num(|s, r| Some(required_min(s, r)))),
    ("static_safety_factor", Get::Num(|s, _| s.static_safety_factor)),
    ("dynamic_safety_factor", Get::Num(|s, _| s.dynamic_safety_factor)),
    ("worst_safety_factor", Get::Num(|s, _| s.worst_safety_factor)),
    ("dynamic_angle_deg", Get::Num(|s, _| Some(s.dynamic_angle_deg))),
    ("reserve_angle_deg", Get::Num(|s, _| Some(s.reserve_angle_deg))),
    ("idle_arc_deg", Get::Num(|s, _| s.idle_arc_deg)),
    ("positive_arc_deg", Get::Num(|s, _| s.positive_arc_deg)),
    ("reverse_arc_deg", Get::Num(|s, _| s.reverse_arc_deg)),
    ("jdp_deg", Get::Num(|s, _| s.jdp_deg)),
    ("max_utilization", Get::Num(|s, _| s.max_utilization)),
    ("critical_mu", Get::Num(|s, _| Some(s.critical_mu))),
    ("payload_margin_kg", Get::Num(|s, _| s.payload_margin_kg)),
    ("payload_margin_sf_kg", Get::Num(|s, _| s.payload_margin_sf_kg)),
    ("braking_margin_m_s2", Get::Num(|s, _| s.braking_margin_m_s2)),
    ("braking_margin_sf_m_s2", Get::Num(|s, _| s.braking_margin_sf_m_s2)),
    ("gross_slip", Get::Flag(|s| s.gross_slip)),
    ("checks_pass", Get::Flag(|s| s.checks_pass)),
];

/// Columns before the key values, and between them and the results.
const LEAD: [&str; 2] = ["point", "point_count"];
const SCENE: [&str; 3] = ["scene", "kind", "level"];

/// The index of a result column by name.
pub fn column(name: &str) -> Option<usize> {
    RESULT_COLUMNS.iter().position(|c| c.0 == name)
}

/// One row: a scene at a point.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepRow {
    /// Global index of the point.
    pub point: u64,
    /// Number of points of the whole sweep.
    pub point_count: u64,
    /// The varied keys' values, in key order.
    pub values: Vec<f64>,
    /// The scene's name.
    pub scene: String,
    /// The scene's kind.
    pub kind: String,
    /// Model level the scene ran at.
    pub level: Level,
    /// In [`RESULT_COLUMNS`] order.
    pub cells: Vec<Cell>,
}

impl SweepRow {
    /// The row of scene summary `s` at a point with key values `values`, its cells in [`RESULT_COLUMNS`] order.
    pub fn of(point: u64, point_count: u64, values: &[f64], s: &SceneSummary, r: &Requirements) -> Self {
        let cells = RESULT_COLUMNS
            .iter()
            .map(|(_, get)| match get {
                Get::Num(f) => Cell::Num(f(s, r)),
                Get::Flag(f) => Cell::Flag(f(s)),
            })
            .collect();
        Self {
            point,
            point_count,
            values: values.to_vec(),
            scene: s.name.clone(),
            kind: s.kind.to_string(),
            level: s.level,
            cells,
        }
    }

    /// A result number by column name (`None` when empty or not a number column).
    pub fn num(&self, name: &str) -> Option<f64> {
        match column(name).and_then(|i| self.cells.get(i)) {
            Some(Cell::Num(v)) => *v,
            _ => None,
        }
    }

    /// A yes/no result by column name (`None` when not a yes/no column).
    pub fn flag(&self, name: &str) -> Option<bool> {
        match column(name).and_then(|i| self.cells.get(i)) {
            Some(Cell::Flag(b)) => Some(*b),
            _ => None,
        }
    }
}

/// The header for these keys.
pub fn header(keys: &[impl AsRef<str>]) -> Vec<String> {
    let keys = keys.iter().map(|k| k.as_ref());
    let names = LEAD.into_iter().chain(keys).chain(SCENE).chain(RESULT_COLUMNS.iter().map(|c| c.0));
    names.map(str::to_string).collect()
}

/// Writes the header and rows.
pub fn write<W: Write>(out: W, keys: &[impl AsRef<str>], rows: &[SweepRow]) -> csv::Result<()> {
    let mut w = csv::Writer::from_writer(out);
    w.write_record(header(keys))?;
    for row in rows {
        let lead = [row.point.to_string(), row.point_count.to_string()];
        let values = row.values.iter().map(f64::to_string);
        let scene = [row.scene.clone(), row.kind.clone(), row.level.to_string()];
        let cells = row.cells.iter().map(|c| match c {
            Cell::Num(Some(x)) => x.to_string(),
            Cell::Num(None) => String::new(),
            Cell::Flag(b) => b.to_string(),
        });
        w.write_record(lead.into_iter().chain(values).chain(scene).chain(cells))?;
    }
    w.flush()?;
    Ok(())
}

/// A sweep CSV read back: its keys (from the header) and rows.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepFile {
    /// The varied keys, in key order.
    pub keys: Vec<String>,
    /// The rows, in point order.
    pub rows: Vec<SweepRow>,
}

/// Reads a sweep CSV; every problem names the file and line.
pub fn read(path: &Path) -> Result<SweepFile, String> {
    let shown = path.display();
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .from_path(path)
        .map_err(|e| format!("{shown}: cannot read: {e}"))?;
    let mut records = reader.records();
    let head = match records.next() {
        None => return Err(format!("{shown}: empty file; expected a sweep CSV starting with its header")),
        Some(r) => r.map_err(|e| format!("{shown}: {e}"))?,
    };
    let head: Vec<&str> = head.iter().collect();
    let keys = keys_of(&head).ok_or_else(|| {
        format!(
            "{shown}: line 1: not a sweep CSV header; expected {} (keys from: {})",
            header(&["<key>"]).join(","),
            KEYS.iter().map(|k| k.0).collect::<Vec<_>>().join(", ")
        )
    })?;
    let mut rows = Vec::new();
    for record in records {
        let record = record.map_err(|e| format!("{shown}: {e}"))?;
        let line = record.position().map_or(0, |p| p.line());
        let row = parse_row(&record, keys.len()).map_err(|m| format!("{shown}: line {line}: {m}"))?;
        rows.push(row);
    }
    Ok(SweepFile { keys, rows })
}

/// The varied keys of a header, when it is a sweep header.
fn keys_of(head: &[&str]) -> Option<Vec<String>> {
    let n = head.len().checked_sub(LEAD.len() + SCENE.len() + RESULT_COLUMNS.len())?;
    let keys: Vec<String> = head[LEAD.len()..LEAD.len() + n].iter().map(|k| k.to_string()).collect();
    let valid = (1..=super::grid::MAX_KEYS).contains(&n)
        && keys.iter().all(|k| KEYS.iter().any(|(known, ..)| known == k))
        && header(&keys) == head;
    valid.then_some(keys)
}

fn parse_row(record: &csv::StringRecord, nkeys: usize) -> Result<SweepRow, String> {
    let field = |i: usize| record.get(i).unwrap_or("");
    let whole =
        |i: usize| field(i).parse::<u64>().map_err(|_| format!("{}: {:?} is not a whole number", LEAD[i], field(i)));
    let number = |i: usize, text: &str| match text.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        _ => Err(format!("column {}: {text:?} is not a finite number", i + 1)),
    };
    let (point, point_count) = (whole(0)?, whole(1)?);
    if point >= point_count {
        return Err(format!("point {point} is not below point_count {point_count}"));
    }
    let values = (0..nkeys).map(|k| number(2 + k, field(2 + k))).collect::<Result<Vec<_>, _>>()?;
    let s = 2 + nkeys;
    let level = field(s + 2)
        .parse::<u8>()
        .ok()
        .and_then(Level::from_number)
        .ok_or_else(|| format!("level: {:?} is not a model level", field(s + 2)))?;
    let cells = RESULT_COLUMNS
        .iter()
        .enumerate()
        .map(|(j, (col, get))| {
            let text = field(s + 3 + j);
            match get {
                Get::Num(_) if text.is_empty() => Ok(Cell::Num(None)),
                Get::Num(_) => number(s + 3 + j, text).map(|x| Cell::Num(Some(x))),
                Get::Flag(_) => match text {
                    "true" => Ok(Cell::Flag(true)),
                    "false" => Ok(Cell::Flag(false)),
                    _ => Err(format!("{col}: {text:?} is not true or false")),
                },
            }
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(SweepRow {
        point,
        point_count,
        values,
        scene: field(s).to_string(),
        kind: field(s + 1).to_string(),
        level,
        cells,
    })
}
