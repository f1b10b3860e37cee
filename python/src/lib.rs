//! `deckland._deckland`: the Rust half of the `deckland` Python package.
//!
//! Thin bindings over the `deckland` library, one module per concept:
//!
//! - [`scenario`]: `Scenario`, read and set by dotted path, checked on every change;
//! - [`analysis`]: `trim` and `linearize`;
//! - [`stepping`]: an approach advanced one control interval at a time by the library's
//!   step, the actions' ranges, and a Python callable as the pitch law;
//! - [`flight`]: `fly`, one recorded approach; [`outputs`]: its summary, time series
//!   and events as Python objects;
//! - [`approach`]: `Approach`, the stepping API;
//! - [`gym`]: the Gymnasium environment's core, one environment or many stepped over
//!   threads; [`render`]: its frames;
//! - [`campaign`]: `campaign`, Monte Carlo approaches in parallel;
//! - [`columns`] and [`convert`]: rows of the CLI's CSV files as columns of numpy
//!   arrays, and serde values as Python objects.
//!
//! The Python package (`python/deckland/__init__.py`) wraps these in its public API:
//! tables become pandas DataFrames when pandas is installed. Every run releases the
//! interpreter while it integrates, except the short steps of `Approach`.

mod analysis;
mod approach;
mod campaign;
mod columns;
mod convert;
mod errors;
mod flight;
mod folders;
mod gym;
mod lateral_step;
mod outputs;
mod rare;
mod render;
mod scenario;
mod six_dof;
mod stepping;

use pyo3::prelude::*;

/// The compiled core of deckland (see the `deckland` package for the documented API).
#[pymodule]
mod _deckland {
    #[pymodule_export]
    use super::analysis::{linearize, trim, LinearModel, Trim};
    #[pymodule_export]
    use super::approach::{bench_stepping, Approach};
    #[pymodule_export]
    use super::campaign::{campaign, campaign_shard, merge_shards_text};
    #[pymodule_export]
    use super::flight::fly;
    #[pymodule_export]
    use super::gym::{Config, Env, VecEnv};
    #[pymodule_export]
    use super::lateral_step::lateral_step;
    #[pymodule_export]
    use super::rare::{rare, rare_batched, rare_repetition};
    #[pymodule_export]
    use super::scenario::Scenario;
    #[pymodule_export]
    use super::six_dof::{linearize_six_dof, trim_six_dof};

    use pyo3::prelude::*;

    #[pymodule_init]
    fn init(module: &Bound<'_, PyModule>) -> PyResult<()> {
        module.add("__version__", env!("CARGO_PKG_VERSION"))?;
        module.add("STATE_NAMES", deckland::aircraft::STATE_NAMES.to_vec())?;
        module.add("INPUT_NAMES", deckland::aircraft::INPUT_NAMES.to_vec())?;
        module.add("MAX_SEED", deckland::scenario::MAX_SEED)?;
        module.add("MAX_RUNS", super::campaign::MAX_RUNS)?;
        module.add("MAX_THREADS", deckland::monte_carlo::MAX_THREADS)?;
        Ok(())
    }
}
