//! The machine around the CNC (docs/machine.md): devices that answer the ladder's outputs
//! with its inputs — a turret that turns while its motor output is on and shows its station
//! on the sensors, a chuck whose clamp switch closes after its travel time, dogs and limit
//! switches worked by the axes — so that a program runs against its machine with no hand
//! on the keyboard. The model is data in the project ([`model`]); [`Plant`] runs it once
//! per tick, before the PLC scan; faults are injected at run time and never saved.

pub mod check;
pub mod expr;
pub mod fields;
mod kinds;
pub mod model;
pub(crate) mod run;
mod turret;

mod error;
mod resolved;
mod status;

pub use error::{Limit, ModelError};
pub use expr::ExprError;
pub use model::{Device, DeviceKind, MachineModel};
pub use resolved::CncView;
pub use run::Plant;
pub use status::{DeviceState, DeviceStatus, FLICKER_MIN_MS, Fault, SLOW_MAX, SLOW_MIN};
