//! The operator panel driven as an operator and an editor drive it: keys held and let go,
//! lamps read, switches and knobs turned, items edited and refused.

use super::*;
use egui::accesskit::Toggled;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use ladder_engine::{Area, ProfileId};
use std::collections::HashMap;

/// What the harness shows: the panel, the memory it reads, the widget's state and every
/// event so far.
struct Shown {
    panel: Panel,
    memory: HashMap<Address, i64>,
    state: PanelViewState,
    events: Vec<PanelEvent>,
}

fn harness(memory: &[(Address, i64)]) -> Harness<'static, Shown> {
    let shown = Shown {
        panel: Panel::preset_988ta(),
        memory: memory.iter().copied().collect(),
        state: PanelViewState::default(),
        events: Vec::new(),
    };
    let mut h = Harness::builder()
        .with_size(egui::vec2(1000.0, 700.0))
        .build_ui_state(
            |ui, s: &mut Shown| {
                let memory = |a: Address| s.memory.get(&a).copied().unwrap_or(0);
                let profile = Profile::get(ProfileId::Gsk988ta);
                let ev = panel_ui(ui, &s.panel, &memory, profile, Lang::En, &mut s.state);
                s.events.extend(ev);
            },
            shown,
        );
    // The form shows the Chinese labels too.
    crate::gui::fonts::install(&h.ctx);
    h.run();
    h
}

fn x(n: u16, b: u8) -> Address {
    Address::bit(Area::X, n, b)
}

fn toggled(h: &Harness<'static, Shown>, label: &str) -> Option<Toggled> {
    h.get_by_label(label).accesskit_node().toggled()
}

#[test]
fn clicking_the_jog_key_presses_and_releases_its_input() {
    let mut h = harness(&[]);
    h.get_by_label("JOG").click();
    h.run();
    assert_eq!(
        h.state().events,
        [PanelEvent::Press(x(2, 3)), PanelEvent::Release(x(2, 3))]
    );
    h.run();
    assert_eq!(
        h.state().events.len(),
        2,
        "one click, one press and release"
    );
}

#[test]
fn a_key_held_down_is_pressed_once_and_released_when_let_go() {
    let mut h = harness(&[]);
    let at = h.get_by_label("X+").rect().center();
    let button = |pressed| egui::Event::PointerButton {
        pos: at,
        button: egui::PointerButton::Primary,
        pressed,
        modifiers: egui::Modifiers::default(),
    };
    h.hover_at(at);
    h.event(button(true));
    h.run();
    assert_eq!(h.state().events, [PanelEvent::Press(x(4, 0))]);
    // Held for longer than any click lasts: two seconds of frames.
    h.run_steps(120);
    assert_eq!(h.state().events.len(), 1, "held, not pressed again");
    h.event(button(false));
    h.run();
    assert_eq!(
        h.state().events,
        [PanelEvent::Press(x(4, 0)), PanelEvent::Release(x(4, 0))]
    );
}

#[test]
fn a_key_held_when_the_edit_mode_opens_is_released() {
    let mut h = harness(&[]);
    let at = h.get_by_label("X-").rect().center();
    h.hover_at(at);
    h.event(egui::Event::PointerButton {
        pos: at,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: egui::Modifiers::default(),
    });
    h.run();
    h.state_mut().state.editing = true;
    h.run();
    assert_eq!(
        h.state().events,
        [PanelEvent::Press(x(4, 1)), PanelEvent::Release(x(4, 1))]
    );
}

#[test]
fn a_lamp_is_lit_by_its_bit_and_a_lamp_key_by_its_lamp() {
    let y = |n, b| Address::bit(Area::Y, n, b);
    let h = harness(&[(y(2, 4), 1), (y(1, 3), 1)]);
    assert_eq!(toggled(&h, "X ref done"), Some(Toggled::True));
    assert_eq!(toggled(&h, "Z ref done"), Some(Toggled::False));
    assert_eq!(toggled(&h, "JOG"), Some(Toggled::True), "the JOG lamp Y1.3");
    assert_eq!(toggled(&h, "AUTO"), Some(Toggled::False));
}

#[test]
fn a_switch_flips_its_bit_and_a_knob_keeps_the_bits_it_does_not_own() {
    // X5 = 0x1f: feed override at 100 % (Gray 1111) and rapid override at 50 % (X5.4).
    let feed = Address::byte(Area::X, 5);
    let mut h = harness(&[(x(0, 5), 1), (feed, 0x1f)]);
    assert_eq!(toggled(&h, "E-stop (NC)"), Some(Toggled::True));
    h.get_by_label("E-stop (NC)").click();
    h.run();
    assert_eq!(h.state().events, [PanelEvent::Set(x(0, 5), 0)]);
    let combo = h.get_by_role_and_label(Role::ComboBox, "Feed override");
    assert_eq!(combo.value().as_deref(), Some("100%"));
    combo.click();
    h.run();
    h.get_by_label("150%").click();
    h.run();
    assert_eq!(
        h.state().events[1..],
        [PanelEvent::Set(feed, 0x18)],
        "Gray 1000 with X5.4 kept"
    );
}

#[test]
fn the_edit_mode_refuses_bad_addresses_and_returns_the_edited_panel() {
    let mut h = harness(&[]);
    h.get_by_label("Edit panel").click();
    h.run();
    h.get_by_label("JOG").click();
    h.run();
    fn input<'h>(h: &'h Harness<'static, Shown>) -> egui_kittest::Node<'h> {
        h.get_by_role_and_label(Role::TextInput, "Input address")
    }
    input(&h).click();
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    input(&h).type_text("Y9.1");
    h.run();
    h.get_by_label("Apply").click();
    h.run();
    assert!(h.state().events.is_empty(), "{:?}", h.state().events);
    h.get_by_label_contains("is not a machine input");
    input(&h).click();
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    input(&h).type_text("x9.0");
    h.run();
    h.get_by_label("Apply").click();
    h.run();
    let [PanelEvent::Edited(p)] = &h.state().events[..] else {
        panic!("{:?}", h.state().events);
    };
    let jog = p.items.iter().find(|i| i.label_en == "JOG").unwrap();
    assert_eq!(jog.kind.input(), Some(x(9, 0)));
    assert_eq!(p.items.len(), Panel::preset_988ta().items.len());

    h.get_by_label("Reset to the preset (GSK988TA)").click();
    h.run();
    assert_eq!(
        h.state().events.last(),
        Some(&PanelEvent::Edited(Panel::default()))
    );
}

#[test]
fn a_new_item_on_a_taken_input_is_refused_with_the_other_item_named() {
    let mut h = harness(&[]);
    h.get_by_label("Edit panel").click();
    h.run();
    h.get_by_label("Add item").click();
    h.run();
    for (field, text) in [("English label", "Second JOG"), ("Input address", "X2.3")] {
        h.get_by_role_and_label(Role::TextInput, field).click();
        h.run();
        h.get_by_role_and_label(Role::TextInput, field)
            .type_text(text);
        h.run();
    }
    h.get_by_label("Apply").click();
    h.run();
    assert!(h.state().events.is_empty());
    h.get_by_label_contains("X0002.3 is already driven by item 6 `JOG`");
}

#[test]
fn positions_are_read_from_name_value_pairs() {
    assert_eq!(
        parse_positions("0%=0; 100% = 15 ;"),
        Some(vec![("0%".into(), 0), ("100%".into(), 15)])
    );
    assert_eq!(parse_positions("low"), None);
    assert_eq!(parse_positions("a=b"), None);
}
