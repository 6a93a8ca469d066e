//! `history` scenes: end tensions and speed as inline arrays or a CSV file
//! (columns `t_s,t1_n,t2_n[,speed_m_s]`, path relative to the sheet), checked sample by sample.

use super::diag::{Collector, join_key};
use super::raw::RawScene;
use super::rules::{At, SPEED_MAX_M_S, direction_keyword, foreign_keys, sorted_times};
use crate::design::{Direction, HistorySample, HistoryScene, Rope};
use std::ops::Range;
use std::path::Path;
use toml::Spanned;

/// Most samples a history may have.
pub const MAX_SAMPLES: usize = 10_000_000;

/// A history scene: its samples (inline arrays or a CSV file, checked sample by sample), the
/// snapshot times within it, its direction (given, or from the sign of the first nonzero speed)
/// and its output step.
pub(super) fn history(
    c: &mut Collector,
    scene: Option<&str>,
    label: &str,
    table_span: &Range<usize>,
    raw: &RawScene,
    rope: Option<&Rope>,
) -> Option<HistoryScene> {
    let at = At { scene, section: label, table_span };
    let foreign_ok = history_foreign_keys(c, at, raw);
    let samples = samples(c, at, raw)?;
    let mut ok = foreign_ok && check_samples(c, at, &samples, rope, raw.csv.as_ref().map(|v| v.span()));
    let (t0, t1) = (samples[0].t_s, samples[samples.len() - 1].t_s);
    let snapshots_s = match &raw.snapshots_s {
        None => Vec::new(),
        Some(s) => {
            if s.get_ref().iter().any(|t| !(t.is_finite() && *t >= t0 && *t <= t1)) {
                c.push(
                    Some(s.span()),
                    scene,
                    &at.key("snapshots_s"),
                    format!("expected times within the history, {t0} ≤ t ≤ {t1} s"),
                );
                ok = false;
            }
            sorted_times(s.get_ref())
        }
    };
    let direction = match &raw.direction {
        None => {
            let first = samples.iter().map(|s| s.speed_m_s).find(|v| *v != 0.0).unwrap_or(0.0);
            if first < 0.0 { Direction::Lower } else { Direction::Lift }
        }
        Some(d) => direction_keyword(c, at, d).unwrap_or_else(|| {
            ok = false;
            Direction::Lift
        }),
    };
    let output_step_s = output_step(c, at, raw, t1 - t0);
    ok &= output_step_s.is_some();
    ok.then_some(HistoryScene { samples, snapshots_s, direction, output_step_s: output_step_s.flatten() })
}

/// Rejects the keys of loads and duty-cycle scenes in a history scene; `false` when any is there.
fn history_foreign_keys(c: &mut Collector, at: At, raw: &RawScene) -> bool {
    foreign_keys(
        c,
        at,
        "history",
        &[
            ("m1_kg", raw.m1_kg.as_ref().map(|v| v.span())),
            ("m2_kg", raw.m2_kg.as_ref().map(|v| v.span())),
            ("accel_m_s2", raw.accel_m_s2.as_ref().map(|v| v.span())),
            ("payload_kg", raw.payload_kg.as_ref().map(|v| v.span())),
            ("emergency_stop_s", raw.emergency_stop_s.as_ref().map(|v| v.span())),
            ("emergency_decel_m_s2", raw.emergency_decel_m_s2.as_ref().map(|v| v.span())),
            ("time_step_s", raw.time_step_s.as_ref().map(|v| v.span())),
            ("return_after_s", raw.return_after_s.as_ref().map(|v| v.span())),
        ],
    )
}

/// The samples, read from the CSV file or the inline arrays (one or the other).
fn samples(c: &mut Collector, at: At, raw: &RawScene) -> Option<Vec<HistorySample>> {
    let inline = raw.t_s.is_some() || raw.t1_n.is_some() || raw.t2_n.is_some() || raw.speed_m_s.is_some();
    match (&raw.csv, inline) {
        (Some(csv), true) => {
            c.push(
                Some(csv.span()),
                at.scene,
                &at.key("csv"),
                "give either csv or the arrays t_s, t1_n, t2_n, speed_m_s, not both",
            );
            None
        }
        (Some(csv), false) => from_csv(c, at, csv),
        (None, _) => from_arrays(c, at, raw),
    }
}

/// The output step over a history of `span_s` seconds: `Some(None)` when not given, `None` when
/// it is not > 0 or gives more than 1e6 rows.
fn output_step(c: &mut Collector, at: At, raw: &RawScene, span_s: f64) -> Option<Option<f64>> {
    let v = match &raw.output_step_s {
        None => return Some(None),
        Some(v) => v,
    };
    let step = *v.get_ref();
    if step.is_finite() && step > 0.0 && span_s / step <= 1e6 {
        Some(Some(step))
    } else {
        c.push(
            Some(v.span()),
            at.scene,
            &at.key("output_step_s"),
            format!("expected a step > 0 s giving at most 1e6 rows over the {span_s} s history"),
        );
        None
    }
}

/// Numbers of an inline array key.
fn numbers(c: &mut Collector, at: At, key: &str, value: &Spanned<toml::Value>) -> Option<Vec<f64>> {
    let toml::Value::Array(items) = value.get_ref() else {
        c.push(Some(value.span()), at.scene, &at.key(key), "expected an array of numbers in a history scene");
        return None;
    };
    let mut out = Vec::with_capacity(items.len());
    for (i, item) in items.iter().enumerate() {
        match item {
            toml::Value::Float(x) => out.push(*x),
            toml::Value::Integer(n) => out.push(*n as f64),
            other => {
                c.push(
                    Some(value.span()),
                    at.scene,
                    &format!("{}[{i}]", at.key(key)),
                    format!("expected a number, found {}", other.type_str()),
                );
                return None;
            }
        }
    }
    Some(out)
}

fn from_arrays(c: &mut Collector, at: At, raw: &RawScene) -> Option<Vec<HistorySample>> {
    let Some(t_s) = &raw.t_s else {
        c.push_at(
            Some(at.table_span.clone()),
            at.scene,
            &at.key("t_s"),
            "missing; a history needs t_s, t1_n, t2_n (arrays) or csv = \"file.csv\"",
        );
        return None;
    };
    let t = t_s.get_ref().clone();
    let mut column = |key: &str, value: &Option<Spanned<toml::Value>>, required: bool| -> Option<Vec<f64>> {
        match value {
            Some(v) => {
                let xs = numbers(c, at, key, v)?;
                if xs.len() != t.len() {
                    c.push(
                        Some(v.span()),
                        at.scene,
                        &at.key(key),
                        format!("expected {} values, one per t_s sample, found {}", t.len(), xs.len()),
                    );
                    return None;
                }
                Some(xs)
            }
            None if required => {
                c.push_at(
                    Some(at.table_span.clone()),
                    at.scene,
                    &at.key(key),
                    "missing; expected an array of tensions per rope (N), one per t_s sample",
                );
                None
            }
            None => Some(vec![0.0; t.len()]),
        }
    };
    let t1 = column("t1_n", &raw.t1_n, true);
    let t2 = column("t2_n", &raw.t2_n, true);
    let v = column("speed_m_s", &raw.speed_m_s, false);
    let (t1, t2, v) = (t1?, t2?, v?);
    Some(
        t.iter()
            .zip(t1)
            .zip(t2)
            .zip(v)
            .map(|(((t, t1), t2), v)| HistorySample { t_s: *t, t1_n: t1, t2_n: t2, speed_m_s: v })
            .collect(),
    )
}

fn from_csv(c: &mut Collector, at: At, csv_key: &Spanned<String>) -> Option<Vec<HistorySample>> {
    let base = Path::new(c.file).parent().unwrap_or(Path::new("."));
    let path = base.join(csv_key.get_ref());
    let shown = path.display().to_string();
    let key = at.key("csv");
    let fail = |c: &mut Collector, msg: String| {
        c.push(Some(csv_key.span()), at.scene, &key, msg);
        None
    };
    let mut reader = match csv::ReaderBuilder::new().trim(csv::Trim::All).from_path(&path) {
        Ok(r) => r,
        Err(e) => return fail(c, format!("cannot read the history CSV {shown}: {e}")),
    };
    let headers = match reader.headers() {
        Ok(h) => h.clone(),
        Err(e) => return fail(c, format!("{shown}: unreadable header: {e}")),
    };
    let col = |name: &str| headers.iter().position(|h| h == name);
    let (Some(it), Some(i1), Some(i2)) = (col("t_s"), col("t1_n"), col("t2_n")) else {
        return fail(
            c,
            format!(
                "{shown}: expected a header with columns t_s,t1_n,t2_n[,speed_m_s], found {:?}",
                headers.iter().collect::<Vec<_>>()
            ),
        );
    };
    let iv = col("speed_m_s");
    if let Some(extra) = headers.iter().find(|h| !matches!(*h, "t_s" | "t1_n" | "t2_n" | "speed_m_s")) {
        return fail(c, format!("{shown}: unknown column {extra:?}; allowed: t_s, t1_n, t2_n, speed_m_s"));
    }
    let mut out = Vec::new();
    for (row, record) in reader.records().enumerate() {
        let line = row + 2;
        let record = match record {
            Ok(r) => r,
            Err(e) => return fail(c, format!("{shown} line {line}: {e}")),
        };
        let field = |i: usize, name: &str| -> Result<f64, String> {
            let text = record.get(i).unwrap_or("");
            text.parse::<f64>().map_err(|_| format!("{shown} line {line}, column {name}: {text:?} is not a number"))
        };
        let parsed = (|| {
            Ok::<_, String>(HistorySample {
                t_s: field(it, "t_s")?,
                t1_n: field(i1, "t1_n")?,
                t2_n: field(i2, "t2_n")?,
                speed_m_s: match iv {
                    Some(i) => field(i, "speed_m_s")?,
                    None => 0.0,
                },
            })
        })();
        match parsed {
            Ok(s) => out.push(s),
            Err(msg) => return fail(c, msg),
        }
        if out.len() > MAX_SAMPLES {
            return fail(c, format!("{shown}: more than {MAX_SAMPLES} samples"));
        }
    }
    if out.is_empty() {
        return fail(c, format!("{shown}: no data rows; a history needs at least two samples"));
    }
    Some(out)
}

/// Sample-by-sample checks: finite, time strictly increasing, tensions > 0, speeds in range,
/// the rope on the pulley (T − m'v² > 0).
fn check_samples(
    c: &mut Collector,
    at: At,
    samples: &[HistorySample],
    rope: Option<&Rope>,
    csv_span: Option<Range<usize>>,
) -> bool {
    let span = csv_span.unwrap_or_else(|| at.table_span.clone());
    let bad = |c: &mut Collector, key: &str, i: usize, msg: String| {
        c.push_at(Some(span.clone()), at.scene, &format!("{}[{i}]", join_key(at.section, key)), msg);
    };
    if samples.len() < 2 {
        bad(c, "t_s", 0, "expected at least two samples".into());
        return false;
    }
    let mut ok = true;
    for (i, s) in samples.iter().enumerate() {
        let before = c.diagnostics.len();
        if !s.t_s.is_finite() || (i > 0 && s.t_s <= samples[i - 1].t_s) {
            bad(c, "t_s", i, format!("= {}: expected finite times in strictly increasing order", s.t_s));
        }
        for (key, v) in [("t1_n", s.t1_n), ("t2_n", s.t2_n)] {
            if !(v.is_finite() && v > 0.0) {
                bad(c, key, i, format!("= {v}: expected a tension per rope > 0 N"));
            }
        }
        if !(s.speed_m_s.is_finite() && s.speed_m_s.abs() <= SPEED_MAX_M_S) {
            bad(c, "speed_m_s", i, format!("= {}: expected |v| ≤ {SPEED_MAX_M_S} m/s", s.speed_m_s));
        } else if let Some(rope) = rope {
            let cf = rope.mass_per_m_kg * s.speed_m_s * s.speed_m_s;
            if s.t1_n.min(s.t2_n) <= cf {
                bad(
                    c,
                    "speed_m_s",
                    i,
                    format!(
                        "= {}: the centrifugal tension m'v² = {cf:.0} N reaches the lower rope tension: the rope would lift off the pulley",
                        s.speed_m_s
                    ),
                );
            }
        }
        if c.diagnostics.len() > before {
            ok = false;
            if c.diagnostics.len() > 50 {
                break;
            }
        }
    }
    ok
}
