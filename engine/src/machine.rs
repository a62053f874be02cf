//! A machine: the PLC and the simulated CNC owned and ticked together, the one value the
//! command line and the editor run. What a user does to a running machine is a
//! [`MachineCommand`]; stimulus scripts are lists of them, so a script and the editor can
//! never drift apart. [`Snapshot`] is what a monitor copies out between ticks.

use crate::address::{Address, Area};
use crate::cnc::command::{CncCommand, CncKey, CncValue};
use crate::cnc::{CncStatus, SimCnc};
use crate::model::Project;
use crate::vm::cnc::NoCnc;
use crate::vm::swap::{SwapError, Swapped};
use crate::vm::{BuildError, Halt, Vm};
use std::fmt;

/// An address with a byte count, as scripts write it (`D0010:2`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Target {
    /// The address.
    pub address: Address,
    /// Bytes: given with `:N`, else the area's natural width (1 for bits).
    pub bytes: u32,
    /// Whether `:N` was written.
    pub explicit: bool,
}

impl Target {
    /// The address as printed in messages: canonical, with `:N` when it was given.
    pub fn text(&self) -> String {
        if self.explicit {
            format!("{}:{}", self.address, self.bytes)
        } else {
            self.address.to_string()
        }
    }
}

/// Something a monitor or a script reads each tick: PLC memory or a CNC value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Probe {
    /// A PLC address.
    Memory(Target),
    /// A `cnc.KEY` value.
    Cnc(CncKey),
}

impl Probe {
    /// How it is named in output and trace headers.
    pub fn text(&self) -> String {
        match self {
            Probe::Memory(t) => t.text(),
            Probe::Cnc(k) => k.text(),
        }
    }
}

/// A value read by a [`Probe`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ProbeValue {
    /// PLC memory, signed at its width.
    Int(i64),
    /// A CNC value.
    Cnc(CncValue),
}

impl fmt::Display for ProbeValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ProbeValue::Int(v) => write!(f, "{v}"),
            ProbeValue::Cnc(v) => write!(f, "{v}"),
        }
    }
}

/// What a user does to a running machine.
#[derive(Clone, Debug, PartialEq)]
pub enum MachineCommand {
    /// Start running (the runner ticks while running).
    Run,
    /// Stop running.
    Stop,
    /// Run N ticks now.
    Tick(u64),
    /// Write a value once.
    Write(Target, i64),
    /// Write a real once.
    WriteReal(Address, f32),
    /// Hold a bit or address at a value.
    Force(Address, i64),
    /// Release a force.
    Unforce(Address),
    /// Add a probe to the watch list.
    Watch(Probe),
    /// Record (or stop recording) a network's power flow, by code network index.
    WatchNetwork(usize, bool),
    /// Power off and on, PLC and CNC.
    PowerCycle,
    /// Level-2 division.
    Division(u32),
    /// A command to the CNC.
    Cnc(CncCommand),
}

/// The PLC and, when attached, the simulated CNC.
pub struct Machine {
    /// The PLC.
    pub plc: Vm,
    /// The CNC; `None` runs the PLC alone (F keeps what the user writes).
    pub cnc: Option<SimCnc>,
    watches: Vec<Probe>,
    running: bool,
}

/// A copy of a machine's state between ticks.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Snapshot {
    /// Ticks run.
    pub ticks: u64,
    /// Virtual time, ms.
    pub now_ms: u64,
    /// The PLC memory image.
    pub memory: Vec<u8>,
    /// Forced bytes: offset, mask, values.
    pub forces: Vec<(u32, u8, u8)>,
    /// Why the PLC stopped.
    pub halt: Option<Halt>,
    /// Recorded power flow of watched networks (per code word).
    pub trace: Vec<u8>,
    /// Which code networks `trace` covers.
    pub watched: Vec<bool>,
    /// Whether the runner is running.
    pub running: bool,
    /// The CNC's screen.
    pub cnc: Option<CncStatus>,
}

impl Machine {
    /// Compiles a project and builds its machine, with the simulated CNC when `with_cnc`.
    pub fn new(project: &Project, with_cnc: bool) -> Result<Machine, BuildError> {
        let plc = Vm::new(project)?;
        let cnc = with_cnc.then(|| SimCnc::new(project.profile, &project.messages));
        Ok(Machine::from_parts(plc, cnc))
    }

    /// A machine from a PLC and an optional CNC.
    pub fn from_parts(plc: Vm, cnc: Option<SimCnc>) -> Machine {
        Machine {
            plc,
            cnc,
            watches: Vec::new(),
            running: false,
        }
    }

    /// One 8 ms tick: the PLC scan and the exchange with the CNC.
    pub fn tick(&mut self) {
        match &mut self.cnc {
            Some(c) => self.plc.tick(c),
            None => self.plc.tick(&mut NoCnc),
        }
    }

    /// Runs `n` ticks, calling `each` after every one.
    pub fn run_ticks(&mut self, n: u64, mut each: impl FnMut(&Machine)) {
        for _ in 0..n {
            self.tick();
            each(self);
        }
    }

    /// Online edit: `plc` (a newly compiled program) takes over the running PLC's memory,
    /// forces and clock between two ticks, and runs from the next tick on. The CNC is not
    /// touched. On an error nothing changes.
    pub fn swap(&mut self, mut plc: Vm) -> Result<Swapped, SwapError> {
        let swapped = plc.take_over(&self.plc)?;
        self.plc = plc;
        Ok(swapped)
    }

    /// Whether the runner should be ticking.
    pub fn running(&self) -> bool {
        self.running
    }

    /// The watch list.
    pub fn watches(&self) -> &[Probe] {
        &self.watches
    }

    /// Carries out a command. A CNC command that cannot apply now (or any CNC command without
    /// a CNC) says why and changes nothing.
    pub fn apply(&mut self, cmd: &MachineCommand) -> Result<(), String> {
        match cmd {
            MachineCommand::Run => self.running = true,
            MachineCommand::Stop => self.running = false,
            MachineCommand::Tick(n) => self.run_ticks(*n, |_| {}),
            MachineCommand::Write(t, v) => self.plc.write(t.address, t.bytes, *v),
            MachineCommand::WriteReal(a, v) => self.plc.write_real(*a, *v),
            MachineCommand::Force(a, v) => self.plc.force(*a, *v),
            MachineCommand::Unforce(a) => self.plc.unforce(*a),
            MachineCommand::Watch(p) => {
                if !self.watches.contains(p) {
                    self.watches.push(*p);
                }
            }
            MachineCommand::WatchNetwork(n, on) => self.plc.watch(*n, *on),
            MachineCommand::PowerCycle => {
                self.plc.power_cycle();
                if let Some(c) = &mut self.cnc {
                    c.power_cycle();
                    self.plc.clear_area(Area::F);
                }
            }
            MachineCommand::Division(n) => self.plc.set_division(*n),
            MachineCommand::Cnc(c) => match &mut self.cnc {
                Some(cnc) => cnc.apply(c)?,
                None => return Err("no CNC is attached (run with the simulated CNC)".into()),
            },
        }
        Ok(())
    }

    /// Reads a probe.
    pub fn read(&self, probe: &Probe) -> Result<ProbeValue, String> {
        match probe {
            Probe::Memory(t) => Ok(ProbeValue::Int(self.plc.read(t.address, t.bytes))),
            Probe::Cnc(k) => match &self.cnc {
                Some(c) => c.value(k).map(ProbeValue::Cnc),
                None => Err("no CNC is attached".into()),
            },
        }
    }

    /// Copies the state out, reusing the snapshot's buffers.
    pub fn snapshot_into(&self, s: &mut Snapshot) {
        s.ticks = self.plc.ticks();
        s.now_ms = self.plc.now_ms();
        s.memory.clear();
        s.memory.extend_from_slice(self.plc.image());
        s.forces.clear();
        s.forces.extend(self.plc.forces());
        s.halt = self.plc.halt().cloned();
        s.trace.clear();
        s.trace.extend_from_slice(self.plc.trace());
        s.watched.clear();
        s.watched.extend_from_slice(self.plc.watched());
        s.running = self.running;
        s.cnc = self.cnc.as_ref().map(SimCnc::status);
    }

    /// A new snapshot.
    pub fn snapshot(&self) -> Snapshot {
        let mut s = Snapshot::default();
        self.snapshot_into(&mut s);
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_machine_can_be_sent_to_a_thread_and_read_back() {
        fn assert_send<T: Send>() {}
        assert_send::<Machine>();
        assert_send::<Snapshot>();
    }
}
