use riprap::scenario::{build, Source};
use std::path::PathBuf;
fn show(text: &str) {
    match Source::from_str(text, "case.toml", PathBuf::from(".")) {
        Err(e) => println!("PARSE: {e}\n"),
        Ok(s) => match build(&s) { Err(e) => println!("BUILD: {e}\n"), Ok(_) => println!("OK\n") },
    }
}
#[test]
fn explore() {
    show("");
    show("[domain]\nmin=[0,0,0]\nmax=[1,1,1]\n");
    show("[run]\r\nname='a'\r\nend_time=1\r\n[domain]\r\nmin=[0,0,0]\r\nmax=[1,1,1]\r\n[[material]]\r\nname='r'\r\ndensity=1\r\nyoung_modulus=1e8\r\npoisson_ratio=0.2\r\nfriction_coefficient=0.5\r\nfoo=1\r\n");
    show("spheres = [\n {kind='list', material='r', spheres=[{position=[0.5,0.5,0.5], diameter=0.1}]},\n {kind='lattice', material='r', foo=3},\n]\n[run]\nname='a'\nend_time=1\n[domain]\nmin=[0,0,0]\nmax=[1,1,1]\n[[material]]\nname='r'\ndensity=1\nyoung_modulus=1e8\npoisson_ratio=0.2\nfriction_coefficient=0.5\n");
    show("[run]\nname='a'\nend_time=1\n[domain]\nmin=[0,0,0]\nmax=[1,1,1]\n[[material]]\nname='r'\ndensity=1\nyoung_modulus=1e8\npoisson_ratio=0.2\nfriction_coefficient=0.5\n[[wall]]\nkind='plane'\nmaterial='r'\npoint=[0,0,0]\nnormal=[0,0,1]\n[[wall]]\nkind='plane'\nmaterial='r'\npoint=[0,0,0]\nnormal=[0,0,1]\nmotion={kind='linear', velocity=[1,0,0], start='x'}\n");
    show("[run]\nname='a'\nend_time=1\n[domain]\nmin=[0,0,0]\nmax=[1,1,1]\n[[material]]\nname='r'\ndensity=1\nyoung_modulus=1e8\npoisson_ratio=0.2\nfriction_coefficient=0.5\n[[wall]]\nkind='plane'\nmaterial='r'\npoint=[0,0,0]\nnormal=[0,0,1]\nmotion={kind='linear', start=1}\n");
}
