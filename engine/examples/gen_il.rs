//! Prints a generated program's instruction list: `cargo run --example gen_il -- STEPS [mixed]`.
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let steps = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(5000);
    let mix = if args.get(2).map(String::as_str) == Some("bits") {
        ladder_engine::generate::Mix::BitLogic
    } else {
        ladder_engine::generate::Mix::Mixed
    };
    print!("{}", ladder_engine::generate::program_il(steps, mix, 1));
}
