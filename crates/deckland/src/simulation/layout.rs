//! Where each block's state lives in the closed loop's state vector.
//!
//! Every block of the loop declares the names of its continuous states; the layout
//! lays them out one block after the other and hands each block its [`Slot`]. Offsets
//! are computed, never written by hand, so a block with another dimension (a PID's one
//! integral against the O-PD's three observer states, a user's own law) changes nothing
//! else.

use crate::environment::{LateralShipMotionState, ShipMotionState};

/// A block's place in the state vector: `len` states from `offset`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Slot {
    /// Index of the block's first state.
    pub offset: usize,
    /// Number of states.
    pub len: usize,
}

impl Slot {
    /// The block's states in `x`.
    #[inline]
    pub fn of<'a>(&self, x: &'a [f64]) -> &'a [f64] {
        &x[self.offset..self.offset + self.len]
    }

    /// The block's states in `x`, to write.
    #[inline]
    pub fn of_mut<'a>(&self, x: &'a mut [f64]) -> &'a mut [f64] {
        &mut x[self.offset..self.offset + self.len]
    }

    /// The block's states in `x` as an array of its known dimension `N` (one bounds
    /// check instead of one per state).
    #[inline(always)]
    pub fn array<const N: usize>(&self, x: &[f64]) -> [f64; N] {
        let mut out = [0.0; N];
        out.copy_from_slice(&x[self.offset..self.offset + N]);
        out
    }

    /// Writes the block's states of known dimension `N` into `x`.
    #[inline(always)]
    pub fn write_array<const N: usize>(&self, x: &mut [f64], values: &[f64; N]) {
        x[self.offset..self.offset + N].copy_from_slice(values);
    }

    /// The block's single state (for one-state blocks).
    #[inline]
    pub fn scalar(&self, x: &[f64]) -> f64 {
        x[self.offset]
    }
}

/// One block's entry in the layout: its name, slot and state names.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BlockStates {
    /// The block's name, e.g. `pitch_law`.
    pub block: &'static str,
    /// Its place in the state vector.
    pub slot: Slot,
    /// The names of its states, in order.
    pub names: Vec<&'static str>,
}

/// The layout of a state vector: the blocks in order.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct StateLayout {
    blocks: Vec<BlockStates>,
    dimension: usize,
}

impl StateLayout {
    /// An empty layout.
    pub fn new() -> Self {
        Self::default()
    }

    /// Appends a block with the given state names and returns its slot.
    pub fn add(&mut self, block: &'static str, names: &[&'static str]) -> Slot {
        let slot = Slot {
            offset: self.dimension,
            len: names.len(),
        };
        self.dimension += names.len();
        self.blocks.push(BlockStates {
            block,
            slot,
            names: names.to_vec(),
        });
        slot
    }

    /// The total number of states.
    pub fn dimension(&self) -> usize {
        self.dimension
    }

    /// The blocks in order.
    pub fn blocks(&self) -> &[BlockStates] {
        &self.blocks
    }

    /// The dotted name (`block.state`) of state `index`.
    pub fn state_name(&self, index: usize) -> Option<String> {
        self.blocks.iter().find_map(|b| {
            let i = index.checked_sub(b.slot.offset)?;
            b.names.get(i).map(|name| format!("{}.{name}", b.block))
        })
    }
}

/// The slots of the loop's blocks in its state vector.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LoopLayout {
    /// Every block, in order, with its state names.
    pub states: StateLayout,
    /// The aircraft plant (its state vector, [`crate::aircraft::Plant::STATE_NAMES`]).
    pub aircraft: Slot,
    /// The ship's heave and pitch shaping filters ([`ShipMotionState`]).
    pub ship: Slot,
    /// The pitch law's own states.
    pub pitch_law: Slot,
    /// The speed loop: ∫ airspeed error dt (m), and the filtered airspeed (m/s).
    pub speed: Slot,
    /// ∫ climb-rate error dt (m).
    pub sink_rate: Slot,
    /// ∫ hook height error dt (m·s).
    pub guidance: Slot,
    /// The deck-motion predictor's own states.
    pub deck_predictor: Slot,
    /// Direct lift control's lift-coefficient increment (–); no state without it.
    pub direct_lift: Slot,
    /// The 3-D approach's roll, yaw and sway filters ([`LateralShipMotionState`]); no
    /// state outside it (as the two below).
    pub ship_lateral: Slot,
    /// The roll law's own states.
    pub roll_law: Slot,
    /// The yaw law's own states.
    pub yaw_law: Slot,
}

impl LoopLayout {
    /// Lays out the blocks, given the state names of the blocks whose states vary (the
    /// plant's first).
    pub fn new(
        aircraft: &[&'static str],
        pitch_law: &[&'static str],
        speed: &[&'static str],
        deck_predictor: &[&'static str],
        direct_lift: bool,
    ) -> Self {
        let mut states = StateLayout::new();
        let aircraft = states.add("aircraft", aircraft);
        let ship = states.add("ship", &ShipMotionState::NAMES);
        let pitch_law = states.add("pitch_law", pitch_law);
        let speed = states.add("speed", speed);
        let sink_rate = states.add("sink_rate", &["climb_rate_error_integral_m"]);
        let guidance = states.add("guidance", &["height_error_integral_m_s"]);
        let deck_predictor = states.add("deck_predictor", deck_predictor);
        let direct_lift = states.add(
            "direct_lift",
            if direct_lift {
                &["lift_coefficient_increment"]
            } else {
                &[]
            },
        );
        Self {
            direct_lift,
            ship_lateral: Slot::default(),
            roll_law: Slot::default(),
            yaw_law: Slot::default(),
            states,
            aircraft,
            ship,
            pitch_law,
            speed,
            sink_rate,
            guidance,
            deck_predictor,
        }
    }

    /// The number of states.
    pub fn dimension(&self) -> usize {
        self.states.dimension()
    }

    /// Lays out the 3-D approach's blocks after the others: the lateral ship filters and
    /// the roll and yaw laws with these state names.
    pub fn add_lateral(&mut self, roll_law: &[&'static str], yaw_law: &[&'static str]) {
        self.ship_lateral = self
            .states
            .add("ship_lateral", &LateralShipMotionState::NAMES);
        self.roll_law = self.states.add("roll_law", roll_law);
        self.yaw_law = self.states.add("yaw_law", yaw_law);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_follow_the_declared_dimensions() {
        let mut layout = StateLayout::new();
        let a = layout.add("a", &["x", "y"]);
        let empty = layout.add("empty", &[]);
        let b = layout.add("b", &["z"]);
        assert_eq!(a, Slot { offset: 0, len: 2 });
        assert_eq!(empty, Slot { offset: 2, len: 0 });
        assert_eq!(b, Slot { offset: 2, len: 1 });
        assert_eq!(layout.dimension(), 3);
        assert_eq!(layout.state_name(2).as_deref(), Some("b.z"));
        assert_eq!(layout.state_name(3), None);
        let x = [1.0, 2.0, 3.0];
        assert_eq!(a.of(&x), &[1.0, 2.0]);
        assert_eq!(b.scalar(&x), 3.0);
        assert!(empty.of(&x).is_empty());
    }
}
