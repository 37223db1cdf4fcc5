//! Where an interface slides, read from the pairs of a solved state, walking from one end.

/// The nominal front: walking the pairs in `order`, the first place where the level
/// `level(i)` (K_T |s| at pair i, MPa) falls below `saturation` (mu P), interpolated linearly
/// between that pair and the one before (mm); the first pair's x when it is already below, the
/// last pair's when none is.
pub(crate) fn nominal_front(
    xs: &[f64],
    level: impl Fn(usize) -> f64,
    saturation: f64,
    order: &mut dyn Iterator<Item = usize>,
) -> f64 {
    let mut previous: Option<(f64, f64)> = None;
    for i in order {
        let (x, level) = (xs[i], level(i));
        if level < saturation {
            return match previous {
                None => x,
                Some((x0, l0)) => x0 + (x - x0) * (saturation - l0) / (level - l0),
            };
        }
        previous = Some((x, level));
    }
    previous.map_or(0.0, |(x, _)| x)
}

/// The last pair of the run of sliding pairs (`sliding(i)`) that starts the walk in `order`;
/// `None` when the first pair does not slide.
pub(crate) fn last_of_run(
    sliding: impl Fn(usize) -> bool,
    order: &mut dyn Iterator<Item = usize>,
) -> Option<usize> {
    let mut last = None;
    for i in order {
        if !sliding(i) {
            break;
        }
        last = Some(i);
    }
    last
}
