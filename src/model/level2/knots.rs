//! Storage of the knots: a vector with spare room at the front as well as at the back.
//!
//! Rope enters the wrap at one end and leaves at the other, and an increment changes only the
//! slip runs attached to the ends. With room at both ends, a node entering, a node leaving and
//! the replacement of an end run all cost time proportional to their own size, not to the
//! number of knots, so the stuck rope in between is never copied.

use super::state::{Knot, KnotKind};
use std::ops::{Deref, DerefMut};

/// Knots in θ order (reads as a slice).
#[derive(Clone, Default)]
pub struct Knots {
    buf: Vec<Knot>,
    /// Index in `buf` of the first knot: `buf[..head]` is spare room.
    head: usize,
}

const FILLER: Knot = Knot { theta_rad: 0.0, tension_n: 0.0, log_n: 0.0, kind: KnotKind::Kink };

impl Knots {
    /// Makes room for at least `extra` knots in front of the first one.
    fn reserve_front(&mut self, extra: usize) {
        if self.head >= extra {
            return;
        }
        let len = self.len();
        let gap = extra.max(len / 4).max(16);
        let mut buf = Vec::with_capacity(gap + len + len / 4 + 16);
        buf.resize(gap, FILLER);
        buf.extend_from_slice(&self.buf[self.head..]);
        self.buf = buf;
        self.head = gap;
    }

    /// Replaces the first `count` knots by `items`.
    pub fn replace_front(&mut self, count: usize, items: &[Knot]) {
        let count = count.min(self.len());
        if items.len() > count {
            self.reserve_front(items.len() - count);
        }
        let start = self.head + count - items.len();
        self.buf[start..start + items.len()].copy_from_slice(items);
        self.head = start;
    }

    /// Replaces the knots from index `from` to the last by `items`.
    pub fn replace_back(&mut self, from: usize, items: &[Knot]) {
        self.buf.truncate(self.head + from.min(self.len()));
        self.buf.extend_from_slice(items);
    }

    /// Inserts a knot before index `index` (cheap near either end).
    pub fn insert(&mut self, index: usize, knot: Knot) {
        if index <= self.len() / 2 {
            self.reserve_front(1);
            let h = self.head;
            self.buf.copy_within(h..h + index, h - 1);
            self.head -= 1;
            self.buf[self.head + index] = knot;
        } else {
            self.buf.insert(self.head + index, knot);
        }
    }

    /// Removes the knot at `index` (cheap near either end).
    pub fn remove(&mut self, index: usize) -> Knot {
        let knot = self[index];
        if index < self.len() / 2 {
            let h = self.head;
            self.buf.copy_within(h..h + index, h + 1);
            self.head += 1;
        } else {
            self.buf.remove(self.head + index);
        }
        knot
    }

    /// Keeps the knots for which `keep` is true.
    pub fn retain(&mut self, keep: impl FnMut(&Knot) -> bool) {
        let head = self.head;
        self.buf.drain(..head);
        self.head = 0;
        self.buf.retain(keep);
    }
}

impl From<Vec<Knot>> for Knots {
    fn from(buf: Vec<Knot>) -> Self {
        Self { buf, head: 0 }
    }
}

impl Deref for Knots {
    type Target = [Knot];
    fn deref(&self) -> &[Knot] {
        &self.buf[self.head..]
    }
}

impl DerefMut for Knots {
    fn deref_mut(&mut self) -> &mut [Knot] {
        &mut self.buf[self.head..]
    }
}

impl<'a> IntoIterator for &'a Knots {
    type Item = &'a Knot;
    type IntoIter = std::slice::Iter<'a, Knot>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

impl PartialEq for Knots {
    fn eq(&self, other: &Self) -> bool {
        self[..] == other[..]
    }
}

impl std::fmt::Debug for Knots {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn knot(theta_rad: f64) -> Knot {
        Knot { theta_rad, tension_n: theta_rad, log_n: 0.0, kind: KnotKind::Node }
    }

    fn thetas(k: &Knots) -> Vec<f64> {
        k.iter().map(|k| k.theta_rad).collect()
    }

    /// Every edit gives the same sequence as the same edit on a plain vector.
    #[test]
    fn edits_match_a_plain_vector() {
        let mut plain: Vec<Knot> = (0..40).map(|i| knot(i as f64)).collect();
        let mut k = Knots::from(plain.clone());
        for step in 0..200 {
            let x = 1000.0 + step as f64;
            match step % 6 {
                0 => {
                    k.insert(1, knot(x));
                    plain.insert(1, knot(x));
                }
                1 => {
                    let i = k.len() - 2;
                    assert_eq!(k.remove(i), plain.remove(i));
                }
                2 => {
                    let items = [knot(x), knot(x + 0.5), knot(x + 0.25)];
                    k.replace_front(2, &items);
                    plain.splice(0..2, items);
                }
                3 => {
                    let from = plain.len() - 3;
                    k.replace_back(from, &[knot(x), knot(x + 0.5)]);
                    plain.splice(from.., [knot(x), knot(x + 0.5)]);
                }
                4 => {
                    assert_eq!(k.remove(2), plain.remove(2));
                    k.insert(k.len() - 1, knot(x));
                    plain.insert(plain.len() - 1, knot(x));
                }
                _ => {
                    k.replace_front(1, &[knot(x), knot(x + 0.1), knot(x + 0.2)]);
                    plain.splice(0..1, [knot(x), knot(x + 0.1), knot(x + 0.2)]);
                }
            }
            assert_eq!(thetas(&k), plain.iter().map(|k| k.theta_rad).collect::<Vec<_>>(), "step {step}");
        }
        k.retain(|k| k.theta_rad < 1100.0);
        plain.retain(|k| k.theta_rad < 1100.0);
        assert_eq!(thetas(&k), plain.iter().map(|k| k.theta_rad).collect::<Vec<_>>());
    }
}
