use riprap::fluid::validation::lid_driven_cavity;
#[test]
fn explore() {
    for n in [16, 32, 64] {
        let t = std::time::Instant::now();
        let r = lid_driven_cavity(100, n, 1e-5, 60.0);
        println!("n {n}: t {:.1} steps {} res {:.1e} err u {:.4} v {:.4}  wall {:.2?}", r.time, r.steps, r.residual, r.max_error.0, r.max_error.1, t.elapsed());
        for (a, b) in r.u_centreline.iter().zip(riprap::fluid::validation::ghia_1982(100).unwrap().0) { print!("({:.4} {:.4} {:.4}) ", a.0, a.1, b.1); }
        println!();
    }
}
