//! The native scan engine against straight-line C: `cargo bench -p ladder-engine --bench native`.
//!
//! The 5000-step bit-logic program of `bench scan` is translated instruction by instruction
//! into one C function (each contact a shift and a mask, each coil a masked store: what a
//! hand-written PLC runtime that compiles to C does), with the bytes and the rung starts the
//! VM's lowering gives them, compiled with `gcc -O2`, and timed in the same run
//! as the interpreter and the native engine. With valgrind installed, all three are also
//! counted in machine instructions per step (callgrind; N and 2N scans, the difference),
//! which stays the same however busy the machine is. Code generation is timed too.
//!
//! `-- --no-valgrind` skips the counts. The binary runs itself as a child
//! (`-- --child ENGINE SCANS`) under callgrind.

use ladder_engine::Op;
use ladder_engine::compiler::{Program, compile};
use ladder_engine::generate::{Mix, program_il};
use ladder_engine::il;
use ladder_engine::model::{Operand, Project};
use ladder_engine::vm::cnc::NoCnc;
use ladder_engine::vm::native::Native;
use ladder_engine::vm::{Engine, IMAGE_BYTES, Layout, Vm};
use std::fmt::Write as _;
use std::path::Path;
use std::process::Command;
use std::time::Instant;

/// The benchmark's program.
fn project() -> Project {
    il::import(&program_il(5000, Mix::BitLogic, 1))
        .project
        .expect("generated programs draw")
}

fn vm(engine: Engine) -> Vm {
    let mut vm = Vm::new(&project()).expect("generated programs compile");
    assert_eq!(vm.set_engine(engine), engine, "{engine:?} is available");
    vm
}

/// The bit-logic program as the body of a C function over `m`, in the order the VM lowers it:
/// level 1, then level 2, which reads X and F from the copy latched at its cycle's start.
fn c_body(program: &Program, layout: &Layout) -> String {
    let mut c = String::new();
    for (b, block) in program.blocks.iter().enumerate() {
        let latched = b == 1;
        for net in &block.networks {
            // A network starts a rung, and so does each coil (the program has no MPS): an LD
            // there empties the stack instead of pushing on it.
            let mut rung_start = true;
            for i in &net.instrs {
                let (byte, bit) = match i.operands.first() {
                    Some(Operand::Addr(a)) => (
                        layout.loc(*a, latched).off as usize & (IMAGE_BYTES - 1),
                        a.bit.unwrap_or(0),
                    ),
                    _ => (0, 0),
                };
                let v = |inv: bool| {
                    let inv = if inv { " ^ 1" } else { "" };
                    format!("((m[{byte}] >> {bit}) & 1{inv})")
                };
                let line = match i.op {
                    Op::Ld | Op::Ldi => {
                        let v = v(i.op == Op::Ldi);
                        if rung_start {
                            format!("s = 0; a = {v};")
                        } else {
                            format!("s = s << 1 | a; a = {v};")
                        }
                    }
                    Op::And | Op::Ani => format!("a &= {};", v(i.op == Op::Ani)),
                    Op::Or | Op::Ori => format!("a |= {};", v(i.op == Op::Ori)),
                    Op::Orb => "a |= s & 1; s >>= 1;".to_string(),
                    Op::Anb => "a &= s & 1; s >>= 1;".to_string(),
                    Op::Out | Op::Outn => {
                        let inv = if i.op == Op::Outn { " ^ 1" } else { "" };
                        format!(
                            "m[{byte}] = (m[{byte}] & {}) | ((a{inv}) << {bit});",
                            !(1u8 << bit)
                        )
                    }
                    other => panic!("the bit-logic program has no {other:?}"),
                };
                rung_start = matches!(i.op, Op::Out | Op::Outn);
                let _ = writeln!(c, "  {line}");
            }
        }
    }
    c
}

/// A C program running the body `scans` times (argv[1]) and printing ns per scan.
fn c_program(body: &str) -> String {
    format!(
        r#"#include <stdio.h>
#include <stdlib.h>
#include <time.h>
static unsigned char image[{IMAGE_BYTES}];
__attribute__((noinline)) static void scan(unsigned char *m) {{
  unsigned a = 0; unsigned long long s = 0;
{body}  (void)s;
}}
int main(int argc, char **argv) {{
  long scans = argc > 1 ? atol(argv[1]) : 20000;
  for (int i = 0; i < {IMAGE_BYTES}; i++) image[i] = (unsigned char)(i * 37);
  for (int i = 0; i < 1000; i++) scan(image);
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  for (long i = 0; i < scans; i++) {{ scan(image); __asm__ volatile("" ::: "memory"); }}
  clock_gettime(CLOCK_MONOTONIC, &t1);
  double ns = (t1.tv_sec - t0.tv_sec) * 1e9 + (t1.tv_nsec - t0.tv_nsec);
  printf("%.1f\n", ns / scans);
  return 0;
}}
"#
    )
}

/// Nanoseconds per scan of `scans` back-to-back ticks.
fn time_vm(vm: &mut Vm, scans: u64) -> f64 {
    for _ in 0..1000 {
        vm.tick(&mut NoCnc);
    }
    let t = Instant::now();
    for _ in 0..scans {
        vm.tick(&mut NoCnc);
    }
    t.elapsed().as_nanos() as f64 / scans as f64
}

/// Callgrind's total for a command.
fn callgrind(program: &Path, args: &[String]) -> Option<u64> {
    let out = Command::new("valgrind")
        .args(["--tool=callgrind", "--callgrind-out-file=/dev/null"])
        .arg(program)
        .args(args)
        .output()
        .ok()?;
    String::from_utf8_lossy(&out.stderr).lines().find_map(|l| {
        let (_, n) = l.split_once("Collected :")?;
        n.trim().parse().ok()
    })
}

/// Instructions per scan: the difference between `n` and `2n` scans.
fn per_scan(program: &Path, args: impl Fn(u64) -> Vec<String>, n: u64) -> Option<f64> {
    let one = callgrind(program, &args(n))?;
    let two = callgrind(program, &args(2 * n))?;
    Some(two.saturating_sub(one) as f64 / n as f64)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if let Some(i) = args.iter().position(|a| a == "--child") {
        let engine = Engine::parse(&args[i + 1]).expect("an engine name");
        let scans: u64 = args[i + 2].parse().expect("a scan count");
        let mut vm = vm(engine);
        for _ in 0..1000 + scans {
            vm.tick(&mut NoCnc);
        }
        return;
    }
    let mut native = vm(Engine::Native);
    let mut interp = vm(Engine::Interpreter);
    let steps = {
        let before = native.executed_steps();
        native.tick(&mut NoCnc);
        (native.executed_steps() - before) as f64
    };

    let t = Instant::now();
    let runs = 20;
    for _ in 0..runs {
        std::hint::black_box(Native::new(native.code()).expect("x86-64"));
    }
    let gen_ms = t.elapsed().as_secs_f64() * 1e3 / f64::from(runs);
    let bytes = native.native().map_or(0, Native::len);
    println!("code generation, {steps} steps: {gen_ms:.2} ms, {bytes} bytes of machine code");

    let dir = std::env::temp_dir().join(format!("ladder-native-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let c_file = dir.join("scan.c");
    let c_exe = dir.join("scan");
    let program = compile(&project()).program;
    std::fs::write(&c_file, c_program(&c_body(&program, native.layout()))).expect("the C file");
    let gcc = Command::new("gcc")
        .args(["-O2", "-o"])
        .arg(&c_exe)
        .arg(&c_file)
        .status();
    let c_ok = matches!(gcc, Ok(s) if s.success());

    let scans = 20_000;
    // Interleaved rounds, each engine's best: the clock of a shared machine drifts.
    let (mut best_n, mut best_i, mut best_c) = (f64::MAX, f64::MAX, f64::MAX);
    for _ in 0..5 {
        best_n = best_n.min(time_vm(&mut native, scans));
        best_i = best_i.min(time_vm(&mut interp, scans / 4));
        if c_ok
            && let Ok(out) = Command::new(&c_exe).arg(scans.to_string()).output()
            && let Ok(ns) = String::from_utf8_lossy(&out.stdout).trim().parse::<f64>()
        {
            best_c = best_c.min(ns);
        }
    }
    println!(
        "bit-logic {steps} steps, by the clock (best of 5): native {:.3} ns/step, interpreter {:.3} ns/step",
        best_n / steps,
        best_i / steps
    );
    if c_ok {
        println!(
            "  gcc -O2 straight-line C {:.3} ns/step; native / C = {:.2}",
            best_c / steps,
            best_n / best_c
        );
    } else {
        println!("  gcc is not available: no C comparison");
    }

    if args.iter().any(|a| a == "--no-valgrind") {
        return;
    }
    let me = std::env::current_exe().expect("this benchmark's path");
    let child =
        |engine: &'static str| move |n: u64| vec!["--child".into(), engine.into(), n.to_string()];
    let n = per_scan(&me, child("native"), 500);
    let i = per_scan(&me, child("interp"), 100);
    let c = if c_ok {
        per_scan(&c_exe, |n| vec![n.to_string()], 500)
    } else {
        None
    };
    match (n, i) {
        (Some(n), Some(i)) => {
            println!(
                "instructions per step (callgrind): native {:.2}, interpreter {:.2}",
                n / steps,
                i / steps
            );
            if let Some(c) = c {
                println!(
                    "  gcc -O2 straight-line C {:.2}; native / C = {:.2}",
                    c / steps,
                    n / c
                );
            }
        }
        _ => println!("valgrind is not available: no instruction counts"),
    }
    if std::env::var_os("KEEP_C").is_none() {
        let _ = std::fs::remove_dir_all(&dir);
    }
}
