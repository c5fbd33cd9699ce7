use riprap::scenario::{build, Source};
use std::path::PathBuf;

const BASE: &str = r#"[run]
name = "t"
end_time = 0.1

[domain]
min = [0.0, 0.0, 0.0]
max = [1.0, 1.0, 1.0]

[[material]]
name = "rock"
density = 2650.0
young_modulus = 1.0e8
poisson_ratio = 0.25
friction_coefficient = 0.5
"#;

fn show(extra: &str) {
    let text = format!("{BASE}{extra}");
    match Source::from_str(&text, "case.toml", PathBuf::from(".")) {
        Err(e) => println!("PARSE: {e}\n"),
        Ok(s) => match build(&s) {
            Err(e) => println!("BUILD: {e}\n"),
            Ok(_) => println!("OK\n"),
        },
    }
}

#[test]
fn explore() {
    show("\n[[wall]]\nkind = \"plane\"\nmaterial = \"rock\"\npoint=[0,0,0]\nnormal=[0,0,1]\nfoo = 1\n");
    show("\n[[wall]]\nkind = \"plane\"\nmaterial = \"rock\"\npoint=[0,0,0]\nnormal=[0,0,1]\nmotion = { kind = \"linear\", velocity = [1,0,0], sotp = 1 }\n");
    show("\n[[wall]]\nkind = \"plane\"\nmaterial = \"rock\"\npoint=[0,0,0]\nnormal=[0,0,1]\nmotion = { kind = \"linar\", velocity = [1,0,0] }\n");
    show("\n[[wall]]\nkind = \"plan\"\nmaterial = \"rock\"\npoint=[0,0,0]\nnormal=[0,0,1]\n");
    show("\n[[wall]]\nmaterial = \"rock\"\npoint=[0,0,0]\nnormal=[0,0,1]\n");
    show("\n[[wall]]\nkind = \"plane\"\nmaterial = \"rock\"\npoint=[0,0,0]\nnormal=[0,0,\"a\"]\n");
    show("\n[[spheres]]\nkind = \"list\"\nmaterial = \"rock\"\nspheres = [\n  { position = [0.5,0.5,0.5], diameter = 0.1 },\n  { position = [0.5,0.5,0.7], diameter = 0.1, colour = 1 },\n]\n");
    show("\n[[spheres]]\nkind = \"random\"\nmaterial = \"rock\"\nmin=[0,0,0]\nmax=[1,1,1]\nsizes = [ { diameter = 0.1, count = 3, foo = 2 } ]\n");
    show("\n[[spheres]]\nkind = \"random\"\nmaterial = \"rock\"\nmin=[0,0,0]\nmax=[1,1,1]\nsizes = [ { diameter = 0.1, count = 3 } ]\nbar = 2\n");
    show("\n[[spheres]]\nkind = \"random\"\nmaterial = \"rock\"\nmin=[0,0,0]\nmax=[1,1,1]\nsizes = [ { diameter = 0.1, count = \"x\" } ]\n");
    show("\n[[spheres]]\nkind = \"random\"\nmaterial = \"rock\"\nmin=[0,0,0]\nmax=[1,1,1]\nsizes = [ { diameter = 0.1, count = -3 } ]\n");
    show("\n[output]\nprobes = [0]\nfoo = 1\n");
    show("\n[contact]\nmodel = \"linear\"\n");
    show("\n[contact]\nmodel = \"lin\"\n");
    show("\n[[contact.pair]]\nmaterials = [\"rock\", \"rock\"]\nfoo = 1\n");
    show("\n[output]\nprobes = [0]\n");
    show("x = = 1\n");
}
