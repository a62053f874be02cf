//! Builds a sample project from its sources: `cargo run -p ladder-engine --example
//! build_sample -- projects/src/lathe-988ta projects/lathe-988ta.ldp`.
//!
//! Sources, next to each other: `NAME.il` (the program), `NAME.symbols.csv`
//! (`address,name,zh,en`), `NAME.data.csv` (`table,address,value,min,max,zh,en`, table one of
//! K D DT DC), `NAME.messages.csv` (`address,number,zh,en`), `NAME.mcodes.csv`
//! (`code,zh,en`, the M-code comment table) and, when the sample has them, `NAME.machine.ron`
//! (the machine model, docs/machine.md) and `NAME.scenarios.ron` (the saved scenarios,
//! docs/scenarios.md).

use ladder_engine::address::{Address, Area};
use ladder_engine::compiler::compile;
use ladder_engine::model::{Comments, DataRow, MCodeRow, MessageTable, Symbol, SymbolTable};
use ladder_engine::{file, il};
use std::process::exit;

fn records(path: &str) -> Vec<csv::StringRecord> {
    let mut r = csv::Reader::from_path(path).unwrap_or_else(|e| {
        eprintln!("{path}: {e}");
        exit(2)
    });
    r.records()
        .map(|x| {
            x.unwrap_or_else(|e| {
                eprintln!("{path}: {e}");
                exit(2)
            })
        })
        .collect()
}

fn comments(zh: &str, en: &str) -> Comments {
    let mut c = Comments::new();
    for (l, t) in [("zh", zh), ("en", en)] {
        if !t.trim().is_empty() {
            c.insert(l.into(), t.trim().into());
        }
    }
    c
}

fn address(path: &str, text: &str) -> Address {
    Address::parse(text).unwrap_or_else(|e| {
        eprintln!("{path}: {e}");
        exit(2)
    })
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (Some(stem), Some(out)) = (args.get(1), args.get(2)) else {
        eprintln!("usage: build_sample SOURCE_STEM OUT.ldp");
        exit(2)
    };
    let il_path = format!("{stem}.il");
    let text = std::fs::read_to_string(&il_path).unwrap_or_else(|e| {
        eprintln!("{il_path}: {e}");
        exit(2)
    });
    let imported = il::import(&text);
    let Some(mut project) = imported.project else {
        for d in &imported.compiled.diagnostics {
            eprintln!(
                "{}",
                ladder_text::diagnostics::render(d, &il_path, ladder_text::Lang::En)
            );
        }
        exit(1)
    };
    let sym_path = format!("{stem}.symbols.csv");
    let rows = records(&sym_path)
        .iter()
        .map(|r| Symbol {
            name: r[1].trim().to_string(),
            address: address(&sym_path, &r[0]),
            comments: comments(&r[2], &r[3]),
        })
        .collect();
    project.symbol_tables = vec![SymbolTable {
        name: "机床信号".into(),
        rows,
    }];
    let data_path = format!("{stem}.data.csv");
    for r in records(&data_path) {
        let a = address(&data_path, &r[1]);
        let value: i64 = r[2].trim().parse().unwrap_or_else(|_| {
            eprintln!("{data_path}: `{}` is not a value", &r[2]);
            exit(2)
        });
        if r[0].trim() == "K" {
            project
                .data
                .k
                .resize(project.data.k.len().max(usize::from(a.number) + 1), 0);
            project.data.k[usize::from(a.number)] = value as u8;
            continue;
        }
        let mut row = DataRow::new(a, value);
        let bound = |s: &str| s.trim().parse::<i64>().ok();
        row.set_min(bound(&r[3]));
        row.set_max(bound(&r[4]));
        row.set_value(value);
        row.symbol = project.symbol_of(a).unwrap_or_default().to_string();
        row.comments = comments(&r[5], &r[6]);
        match a.area {
            Area::D => project.data.d.push(row),
            Area::Dt => project.data.dt.push(row),
            Area::Dc => project.data.dc.push(row),
            _ => {
                eprintln!("{data_path}: {a} is not a K, D, DT or DC address");
                exit(2)
            }
        }
    }
    let msg_path = format!("{stem}.messages.csv");
    for r in records(&msg_path) {
        let a = address(&msg_path, &r[0]);
        let Some(k) = MessageTable::row_of(a) else {
            eprintln!("{msg_path}: {a} is not an A bit");
            exit(2)
        };
        project.messages.rows[k].number = r[1].trim().parse().ok();
        project.messages.rows[k].texts = comments(&r[2], &r[3]);
    }
    let m_path = format!("{stem}.mcodes.csv");
    for r in records(&m_path) {
        let code = r[0].trim().parse().unwrap_or_else(|_| {
            eprintln!("{m_path}: `{}` is not an M code", &r[0]);
            exit(2)
        });
        project.m_codes.push(MCodeRow {
            code,
            comments: comments(&r[1], &r[2]),
        });
    }
    // The machine model, when the sample has one.
    let machine_path = format!("{stem}.machine.ron");
    if let Ok(text) = std::fs::read_to_string(&machine_path) {
        project.machine = ron::from_str(&text).unwrap_or_else(|e| {
            eprintln!("{machine_path}: {e}");
            exit(2)
        });
    }
    // The saved scenarios, when the sample has some.
    let scenarios_path = format!("{stem}.scenarios.ron");
    if let Ok(text) = std::fs::read_to_string(&scenarios_path) {
        project.scenarios = ron::from_str(&text).unwrap_or_else(|e| {
            eprintln!("{scenarios_path}: {e}");
            exit(2)
        });
    }
    project.version.set(
        "",
        "Ladder Studio",
        "1.0",
        "GSK988TA 车床样例梯形图 / GSK988TA lathe sample ladder",
    );
    let compiled = compile(&project);
    for d in &compiled.diagnostics {
        eprintln!(
            "{}",
            ladder_text::diagnostics::render(d, out, ladder_text::Lang::En)
        );
    }
    if compiled.errors() + compiled.warnings() > 0 {
        exit(1);
    }
    file::save(&project, std::path::Path::new(out)).unwrap_or_else(|e| {
        eprintln!("{e}");
        exit(2)
    });
    let _ = std::fs::remove_file(format!("{out}.bak"));
    println!(
        "{out}: {} steps, 0 errors, 0 warnings",
        compiled.steps.total
    );
}
