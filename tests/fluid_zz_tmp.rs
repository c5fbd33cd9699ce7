use glam::DVec3;
use riprap::fluid::{Boundaries, Fluid, FluidParameters, StaggeredGrid};
use std::f64::consts::TAU;
#[test]
fn tmp() {
    let nu = 0.1;
    let exact = |x: DVec3, t: f64| { let f = (-2.0 * nu * t).exp(); DVec3::new(x.x.sin() * x.z.cos() * f, 0.0, -x.x.cos() * x.z.sin() * f) };
    let n = 32;
    let mk = |cfl: f64| { let d = TAU / n as f64;
        let grid = StaggeredGrid::new([n, 1, n], DVec3::new(TAU, d, TAU), DVec3::ZERO);
        let mut par = FluidParameters::laminar(1.0, nu); par.time_step.cfl = cfl; par.time_step.viscous = 0.24;
        let mut f = Fluid::new(grid, Boundaries::periodic(), par).unwrap(); f.set_velocity(|x| exact(x, 0.0)); f };
    let adaptive = |cfl: f64| { let mut f = mk(cfl); let mut dts = vec![]; while f.time() < 1.0 { dts.push(f.step_adaptive(1.0)); } (f, dts) };
    let fixed = |steps: usize| { let mut f = mk(0.3); for _ in 0..steps { f.step(1.0/steps as f64); } f };
    let diff = |a: &Fluid, b: &Fluid| a.velocity()[0].iter().zip(b.velocity()[0]).fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    let reference = fixed(2000);
    for cfl in [0.3, 0.15, 0.075] { let (f, dts) = adaptive(cfl); println!("cfl {cfl}: steps {} err {:.3e} first dts {:?} last {:?}", f.steps(), diff(&f, &reference), &dts[..3], &dts[dts.len()-3..]); }
    for s in [40, 80, 160] { let f = fixed(s); println!("fixed {s}: err {:.3e}", diff(&f, &reference)); }
}
