//! The runner's pass for what follows the wrap on a grid of its own (rope elements carried
//! through the wrap, [`crate::model::track`]): the model is settled and stepped to each instant
//! of the grid in turn, and the follower reads the state there; where the follower wants to see
//! the state between two of its instants (the root of a force), it keeps the state of the
//! earlier one ([`Kept`]) and asks for copies of it stepped on ([`Kept::at`]). The follower
//! never steps a model itself.

use super::WrapModel;

/// A state kept at one instant of the grid, to be stepped on (as a copy) to later instants.
#[derive(Debug, Clone)]
pub struct Kept<M> {
    t_s: f64,
    state: M,
}

impl<M: WrapModel + Clone> Kept<M> {
    /// The instant the state was kept at (s).
    pub fn t_s(&self) -> f64 {
        self.t_s
    }

    /// A copy of the kept state stepped to `t_s` (at or after [`Self::t_s`]).
    pub fn at(&self, t_s: f64) -> Result<M, M::Error> {
        let mut model = self.state.clone();
        model.advance_to(t_s)?;
        Ok(model)
    }
}

/// What a follower is shown at each instant of its grid.
pub struct Instant<'a, M> {
    /// The instant (s).
    pub t_s: f64,
    /// The state there.
    pub model: &'a M,
    /// The state at the previous instant, when the follower asked for it to be kept.
    pub before: Option<&'a Kept<M>>,
}

/// Settles `model` and steps it to each of `times` (ascending) in turn, showing `follow` the
/// state there; `follow` returns whether the state is to be kept for the next instant
/// ([`Instant::before`]).
pub fn follow<M: WrapModel + Clone>(
    mut model: M,
    times: &[f64],
    mut follow: impl FnMut(Instant<'_, M>) -> Result<bool, M::Error>,
) -> Result<(), M::Error> {
    model.settle()?;
    let mut before: Option<Kept<M>> = None;
    for &t_s in times {
        model.advance_to(t_s)?;
        let keep = follow(Instant { t_s, model: &model, before: before.as_ref() })?;
        before = keep.then(|| Kept { t_s, state: model.clone() });
    }
    Ok(())
}
