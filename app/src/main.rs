//! The `ladder-studio` binary: the command line (`ladder_cli`), with the editor window to open
//! when no subcommand is given.

fn main() {
    let editor = |start: ladder_cli::EditorStart| {
        ladder_studio::gui::run(ladder_studio::gui::Start {
            project: start.project,
            run: start.run,
            nc: start.nc,
            lang: start.lang,
        })
    };
    let code = ladder_cli::run(
        std::env::args_os(),
        &editor,
        &mut std::io::stdout().lock(),
        &mut std::io::stderr().lock(),
    );
    std::process::exit(code);
}
