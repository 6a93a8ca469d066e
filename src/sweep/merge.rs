//! `wrapcalc merge`: joins shard CSVs into the sweep.csv a single run gives. The shards must
//! agree on the header and on the number of points, and together hold every point exactly once
//! (all rows of a point in one shard); rows are put in point order whatever order the files
//! come in.

use super::SweepError;
use super::csv::{self, SweepFile};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Reads, checks and joins shard files.
pub fn merge(paths: &[PathBuf]) -> Result<SweepFile, SweepError> {
    let err = |message: String| SweepError::Merge { message };
    if paths.is_empty() {
        return Err(err("no shard files given".into()));
    }
    let files =
        paths.iter().map(|p| csv::read(p).map(|f| (p.as_path(), f))).collect::<Result<Vec<_>, _>>().map_err(err)?;
    let (first_path, first) = &files[0];
    let mut count: Option<(u64, &Path)> = None;
    // Point → (file, rows of that point in file order).
    let mut points: BTreeMap<u64, (&Path, Vec<csv::SweepRow>)> = BTreeMap::new();
    for (path, file) in &files {
        if file.keys != first.keys {
            return Err(err(format!(
                "{}: varies {} but {} varies {}: shards of different sweeps",
                path.display(),
                file.keys.join(", "),
                first_path.display(),
                first.keys.join(", ")
            )));
        }
        let mut last: Option<u64> = None;
        for row in &file.rows {
            match count {
                Some((n, from)) if n != row.point_count => {
                    return Err(err(format!(
                        "{}: point_count {} but {} has {n}: shards of different sweeps",
                        path.display(),
                        row.point_count,
                        from.display()
                    )));
                }
                Some(_) => {}
                None => count = Some((row.point_count, path)),
            }
            if last != Some(row.point) {
                if let Some((other, _)) = points.get(&row.point) {
                    return Err(err(format!(
                        "point {} appears twice: in {} and in {}",
                        row.point,
                        other.display(),
                        path.display()
                    )));
                }
                points.insert(row.point, (path, Vec::new()));
                last = Some(row.point);
            }
            if let Some((_, rows)) = points.get_mut(&row.point) {
                rows.push(row.clone());
            }
        }
    }
    let Some((n, _)) = count else {
        return Err(err("the shards hold no rows: nothing to merge".into()));
    };
    if let Some(missing) = (0..n).find(|p| !points.contains_key(p)) {
        let held = points.len();
        return Err(err(format!(
            "point {missing} of 0..{n} is in none of the shards ({held} of {n} points present): is a shard missing?"
        )));
    }
    let rows = points.into_values().flat_map(|(_, rows)| rows).collect();
    Ok(SweepFile { keys: first.keys.clone(), rows })
}
