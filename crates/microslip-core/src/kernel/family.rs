//! Solves along a family, and only there (issue 47). A solver whose answers move little from one
//! call to the next (a sweep's rows, a target scan, a fit's residuals) may keep what it learned
//! and start the next solve from it; but a solve is a function call: `solve` twice, whatever ran
//! between, gives the same bits. The two meet here: what a solver keeps lives in the memory of a
//! [`scope`], opened by the operation that walks the family (the study layer's sweeps, the
//! target scan, the fit, the cycle and the comparisons) without naming any problem, and dropped
//! when that operation ends. Outside a scope [`kept`] answers `None` and the solver solves cold.
//! So a scoped operation's answers depend on its own inputs and their order only (the same sweep
//! twice gives the same bytes), and a plain solve is the cold reference whatever ran before.
//!
//! The memory is per thread (a scope runs on the thread that opened it); a scope opened inside
//! another joins it (a fit's sweep of residuals is the fit's family). What is kept is typed: each
//! solver keeps one value of its own type, created by `Default` on first use in the scope.

use std::any::Any;
use std::cell::RefCell;

/// What the solvers keep inside one scope: one value per type.
#[derive(Default)]
pub struct Memory {
    kept: Vec<Box<dyn Any>>,
}

thread_local! {
    /// The open scope's memory on this thread, if a scope is open.
    static OPEN: RefCell<Option<Memory>> = const { RefCell::new(None) };
    /// Whether [`cold`] runs: scopes open nothing.
    static COLD: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Runs `f` with every solve in it cold, the scopes it opens included (they open nothing): the
/// reference a scope's answers and speed are measured against (`cargo bench`, tests). An open
/// scope around it is put aside meanwhile and kept.
pub fn cold<R>(f: impl FnOnce() -> R) -> R {
    /// Restores the scope and the flag when `f` returns or unwinds.
    struct Restore(Option<Memory>, bool);
    impl Drop for Restore {
        fn drop(&mut self) {
            COLD.set(self.1);
            let memory = self.0.take();
            OPEN.with(|open| *open.borrow_mut() = memory);
        }
    }
    let aside = OPEN.with(|open| open.borrow_mut().take());
    let _restore = Restore(aside, COLD.replace(true));
    f()
}

/// Runs `f` inside a family scope: solves in it may continue from the earlier solves of `f`
/// (see the module doc). Starts empty and is dropped when `f` returns (or unwinds); inside an
/// open scope it joins that one.
pub fn scope<R>(f: impl FnOnce() -> R) -> R {
    Family::default().run(f)
}

/// A scope held across calls, for a lazy walk (an iterator of rows computed as they are read):
/// each [`Family::run`] reopens it with what the previous runs kept.
#[derive(Default)]
pub struct Family {
    memory: Memory,
}

impl Family {
    /// Runs `f` in this family's scope; inside another open scope, in that one.
    pub fn run<R>(&mut self, f: impl FnOnce() -> R) -> R {
        if is_open() || COLD.get() {
            return f();
        }
        /// Takes the memory back when `f` returns or unwinds.
        struct Close<'a>(&'a mut Memory);
        impl Drop for Close<'_> {
            fn drop(&mut self) {
                if let Some(memory) = OPEN.with(|open| open.borrow_mut().take()) {
                    *self.0 = memory;
                }
            }
        }
        OPEN.with(|open| *open.borrow_mut() = Some(std::mem::take(&mut self.memory)));
        let _close = Close(&mut self.memory);
        f()
    }
}

/// Whether a scope is open on this thread.
pub fn is_open() -> bool {
    OPEN.with(|open| open.borrow().is_some())
}

/// Runs `f` with the open scope's value of type `T` (its default on first use); `None`, without
/// running `f`, outside a scope. The value is taken out while `f` runs, so `f` may use
/// [`kept`] for another type (a solver calling another); a nested use of the same type sees a
/// fresh default, and what it keeps is dropped.
pub fn kept<T: Default + 'static, R>(f: impl FnOnce(&mut T) -> R) -> Option<R> {
    let taken = OPEN.with(|open| {
        let mut open = open.borrow_mut();
        let memory = open.as_mut()?;
        let at = memory.kept.iter().position(|k| k.is::<T>());
        Some(at.map_or_else(
            || Box::new(T::default()) as Box<dyn Any>,
            |i| memory.kept.swap_remove(i),
        ))
    })?;
    let mut value = taken;
    let result = f(value
        .downcast_mut::<T>()
        .expect("stored under its own type"));
    OPEN.with(|open| {
        if let Some(memory) = open.borrow_mut().as_mut()
            && !memory.kept.iter().any(|k| k.is::<T>())
        {
            memory.kept.push(value);
        }
    });
    Some(result)
}

/// `iter` with each item computed inside one [`Family`]: a lazy sweep's rows continue from each
/// other, and from nothing else.
pub fn iter<I: Iterator>(iter: I) -> Scoped<I> {
    Scoped {
        iter,
        family: Family::default(),
    }
}

/// The iterator of [`iter`].
pub struct Scoped<I> {
    iter: I,
    family: Family,
}

impl<I: Iterator> Iterator for Scoped<I> {
    type Item = I::Item;

    fn next(&mut self) -> Option<I::Item> {
        let Scoped { iter, family } = self;
        family.run(|| iter.next())
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        self.iter.size_hint()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Default)]
    struct Count(u32);

    fn count() -> Option<u32> {
        kept(|c: &mut Count| {
            c.0 += 1;
            c.0
        })
    }

    #[test]
    fn outside_a_scope_nothing_is_kept() {
        assert_eq!(count(), None);
        assert!(!is_open());
    }

    #[test]
    fn a_scope_starts_empty_keeps_within_and_forgets_on_exit() {
        assert_eq!(scope(|| (count(), count())), (Some(1), Some(2)));
        assert_eq!(scope(count), Some(1));
        assert!(!is_open());
        assert_eq!(count(), None);
    }

    #[test]
    fn a_nested_scope_joins_the_outer() {
        let inner = scope(|| {
            count();
            scope(count)
        });
        assert_eq!(inner, Some(2));
    }

    #[test]
    fn a_lazy_walk_keeps_across_its_items_only() {
        let walk = iter((0..3).map(|_| count().unwrap()));
        assert!(!is_open());
        // Another scope between the items does not see the walk's memory, nor it the other's.
        let mut seen = Vec::new();
        for n in walk {
            seen.push(n);
            assert_eq!(scope(count), Some(1));
        }
        assert_eq!(seen, [1, 2, 3]);
    }

    #[test]
    fn cold_opens_no_scope_and_keeps_the_one_around_it() {
        let seen = scope(|| {
            count();
            let inside = cold(|| scope(count));
            (inside, count())
        });
        assert_eq!(seen, (None, Some(2)));
        assert!(!COLD.get());
    }

    #[test]
    fn a_panic_closes_the_scope() {
        let caught = std::panic::catch_unwind(|| scope(|| panic!("inside")));
        assert!(caught.is_err());
        assert!(!is_open());
    }

    #[test]
    fn types_are_kept_apart() {
        #[derive(Default)]
        struct Other(u32);
        let both = scope(|| {
            count();
            let other = kept(|o: &mut Other| {
                o.0 += 10;
                // Another type used inside.
                count()
            });
            (other, kept(|o: &mut Other| o.0), count())
        });
        assert_eq!(both, (Some(Some(2)), Some(10), Some(3)));
    }
}
