//! Shards: a sweep cut into `N` contiguous blocks of cases, one per machine
//! or batch job (README, "Studies beyond one machine").
//!
//! Shard `K` of `N` (1 <= K <= N) of a sweep of `n` cases runs the cases
//! `floor((K−1)·n/N) … floor(K·n/N) − 1`: the blocks are contiguous, in case
//! order, cover every case once, and their sizes differ by at most one.
//! Blocks may be empty when `N > n`.

use std::fmt;
use std::ops::Range;
use std::str::FromStr;

/// The `K`-th of `N` blocks of a sweep's cases (1 <= K <= N).
///
/// ```
/// use rocking_scenario::Shard;
///
/// let shard: Shard = "2/3".parse()?;
/// assert_eq!((shard.k(), shard.n()), (2, 3));
/// assert_eq!(shard.cases(10), 3..6); // 0..3, 3..6, 6..10
/// # Ok::<(), String>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    k: usize,
    n: usize,
}

impl Shard {
    /// Shard `k` of `n`; an error unless 1 <= k <= n.
    pub fn new(k: usize, n: usize) -> Result<Self, String> {
        if n == 0 || k == 0 || k > n {
            return Err(format!("shard {k}/{n} does not exist: give K/N with 1 <= K <= N"));
        }
        Ok(Self { k, n })
    }

    /// The shard's number, 1 to [`Shard::n`].
    pub fn k(&self) -> usize {
        self.k
    }

    /// The number of shards.
    pub fn n(&self) -> usize {
        self.n
    }

    /// The cases of this shard in a sweep of `total` cases:
    /// `floor((k−1)·total/n) .. floor(k·total/n)`.
    pub fn cases(&self, total: usize) -> Range<usize> {
        block_start(self.k - 1, self.n, total)..block_start(self.k, self.n, total)
    }
}

/// `floor(i·total/n)`, without overflow (the product may not fit a `usize`).
fn block_start(i: usize, n: usize, total: usize) -> usize {
    let start = (i as u128 * total as u128) / n as u128;
    // start <= total since i <= n.
    usize::try_from(start).unwrap_or(total)
}

impl FromStr for Shard {
    type Err = String;

    /// `"K/N"`, e.g. `"3/16"`.
    fn from_str(text: &str) -> Result<Self, String> {
        let bad = || format!("{text:?} is not a shard: give K/N with 1 <= K <= N, e.g. 3/16");
        let (k, n) = text.split_once('/').ok_or_else(bad)?;
        let k = k.trim().parse::<usize>().map_err(|_| bad())?;
        let n = n.trim().parse::<usize>().map_err(|_| bad())?;
        Self::new(k, n)
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.k, self.n)
    }
}
