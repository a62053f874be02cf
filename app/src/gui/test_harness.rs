//! The editor's UI harness for the modules' own tests: the app on a project saved into a fresh
//! `tempfile` folder, driven headless through egui_kittest. (The integration tests in
//! `app/tests/` build on the same pattern in `app/tests/common/`.)

use super::LadderApp;
use super::i18n::Lang;
use egui_kittest::Harness;
use ladder_engine::model::Project;

thread_local! {
    /// The folders made for the test running on this thread, removed when its thread ends
    /// (each test has its own), after its harness and whatever that wrote as it closed.
    static FOLDERS: std::cell::RefCell<Vec<tempfile::TempDir>> =
        const { std::cell::RefCell::new(Vec::new()) };
}

/// The editor on a saved copy of `project` in language `lang`, after its first frames.
pub fn on_project(project: &Project, lang: Lang) -> Harness<'static, LadderApp> {
    let dir = tempfile::Builder::new()
        .prefix("ladder-ui-")
        .tempdir()
        .expect("a temporary folder");
    let path = dir.path().join("project.ldp");
    FOLDERS.with(|f| f.borrow_mut().push(dir));
    ladder_engine::file::save(project, &path).expect("the project saves");
    let mut h = Harness::builder()
        .with_size(egui::vec2(1280.0, 800.0))
        .build_eframe(move |cc| {
            let mut app = LadderApp::from_creation(cc, Some(path));
            app.settings.lang = lang;
            app
        });
    h.run();
    h
}
