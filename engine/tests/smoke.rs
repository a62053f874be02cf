//! A first end-to-end check of the IL → ladder → IL path.
use ladder_engine::compiler::compile;
use ladder_engine::il;

#[test]
fn smoke() {
    let text = "LEVEL1\nLD X0000.5\nOUT G0008.4\nLEVEL2\nLD X0002.1\nOR Y0003.7\nANI X0002.2\nOUT Y0003.7\nLD R0001.0\nMPS\nAND R0002.0\nOUT R0003.0\nMRD\nLD R0004.0\nOR R0005.0\nANB\nOUT R0006.0\nMPP\nOUT R0007.0\nLD R0010.0\nTMRB T0000 DT0004 R0300.0\nLD R0011.0\nCALL P0001\nSUB P0001 \"TOOL\"\nLD R0012.0\nCODB 1 4 R0100 R0200 1 2 3 4\nLBL L0001\n";
    let imp = il::import(text);
    for d in &imp.compiled.diagnostics {
        eprintln!("{}", d.render("x"));
    }
    let p = imp.project.unwrap();
    let c = compile(&p);
    for d in &c.diagnostics {
        eprintln!("{}", d.render("x"));
    }
    let out = il::print(&c.program);
    eprintln!("{out}");
    let imp2 = il::import(&out);
    let c2 = compile(imp2.project.as_ref().unwrap());
    assert_eq!(il::print(&c2.program), out);
}
