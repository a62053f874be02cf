//! Why a machine model cannot run, in both languages (`check` codes M001–M005).

use super::expr::ExprError;
use crate::address::{Address, AddressError};
use std::fmt;

/// Why a machine model cannot run (`check` codes M001–M005).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum ModelError {
    /// M001: not a name.
    Name(String),
    /// M001: a name used twice.
    NameTwice {
        /// The name.
        name: String,
        /// The first device with it.
        first: usize,
    },
    /// M002: an address that does not read or is out of range.
    Address {
        /// The device.
        device: String,
        /// The field.
        field: &'static str,
        /// Why.
        error: AddressError,
    },
    /// M002: an input binding outside X.
    NotInput {
        /// The device.
        device: String,
        /// The field.
        field: &'static str,
        /// The address.
        address: Address,
    },
    /// M002: a byte address where a bit is needed.
    NotBit {
        /// The device.
        device: String,
        /// The field.
        field: &'static str,
        /// The address.
        address: Address,
    },
    /// M003: an impossible parameter.
    Parameter {
        /// The device.
        device: String,
        /// The field.
        field: &'static str,
        /// Its allowed values.
        limit: Limit,
    },
    /// M004: a condition that does not read.
    Expression {
        /// The device.
        device: String,
        /// The field.
        field: &'static str,
        /// Why.
        error: ExprError,
    },
    /// M003: an axis's power-on position that is not a length in range, or an axis the CNC
    /// does not have.
    Start {
        /// The axis, 0 = X.
        axis: usize,
    },
    /// M005: two devices write one input.
    TwoWriters {
        /// The later device.
        device: String,
        /// The input.
        address: Address,
        /// The device that writes it first.
        other: String,
    },
}

/// What an impossible device parameter must be (docs/machine.md gives each field's).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Limit {
    /// A whole number from the first to the second.
    Range(u32, u32),
    /// A whole number from this one up.
    AtLeast(u32),
    /// A station from 1 to the turret's number of stations.
    Station,
    /// Enough code bits for every station's code, at most 32.
    CodeBits,
    /// A position window of at least one tick (station_ms × window_pct ≥ 800).
    WindowTick,
    /// A CCW output or a direction output, not both.
    OneDirection,
    /// from_mm ≤ to_mm, both finite.
    Ordered,
    /// period_ms ≥ 1 and on_ms ≤ period_ms.
    PulseOn,
}

/// The English, as docs/machine.md writes the limits.
impl fmt::Display for Limit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Limit::Range(lo, hi) => write!(f, "{lo}…{hi}"),
            Limit::AtLeast(lo) => write!(f, "{lo}…"),
            Limit::Station => f.write_str("1…stations"),
            Limit::CodeBits => f.write_str("enough bits for every station's code, at most 32"),
            Limit::WindowTick => {
                f.write_str("a window of at least one tick: station_ms × window_pct ≥ 800")
            }
            Limit::OneDirection => {
                f.write_str("either a CCW output or a direction output, not both")
            }
            Limit::Ordered => f.write_str("from_mm ≤ to_mm, both finite"),
            Limit::PulseOn => f.write_str("period_ms ≥ 1 and on_ms ≤ period_ms"),
        }
    }
}

impl ModelError {
    /// The diagnostic code.
    pub fn code(&self) -> &'static str {
        match self {
            ModelError::Name(_) | ModelError::NameTwice { .. } => "M001",
            ModelError::Address { .. }
            | ModelError::NotInput { .. }
            | ModelError::NotBit { .. } => "M002",
            ModelError::Parameter { .. } | ModelError::Start { .. } => "M003",
            ModelError::Expression { .. } => "M004",
            ModelError::TwoWriters { .. } => "M005",
        }
    }
}

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ModelError::Name(n) => write!(
                f,
                "device name `{n}` is not valid: use letters, digits and _, starting with a letter, not an address, at most 24 characters"
            ),
            ModelError::NameTwice { name, first } => write!(
                f,
                "device name `{name}` is taken by device {}: give it another name",
                first + 1
            ),
            ModelError::Address {
                device,
                field,
                error,
            } => write!(f, "device `{device}`, {field}: {error}"),
            ModelError::NotInput {
                device,
                field,
                address,
            } => write!(
                f,
                "device `{device}`, {field}: {address} is not an input; a device writes X bits (the PLC's inputs)"
            ),
            ModelError::NotBit {
                device,
                field,
                address,
            } => write!(
                f,
                "device `{device}`, {field}: {address} is a byte; write a bit address such as {address}.0"
            ),
            ModelError::Parameter {
                device,
                field,
                limit,
            } => write!(
                f,
                "device `{device}`, {field} is impossible: allowed {limit}"
            ),
            ModelError::Expression {
                device,
                field,
                error,
            } => write!(f, "device `{device}`, {field}: {error}"),
            ModelError::Start { axis } => write!(
                f,
                "the power-on position (start_mm) of axis {} is impossible: allowed −100000…100000 mm, 5 axes at most",
                axis + 1
            ),
            ModelError::TwoWriters {
                device,
                address,
                other,
            } => write!(
                f,
                "devices `{other}` and `{device}` both write {address}: one input is driven by one device; remove one of the bindings"
            ),
        }
    }
}
