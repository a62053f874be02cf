//! Printing in the editor driven headless: the preview opens on the sample and its pages turn,
//! Ctrl+P sends one PDF to the (scripted) print queue, and without a queue the PDF is saved
//! where the user says (docs/printing.md, "In the editor").

use crate::common::*;
use egui::{Key, Modifiers};
use ladder_studio::gui::printing::{PrintState, ScriptedQueue};

fn on_sample() -> Harness<'static, LadderApp> {
    let dir = tempfile_dir();
    let path = dir.join("lathe-988ta.ldp");
    std::fs::copy(
        concat!(env!("CARGO_MANIFEST_DIR"), "/../projects/lathe-988ta.ldp"),
        &path,
    )
    .unwrap();
    let mut h = harness(Some(path), Lang::En);
    h.run();
    h
}

fn queue(h: &mut Harness<'static, LadderApp>, present: bool) -> ScriptedQueue {
    let q = ScriptedQueue {
        present,
        ..ScriptedQueue::default()
    };
    h.state_mut()
        .with(|f: &mut PrintState, _| f.queue = Box::new(q.clone()));
    q
}

fn output(h: &Harness<'static, LadderApp>) -> String {
    h.state()
        .output()
        .iter()
        .map(|l| l.text.clone())
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn the_preview_opens_on_the_sample_and_its_pages_turn() {
    let mut h = on_sample();
    h.get_by_label("File").click();
    h.run();
    h.get_by_label("Print preview").click();
    h.run();
    let total = h
        .state()
        .feature::<PrintState>()
        .preview
        .as_ref()
        .expect("the preview is open")
        .doc
        .pages
        .len();
    assert!(total > 3, "{total} pages");
    h.get_by_label(&format!("Page 1/{total}"));
    h.get_by_label("▶").click();
    h.run();
    h.get_by_label(&format!("Page 2/{total}"));
    h.get_by_label("▶").click();
    h.run();
    h.get_by_label("◀").click();
    h.run();
    assert_eq!(
        h.state()
            .feature::<PrintState>()
            .preview
            .as_ref()
            .unwrap()
            .page,
        1
    );
    // It opened at fit width; zoom in: the page is drawn larger and fit width is off.
    let fitted = h
        .state()
        .feature::<PrintState>()
        .preview
        .as_ref()
        .unwrap()
        .zoom;
    assert!(
        h.state()
            .feature::<PrintState>()
            .preview
            .as_ref()
            .unwrap()
            .fit
    );
    h.get_by_label("+").click();
    h.run();
    let p = h.state().feature::<PrintState>().preview.as_ref().unwrap();
    assert!(p.zoom > fitted && !p.fit, "{} after {fitted}", p.zoom);
}

#[test]
fn the_preview_opens_at_fit_width() {
    let mut h = on_sample();
    h.state_mut()
        .ask(ladder_studio::gui::command::Command::PrintPreview);
    h.run();
    h.run();
    let p = h.state().feature::<PrintState>().preview.as_ref().unwrap();
    // An A4 page (595 pt) in a preview window about 760 px wide: more than 100 %.
    assert!(p.fit && (100..=140).contains(&p.zoom), "{}", p.zoom);
}

#[test]
fn the_printer_is_chosen_from_the_queue_list_with_the_default_preselected() {
    use ladder_studio::gui::printing::Printers;
    let mut h = on_sample();
    let q = ScriptedQueue {
        present: true,
        printers: Printers {
            names: vec!["office".into(), "shop-floor".into()],
            default: Some("shop-floor".into()),
        },
        ..ScriptedQueue::default()
    };
    h.state_mut()
        .with(|f: &mut PrintState, _| f.queue = Box::new(q.clone()));
    h.state_mut()
        .ask(ladder_studio::gui::command::Command::PageSetup);
    h.run();
    h.run();
    assert_eq!(
        h.state()
            .feature::<PrintState>()
            .chosen_printer(h.state().settings())
            .as_deref(),
        Some("shop-floor")
    );
    h.get_by_role_and_label(egui::accesskit::Role::ComboBox, "Printer")
        .click();
    h.run();
    assert!(h.query_by_label("shop-floor (default)").is_some());
    h.get_by_label("office").click();
    h.run();
    assert_eq!(
        h.state().settings().page_setup.printer.as_deref(),
        Some("office"),
        "kept in the settings"
    );
    h.key_press_modifiers(Modifiers::COMMAND, Key::P);
    h.run();
    let jobs = q.jobs.lock().unwrap();
    assert_eq!(jobs[0].1.as_deref(), Some("office"));
}

#[test]
fn a_network_range_in_the_page_setup_prints_those_networks() {
    let mut h = on_sample();
    h.state_mut().settings_mut().page_setup.networks = "LEVEL2:3-5".into();
    let doc = h
        .state_mut()
        .with_context(|cx| PrintState::document(cx))
        .unwrap();
    let titles: Vec<String> = doc
        .pages
        .iter()
        .flat_map(|p| p.texts())
        .filter(|t| t.starts_with("N0") && t.len() >= 5)
        .map(|t| t[..5].to_string())
        .collect();
    assert_eq!(titles, ["N0003", "N0004", "N0005"]);
}

#[test]
fn without_a_queue_the_preview_says_so() {
    let mut h = on_sample();
    queue(&mut h, false);
    scripted(&mut h, vec![None]);
    h.state_mut()
        .ask(ladder_studio::gui::command::Command::PrintPreview);
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::P);
    h.run();
    h.run();
    assert!(
        h.state().feature::<PrintState>().preview.is_some(),
        "the preview stays open"
    );
    assert_eq!(
        h.query_all_by_label_contains("no print queue").count(),
        2,
        "the notice is in the preview, not only in the output behind it"
    );
}

#[test]
fn ctrl_p_sends_one_pdf_to_the_print_queue() {
    let mut h = on_sample();
    let q = queue(&mut h, true);
    h.key_press_modifiers(Modifiers::COMMAND, Key::P);
    h.run();
    let jobs = q.jobs.lock().unwrap();
    assert_eq!(jobs.len(), 1, "one job");
    assert!(jobs[0].0.starts_with(b"%PDF-"), "a PDF");
    let out = output(&h);
    assert!(
        out.contains("Sent to the print queue") && out.contains("scripted-1"),
        "{out}"
    );
}

#[test]
fn without_a_print_queue_the_pdf_is_saved_where_the_user_says() {
    let mut h = on_sample();
    let q = queue(&mut h, false);
    let target = tempfile_dir().join("printed.pdf");
    scripted(&mut h, vec![Some(target.clone())]);
    h.key_press_modifiers(Modifiers::COMMAND, Key::P);
    h.run();
    h.run();
    assert!(q.jobs.lock().unwrap().is_empty());
    let bytes = std::fs::read(&target).expect("the PDF is saved");
    assert!(bytes.starts_with(b"%PDF-"));
    let out = output(&h);
    assert!(
        out.contains("no print queue") && out.contains("printed.pdf"),
        "{out}"
    );
}

#[test]
fn the_selected_networks_alone_print_when_asked() {
    let mut h = on_sample();
    let all = h
        .state_mut()
        .with_context(|cx| PrintState::document(cx))
        .unwrap()
        .pages
        .len();
    {
        let app = h.state_mut();
        app.settings_mut().page_setup.selection_only = true;
        app.settings_mut().page_setup.tables = false;
    }
    let one = h
        .state_mut()
        .with_context(|cx| PrintState::document(cx))
        .unwrap();
    assert!(one.pages.len() < all, "{} against {all}", one.pages.len());
    let titles: Vec<&str> = one
        .pages
        .iter()
        .flat_map(|p| p.texts())
        .filter(|t| t.starts_with('N') && t.chars().nth(1).is_some_and(|c| c.is_ascii_digit()))
        .collect();
    assert_eq!(titles.len(), 1, "{titles:?}");
}

#[test]
fn export_as_svg_writes_a_file_per_page() {
    let mut h = on_sample();
    h.state_mut().settings_mut().page_setup.selection_only = true;
    let dir = tempfile_dir();
    scripted(&mut h, vec![Some(dir.join("net.svg"))]);
    h.get_by_label("File").click();
    h.run();
    h.get_by_label("Export as PDF/SVG…").click();
    h.run();
    h.run();
    let names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(
        names.iter().any(|n| n == "net-1.svg" || n == "net.svg"),
        "{names:?}"
    );
}
