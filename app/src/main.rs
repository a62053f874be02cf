//! The `ladder-studio` binary: hands its arguments to the library.

fn main() {
    let code = ladder_studio::cli::run(
        std::env::args_os(),
        &mut std::io::stdout().lock(),
        &mut std::io::stderr().lock(),
    );
    std::process::exit(code);
}
