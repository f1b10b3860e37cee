//! One entry of an observation: what the longitudinal and the lateral entries share.

/// One entry of the observation: its name, unit, where it comes from, and its scale
/// and realistic range (the normalised value is (raw − offset)/scale, clipped to the
/// range's image).
#[derive(Debug, Clone, Copy)]
pub(crate) struct ObservationSpec {
    pub name: &'static str,
    pub unit: &'static str,
    pub source: &'static str,
    pub scale: f64,
    pub low: f64,
    pub high: f64,
}
