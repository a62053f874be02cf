//! The machine model in the project: saved only when it exists (schema 4, older files keep
//! their bytes), checked by `check` (M001–M005, W010, W011), and used by scripts (`device`
//! lines, the refusal to `set` a driven input).

use ladder_engine::compiler::Code;
use ladder_engine::compiler::compile;
use ladder_engine::devices::model::{Actuator, Logic};
use ladder_engine::devices::{Device, DeviceKind, MachineModel};
use ladder_engine::machine::{DeviceAction, MachineCommand};
use ladder_engine::model::{PanelItem, PanelKind, Project};
use ladder_engine::sim::{Options, Script, ScriptCommand};
use ladder_engine::{Address, Profile, ProfileId, file};

fn a(t: &str) -> Address {
    Address::parse(t).unwrap()
}

fn follower(name: &str, input: &str, when: &str) -> Device {
    Device {
        name: name.into(),
        kind: DeviceKind::Follower(Logic {
            input: a(input),
            when: when.into(),
            on_ms: 0,
            off_ms: 0,
        }),
    }
}

fn with(devices: Vec<Device>) -> Project {
    Project {
        machine: MachineModel {
            devices,
            start_mm: vec![],
        },
        ..Project::default()
    }
}

fn codes(p: &Project) -> Vec<(Code, usize, String)> {
    compile(p)
        .diagnostics
        .into_iter()
        .filter(|d| d.location.block_label == "MACHINE")
        .map(|d| {
            let message = ladder_text::diagnostics::message(&d, ladder_text::Lang::En);
            (d.code, d.location.network, message)
        })
        .collect()
}

#[test]
fn a_project_without_a_machine_saves_as_before_and_one_with_it_as_version_4() {
    let p = Project::default();
    let text = file::to_string(&p);
    assert!(text.starts_with("LADDER-STUDIO-PROJECT v3 "), "{text}");
    assert!(!text.contains("machine"));
    let p = with(vec![follower("ready", "X0001.5", "1")]);
    let text = file::to_string(&p);
    assert!(text.starts_with("LADDER-STUDIO-PROJECT v4 "));
    assert_eq!(file::from_bytes(text.as_bytes()).unwrap(), p);
    // A version-3 header over a body with a machine: the header was changed.
    let body = text.split_once('\n').unwrap().1.trim_end_matches('\n');
    let mut h = crc32fast::Hasher::new();
    let header = "LADDER-STUDIO-PROJECT v3 crc32=";
    h.update(header.as_bytes());
    h.update(b"\n");
    h.update(body.as_bytes());
    h.update(b"\n");
    let forged = format!("{header}{:08x}\n{body}\n", h.finalize());
    let e = file::from_bytes(forged.as_bytes()).unwrap_err().to_string();
    assert!(e.contains("version 4 introduced"), "{e}");
}

#[test]
fn check_reports_each_machine_problem_with_its_code_and_device() {
    let mut chuck = Actuator {
        advance: a("Y0000.6"),
        retract: None,
        travel_ms: 0,
        at_advanced: Some(a("X0001.6")),
        at_retracted: None,
        moving: None,
        start_advanced: false,
    };
    let p = with(vec![
        follower("R10", "X0001.0", "1"),
        follower("ok", "X0001.1", "Y0000.1 &"),
        follower("ok", "X0001.2", "1"),
        follower("bad_input", "Y0001.0", "1"),
        Device {
            name: "chuck".into(),
            kind: DeviceKind::Actuator(chuck.clone()),
        },
        follower("twice", "X0001.6", "1"),
        follower("range", "X0200.0", "1"),
    ]);
    let found = codes(&p);
    let has = |code: Code, device: usize, text: &str| {
        assert!(
            found
                .iter()
                .any(|(c, d, m)| *c == code && *d == device && m.contains(text)),
            "{code:?} at device {device} with `{text}` in {found:#?}"
        );
    };
    has(Code::M001DeviceName, 0, "`R10` is not valid");
    has(Code::M004DeviceCondition, 1, "the condition ends");
    has(Code::M001DeviceName, 2, "taken by device 2");
    has(Code::M002DeviceAddress, 3, "not an input");
    has(Code::M003DeviceParameter, 4, "travel_ms");
    has(Code::M005InputTwice, 5, "both write X0001.6");
    has(Code::M002DeviceAddress, 6, "out of range");
    assert!(compile(&p).errors() > 0);

    // Warnings need the program: a device reading an output nothing writes, and a panel
    // item driving a device's input.
    chuck.travel_ms = 300;
    let mut p = with(vec![Device {
        name: "chuck".into(),
        kind: DeviceKind::Actuator(chuck),
    }]);
    p.panel.items.push(PanelItem::new(
        "卡盘夹紧到位",
        "Chuck clamped",
        PanelKind::Switch {
            input: a("X0001.6"),
        },
        0,
        0,
    ));
    let found = codes(&p);
    assert!(
        found
            .iter()
            .any(|(c, _, m)| *c == Code::W010DeviceReadsNothing && m.contains("Y0000.6")),
        "{found:#?}"
    );
    assert!(
        found
            .iter()
            .any(|(c, _, m)| *c == Code::W011PanelDrivesDeviceInput && m.contains("X0001.6")),
        "{found:#?}"
    );
    assert_eq!(compile(&p).errors(), 0);
}

fn parse(text: &str, machine: Option<&MachineModel>) -> Result<Script, String> {
    Script::parse_with(
        text,
        Profile::get(ProfileId::Gsk988ta),
        &Options {
            cnc: true,
            read_file: &|p| Err(format!("no {p}")),
            machine,
            project: None,
        },
    )
    .map_err(|e| {
        format!(
            "{}: {}",
            e.line,
            ladder_text::script::script_error(&e, ladder_text::Lang::En)
        )
    })
}

#[test]
fn scripts_name_devices_and_may_not_set_what_a_device_drives() {
    let p = with(vec![follower("ready", "X0001.5", "1")]);
    let m = Some(&p.machine);
    let e = parse("scan\nset X0001.5 1", m).unwrap_err();
    assert!(
        e.starts_with("2: ") && e.contains("driven by device `ready`"),
        "{e}"
    );
    assert!(
        e.contains("force X0001.5") && e.contains("--no-machine"),
        "{e}"
    );
    assert!(
        parse("set X0001 32", m).is_err(),
        "a byte over a driven bit"
    );
    assert!(parse("set X0001.4 1\nforce X0001.5 0", m).is_ok());
    assert!(parse("set X0001.5 1", None).is_ok(), "--no-machine");
    let s = parse(
        "device ready fault stuck 0 X0001.5\ndevice READY fault slow 2.5\ndevice ready ok\nexpect device.ready 1",
        m,
    )
    .unwrap();
    assert!(matches!(
        s.commands[0].1,
        ScriptCommand::Do(MachineCommand::Device(0, DeviceAction::Fault(_)))
    ));
    assert_eq!(s.commands[3].1, ScriptCommand::ExpectDevice(0, 1));
    for (line, want) in [
        (
            "device chuck ok",
            "no device is named `chuck` (devices: ready)",
        ),
        ("device ready fault stuck 2", "0 or 1"),
        (
            "device ready fault stuck 1 X0001.4",
            "does not write X0001.4",
        ),
        ("device ready fault slow 0", "0.1…1000"),
        ("device ready fault melt", "usage: device NAME"),
        ("device ready", "usage: device NAME"),
    ] {
        let e = parse(line, m).unwrap_err();
        assert!(e.contains(want), "{line}: {e}");
    }
    let e = parse("device ready ok", None).unwrap_err();
    assert!(e.contains("--no-machine"), "{e}");
}

#[test]
fn a_force_wins_over_a_device_and_a_new_model_keeps_the_faults_by_name() {
    use ladder_engine::devices::Fault;
    use ladder_engine::machine::Machine;
    let mut p = ladder_engine::il::import("LEVEL1\nNETWORK\nLD X0001.5\nOUT Y0001.0\n")
        .project
        .expect("valid IL");
    p.machine.devices = vec![follower("ready", "X0001.5", "1")];
    let mut m = Machine::new(&p, false).expect("it compiles");
    let y = a("Y0001.0");
    m.tick();
    assert_eq!(
        m.plc().read(y, 1),
        1,
        "the device answers in the first tick"
    );
    m.apply(&MachineCommand::Force(a("X0001.5"), 0)).unwrap();
    m.tick();
    assert_eq!(m.plc().read(y, 1), 0, "the force wins");
    m.apply(&MachineCommand::Unforce(a("X0001.5"))).unwrap();
    m.tick();
    assert_eq!(m.plc().read(y, 1), 1);
    // A fault, then the model edited online: the device keeps its fault.
    let stuck = Fault::Stuck {
        value: false,
        input: None,
    };
    m.apply(&MachineCommand::Device(0, DeviceAction::Fault(stuck)))
        .unwrap();
    m.tick();
    assert_eq!(m.plc().read(y, 1), 0);
    let mut edited = p.machine.clone();
    edited.devices.insert(0, follower("other", "X0002.0", "0"));
    m.apply(&MachineCommand::LoadModel(Box::new(edited)))
        .unwrap();
    m.tick();
    assert_eq!(m.plc().read(y, 1), 0, "still stuck after the edit");
    assert_eq!(m.snapshot().devices[1].fault, Some(stuck));
    m.apply(&MachineCommand::Device(1, DeviceAction::Ok))
        .unwrap();
    m.tick();
    assert_eq!(m.plc().read(y, 1), 1);
    // Without the model the input keeps what is written.
    let mut bare = Machine::new(&p, false).unwrap().without_devices();
    bare.tick();
    assert_eq!(bare.plc().read(y, 1), 0);
    assert_eq!(
        bare.apply(&MachineCommand::Device(0, DeviceAction::Ok)),
        Err(ladder_engine::refusal::Refusal::NoMachineModel)
    );
}

#[test]
fn every_field_of_every_kind_reads_back_and_a_wrong_text_is_refused_in_both_languages() {
    use ladder_engine::devices::fields;
    let profile = Profile::get(ProfileId::Gsk988ta);
    for kind in DeviceKind::templates() {
        let fs = fields::fields(&kind);
        assert!(!fs.is_empty());
        let mut copy = kind.clone();
        for f in &fs {
            fields::set(&mut copy, f.name, &f.text, profile)
                .unwrap_or_else(|e| panic!("{} {}: {e:?}", kind.name(), f.name));
        }
        assert_eq!(copy, kind, "{}", kind.name());
    }
    let mut chuck = DeviceKind::templates().remove(1);
    let said = |e: &fields::FieldError, lang| ladder_text::errors::field_error(e, lang);
    let e = fields::set(&mut chuck, "at_advanced", "Y0001.6", profile).unwrap_err();
    assert!(
        said(&e, ladder_text::Lang::En).contains("not an input")
            && said(&e, ladder_text::Lang::Zh).contains("不是输入"),
        "{e:?}"
    );
    let e = fields::set(&mut chuck, "travel_ms", "0", profile).unwrap_err();
    assert!(
        said(&e, ladder_text::Lang::En).contains("1…600000"),
        "{e:?}"
    );
    fields::set(&mut chuck, "retract", "", profile).unwrap();
    fields::set(&mut chuck, "moving", "x2.0", profile).unwrap();
    match &chuck {
        DeviceKind::Actuator(a) => {
            assert_eq!(a.retract, None);
            assert_eq!(a.moving, Some(Address::parse("X0002.0").unwrap()));
        }
        _ => unreachable!(),
    }
    // The turret's lock stage appears with its unlock output and goes with it.
    let mut turret = DeviceKind::templates().remove(2);
    fields::set(&mut turret, "lock.unlock", "Y0001.0", profile).unwrap();
    assert!(fields::fields(&turret).iter().any(|f| f.name == "lock.ms"));
    fields::set(&mut turret, "lock.unlock", "", profile).unwrap();
    assert!(!fields::fields(&turret).iter().any(|f| f.name == "lock.ms"));
    let e = fields::set(&mut turret, "code.encoding", "Octal", profile).unwrap_err();
    assert!(said(&e, ladder_text::Lang::En).contains("OneHot"), "{e:?}");
}

#[test]
fn fault_lines_keep_their_bounds_and_a_device_may_read_the_cnc_s_signals() {
    let p = with(vec![follower("ready", "X0001.5", "F0000.7 & !K0000.1")]);
    let m = Some(&p.machine);
    for (line, want) in [
        ("device ready fault slow 0.01", "0.1…1000"),
        ("device ready fault flicker 8", "at least 16 ms"),
        ("device ready fault stuck 2", "`2` is not 0 or 1"),
    ] {
        let e = parse(line, m).unwrap_err();
        assert!(e.contains(want), "{line}: {e}");
    }
    assert!(
        parse(
            "device ready fault slow 0.5\ndevice ready fault flicker 16",
            m
        )
        .is_ok()
    );
    // F is the CNC's, K the data tables': no W010 for them.
    assert!(codes(&p).is_empty(), "{:?}", codes(&p));
}
