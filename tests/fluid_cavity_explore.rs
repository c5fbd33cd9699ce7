use riprap::fluid::validation::{ghia_1982, lid_driven_cavity};
#[test]
#[ignore]
fn explore() {
    let re: u32 = std::env::var("RE").unwrap().parse().unwrap();
    let n: usize = std::env::var("N").unwrap().parse().unwrap();
    let t = std::time::Instant::now();
    let r = lid_driven_cavity(re, n, 1e-5, 200.0);
    println!("Re {re} n {n}: t {:.1} steps {} res {:.1e} err u {:.4} v {:.4}  wall {:.2?}", r.time, r.steps, r.residual, r.max_error.0, r.max_error.1, t.elapsed());
    let (gu, gv) = ghia_1982(re).unwrap();
    for (a, b) in r.u_centreline.iter().zip(gu) { print!("({:.4} {:.4} {:.4}) ", a.0, a.1, b.1); }
    println!();
    for (a, b) in r.v_centreline.iter().zip(gv) { print!("({:.4} {:.4} {:.4}) ", a.0, a.1, b.1); }
    println!();
}
