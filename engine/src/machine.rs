//! A machine: the PLC and the simulated CNC owned and ticked together, the one value the
//! command line and the editor run. What a user does to a running machine is a
//! [`MachineCommand`]; stimulus scripts are lists of them, so a script and the editor can
//! never drift apart. [`Snapshot`] is what a monitor copies out between ticks.

pub use crate::address::Target;
use crate::address::{Address, Area};
use crate::cnc::command::{CncCommand, CncError, CncKey, CncValue};
use crate::cnc::{CncStatus, SimCnc};
use crate::devices::{DeviceStatus, Fault, MachineModel, ModelError, Plant};
use crate::model::Project;
use crate::refusal::Refusal;
use crate::vm::cnc::NoCnc;
use crate::vm::swap::{SwapError, Swapped};
use crate::vm::{BuildError, Halt, Vm};
use std::fmt;

mod scenarios;

/// Something a monitor or a script reads each tick: PLC memory or a CNC value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Probe {
    /// A PLC address.
    Memory(Target),
    /// A `cnc.KEY` value.
    Cnc(CncKey),
    /// A device's main value (`device.NAME`, docs/machine.md, "Values"), by its index.
    Device(usize),
}

impl Probe {
    /// How it is named in output and trace headers.
    pub fn text(&self) -> String {
        match self {
            Probe::Memory(t) => t.text(),
            Probe::Cnc(k) => k.text(),
            Probe::Device(i) => format!("device.{i}"),
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
    /// Write the inverse of a bit's value as the machine holds it when the command runs (the
    /// editor's toggle: a value read from an older snapshot could write the wrong way).
    Invert(Address),
    /// Release a bit's force if it is forced, else force it to the inverse of its value, both
    /// decided by the machine when the command runs, so quick presses never act on a stale
    /// state.
    ToggleForce(Address),
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
    /// Something done to a device of the machine model, by its index.
    Device(usize, DeviceAction),
    /// The machine model replaced (edited online): unchanged devices keep their state, every
    /// device its fault, by name.
    LoadModel(Box<MachineModel>),
    /// Apply a saved scenario (docs/scenarios.md), remembering how to undo each action.
    Scenario(Box<crate::scenario::Applied>),
    /// Release an applied scenario, by name: what it changed goes back as it was.
    Release(String),
}

/// What a user does to one device of the machine model.
#[derive(Clone, Debug, PartialEq)]
pub enum DeviceAction {
    /// Inject a fault.
    Fault(Fault),
    /// Clear its fault.
    Ok,
    /// Back to its power-on state (a refilled lubricator, a reset counter).
    Reset,
}

/// The PLC and, when attached, the simulated CNC.
pub struct Machine {
    /// The PLC.
    plc: Vm,
    /// The CNC; `None` runs the PLC alone (F keeps what the user writes).
    cnc: Option<SimCnc>,
    /// The machine model; `None` runs without one (inputs keep what the user writes).
    plant: Option<Plant>,
    watches: Vec<Probe>,
    running: bool,
    /// The scenarios applied, oldest first, each with its undo list.
    applied: Vec<(String, Vec<crate::scenario::Undo>)>,
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
    /// The machine model's devices.
    pub devices: Vec<DeviceStatus>,
    /// The scan time in steps: the last tick's and the most since power-on.
    pub tick_steps: (u64, u64),
    /// Every forced address: the bits of byte areas one by one (a whole forced byte as the
    /// byte), 4-byte values whole.
    pub forced: Vec<Address>,
    /// The saved scenarios applied now, by name, oldest first.
    pub scenarios: Vec<String>,
}

impl Machine {
    /// Compiles a project and builds its machine, with the simulated CNC when `with_cnc`
    /// and the project's machine model when it has one.
    pub fn new(project: &Project, with_cnc: bool) -> Result<Machine, BuildError> {
        let compiled = crate::compiler::compile(project);
        if compiled.errors() > 0 {
            return Err(crate::vm::code::LowerError::CompileErrors(
                compiled.errors(),
            ));
        }
        Machine::from_program(project, &compiled.program, with_cnc)
    }

    /// The one way a machine is built (the CLI, scripts, the editor online): `program`, an
    /// error-free compilation of `project` (or a list run as written, with a default
    /// project), on a PLC with the project's level-2 division and data tables, the simulated
    /// CNC with its messages when `with_cnc`, and the project's machine model.
    pub fn from_program(
        project: &Project,
        program: &crate::compiler::Program,
        with_cnc: bool,
    ) -> Result<Machine, BuildError> {
        let mut plc = Vm::from_program(program, project.profile())?;
        plc.set_division(project.level2_division);
        plc.load_data_tables(project);
        let cnc = with_cnc.then(|| SimCnc::new(project.profile, &project.messages));
        let mut m = Machine::from_parts(plc, cnc);
        // The compiler's check refuses a model with errors; a list run as written has none.
        m.load_model(&project.machine)
            .map_err(crate::vm::code::LowerError::Model)?;
        Ok(m)
    }

    /// The PLC, to read.
    pub fn plc(&self) -> &Vm {
        &self.plc
    }

    /// The PLC, to write memory, force and step (scripts, tests, the runner).
    pub fn plc_mut(&mut self) -> &mut Vm {
        &mut self.plc
    }

    /// The simulated CNC, if attached.
    pub fn cnc(&self) -> Option<&SimCnc> {
        self.cnc.as_ref()
    }

    /// The simulated CNC, to command directly (a script's own CNC actions, tests).
    pub fn cnc_mut(&mut self) -> Option<&mut SimCnc> {
        self.cnc.as_mut()
    }

    /// The PLC and the CNC at once, to tick one against the other by hand (the bench's
    /// timed exchange).
    pub fn parts_mut(&mut self) -> (&mut Vm, Option<&mut SimCnc>) {
        (&mut self.plc, self.cnc.as_mut())
    }

    /// The machine without its model (`sim --no-machine`): inputs keep what is written.
    pub fn without_devices(mut self) -> Machine {
        self.plant = None;
        self
    }

    /// The machine model running, if any.
    pub fn plant(&self) -> Option<&Plant> {
        self.plant.as_ref()
    }

    /// Replaces the machine model (an online edit): the axes stay where they are, and each
    /// device keeps its state when its definition did not change, its fault in any case
    /// ([`Plant::take_over`]).
    pub fn load_model(&mut self, model: &MachineModel) -> Result<(), ModelError> {
        if model.devices.is_empty() {
            self.plant = None;
            return Ok(());
        }
        let mut plant = Plant::new(model, self.plc.profile())?;
        if let Some(old) = &self.plant {
            plant.take_over(old);
        }
        self.plant = Some(plant);
        Ok(())
    }

    /// A machine from a PLC and an optional CNC.
    pub fn from_parts(plc: Vm, cnc: Option<SimCnc>) -> Machine {
        Machine {
            plc,
            cnc,
            plant: None,
            watches: Vec::new(),
            running: false,
            applied: Vec::new(),
        }
    }

    /// One 8 ms tick: the machine model's devices, then the PLC scan and the exchange with
    /// the CNC (docs/machine.md, "When devices run").
    pub fn tick(&mut self) {
        if let Some(p) = &mut self.plant {
            p.step(self.plc.image_mut(), self.cnc.as_ref());
        }
        match &mut self.cnc {
            Some(c) => self.plc.tick(c),
            None => self.plc.tick(&mut NoCnc),
        }
    }

    /// Steps the machine model alone, as a tick does before the scan (for `bench`).
    pub fn step_devices(&mut self) {
        if let Some(p) = &mut self.plant {
            p.step(self.plc.image_mut(), self.cnc.as_ref());
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

    /// How a probe is named in output and trace headers: `device.NAME` for a device.
    pub fn probe_name(&self, p: &Probe) -> String {
        match (p, &self.plant) {
            (Probe::Device(i), Some(plant)) => match plant.names().nth(*i) {
                Some(n) => format!("device.{n}"),
                None => p.text(),
            },
            _ => p.text(),
        }
    }

    /// The watch list.
    pub fn watches(&self) -> &[Probe] {
        &self.watches
    }

    /// Carries out a command. A CNC command that cannot apply now (or any CNC command without
    /// a CNC) says why and changes nothing.
    pub fn apply(&mut self, cmd: &MachineCommand) -> Result<(), Refusal> {
        match cmd {
            MachineCommand::Run => self.running = true,
            MachineCommand::Stop => self.running = false,
            MachineCommand::Tick(n) => self.run_ticks(*n, |_| {}),
            MachineCommand::Write(t, v) => self.plc.write(t.address, t.bytes, *v),
            MachineCommand::WriteReal(a, v) => self.plc.write_real(*a, *v),
            MachineCommand::Force(a, v) => self.plc.force(*a, *v),
            MachineCommand::Unforce(a) => self.plc.unforce(*a),
            MachineCommand::Invert(a) => {
                let v = self.plc.read(*a, 1);
                self.plc.write(*a, 1, i64::from(v == 0));
            }
            MachineCommand::ToggleForce(a) => {
                if self.plc.is_forced(*a) {
                    self.plc.unforce(*a);
                } else {
                    let v = self.plc.read(*a, 1);
                    self.plc.force(*a, i64::from(v == 0));
                }
            }
            MachineCommand::Watch(p) => {
                if !self.watches.contains(p) {
                    self.watches.push(*p);
                }
            }
            MachineCommand::WatchNetwork(n, on) => self.plc.watch(*n, *on),
            MachineCommand::PowerCycle => {
                if let Some(p) = &mut self.plant {
                    p.power_cycle();
                }
                self.plc.power_cycle();
                if let Some(c) = &mut self.cnc {
                    c.power_cycle();
                    self.plc.clear_area(Area::F);
                }
            }
            MachineCommand::Division(n) => self.plc.set_division(*n),
            MachineCommand::Cnc(c) => match &mut self.cnc {
                Some(cnc) => cnc.apply(c)?,
                None => {
                    return Err(Refusal::NoCnc);
                }
            },
            MachineCommand::Device(i, action) => {
                let Some(p) = &mut self.plant else {
                    return Err(Refusal::NoMachineModel);
                };
                if *i >= p.names().count() {
                    return Err(Refusal::NoDevice(*i));
                }
                match action {
                    DeviceAction::Fault(f) => p.set_fault(*i, Some(*f)),
                    DeviceAction::Ok => p.set_fault(*i, None),
                    DeviceAction::Reset => p.reset(*i),
                }
            }
            MachineCommand::LoadModel(model) => self.load_model(model).map_err(Refusal::Model)?,
            MachineCommand::Scenario(applied) => self.apply_scenario(applied)?,
            MachineCommand::Release(name) => self.release_scenario(name)?,
        }
        Ok(())
    }

    /// Reads a probe. A CNC value can be refused (an axis beyond #8130), as can a probe of
    /// a part the machine runs without; the refusal reads in either language.
    pub fn read(&self, probe: &Probe) -> Result<ProbeValue, CncError> {
        match probe {
            Probe::Memory(t) => Ok(ProbeValue::Int(self.plc.read(t.address, t.bytes))),
            Probe::Cnc(k) => match &self.cnc {
                Some(c) => c.value(k).map(ProbeValue::Cnc),
                None => Err(CncError::NoCnc),
            },
            Probe::Device(i) => self
                .plant
                .as_ref()
                .and_then(|p| p.value(*i))
                .map(ProbeValue::Int)
                .ok_or(CncError::NoMachineModel),
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
        s.forced.clear();
        let layout = self.plc.layout();
        for &(off, mask, _) in &s.forces {
            let Some(whole) = layout.address_at(off, None) else {
                continue;
            };
            if whole.area.element_bytes() == 4 || mask == 0xFF {
                if !s.forced.contains(&whole) {
                    s.forced.push(whole);
                }
            } else {
                s.forced.extend(
                    (0..8)
                        .filter(|b| mask >> b & 1 == 1)
                        .filter_map(|b| layout.address_at(off, Some(b))),
                );
            }
        }
        s.halt = self.plc.halt().cloned();
        s.trace.clear();
        s.trace.extend_from_slice(self.plc.trace());
        s.watched.clear();
        s.watched.extend_from_slice(self.plc.watched());
        s.running = self.running;
        s.tick_steps = self.plc.tick_steps();
        s.cnc = self.cnc.as_ref().map(SimCnc::status);
        match &self.plant {
            Some(p) => p.status_into(&mut s.devices),
            None => s.devices.clear(),
        }
        // Compared, not rebuilt: the list changes only when a scenario is applied or released.
        if !s
            .scenarios
            .iter()
            .map(String::as_str)
            .eq(self.applied_scenarios())
        {
            s.scenarios = self.applied_scenarios().map(String::from).collect();
        }
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
