//! Work spread over threads with the calling thread taking part: how `_VecEnv` steps its
//! environments.
//!
//! A vectorised step is short (64 environments, about 1 ms of work in all) and comes
//! again as soon as Python has read the results, so what a thread pool costs at each
//! call weighs: waking sleeping threads, the calling thread waiting idle while others
//! work, more threads than cores, and items moving between cores from call to call.
//! Here the threads are exactly `threads`: the calling thread, which starts on the items
//! at once, and `threads − 1` helpers of a pool of that size ([`helpers`]). The items
//! are cut into one block per thread; each thread works its own block, then takes what
//! is left of the others', so the threads end within about one item of each other and an
//! item stays on one core from call to call. Between calls and at a call's end the
//! threads wait awake for a short while ([`KEEP_AWAKE`]) rather than sleep. Which thread
//! works an item changes nothing in its result.

use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::{Mutex, OnceLock, PoisonError};
use std::time::{Duration, Instant};

use rayon::{ThreadPool, ThreadPoolBuilder};

/// The threads the vectorised environment steps on, the calling thread included:
/// `RAYON_NUM_THREADS` if a positive integer, else one per core.
fn threads() -> usize {
    std::env::var("RAYON_NUM_THREADS")
        .ok()
        .and_then(|v| v.trim().parse::<usize>().ok())
        .filter(|&n| n > 0)
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, usize::from))
}

/// The helper threads, [`threads`] less the calling one (none with one thread), built
/// at the first vectorised step and shared by every vectorised environment.
pub(super) fn helpers() -> Option<&'static ThreadPool> {
    static HELPERS: OnceLock<Option<ThreadPool>> = OnceLock::new();
    HELPERS
        .get_or_init(|| {
            let helpers = threads() - 1;
            if helpers == 0 {
                return None;
            }
            ThreadPoolBuilder::new()
                .num_threads(helpers)
                .thread_name(|i| format!("deckland-gym-{i}"))
                .build()
                .ok()
        })
        .as_ref()
}

/// Calls `work(i, &mut items[i])` once for every item, over the calling thread and the
/// threads of `helpers` (at most one thread per item).
///
/// The items are cut into one block per thread, in order: each thread takes its own
/// block's items from the front, then the others' from the back, so that from one call to
/// the next an item is mostly worked by the same thread, its data in that core's cache
/// (the calling thread has the first block, a helper the block of its index in the pool,
/// or any block not yet taken).
pub(super) fn for_each_item<T, F>(helpers: Option<&ThreadPool>, items: &mut [T], work: F)
where
    T: Send,
    F: Fn(usize, &mut T) + Sync,
{
    let count = helpers.map_or(0, |pool| {
        pool.current_num_threads()
            .min(items.len().saturating_sub(1))
    });
    let Some(pool) = helpers.filter(|_| count > 0) else {
        for (i, item) in items.iter_mut().enumerate() {
            work(i, item);
        }
        return;
    };
    let blocks = Blocks::new(items, count + 1);
    CALLS.fetch_add(1, Ordering::Relaxed);
    pool.in_place_scope(|scope| {
        for _ in 0..count {
            scope.spawn(|_| {
                let own = blocks.claim(rayon::current_thread_index().map_or(0, |w| w + 1));
                blocks.drain(own, &work);
            });
        }
        let own = blocks.claim(0);
        blocks.drain(own, &work);
        // The helpers' last items awaited awake (about one item's work, less than a
        // sleeping thread takes to wake), for at most `KEEP_AWAKE`; then asleep, as the
        // scope waits (and a helper's panic comes back).
        let until = Instant::now() + KEEP_AWAKE;
        while blocks.done.load(Ordering::Acquire) < blocks.len && Instant::now() < until {
            spin(64);
        }
    });
    // Keep the helpers awake a little for the next call (see [`KEEP_AWAKE`]).
    let call = CALLS.load(Ordering::Relaxed);
    for _ in 0..count {
        pool.spawn(move || {
            let until = Instant::now() + KEEP_AWAKE;
            while CALLS.load(Ordering::Relaxed) == call && Instant::now() < until {
                spin(64);
            }
        });
    }
}

/// `rounds` rounds of the processor's busy-waiting hint.
fn spin(rounds: u32) {
    for _ in 0..rounds {
        std::hint::spin_loop();
    }
}

/// The calls of [`for_each_item`] begun.
static CALLS: AtomicU64 = AtomicU64::new(0);

/// How long a thread waits awake: the helpers for the next call after one, before the
/// pool lets them sleep (about what Python takes between two steps with a small policy),
/// and the calling thread for the helpers' last items. A sleeping thread takes tens of µs
/// to wake (more in a virtual machine), which its core would lose at each step.
const KEEP_AWAKE: Duration = Duration::from_micros(100);

/// One block: whether a thread has taken it as its own, and the index of its first item
/// not yet worked with those items.
struct Block<'a, T> {
    taken: AtomicBool,
    items: Mutex<(usize, &'a mut [T])>,
}

/// The items cut into blocks, one per thread, each the index of its first item not yet
/// taken and those items.
struct Blocks<'a, T> {
    blocks: Vec<Block<'a, T>>,
    /// The number of items.
    len: usize,
    /// The items worked.
    done: AtomicUsize,
}

impl<'a, T> Blocks<'a, T> {
    fn new(items: &'a mut [T], count: usize) -> Self {
        let len = items.len();
        let size = len.div_ceil(count);
        let blocks = items
            .chunks_mut(size.max(1))
            .enumerate()
            .map(|(b, chunk)| Block {
                taken: AtomicBool::new(false),
                items: Mutex::new((b * size, chunk)),
            })
            .collect();
        Self {
            blocks,
            len,
            done: AtomicUsize::new(0),
        }
    }

    /// The block a thread takes as its own: `preferred` if not yet taken, else any not
    /// yet taken (None: every block has its thread).
    fn claim(&self, preferred: usize) -> Option<usize> {
        let take = |b: usize| {
            self.blocks
                .get(b)
                .is_some_and(|block| !block.taken.swap(true, Ordering::Relaxed))
        };
        if take(preferred) {
            return Some(preferred);
        }
        (0..self.blocks.len()).find(|&b| take(b))
    }

    /// The next item of block `b`: its first (`front`) or its last not yet taken.
    fn pop(&self, b: usize, front: bool) -> Option<(usize, &'a mut T)> {
        let mut block = self.blocks[b]
            .items
            .lock()
            .unwrap_or_else(PoisonError::into_inner);
        let (start, items) = (block.0, std::mem::take(&mut block.1));
        if front {
            let (first, rest) = items.split_first_mut()?;
            *block = (start + 1, rest);
            Some((start, first))
        } else {
            let (last, rest) = items.split_last_mut()?;
            let index = start + rest.len();
            *block = (start, rest);
            Some((index, last))
        }
    }

    /// Works the items of block `own` from its front, then those left in the others
    /// from their backs.
    fn drain(&self, own: Option<usize>, work: &(impl Fn(usize, &mut T) + Sync)) {
        if let Some(own) = own {
            while let Some((i, item)) = self.pop(own, true) {
                work(i, item);
                self.done.fetch_add(1, Ordering::Release);
            }
        }
        let start = own.unwrap_or(0);
        let count = self.blocks.len();
        for b in (1..=count).map(|d| (start + d) % count) {
            while let Some((i, item)) = self.pop(b, false) {
                work(i, item);
                self.done.fetch_add(1, Ordering::Release);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pool(threads: usize) -> ThreadPool {
        ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a thread pool")
    }

    #[test]
    fn every_item_is_worked_once_with_its_own_index() {
        let helpers = pool(2);
        for pool in [None, Some(&helpers)] {
            for n in [0, 1, 2, 3, 64, 1000] {
                let mut items: Vec<(usize, u32)> = vec![(usize::MAX, 0); n];
                for_each_item(pool, &mut items, |i, item| {
                    item.0 = i;
                    item.1 += 1;
                });
                assert!(items.iter().enumerate().all(|(i, item)| *item == (i, 1)));
            }
        }
    }

    #[test]
    fn the_calling_thread_and_a_helper_share_the_items() {
        // Each thread's first item waits for the other thread to have started one: both
        // take part, whichever wakes first.
        let helpers = pool(1);
        let started = Mutex::new(Vec::new());
        let mut items = vec![None; 50];
        for_each_item(Some(&helpers), &mut items, |_, item| {
            let me = std::thread::current().id();
            let give_up = std::time::Instant::now() + std::time::Duration::from_secs(60);
            loop {
                let mut seen = started.lock().expect("not poisoned");
                if !seen.contains(&me) {
                    seen.push(me);
                }
                if seen.len() >= 2 || std::time::Instant::now() > give_up {
                    break;
                }
                drop(seen);
                std::thread::yield_now();
            }
            *item = Some(me);
        });
        let mut threads: Vec<_> = items
            .iter()
            .map(|t| t.expect("every item worked"))
            .collect();
        threads.dedup();
        threads.sort_by_key(|t| format!("{t:?}"));
        threads.dedup();
        assert_eq!(threads.len(), 2);
    }

    #[test]
    fn a_thread_works_its_own_block_from_the_front_then_the_others_from_the_back() {
        let mut items: Vec<usize> = (0..10).collect();
        let blocks = Blocks::new(&mut items, 3); // [0, 4), [4, 8), [8, 10)
        assert_eq!(blocks.claim(1), Some(1));
        assert_eq!(blocks.claim(1), Some(0)); // taken: the first free one
        assert_eq!(blocks.claim(7), Some(2));
        assert_eq!(blocks.claim(0), None);
        let order = Mutex::new(Vec::new());
        blocks.drain(Some(1), &|i, item: &mut usize| {
            assert_eq!(i, *item);
            order.lock().expect("not poisoned").push(i);
        });
        let order = order.into_inner().expect("not poisoned");
        assert_eq!(order, [4, 5, 6, 7, 9, 8, 3, 2, 1, 0]);
    }
}
